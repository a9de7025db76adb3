// hydrocoef plot fit|curves|surface|history|simulation|steady: PNG or SVG
// pictures of stored fits, coefficient curves, surfaces, a run's force history
// (its stored window and statistics) and simulations, drawn by gnuplot,
// with the plotted values beside the image (NAME.dat) and the script (NAME.gp).
#include <algorithm>
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "cli/plot_common.hpp"
#include "src/core/error.hpp"
#include "src/dynamics/surface_source.hpp"
#include "src/dynamics/vehicle.hpp"
#include "src/fit/fit_names.hpp"
#include "src/pipeline/fit_stored_runs.hpp"
#include "src/plot/history_plot.hpp"
#include "src/plot/plots.hpp"
#include "src/store/database.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef::cli {
namespace {

struct FitPlotArgs : CommonPlotArgs {
  std::string name;
};
struct CurvesPlotArgs : CommonPlotArgs {
  std::optional<std::string> name;
  std::optional<std::string> body, dof, terms, by;
  std::string curve = "polynomial:2";
};
struct SurfacePlotArgs : CommonPlotArgs {
  std::string name;
  std::optional<std::string> surface_output;
};
struct HistoryPlotArgs : CommonPlotArgs {
  std::int64_t run = 0;
};
struct SimulationPlotArgs : CommonPlotArgs {
  std::string trajectory;
  std::optional<std::string> experiment;
  std::string component = "r";
};
struct SteadyPlotArgs : CommonPlotArgs {
  std::string vehicle;
  std::string dof = "N";
  std::vector<double> taus;
  std::optional<double> tau_from, tau_to;
  std::size_t count = 6;
  std::optional<std::string> points;
  std::size_t samples = 0;
  std::uint64_t seed = 1;
  std::vector<double> percentiles;
};

}  // namespace

