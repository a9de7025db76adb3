// The report page being written (src/report/report.hpp): its HTML, and the
// figures rendered into plots/ and embedded in it. Shared by the files that
// write the report's sections; not part of the library's interface.
#pragma once

#include <filesystem>
#include <sstream>
#include <string>

#include "src/core/error.hpp"
#include "src/plot/figure.hpp"
#include "src/report/report.hpp"

namespace hydrocoef::report::detail {

/// A number for a table cell: `digits` significant digits; "n/a", "inf" or
/// "-inf" for a value that is not finite.
std::string num(double value, int digits = 6);

class Page {
 public:
  Page(std::filesystem::path plots_dir, ReportResult& result) : plots_dir_(std::move(plots_dir)), result_(result) {}
  std::ostringstream html;

  /// Renders a figure to plots/STEM.svg and embeds it in a <figure
  /// id="STEM">; a figure that cannot be made or drawn (InputError) becomes
  /// a note on the page and in the result. Returns whether it was drawn.
  template <typename MakeFigure>
  bool figure(const std::string& stem, const std::string& caption, MakeFigure make, int height = 560) {
    try {
      return embed(stem, caption, make(), height);
    } catch (const InputError& e) {
      note(caption, e.what());
      return false;
    }
  }

  ReportResult& result() { return result_; }

 private:
  bool embed(const std::string& stem, const std::string& caption, const plot::Figure& figure, int height);
  void note(const std::string& caption, const std::string& why);

  std::filesystem::path plots_dir_;
  ReportResult& result_;
};

}  // namespace hydrocoef::report::detail
