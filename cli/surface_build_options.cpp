// The options of `hydrocoef surface build` and the specification they describe.
#include "cli/surface_build_options.hpp"

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/surface/grid_table.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef::cli {

void add_surface_build_options(CLI::App& command, SurfaceBuildArgs& args) {
  command.add_option("name", args.name, "Surface name")->required();
  command.add_option("--body", args.body, "Body whose runs are used")->required();
  command.add_option("--outputs", args.outputs, "Force components, e.g. X or X,Y,N")->required()->delimiter(',');
  command.add_option("--axes", args.axes, "Axes: velocity components (u..r) or disturbance names, e.g. u,current_v")
      ->required()
      ->delimiter(',');
  command
      .add_option("--method", args.method,
                  "nearest, linear, pchip, makima, natural-spline (gridded runs), rbf or gp (scattered runs; gp: a "
                  "Gaussian process that also states its standard deviation)")
      ->capture_default_str();
  command.add_option("--extrapolate", args.extrapolate,
                     "Out-of-range policy for every axis, or AXIS=POLICY (repeatable): error (default), clamp, linear, "
                     "method; for rbf and gp: error, clamp, extrapolate");
  command.add_option(
      "--where", args.where,
      "Select runs: NAME=VALUE, NAME!=VALUE, NAME<VALUE (<=, >, >=) or NAME=FROM:TO on a velocity component "
      "(SI) or disturbance; repeatable, all must hold");
  command.add_flag("--replace", args.replace, "Replace a stored surface of the same name");
  command.add_option("--exclude-run", args.exclude_runs,
                     "Leave out the run with this id (repeatable; leave-one-out by hand)");
  add_mirror_options(command, args.mirror, args.mirror_odd);
  command.add_option("--kernel", args.kernel,
                     "RBF kernel: cubic (default), thin-plate, linear; GP kernel: matern52 (default), "
                     "squared-exponential");
  command.add_option("--degree", args.degree, "RBF polynomial or GP mean degree (0, 1, 2)")->capture_default_str();
  command.add_option("--starts", args.starts, "GP: optimiser starts of the hyperparameter search (1 to 100)")
      ->capture_default_str();
  command.add_option("--seed", args.seed, "GP: seed of the optimiser starts after the third")->capture_default_str();
  command.add_option("--smoothing", args.smoothing, "RBF smoothing (0 interpolates)")->capture_default_str();
  command.add_option("--resample", args.resample,
                     "Tabulate the RBF on a grid: AXIS=FROM:TO:COUNT or AXIS=X1,X2,... (one per axis)");
  command.add_option("--resample-method", args.resample_method, "Interpolation of the resampled grid")
      ->capture_default_str();
  command
      .add_option("--far-threshold", args.far_threshold,
                  "Report grid points farther than this from every run (fraction of the runs' range)")
      ->capture_default_str();
}

/// The build specification the options describe (names and grammar checked
/// before any run is read).
SurfaceBuildSpec surface_build_spec(const SurfaceBuildArgs& args) {
  SurfaceBuildSpec spec;
  SurfaceSpec& surface = spec.surface;
  surface.axes = args.axes;
  surface.outputs = args.outputs;
  surface.method = args.method;
  if (args.method != "rbf" && args.method != "gp") parse_interpolation(args.method);
  surface.out_of_range = out_of_range_policies(args.axes, args.extrapolate, "--extrapolate");
  spec.where = args.where;
  spec.exclude_runs = args.exclude_runs;
  spec.mirror_planes = args.mirror;
  spec.mirror_odd = args.mirror_odd;
  if (args.degree < 0 || args.degree > 2)
    throw InputError("--degree " + std::to_string(args.degree) + ": expected 0, 1 or 2");
  if (args.method == "gp") {
    surface.gp.kernel = parse_gp_kernel(args.kernel.value_or("matern52"));
    surface.gp.mean_degree = args.degree;
    if (args.starts < 1 || args.starts > 100)
      throw InputError("--starts " + std::to_string(args.starts) + ": expected 1 to 100");
    surface.gp.starts = args.starts;
    surface.gp.seed = args.seed;
  } else {
    surface.rbf.kernel = parse_rbf_kernel(args.kernel.value_or("cubic"));
  }
  surface.rbf.polynomial_degree = args.degree;
  surface.rbf.smoothing = args.smoothing;
  surface.resample_method = args.resample_method;
  surface.far_threshold = args.far_threshold;
  if (args.resample.empty()) return spec;
  if (args.method != "rbf") throw InputError("--resample tabulates an RBF surface; it needs --method rbf");
  surface.resample = resample_grid(args.axes, args.resample, "--resample");
  parse_interpolation(args.resample_method);
  return spec;
}

}  // namespace hydrocoef::cli
