#include "src/plot/figure.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "src/core/atomic_file.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"

extern char** environ;

namespace hydrocoef::plot {
namespace {

// Colour-blind-safe palette (Okabe-Ito), then greys.
constexpr std::array<const char*, 8> kPalette = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                                 "#E69F00", "#56B4E9", "#000000", "#999999"};
constexpr const char* kShade = "#DDDDDD";

// A number as gnuplot reads it: shortest_number, but NaN and the infinities
// as gnuplot spells them ("NaN", "Inf", "-Inf").
std::string gnuplot_number(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "Inf" : "-Inf";
  return shortest_number(value);
}

std::string quoted(const std::string& text) { return escape::gnuplot_string(text); }

/// A gnuplot string expression of several lines: single-quoted pieces (which
/// gnuplot never expands) joined by a double-quoted line feed.
std::string joined_lines(const std::vector<std::string>& lines) {
  if (lines.empty()) return "''";
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i) out += (i ? ".\"\\n\"." : "") + quoted(lines[i]);
  return out;
}

std::string lower_extension(const std::filesystem::path& path) { return lower(path.extension().string()); }

void check_figure(const Figure& figure) {
  if (figure.panels.empty()) throw InputError("plot '" + figure.title + "': nothing to draw (no panels)");
  for (const auto& panel : figure.panels) {
    bool any = panel.map.has_value();
    for (const auto& s : panel.series) {
      if (s.x.size() != s.y.size())
        throw InputError("plot series '" + s.title + "': " + std::to_string(s.x.size()) + " x values but " +
                         std::to_string(s.y.size()) + " y values");
      if ((s.style == Series::Style::Band) != !s.y_high.empty() ||
          (s.style == Series::Style::Band && s.y_high.size() != s.x.size()))
        throw InputError("plot series '" + s.title + "': a band needs one upper value per x value, other series none");
      any = any || !s.x.empty();
    }
    if (!any) throw InputError("plot panel '" + panel.title + "': nothing to draw (no values)");
    if (panel.map) {
      const auto& m = *panel.map;
      if (m.x.size() < 2 || m.y.size() < 2 || m.z.size() != m.x.size() * m.y.size())
        throw InputError("colour map '" + panel.title + "': expected at least a 2 x 2 grid with nx * ny values");
      for (double z : m.z)
        if (!std::isfinite(z)) throw InputError("colour map '" + panel.title + "': a value is not finite");
    }
  }
}

/// Index of each block in the data file: per panel, the map (if any) then
/// each non-empty series; -1 for an empty series.
struct BlockIndex {
  std::vector<int> map;                  ///< per panel, -1 when none
  std::vector<std::vector<int>> series;  ///< per panel, per series
};

BlockIndex block_index(const Figure& figure) {
  BlockIndex index;
  int next = 0;
  for (const auto& panel : figure.panels) {
    index.map.push_back(panel.map ? next++ : -1);
    auto& list = index.series.emplace_back();
    for (const auto& s : panel.series) list.push_back(s.x.empty() ? -1 : next++);
  }
  return index;
}

void write_file(const std::filesystem::path& path, const std::string& text) { write_file_atomically(path, text); }

/// Runs `program script` with stdout and stderr to `log`, an existing file
/// (a TemporaryFile, never followed if a link); returns the exit status, or
/// throws when the program cannot be started.
int run_gnuplot(const std::string& program, const std::filesystem::path& script, const std::filesystem::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_TRUNC | O_NOFOLLOW, 0);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::string arg0 = program;
  std::string arg1 = script.string();
  char* argv[] = {arg0.data(), arg1.data(), nullptr};
  pid_t pid = 0;
  const int spawned = program.find('/') == std::string::npos
                          ? posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv, environ)
                          : posix_spawn(&pid, program.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
    throw InputError("cannot run gnuplot ('" + program + "': " + std::strerror(spawned) +
                     "); install Debian's gnuplot-nox package or set "
                     "HYDROCOEF_GNUPLOT to the gnuplot program");
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw InputError("gnuplot: waitpid failed (" + std::string(std::strerror(errno)) + ")");
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

/// Whether an image ends as a whole file of its format does: PNG with its
/// IEND chunk, SVG with its closing tag.
bool image_is_whole(const std::string& bytes, ImageFormat format) {
  if (format == ImageFormat::Png) {
    static const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
    return bytes.size() >= iend.size() && bytes.compare(bytes.size() - iend.size(), iend.size(), iend) == 0;
  }
  const std::size_t end = bytes.rfind("</svg>");
  return end != std::string::npos && bytes.find_first_not_of(" \t\r\n", end + 6) == std::string::npos;
}

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The line of gnuplot's messages that says what went wrong.
std::string first_error_line(const std::string& log) {
  std::istringstream in(log);
  std::string line, last;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t^") == std::string::npos) continue;
    if (line.find("rror") != std::string::npos) return line;
    last = line;
  }
  return last;
}

}  // namespace

