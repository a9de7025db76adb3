// Figures rendered by gnuplot: valid PNG and SVG of the requested size, the
// data file holding exactly the plotted values, deterministic output, and
// clear errors when gnuplot is missing or fails.
#include "src/plot/figure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "src/core/error.hpp"
#include "tests/support/plot_data.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::plot {
namespace {

using test::PlotBlocks;
using test::TempDir;

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Width and height from a PNG's IHDR chunk; {0, 0} when not a PNG.
std::pair<unsigned, unsigned> png_size(const std::string& bytes) {
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || bytes.compare(12, 4, "IHDR") != 0)
    return {0, 0};
  auto be32 = [&](std::size_t at) {
    unsigned v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

PlotBlocks read_blocks(const std::filesystem::path& path) { return test::read_plot_blocks(path); }

Figure sample_figure() {
  Figure figure;
  figure.title = "test figure with 'quotes' and \"double quotes\"";
  Panel panel;
  panel.x_label = "u [m/s]";
  panel.y_label = "X [N]";
  Series points{"points", Series::Style::Points, 0, {0.1, 0.2, 0.3}, {1.0 / 3.0, 2.5e-7, -4.0}};
  Series line{"a line u|u|", Series::Style::Line, 1, {}, {}};
  for (int i = 0; i <= 50; ++i) {
    line.x.push_back(0.1 + 0.004 * i);
    line.y.push_back(std::sin(line.x.back()) * 1e-3);
  }
  panel.series = {points, line};
  panel.shaded.push_back({0.0, 0.1, std::nullopt, std::nullopt});
  panel.shaded_title = "outside";
  panel.x_range = std::array<double, 2>{0.0, 0.35};
  figure.panels.push_back(panel);
  return figure;
}

TEST(Figure, RendersPngOfTheRequestedSizeWithItsValues) {
  TempDir dir;
  RenderOptions options;
  options.width = 640;
  options.height = 480;
  const Figure figure = sample_figure();
  const auto files = render(figure, dir / "sub/one.png", options);
  EXPECT_EQ(files.format, ImageFormat::Png);
  EXPECT_EQ(files.data, dir / "sub/one.dat");
  EXPECT_EQ(files.script, dir / "sub/one.gp");
  const auto [w, h] = png_size(slurp(files.image));
  EXPECT_EQ(w, 640u);
  EXPECT_EQ(h, 480u);
  const auto blocks = read_blocks(files.data);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].first, "points");
  ASSERT_EQ(blocks[0].second.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(blocks[0].second[i][0],
              figure.panels[0].series[0].x[i]);  // exact: round-trip text
    EXPECT_EQ(blocks[0].second[i][1], figure.panels[0].series[0].y[i]);
  }
  ASSERT_EQ(blocks[1].second.size(), 51u);
  EXPECT_EQ(blocks[1].second[50][1], figure.panels[0].series[1].y[50]);
  const std::string script = slurp(files.script);
  EXPECT_NE(script.find("pngcairo size 640,480"), std::string::npos);
  EXPECT_NE(script.find("rectangle from first 0, graph 0 to first 0.1, graph 1"), std::string::npos) << script;
}

TEST(Figure, RendersSvgDeterministically) {
  TempDir dir;
  const auto a = render(sample_figure(), dir / "a.svg");
  const auto b = render(sample_figure(), dir / "b.svg");
  const std::string svg = slurp(a.image);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("width=\"900\" height=\"600\""), std::string::npos) << svg.substr(0, 400);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("a line u|u|"),
            std::string::npos);  // legend text, noenhanced
  // Same figure, same bytes (only the file names in the scripts differ).
  EXPECT_EQ(svg, slurp(b.image));
  EXPECT_EQ(slurp(a.data), slurp(b.data));
}

TEST(Figure, ColourMapBlockIsAGrid) {
  TempDir dir;
  Figure figure;
  figure.title = "map";
  Panel panel;
  ColourMap map;
  map.x = {0.0, 1.0, 2.0};
  map.y = {10.0, 20.0};
  for (double y : map.y)
    for (double x : map.x) map.z.push_back(x + y);
  map.z_label = "z";
  panel.map = map;
  panel.series.push_back({"runs", Series::Style::Points, 6, {0.0, 2.0}, {10.0, 20.0}});
  figure.panels.push_back(panel);
  const auto files = render(figure, dir / "map.svg");
  const auto blocks = read_blocks(files.data);
  ASSERT_EQ(blocks.size(), 2u);
  ASSERT_EQ(blocks[0].second.size(), 6u);
  EXPECT_EQ(blocks[0].second[4], (std::vector<double>{1.0, 20.0, 21.0}));
  EXPECT_NE(slurp(files.script).find("with image"), std::string::npos);
}

TEST(Figure, RefusesBadInput) {
  TempDir dir;
  EXPECT_THROW(image_format("plot.jpg"), InputError);
  Figure figure = sample_figure();
  figure.panels[0].series[0].y.pop_back();
  EXPECT_THROW(render(figure, dir / "x.png"), InputError);
  EXPECT_THROW(render(Figure{}, dir / "x.png"), InputError);
  RenderOptions tiny;
  tiny.width = 10;
  EXPECT_THROW(render(sample_figure(), dir / "x.png", tiny), InputError);
}

/// Sets an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(Figure, MissingOrFailingGnuplotIsAClearInputError) {
  TempDir dir;
  {
    ScopedEnv env("HYDROCOEF_GNUPLOT", "/nonexistent/gnuplot");
    try {
      render(sample_figure(), dir / "x.png");
      FAIL() << "expected InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("gnuplot-nox"), std::string::npos) << e.what();
    }
  }
  {
    ScopedEnv env("HYDROCOEF_GNUPLOT", "false");
    try {
      render(sample_figure(), dir / "x.png");
      FAIL() << "expected InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("gnuplot failed"), std::string::npos) << e.what();
    }
  }
  // gnuplot's own error is quoted: an unwritable output directory.
  EXPECT_THROW(render(sample_figure(), "/proc/hydrocoef-no/x.png"), InputError);
}

}  // namespace
}  // namespace hydrocoef::plot
