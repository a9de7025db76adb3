// The plots of include/hydrocoef/plot.hpp: `hydrocoef plot` as library calls.
// Each makes its figure (src/plot), draws it through gnuplot (src/plot/figure)
// and reports the files written, as the command prints them.
#include "src/api/internal.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "src/api/vehicle_inputs.hpp"
#include "src/core/damping_terms.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/plot/history_plot.hpp"
#include "src/plot/plots.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

/// "asr-v:X(1,u,u|u|)" -> "fit-asr-v_X_1_u_u_u_.png": a default image name.
std::string default_image(const std::string& kind, const std::string& name) {
  std::string out = kind + "-";
  for (char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
  return out + ".png";
}

/// "900x600" as pixels; InputError naming --size otherwise.
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

/// Draws the figure to the image (`image.image` or the default name) and reports the files.
PlotFiles render(const plot::Figure& figure, const std::string& default_name, const ImageOptions& image,
                 const std::string& default_size = "900x600") {
  image.validate();
  const std::string path = image.image.empty() ? default_name : image.image;
  plot::image_format(path);  // refuse a bad name before drawing anything
  const auto files = plot::render(figure, path, parse_size(image.size.empty() ? default_size : image.size));
  PlotFiles out;
  out.title = figure.title;
  out.image = files.image.string();
  out.data = files.data.string();
  out.script = files.script.string();
  out.format = files.format == plot::ImageFormat::Png ? "png" : "svg";
  out.width = files.width;
  out.height = files.height;
  for (const auto& panel : figure.panels) {
    if (panel.map) out.series.push_back({panel.title, "colour map", panel.map->x.size() * panel.map->y.size()});
    for (const auto& s : panel.series) out.series.push_back({panel.title, s.title, s.x.size()});
  }
  return out;
}

/// The store of a database, its mutex held by the caller.
RunDatabase& store_of(const Database& database) { return Database::Access::impl(database).open_store(); }

}  // namespace

void ImageOptions::validate() const {
  if (!size.empty()) parse_size(size);
  if (!image.empty()) plot::image_format(image);
}

std::string PlotFiles::text() const {
  // The title holds names read from the database and the paths the user's
  // file names: each printed through escape::one_line.
  std::ostringstream out;
  out << "plot " << escape::one_line(title) << "\n  wrote " << escape::one_line(image) << " (" << format << ", "
      << width << "x" << height << " px)\n  values " << escape::one_line(data) << ", gnuplot script "
      << escape::one_line(script) << '\n';
  return out.str();
}

std::string PlotFiles::json() const {
  nlohmann::json out = {{"title", title},   {"image", image}, {"data", data},    {"script", script},
                        {"format", format}, {"width", width}, {"height", height}};
  out["series"] = nlohmann::json::array();
  for (const auto& s : series) out["series"].push_back({{"panel", s.panel}, {"title", s.title}, {"points", s.points}});
  return escape::json_text(out, 2) + '\n';
}

PlotFiles plot_fit(const Database& database, const std::string& name, const ImageOptions& image) {
  image.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  return render(plot::fit_figure(store_of(database), name), default_image("fit", name), image);
}

void CurvesPlotOptions::validate() const {
  if (name.empty() && (body.empty() || dof.empty() || terms.empty()))
    throw InputError("plot curves: give a fit name, or --body, --dof and --terms as given to fit --by");
  parse_curve(curve);
}

PlotFiles plot_curves(const Database& database, const CurvesPlotOptions& options, const ImageOptions& image) {
  options.validate();
  image.validate();
  const std::string base = !options.name.empty() ? options.name
                                                 : options.body + ":" + options.dof + "(" +
                                                       format_damping_terms(parse_damping_terms(options.terms)) + ")";
  const auto [kind, degree] = parse_curve(options.curve);
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  RunDatabase& store = store_of(database);
  if (!options.by.empty()) {
    bool found = false;
    for (const auto& record : store.fits())
      if (const auto level = fit_level(record.name, base); level && level->first == options.by) found = true;
    if (!found)
      throw InputError("no per-level fits '" + base + "[" + options.by + "=...]' in " + impl.path +
                       " (hydrocoef fit ... --by " + options.by + " stores them)");
  }
  return render(plot::curves_figure(store, base, kind, degree), default_image("curves", base), image);
}

PlotFiles plot_surface(const Database& database, const std::string& name, const std::string& output,
                       const ImageOptions& image) {
  image.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  const std::optional<std::string> which = output.empty() ? std::nullopt : std::optional<std::string>(output);
  return render(plot::surface_figure(store_of(database), name, which), default_image("surface", name), image);
}

PlotFiles plot_history(const Database& database, std::int64_t run, const ImageOptions& image) {
  image.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  RunDatabase& store = store_of(database);
  const auto runs = store.runs();
  const auto found = std::find_if(runs.begin(), runs.end(), [&](const StoredRun& r) { return r.id == run; });
  if (found == runs.end())
    throw InputError(SourceLocation{impl.path}, "no run " + std::to_string(run) + "; 'hydrocoef runs' lists them");
  const plot::Figure figure = plot::history_figure(*found, store.run_trace(run));
  // 260 px per panel (one per averaged component).
  return render(figure, default_image("history", "run-" + std::to_string(run)), image,
                "900x" + std::to_string(200 + 260 * figure.panels.size()));
}