ImageFormat image_format(const std::filesystem::path& image) {
  const std::string ext = lower_extension(image);
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".svg") return ImageFormat::Svg;
  throw InputError(image.string() + ": expected an image file name ending in .png or .svg");
}

std::string data_file_text(const Figure& figure) {
  const BlockIndex index = block_index(figure);
  std::string out = "# hydrocoef plot data: " + escape::gnuplot_comment(figure.title) +
                    "\n# one block per series (gnuplot index), separated by "
                    "two blank lines\n";
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const Panel& panel = figure.panels[p];
    if (panel.map) {
      const auto& m = *panel.map;
      out += "# block " + std::to_string(index.map[p]) + ": colour map of " + escape::gnuplot_comment(panel.title) +
             "\n# x y z\n";
      for (std::size_t j = 0; j < m.y.size(); ++j) {
        for (std::size_t i = 0; i < m.x.size(); ++i)
          out += gnuplot_number(m.x[i]) + " " + gnuplot_number(m.y[j]) + " " + gnuplot_number(m.z[j * m.x.size() + i]) +
                 "\n";
        out += "\n";
      }
      out += "\n";
    }
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const Series& series = panel.series[s];
      if (index.series[p][s] < 0) continue;
      const bool band = series.style == Series::Style::Band;
      out += "# block " + std::to_string(index.series[p][s]) + ": " + escape::gnuplot_comment(series.title) +
             (band ? "\n# x y_low y_high\n" : "\n# x y\n");
      for (std::size_t i = 0; i < series.x.size(); ++i)
        out += gnuplot_number(series.x[i]) + " " + gnuplot_number(series.y[i]) +
               (band ? " " + gnuplot_number(series.y_high[i]) : std::string()) + "\n";
      out += "\n\n";
    }
  }
  return out;
}

namespace {

std::string script_text(const Figure& figure, const std::filesystem::path& data, const std::filesystem::path& image,
                        ImageFormat format, const RenderOptions& options) {
  const BlockIndex index = block_index(figure);
  const bool png = format == ImageFormat::Png;
  std::ostringstream gp;
  gp << "# hydrocoef plot: " << escape::gnuplot_comment(figure.title) << "\n";
  gp << "set encoding utf8\n";
  if (png)
    gp << "set terminal pngcairo size " << options.width << "," << options.height
       << " noenhanced font 'sans,10' background rgb 'white'\n";
  else
    gp << "set terminal svg size " << options.width << "," << options.height
       << " noenhanced font 'sans,10' background rgb 'white'\n";
  gp << "set output " << quoted(image.string()) << "\n";
  gp << "set grid lc rgb '#E0E0E0'\nset key below left Left reverse samplen "
        "2\nset border lw 1\n";
  // Tic labels of up to 6 significant digits: gnuplot's default repeats a
  // label where small values (a moment of 1e-7 N m, an sd of 3.5e-5) differ
  // in a digit it leaves out.
  gp << "set format x '%.6g'\nset format y '%.6g'\nset format cb '%.6g'\n";
  gp << "set palette defined (0 '#440154', 1 '#3B528B', 2 '#21918C', 3 "
        "'#5EC962', 4 '#FDE725')\n";
  const std::string file = quoted(data.string());
  if (figure.panels.size() > 1)
    gp << "set multiplot layout " << figure.panels.size() << ",1 title " << quoted(figure.title) << "\n";
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const Panel& panel = figure.panels[p];
    // One panel: the figure's title over the panel's, on two lines.
    std::vector<std::string> lines;
    if (figure.panels.size() == 1 && !figure.title.empty()) lines.push_back(figure.title);
    if (!panel.title.empty()) lines.push_back(panel.title);
    gp << "unset object\nset title " << joined_lines(lines) << "\n";
    gp << "set xlabel " << quoted(panel.x_label) << "\nset ylabel " << quoted(panel.y_label) << "\n";
    if (panel.x_range)
      gp << "set xrange [" << gnuplot_number((*panel.x_range)[0]) << ":" << gnuplot_number((*panel.x_range)[1])
         << "]\n";
    else
      gp << "set autoscale x\n";
    if (panel.y_range)
      gp << "set yrange [" << gnuplot_number((*panel.y_range)[0]) << ":" << gnuplot_number((*panel.y_range)[1])
         << "]\n";
    else
      gp << "set autoscale y\n";
    if (panel.map) {
      gp << "set colorbox\nset cblabel " << quoted(panel.map->z_label) << " offset 1.5,0\nset autoscale cb\n";
    } else {
      gp << "unset colorbox\n";
    }
    int object = 1;
    for (const auto& r : panel.shaded) {
      gp << "set object " << object++ << " rectangle from first " << gnuplot_number(r.x0) << ", "
         << (r.y0 ? "first " + gnuplot_number(*r.y0) : std::string("graph 0")) << " to first " << gnuplot_number(r.x1)
         << ", " << (r.y1 ? "first " + gnuplot_number(*r.y1) : std::string("graph 1")) << " behind fc rgb '" << kShade
         << "' fs solid 1.0 noborder\n";
    }
    std::vector<std::string> clauses;
    if (panel.map)
      clauses.push_back(file + " index " + std::to_string(index.map[p]) + " using 1:2:3 with image notitle");
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const Series& series = panel.series[s];
      if (index.series[p][s] < 0) continue;
      const std::string colour = kPalette[series.colour % kPalette.size()];
      std::string clause = file + " index " + std::to_string(index.series[p][s]) +
                           (series.style == Series::Style::Band ? " using 1:2:3 with " : " using 1:2 with ");
      switch (series.style) {
        case Series::Style::Band:
          clause += "filledcurves fc rgb '" + colour + "' fs transparent solid 0.25 noborder";
          break;
        case Series::Style::Points: clause += "points pt 7 ps 0.8 lc rgb '" + colour + "'"; break;
        case Series::Style::Line: clause += "lines lw 2 lc rgb '" + colour + "'"; break;
        case Series::Style::DashedLine: clause += "lines lw 2 dt 2 lc rgb '" + colour + "'"; break;
      }
      clause += series.title.empty() ? " notitle" : " title " + quoted(series.title);
      clauses.push_back(clause);
    }
    if (!panel.shaded.empty() && !panel.shaded_title.empty())
      clauses.push_back(std::string("keyentry with boxes fs solid 1.0 fc rgb '") + kShade + "' title " +
                        quoted(panel.shaded_title));
    gp << "plot ";
    for (std::size_t c = 0; c < clauses.size(); ++c) gp << (c ? ", \\\n     " : "") << clauses[c];
    gp << "\n";
  }
  if (figure.panels.size() > 1) gp << "unset multiplot\n";
  gp << "unset output\n";
  return gp.str();
}

}  // namespace

