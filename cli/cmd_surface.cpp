// hydrocoef surface build|rebuild|list|show: coefficient surfaces from stored
// runs, kept in the database with their quality figures. The work and the
// printing are the library's (hydrocoef/surface.hpp); this parses.
#include <iostream>
#include <memory>
#include <optional>

#include "cli/common.hpp"
#include "hydrocoef/database.hpp"
#include "hydrocoef/surface.hpp"
#include "src/surface/surface_build_spec.hpp"

namespace hydrocoef::cli {
namespace {

struct BuildArgs {
  hydrocoef::SurfaceBuildOptions options;
  std::optional<std::string> kernel;  ///< default: cubic (rbf), matern52 (gp)
  int degree = 1;
  std::vector<std::string> resample;  ///< AXIS=FROM:TO:COUNT or AXIS=X1,X2,...
  bool json = false;
};

void build(BuildArgs& args, const GlobalOptions& global) {
  auto& options = args.options;
  if (args.kernel) (options.method == "gp" ? options.gp_kernel : options.rbf_kernel) = *args.kernel;
  options.rbf_degree = options.gp_degree = args.degree;
  // Breakpoints are read for an RBF only; for another method the option's
  // presence is what validate() refuses.
  if (options.method == "rbf" && !args.resample.empty())
    options.resample = resample_grid(options.axes, args.resample, "--resample");
  else
    options.resample.assign(args.resample.size(), {});
  options.validate();
  auto db = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadWrite);
  const auto report = hydrocoef::surface_build(db, options);
  std::cout << (args.json ? report.json() : report.text());
}

struct NameArgs {
  hydrocoef::SurfaceRebuildOptions rebuild;
  std::optional<std::string> body;
  bool json = false;
};

void rebuild(NameArgs& args, const GlobalOptions& global) {
  args.rebuild.body = args.body.value_or("");
  auto db = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadWrite);
  const auto report = hydrocoef::surface_rebuild(db, args.rebuild);
  std::cout << (args.json ? report.json() : report.text());
}

void list(const NameArgs& args, const GlobalOptions& global) {
  const auto db = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
  const auto list = hydrocoef::surface_list(db, args.body.value_or(""));
  std::cout << (args.json ? list.json() : list.text());
}

void show(const NameArgs& args, const GlobalOptions& global) {
  const auto db = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
  const auto report = hydrocoef::surface_show(db, args.rebuild.name);
  std::cout << (args.json ? report.json() : report.text());
}

void add_build_options(CLI::App& command, BuildArgs& args) {
  auto& o = args.options;
  command.add_option("name", o.name, "Surface name")->required();
  command.add_option("--body", o.body, "Body whose runs are used")->required();
  command.add_option("--outputs", o.outputs, "Force components, e.g. X or X,Y,N")->required()->delimiter(',');
  command.add_option("--axes", o.axes, "Axes: velocity components (u..r) or disturbance names, e.g. u,current_v")
      ->required()
      ->delimiter(',');
  command
      .add_option("--method", o.method,
                  "nearest, linear, pchip, makima, natural-spline (gridded runs), rbf or gp (scattered runs; gp: a "
                  "Gaussian process that also states its standard deviation)")
      ->capture_default_str();
  command.add_option("--extrapolate", o.extrapolate,
                     "Out-of-range policy for every axis, or AXIS=POLICY (repeatable): error (default), clamp, linear, "
                     "method; for rbf and gp: error, clamp, extrapolate");
  command.add_option(
      "--where", o.where,
      "Select runs: NAME=VALUE, NAME!=VALUE, NAME<VALUE (<=, >, >=) or NAME=FROM:TO on a velocity component "
      "(SI) or disturbance; repeatable, all must hold");
  command.add_flag("--replace", o.replace, "Replace a stored surface of the same name");
  command.add_option("--exclude-run", o.exclude_runs,
                     "Leave out the run with this id (repeatable; leave-one-out by hand)");
  add_mirror_options(command, o.mirror, o.mirror_odd);
  command.add_option("--kernel", args.kernel,
                     "RBF kernel: cubic (default), thin-plate, linear; GP kernel: matern52 (default), "
                     "squared-exponential");
  command.add_option("--degree", args.degree, "RBF polynomial or GP mean degree (0, 1, 2)")->capture_default_str();
  command.add_option("--starts", o.gp_starts, "GP: optimiser starts of the hyperparameter search (1 to 100)")
      ->capture_default_str();
  command.add_option("--seed", o.gp_seed, "GP: seed of the optimiser starts after the third")->capture_default_str();
  command.add_option("--smoothing", o.rbf_smoothing, "RBF smoothing (0 interpolates)")->capture_default_str();
  command.add_option("--resample", args.resample,
                     "Tabulate the RBF on a grid: AXIS=FROM:TO:COUNT or AXIS=X1,X2,... (one per axis)");
  command.add_option("--resample-method", o.resample_method, "Interpolation of the resampled grid")
      ->capture_default_str();
  command
      .add_option("--far-threshold", o.far_threshold,
                  "Report grid points farther than this from every run (fraction of the runs' range)")
      ->capture_default_str();
  command.add_flag("--json", args.json, "Machine-readable output");
}

}  // namespace

void add_surface_command(CLI::App& app, const GlobalOptions& global) {
  auto* surface = app.add_subcommand("surface", "Build, rebuild, list and show coefficient surfaces");
  surface->require_subcommand(1);

  auto build_args = std::make_shared<BuildArgs>();
  auto* b = surface->add_subcommand(
      "build",
      "Build a surface from a body's runs and store it. Runs that fill a grid over the axes give a gridded table "
      "(nearest, linear, pchip, makima, natural-spline); scattered runs need --method rbf (optionally tabulated "
      "with --resample). Outputs are forces on the body.");
  add_build_options(*b, *build_args);
  b->callback([build_args, &global] { build(*build_args, global); });

  auto rebuild_args = std::make_shared<NameArgs>();
  auto* r = surface->add_subcommand("rebuild",
                                    "Build stored surfaces again from the current runs, with the options "
                                    "they were built with (one by name, or every --stale one)");
  r->add_option("name", rebuild_args->rebuild.name, "Surface name (omit with --stale or to rebuild all)");
  r->add_option("--body", rebuild_args->body, "Only this body's surfaces");
  r->add_flag("--stale", rebuild_args->rebuild.stale_only, "Only surfaces whose runs changed");
  r->add_flag("--json", rebuild_args->json, "Machine-readable output");
  r->callback([rebuild_args, &global] { rebuild(*rebuild_args, global); });

  auto list_args = std::make_shared<NameArgs>();
  auto* l = surface->add_subcommand("list", "List stored surfaces");
  l->add_option("--body", list_args->body, "Only this body's surfaces");
  l->add_flag("--json", list_args->json, "Machine-readable output");
  l->callback([list_args, &global] { list(*list_args, global); });

  auto show_args = std::make_shared<NameArgs>();
  auto* s = surface->add_subcommand("show", "Show one surface: axes, ranges, policies, quality, provenance");
  s->add_option("name", show_args->rebuild.name, "Surface name")->required();
  s->add_flag("--json", show_args->json, "Machine-readable output (breakpoints included)");
  s->callback([show_args, &global] { show(*show_args, global); });
}

}  // namespace hydrocoef::cli
