#include "src/report/report_page.hpp"

#include <cmath>
#include <fstream>

namespace hydrocoef::report::detail {
namespace {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string num(double value, int digits) {
  if (!std::isfinite(value)) return std::isnan(value) ? "n/a" : (value > 0 ? "inf" : "-inf");
  std::ostringstream out;
  out.precision(digits);
  out << value;
  return out.str();
}

bool Page::embed(const std::string& stem, const std::string& caption, const plot::Figure& figure, int height) {
  plot::RenderOptions options;
  options.width = 960;
  options.height = height;
  const auto files = plot::render(figure, plots_dir_ / (stem + ".svg"), options);
  result_.plots.push_back(files.image);
  html << "<figure id=\"" << html_escape(stem) << "\"><img alt=\"" << html_escape(caption) << "\" width=\""
       << options.width << "\" height=\"" << options.height << "\" src=\"data:image/svg+xml;base64,"
       << base64(read_file(files.image)) << "\"><figcaption>" << html_escape(caption) << " (values: <code>plots/"
       << html_escape(stem) << ".dat</code>)</figcaption></figure>\n";
  return true;
}

void Page::note(const std::string& caption, const std::string& why) {
  result_.notes.push_back(caption + ": " + why);
  html << "<p class=\"note\">" << html_escape(caption) << ": not drawn (" << html_escape(why) << ")</p>\n";
}

}  // namespace hydrocoef::report::detail