void add_plot_command(CLI::App& app, const GlobalOptions& global) {
  auto* plot_cmd = app.add_subcommand("plot",
                                      "Draw fits, coefficient curves, surfaces, run histories and simulations "
                                      "(PNG or SVG, through gnuplot)");
  plot_cmd->require_subcommand(1);

  auto fit_args = std::make_shared<FitPlotArgs>();
  auto* fit = plot_cmd->add_subcommand("fit",
                                       "Force against velocity: CFD runs as points, the fitted law as a "
                                       "curve, one per level of a fit --by");
  fit->add_option("name", fit_args->name, "Stored fit name (per-level fits NAME@LEVEL=VALUE are drawn together)")
      ->required();
  add_common(fit, *fit_args);
  fit->callback([fit_args, &global] {
    RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
    render_and_print(plot::fit_figure(database, fit_args->name), default_image("fit", fit_args->name), *fit_args);
  });

  auto curves_args = std::make_shared<CurvesPlotArgs>();
  auto* curves = plot_cmd->add_subcommand("curves",
                                          "Each damping coefficient against a disturbance: per-level "
                                          "values and the fitted curve");
  curves->add_option("name", curves_args->name, "Base name of stored per-level fits (NAME@LEVEL=VALUE)");
  curves->add_option("--body", curves_args->body, "Without a name: the body of the fits");
  curves->add_option("--dof", curves_args->dof, "Without a name: force component X..N");
  curves->add_option("--terms", curves_args->terms, "Without a name: the law's terms, e.g. u,u|u|");
  curves->add_option("--by", curves_args->by, "The disturbance the fits were made per level of (checked)");
  curves->add_option("--curve", curves_args->curve, "polynomial:D (least squares, degree D) or pchip")
      ->capture_default_str();
  add_common(curves, *curves_args);
  curves->callback([curves_args, &global] {
    const auto& a = *curves_args;
    const std::string base = a.name ? *a.name : curves_base_name(a.body, a.dof, a.terms);
    const auto [kind, degree] = parse_curve(a.curve);
    RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
    if (a.by) {
      bool found = false;
      for (const auto& record : database.fits())
        if (const auto level = fit_level(record.name, base); level && level->first == *a.by) found = true;
      if (!found)
        throw InputError("no per-level fits '" + base + "[" + *a.by + "=...]' in " + global.database +
                         " (hydrocoef fit ... --by " + *a.by + " stores them)");
    }
    render_and_print(plot::curves_figure(database, base, kind, degree), default_image("curves", base), a);
  });

  auto surface_args = std::make_shared<SurfacePlotArgs>();
  auto* surface = plot_cmd->add_subcommand("surface",
                                           "A stored surface: a curve (1 axis) or a colour map (2 axes) "
                                           "with its runs and the out-of-range regions");
  surface->add_option("name", surface_args->name, "Stored surface name")->required();
  surface->add_option("--output", surface_args->surface_output, "The surface's output to draw (default: its first)");
  add_common(surface, *surface_args, true);
  surface->callback([surface_args, &global] {
    RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
    render_and_print(plot::surface_figure(database, surface_args->name, surface_args->surface_output),
                     default_image("surface", surface_args->name), *surface_args);
  });

  auto history_args = std::make_shared<HistoryPlotArgs>();
  auto* history = plot_cmd->add_subcommand(
      "history",
      "One run's force history as stored: the history in brief (each bin's least and largest value), each averaged "
      "component's window, its mean (or the final iterate of a converged run) with its standard error, spread and "
      "trend");
  history->add_option("run", history_args->run, "Run id (hydrocoef runs lists them)")->required();
  add_common(history, *history_args);
  history->get_option("--size")
      ->description("Image size WIDTHxHEIGHT [pixels]; default 900 wide and 260 per panel plus 200")
      ->default_str("");
  history->callback([history_args, history, &global] {
    RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
    const std::int64_t id = history_args->run;
    const auto runs = database.runs();
    const auto found = std::find_if(runs.begin(), runs.end(), [&](const StoredRun& run) { return run.id == id; });
    if (found == runs.end())
      throw InputError(SourceLocation{global.database},
                       "no run " + std::to_string(id) + "; 'hydrocoef runs' lists them");
    const plot::Figure figure = plot::history_figure(*found, database.run_trace(id));
    // Without --size: 260 px per panel (one per averaged component).
    HistoryPlotArgs args = *history_args;
    if (history->get_option("--size")->count() == 0)
      args.size = "900x" + std::to_string(200 + 260 * figure.panels.size());
    render_and_print(figure, default_image("history", "run-" + std::to_string(id)), args);
  });

  auto sim_args = std::make_shared<SimulationPlotArgs>();
  auto* sim = plot_cmd->add_subcommand("simulation",
                                       "Velocity against time from hydrocoef simulate --out, with "
                                       "a measured record overlaid");
  sim->add_option("--trajectory", sim_args->trajectory, "Trajectory CSV (hydrocoef simulate --out)")->required();
  sim->add_option("--experiment", sim_args->experiment, "Measured CSV (t and velocity columns, units in brackets)");
  sim->add_option("--component", sim_args->component, "Velocity component u, v, w, p, q or r")->capture_default_str();
  add_common(sim, *sim_args);
  sim->callback([sim_args] {
    std::optional<std::filesystem::path> experiment;
    if (sim_args->experiment) experiment = *sim_args->experiment;
    render_and_print(plot::simulation_figure(sim_args->trajectory, experiment, sim_args->component),
                     default_image("simulation", sim_args->component), *sim_args);
  });

  auto steady_args = std::make_shared<SteadyPlotArgs>();
  auto* steady = plot_cmd->add_subcommand("steady",
                                          "Steady velocity against a constant force in one DOF "
                                          "(equilibrium solver, attitude held)");
  steady->add_option("--vehicle", steady_args->vehicle, "Vehicle description (JSON)")->required();
  steady->add_option("--dof", steady_args->dof, "Force component X..N; its own velocity is drawn (N -> r)")
      ->capture_default_str();
  steady->add_option("--tau", steady_args->taus, "Forces to solve at [N or N m] (repeatable)");
  steady->add_option("--tau-from", steady_args->tau_from, "First force of an even range [N or N m]");
  steady->add_option("--tau-to", steady_args->tau_to, "Last force of an even range [N or N m]");
  steady->add_option("--count", steady_args->count, "Number of forces in the range")->capture_default_str();
  steady->add_option("--experiment-points", steady_args->points,
                     "Measured steady points: CSV with a header and rows force,velocity (SI)");
  steady->add_option("--samples", steady_args->samples,
                     "Draw the uncertain damping N times and shade the steady velocity's interval (as equilibrium "
                     "--samples)");
  steady->add_option("--seed", steady_args->seed, "Seed of the draws")->capture_default_str();
  steady
      ->add_option("--percentiles", steady_args->percentiles,
                   "The band's percentiles, comma-separated (default 2.5,97.5)")
      ->delimiter(',');
  add_common(steady, *steady_args);
  steady->callback([steady_args, &global] {
    const auto& a = *steady_args;
    const auto dof = force_index(a.dof);
    if (!dof) throw InputError("--dof '" + a.dof + "': expected X, Y, Z, K, M or N");
    const std::vector<double> taus = steady_forces(a.taus, a.tau_from, a.tau_to, a.count);
    auto database = std::make_shared<std::unique_ptr<RunDatabase>>();
    const SurfaceResolver resolver = [database, &global](const std::string& name) {
      if (!*database) *database = std::make_unique<RunDatabase>(global.database, RunDatabase::OpenMode::ReadOnly);
      return load_surface(**database, name).surface;
    };
    VehicleDescription vehicle = load_vehicle(a.vehicle);
    resolve_stored_records(vehicle, global.database);
    const VehicleModel model(std::move(vehicle), resolver);
    std::vector<plot::SteadyPoint> measured;
    if (a.points) measured = plot::read_steady_points(*a.points);
    const std::string name = model.description().name.empty() ? a.vehicle : model.description().name;
    if (a.samples == 0) {
      render_and_print(plot::steady_figure(model, *dof, taus, measured, name), default_image("steady", a.dof), a);
      return;
    }
    const DampingDraws draws(model.damping(), model.description().damping);
    if (!draws.any()) throw InputError("--samples: nothing in the vehicle's damping has an uncertainty to draw from");
    EnsembleOptions options;
    options.samples = a.samples;
    options.seed = a.seed;
    options.percentiles = a.percentiles.empty() ? std::vector<double>{2.5, 97.5} : a.percentiles;
    check_ensemble_options(options);
    const plot::SteadyBandOptions band{draws, options};
    render_and_print(plot::steady_figure(model, *dof, taus, measured, name, &band), default_image("steady", a.dof), a);
  });
}

}  // namespace hydrocoef::cli
