// hydrocoef plot fit|curves|surface|history|simulation|steady|coefficient: PNG
// or SVG pictures of stored fits, coefficient curves, surfaces, a run's force
// history (its stored window and statistics), simulations and the runs'
// non-dimensional coefficients (cmd_plot_coefficient.cpp), drawn by gnuplot, with
// the plotted values beside the image (NAME.dat) and the script (NAME.gp).
// The work is include/hydrocoef/plot.hpp; this file parses and prints.
#include <memory>

#include "cli/common.hpp"
#include "cli/plot_common.hpp"
#include "cli/sampling_options.hpp"
#include "hydrocoef/plot.hpp"

namespace hydrocoef::cli {
namespace {

Database read_only(const GlobalOptions& global) { return Database::open(global.database, OpenMode::ReadOnly); }

void add_database_plots(CLI::App* plot_cmd, const GlobalOptions& global) {
  struct FitArgs : CommonPlotArgs {
    std::string name;
  };
  auto fit_args = std::make_shared<FitArgs>();
  auto* fit = plot_cmd->add_subcommand("fit",
                                       "Force against velocity: CFD runs as points, the fitted law as a "
                                       "curve, one per level of a fit --by");
  fit->add_option("name", fit_args->name, "Stored fit name (per-level fits NAME@LEVEL=VALUE are drawn together)")
      ->required();
  add_common(fit, *fit_args);
  fit->callback(
      [fit_args, &global] { print_plot(plot_fit(read_only(global), fit_args->name, fit_args->image), *fit_args); });

  struct CurvesArgs : CommonPlotArgs {
    CurvesPlotOptions options;
  };
  auto curves_args = std::make_shared<CurvesArgs>();
  auto* curves = plot_cmd->add_subcommand("curves",
                                          "Each damping coefficient against a disturbance: per-level "
                                          "values and the fitted curve");
  CurvesPlotOptions& c = curves_args->options;
  curves->add_option("name", c.name, "Base name of stored per-level fits (NAME@LEVEL=VALUE)");
  curves->add_option("--body", c.body, "Without a name: the body of the fits");
  curves->add_option("--dof", c.dof, "Without a name: force component X..N");
  curves->add_option("--terms", c.terms, "Without a name: the law's terms, e.g. u,u|u|");
  curves->add_option("--by", c.by, "The disturbance the fits were made per level of (checked)");
  curves->add_option("--curve", c.curve, "polynomial:D (least squares, degree D) or pchip")->capture_default_str();
  add_common(curves, *curves_args);
  curves->callback([curves_args, &global] {
    print_plot(plot_curves(read_only(global), curves_args->options, curves_args->image), *curves_args);
  });

  struct SurfaceArgs : CommonPlotArgs {
    std::string name;
    std::string output;
  };
  auto surface_args = std::make_shared<SurfaceArgs>();
  auto* surface = plot_cmd->add_subcommand("surface",
                                           "A stored surface: a curve (1 axis) or a colour map (2 axes) "
                                           "with its runs and the out-of-range regions");
  surface->add_option("name", surface_args->name, "Stored surface name")->required();
  surface->add_option("--output", surface_args->output, "The surface's output to draw (default: its first)");
  add_common(surface, *surface_args, true);
  surface->callback([surface_args, &global] {
    const auto& a = *surface_args;
    print_plot(plot_surface(read_only(global), a.name, a.output, a.image), a);
  });

  struct HistoryArgs : CommonPlotArgs {
    std::int64_t run = 0;
  };
  auto history_args = std::make_shared<HistoryArgs>();
  auto* history = plot_cmd->add_subcommand(
      "history",
      "One run's force history as stored: the history in brief (each bin's least and largest value), each averaged "
      "component's window, its mean (or the final iterate of a converged run) with its standard error, spread and "
      "trend");
  history->add_option("run", history_args->run, "Run id (hydrocoef runs lists them)")->required();
  add_common(history, *history_args, false, "");
  history->get_option("--size")->description(
      "Image size WIDTHxHEIGHT [pixels]; default 900 wide and 260 per panel plus 200");
  history->callback([history_args, &global] {
    print_plot(plot_history(read_only(global), history_args->run, history_args->image), *history_args);
  });
}

void add_dynamics_plots(CLI::App* plot_cmd, const GlobalOptions& global) {
  struct SimulationArgs : CommonPlotArgs {
    std::string trajectory, experiment, component = "r";
  };
  auto sim_args = std::make_shared<SimulationArgs>();
  auto* sim = plot_cmd->add_subcommand("simulation",
                                       "Velocity against time from hydrocoef simulate --out, with "
                                       "a measured record overlaid");
  sim->add_option("--trajectory", sim_args->trajectory, "Trajectory CSV (hydrocoef simulate --out)")->required();
  sim->add_option("--experiment", sim_args->experiment, "Measured CSV (t and velocity columns, units in brackets)");
  sim->add_option("--component", sim_args->component, "Velocity component u, v, w, p, q or r")->capture_default_str();
  add_common(sim, *sim_args);
  sim->callback([sim_args] {
    const auto& a = *sim_args;
    print_plot(plot_simulation(a.trajectory, a.experiment, a.component, a.image), a);
  });

  struct SteadyArgs : CommonPlotArgs {
    SteadyPlotOptions options;
  };
  auto steady_args = std::make_shared<SteadyArgs>();
  SteadyPlotOptions& s = steady_args->options;
  auto* steady = plot_cmd->add_subcommand("steady",
                                          "Steady velocity against a constant force in one DOF "
                                          "(equilibrium solver, attitude held)");
  steady->add_option("--vehicle", s.vehicle, "Vehicle description (JSON)")->required();
  steady->add_option("--dof", s.dof, "Force component X..N; its own velocity is drawn (N -> r)")->capture_default_str();
  steady->add_option("--tau", s.taus, "Forces to solve at [N or N m] (repeatable)");
  steady->add_option("--tau-from", s.tau_from, "First force of an even range [N or N m]");
  steady->add_option("--tau-to", s.tau_to, "Last force of an even range [N or N m]");
  steady->add_option("--count", s.count, "Number of forces in the range")->capture_default_str();
  steady->add_option("--experiment-points", s.experiment_points,
                     "Measured steady points: CSV with a header and rows force,velocity (SI)");
  steady->add_option("--samples", s.sampling.samples,
                     "Draw the uncertain damping N times and shade the steady velocity's interval (as equilibrium "
                     "--samples)");
  steady->add_option("--seed", s.sampling.seed, "Seed of the draws")->capture_default_str();
  steady
      ->add_option("--percentiles", s.sampling.percentiles,
                   "The band's percentiles, comma-separated (default 2.5,97.5)")
      ->delimiter(',');
  add_common(steady, *steady_args);
  steady->callback([steady_args, &global] {
    steady_args->options.database = global.database;
    print_plot(plot_steady(steady_args->options, steady_args->image), *steady_args);
  });
}

}  // namespace

void add_plot_command(CLI::App& app, const GlobalOptions& global) {
  auto* plot_cmd = app.add_subcommand("plot",
                                      "Draw fits, coefficient curves, surfaces, run histories, simulations and "
                                      "the runs' non-dimensional coefficients (PNG or SVG, through gnuplot)");
  plot_cmd->require_subcommand(1);
  add_database_plots(plot_cmd, global);
  add_dynamics_plots(plot_cmd, global);
  add_coefficient_plot(plot_cmd, global);
}

}  // namespace hydrocoef::cli
