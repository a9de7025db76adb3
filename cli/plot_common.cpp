// What every plot subcommand shares (cli/plot_common.hpp).
#include "cli/plot_common.hpp"

#include <cctype>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "src/core/damping_terms.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef::cli {
namespace {

plot::RenderOptions parse_size(const std::string& text) {
  const auto x = text.find('x');
  plot::RenderOptions options;
  try {
    if (x == std::string::npos) throw std::invalid_argument(text);
    std::size_t used_w = 0, used_h = 0;
    options.width = std::stoi(text.substr(0, x), &used_w);
    options.height = std::stoi(text.substr(x + 1), &used_h);
    if (used_w != x || used_h != text.size() - x - 1) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw InputError("--size '" + text + "': expected WIDTHxHEIGHT in pixels, e.g. 900x600");
  }
  return options;
}

void print_result(const plot::Figure& figure, const plot::RenderedFiles& files, const CommonPlotArgs& args) {
  const char* format = files.format == plot::ImageFormat::Png ? "png" : "svg";
  if (args.json) {
    nlohmann::json out = {{"title", figure.title},
                          {"image", files.image.string()},
                          {"data", files.data.string()},
                          {"script", files.script.string()},
                          {"format", format},
                          {"width", files.width},
                          {"height", files.height}};
    out["series"] = nlohmann::json::array();
    for (const auto& panel : figure.panels) {
      if (panel.map)
        out["series"].push_back(
            {{"panel", panel.title}, {"title", "colour map"}, {"points", panel.map->x.size() * panel.map->y.size()}});
      for (const auto& s : panel.series)
        out["series"].push_back({{"panel", panel.title}, {"title", s.title}, {"points", s.x.size()}});
    }
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  // The title holds names read from the database and the paths the user's
  // file name: each printed through escape::one_line.
  std::cout << "plot " << escape::one_line(figure.title) << "\n  wrote " << escape::one_line(files.image.string())
            << " (" << format << ", " << files.width << "x" << files.height << " px)\n  values "
            << escape::one_line(files.data.string()) << ", gnuplot script " << escape::one_line(files.script.string())
            << '\n';
}

}  // namespace

std::string default_image(const std::string& kind, const std::string& name) {
  std::string out = kind + "-";
  for (char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
  return out + ".png";
}

void render_and_print(const plot::Figure& figure, const std::string& default_name, const CommonPlotArgs& args) {
  const std::string image = args.output.value_or(default_name);
  plot::image_format(image);  // refuse a bad name before drawing anything
  const auto files = plot::render(figure, image, parse_size(args.size));
  print_result(figure, files, args);
}

/// surface_style: the image is -o only, since --output names the surface's output there.
void add_common(CLI::App* command, CommonPlotArgs& args, bool surface_style) {
  command->add_option(surface_style ? "-o" : "-o,--output", args.output,
                      "Image to write: FILE.png or FILE.svg (FILE.dat, FILE.gp beside it)");
  command->add_option("--size", args.size, "Image size WIDTHxHEIGHT [pixels]")->capture_default_str();
  command->add_flag("--json", args.json, "Print JSON: the files written and the series drawn");
}

std::vector<double> steady_forces(const std::vector<double>& taus, std::optional<double> from, std::optional<double> to,
                                  std::size_t count) {
  std::vector<double> out = taus;
  if (from || to) {
    if (!from || !to || !(*to > *from) || count < 2 || count > 1000)
      throw InputError("--tau-from/--tau-to/--count: expected FROM < TO and a count of 2 to 1000");
    for (std::size_t i = 0; i < count; ++i)
      out.push_back(*from + (*to - *from) * static_cast<double>(i) / static_cast<double>(count - 1));
  }
  if (out.empty()) throw InputError("plot steady: give --tau values or --tau-from, --tau-to and --count");
  return out;
}

std::string curves_base_name(const std::optional<std::string>& body, const std::optional<std::string>& dof,
                             const std::optional<std::string>& terms) {
  if (!body || !dof || !terms)
    throw InputError("plot curves: give a fit name, or --body, --dof and --terms as given to fit --by");
  return *body + ":" + *dof + "(" + format_damping_terms(parse_damping_terms(*terms)) + ")";
}

}  // namespace hydrocoef::cli