std::string gnuplot_script(const Figure& figure, const std::filesystem::path& data, const std::filesystem::path& image,
                           const RenderOptions& options) {
  return script_text(figure, data, image, image_format(image), options);
}

RenderedFiles render(const Figure& figure, const std::filesystem::path& image, const RenderOptions& options) {
  RenderedFiles files;
  files.format = image_format(image);
  if (options.width < 200 || options.width > 4000 || options.height < 150 || options.height > 4000)
    throw InputError("plot size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                     ": expected a width of 200 to 4000 and a height of 150 to 4000 pixels");
  check_figure(figure);
  const std::filesystem::path absolute = std::filesystem::absolute(image);
  // The script names the image and data files in gnuplot strings, which
  // cannot hold a line break: such a path is refused, never altered.
  if (escape::one_line(absolute.string()) != absolute.string())
    throw InputError(image.string() + ": expected an image path of printable UTF-8 without control characters");
  const std::filesystem::path dir = absolute.parent_path();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the directory (" + ec.message() + ")");
  files.image = absolute;
  files.data = std::filesystem::path(absolute).replace_extension(".dat");
  files.script = std::filesystem::path(absolute).replace_extension(".gp");
  files.width = options.width;
  files.height = options.height;
  write_file(files.data, data_file_text(figure));
  write_file(files.script, gnuplot_script(figure, files.data, files.image, options));
  // gnuplot draws into a temporary beside the image, renamed onto it only
  // when gnuplot succeeded: the image is whole or not there. The script kept
  // for the user names the image itself; the one run names the temporary.
  // Every temporary is created here first (TemporaryFile): gnuplot only
  // truncates files hydrocoef made, never a link planted at their names.
  TemporaryFile drawing(files.image);
  const TemporaryFile run_script(files.script);  // never committed: removed at the end
  write_file(run_script.temporary(), script_text(figure, files.data, drawing.temporary(), files.format, options));

  const char* configured = std::getenv("HYDROCOEF_GNUPLOT");
  const std::string program = configured && *configured ? configured : "gnuplot";
  const TemporaryFile log(std::filesystem::path(absolute).replace_extension(".gnuplot.log"));  // never committed
  const int status = run_gnuplot(program, run_script.temporary(), log.temporary());
  const std::string messages = read_all(log.temporary());
  if (status == 127)
    throw InputError("cannot run gnuplot ('" + program +
                     "' not found); install Debian's gnuplot-nox package or "
                     "set HYDROCOEF_GNUPLOT");
  if (status != 0)
    throw InputError("gnuplot failed on " + files.script.string() + " (exit " + std::to_string(status) +
                     "): " + printable_text(first_error_line(messages), 300));
  if (!std::filesystem::exists(drawing.temporary()) || std::filesystem::file_size(drawing.temporary()) == 0)
    throw InputError("gnuplot wrote no image " + files.image.string() + ": " +
                     printable_text(first_error_line(messages), 300));
  // gnuplot may exit 0 after a failed write (a full disk): the image must end
  // as its format ends.
  if (!image_is_whole(read_all(drawing.temporary()), files.format))
    throw InputError("cannot write '" + files.image.string() +
                     "': gnuplot left it incomplete (a full disk or a file-size limit?)");
  drawing.commit();
  return files;
}

}  // namespace hydrocoef::plot