PlotFiles plot_simulation(const std::string& trajectory_csv, const std::string& experiment,
                          const std::string& component, const ImageOptions& image) {
  image.validate();
  std::optional<std::filesystem::path> measured;
  if (!experiment.empty()) measured = experiment;
  return render(plot::simulation_figure(trajectory_csv, measured, component), default_image("simulation", component),
                image);
}

void SteadyPlotOptions::validate() const {
  if (!force_index(dof)) throw InputError("--dof '" + dof + "': expected X, Y, Z, K, M or N");
  const bool range = !std::isnan(tau_from) || !std::isnan(tau_to);
  if (range && (!(tau_to > tau_from) || count < 2 || count > 1000))
    throw InputError("--tau-from/--tau-to/--count: expected FROM < TO and a count of 2 to 1000");
  if (taus.empty() && !range) throw InputError("plot steady: give --tau values or --tau-from, --tau-to and --count");
  if (sampling.samples > 0) ensemble_options(sampling, {2.5, 97.5});
}

PlotFiles plot_steady(const SteadyPlotOptions& options, const ImageOptions& image) {
  options.validate();
  image.validate();
  const std::size_t dof = *force_index(options.dof);
  std::vector<double> taus = options.taus;
  if (!std::isnan(options.tau_from))
    for (std::size_t i = 0; i < options.count; ++i)
      taus.push_back(options.tau_from + (options.tau_to - options.tau_from) * static_cast<double>(i) /
                                            static_cast<double>(options.count - 1));
  const VehicleModel model = load_vehicle_model(options.vehicle, options.database);
  std::vector<plot::SteadyPoint> measured;
  if (!options.experiment_points.empty()) measured = plot::read_steady_points(options.experiment_points);
  const std::string name = !model.description().name.empty() ? model.description().name
                           : is_json_text(options.vehicle)   ? std::string("vehicle JSON")
                                                             : options.vehicle;
  if (options.sampling.samples == 0)
    return render(plot::steady_figure(model, dof, taus, measured, name), default_image("steady", options.dof), image);
  const DampingDraws draws = model_draws(model);
  const plot::SteadyBandOptions band{draws, ensemble_options(options.sampling, {2.5, 97.5})};
  return render(plot::steady_figure(model, dof, taus, measured, name, &band), default_image("steady", options.dof),
                image);
}

namespace {

constexpr std::array<std::string_view, 6> kCoefficientNames = {"C_X", "C_Y", "C_Z", "C_K", "C_M", "C_N"};

}  // namespace

void CoefficientPlotOptions::validate() const {
  if (std::find(kCoefficientNames.begin(), kCoefficientNames.end(), coefficient) == kCoefficientNames.end())
    throw InputError("--coefficient '" + coefficient + "': expected C_X, C_Y, C_Z, C_K, C_M or C_N");
  if (against != "Re" && against != "Fn" && against != "U")
    throw InputError("--against '" + against + "': expected Re, Fn or U");
  runs.validate();
}

PlotFiles plot_coefficient(const Database& database, const CoefficientPlotOptions& options, const ImageOptions& image) {
  options.validate();
  image.validate();
  const RunCoefficients table = run_coefficients(database, options.runs);
  const auto c = static_cast<std::size_t>(
      std::find(kCoefficientNames.begin(), kCoefficientNames.end(), options.coefficient) - kCoefficientNames.begin());
  const std::vector<double>& x = options.against == "Re"   ? table.reynolds
                                 : options.against == "Fn" ? table.froude
                                                           : table.speed;
  const std::vector<double>& y = table.coefficient[c];
  plot::Panel panel;
  panel.title = options.coefficient + " against " + options.against;
  panel.x_label = options.against == "Re"   ? "Re = U L / nu"
                  : options.against == "Fn" ? "Fn = U / sqrt(g L), g = 9.80665 m/s^2"
                                            : "U = |(u, v, w)| [m/s]";
  panel.y_label = options.coefficient + (c < 3 ? " = F / (1/2 rho U^2 A)" : " = M / (1/2 rho U^2 A L)") +
                  " (body axes, on the body)";
  std::size_t colour = 0;
  for (const auto& reference : table.references) {
    plot::Series series;
    series.title = "body '" + reference.body + "': area '" + reference.area_name + "' " +
                   significant(reference.area, 6) + " m^2, L " + significant(reference.length, 6) + " m";
    series.style = plot::Series::Style::Points;
    series.colour = colour++;
    for (std::size_t i = 0; i < table.size(); ++i)
      if (table.body[i] == reference.body && std::isfinite(x[i]) && std::isfinite(y[i])) {
        series.x.push_back(x[i]);
        series.y.push_back(y[i]);
      }
    if (!series.x.empty()) panel.series.push_back(std::move(series));
  }
  if (panel.series.empty())
    throw InputError(SourceLocation{database.path()}, "no selected run has both " + options.coefficient + " and " +
                                                          options.against +
                                                          "; 'hydrocoef runs --coefficients' says why for each run");
  plot::Figure figure;
  figure.title = options.coefficient + " against " + options.against;
  figure.panels.push_back(std::move(panel));
  return render(figure, default_image("coefficient", options.coefficient + "-" + options.against), image);
}

}  // namespace api
}  // namespace hydrocoef
