// Figures drawn by gnuplot: a plot is described as plain data (panels of
// point and line series, an optional colour map, shaded rectangles), written
// as a gnuplot script and a data file beside the image, and rendered by
// running Debian's gnuplot (terminals pngcairo and svg) as a child process.
//
// Files for an image PATH/NAME.png or PATH/NAME.svg:
//   NAME.dat  every plotted number, one block per series (gnuplot `index`),
//             blocks separated by two blank lines, each opened by a comment
//             line "# block K: TITLE" and a comment naming its columns;
//             numbers in shortest round-trip form, so a reader gets exactly
//             the values that were drawn.
//   NAME.gp   the gnuplot script (rerun it with `gnuplot NAME.gp`).
// Output is deterministic: the same figure gives the same bytes.
//
// Units are the caller's: labels carry them; numbers are plotted as given.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace hydrocoef::plot {

/// One set of (x, y) values drawn as points or as a line.
struct Series {
  /// Band: the region between y (lower edge) and y_high (upper edge),
  /// shaded in the series' colour, e.g. a percentile band of a simulation.
  enum class Style { Points, Line, DashedLine, Band };
  std::string title;  ///< legend text; empty: no legend entry
  Style style = Style::Line;
  std::size_t colour = 0;  ///< index into a fixed palette; points and line of one level share it
  std::vector<double> x;
  std::vector<double> y;       ///< same length as x
  std::vector<double> y_high;  ///< Band only: the upper edge, same length as x
};

/// Values z(x, y) on a regular grid drawn as a coloured map.
struct ColourMap {
  std::vector<double> x;  ///< increasing, size nx
  std::vector<double> y;  ///< increasing, size ny
  std::vector<double> z;  ///< z[j * nx + i] at (x[i], y[j])
  std::string z_label;    ///< colour-bar label with its unit
};

/// A grey rectangle behind the data, e.g. a region outside a surface's range.
/// Missing y bounds reach the panel's edge.
struct ShadedRegion {
  double x0 = 0.0, x1 = 0.0;
  std::optional<double> y0, y1;
};

struct Panel {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<Series> series;
  std::optional<ColourMap> map;
  std::vector<ShadedRegion> shaded;
  std::string shaded_title;  ///< legend text of the shaded regions
  std::optional<std::array<double, 2>> x_range;
  std::optional<std::array<double, 2>> y_range;
};

/// Panels are stacked top to bottom in one image.
struct Figure {
  std::string title;
  std::vector<Panel> panels;
};

enum class ImageFormat { Png, Svg };

/// By the file's extension (.png or .svg, any case); InputError otherwise.
ImageFormat image_format(const std::filesystem::path& image);

struct RenderedFiles {
  std::filesystem::path image;
  std::filesystem::path data;    ///< NAME.dat beside the image
  std::filesystem::path script;  ///< NAME.gp beside the image
  ImageFormat format = ImageFormat::Png;
  int width = 0;   ///< pixels
  int height = 0;  ///< pixels
};

struct RenderOptions {
  int width = 900;   ///< pixels, 200..4000
  int height = 600;  ///< pixels per image (all panels), 150..4000
};

/// Writes NAME.dat and NAME.gp and runs gnuplot on them to write the image.
/// The program is `gnuplot` on PATH, or $HYDROCOEF_GNUPLOT when set.
/// InputError when the figure is empty or inconsistent (series of unequal
/// lengths, a non-finite value in a map), the directory cannot be written,
/// gnuplot is missing ("install Debian's gnuplot-nox") or fails (its first
/// error line is quoted), or it produced no image.
RenderedFiles render(const Figure& figure, const std::filesystem::path& image, const RenderOptions& options = {});

/// The gnuplot script render() writes, for the given data file and image.
std::string gnuplot_script(const Figure& figure, const std::filesystem::path& data, const std::filesystem::path& image,
                           const RenderOptions& options);
/// The data file render() writes.
std::string data_file_text(const Figure& figure);

}  // namespace hydrocoef::plot
