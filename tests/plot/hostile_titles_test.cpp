// gnuplot scripts with every name of the hostile corpus as the figure, panel,
// axis, colour-bar, series and shading titles, run by the real gnuplot: no
// command runs (the corpus tries backquotes, system(), macros and new
// lines, each touching a file PWNED), the only files are the image and its
// .dat and .gp, and the SVG is well-formed XML.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <set>
#include <string>

#include "src/core/error.hpp"
#include "src/plot/figure.hpp"
#include "tests/support/hostile_names.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/xml_numbers.hpp"

namespace hydrocoef::plot {
namespace {

using test::TempDir;

bool gnuplot_present() { return std::system("gnuplot --version > /dev/null 2>&1") == 0; }

Figure figure_named(const std::string& name, bool two_panels) {
  Figure figure;
  figure.title = name;
  for (int p = 0; p < (two_panels ? 2 : 1); ++p) {
    Panel panel;
    panel.title = name;
    panel.x_label = name;
    panel.y_label = name;
    Series series;
    series.title = name;
    series.x = {0.0, 1.0, 2.0};
    series.y = {1.0, 0.5, 2.0};
    panel.series.push_back(series);
    panel.shaded.push_back({1.5, 2.0, std::nullopt, std::nullopt});
    panel.shaded_title = name;
    if (p == 1) panel.map = ColourMap{{0.0, 1.0}, {0.0, 1.0}, {1.0, 2.0, 3.0, 4.0}, name};
    figure.panels.push_back(panel);
  }
  return figure;
}

// Runs the test body in `dir` (gnuplot's working directory is hydrocoef's).
class InDirectory {
 public:
  explicit InDirectory(const std::filesystem::path& dir) : previous_(std::filesystem::current_path()) {
    std::filesystem::current_path(dir);
  }
  ~InDirectory() { std::filesystem::current_path(previous_); }

 private:
  std::filesystem::path previous_;
};

TEST(HostileNamesInGnuplot, NoCommandRunsAndTheSvgIsWellFormed) {
  if (!gnuplot_present()) GTEST_SKIP() << "gnuplot is not installed";
  TempDir dir;
  InDirectory here(dir.path());
  const auto names = test::hostile_names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    SCOPED_TRACE(testing::PrintToString(names[i]));
    const bool png = i % 8 == 0;
    const std::filesystem::path image = dir / (png ? "plot.png" : "plot.svg");
    ASSERT_NO_THROW(render(figure_named(names[i], i % 2 == 1), image, {400, 300}));
    if (!png) {
      const auto root = test::read_xml(image);
      ASSERT_TRUE(root) << "ill-formed SVG";
      EXPECT_STREQ(root->GetName(), "svg");
    }
    std::set<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
      files.insert(entry.path().filename().string());
    for (const auto& file : files)
      EXPECT_TRUE(file == "plot.png" || file == "plot.svg" || file == "plot.dat" || file == "plot.gp") << file;
    ASSERT_FALSE(std::filesystem::exists(dir / "PWNED"));
    ASSERT_FALSE(std::filesystem::exists("/tmp/PWNED"));
  }
}

TEST(HostileNamesInGnuplot, AnImagePathWithALineBreakIsRefusedNotAltered) {
  TempDir dir;
  try {
    render(figure_named("a", false), dir / "a\nb.svg");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("control characters"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace hydrocoef::plot
