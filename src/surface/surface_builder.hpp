// Coefficient surfaces built from stored CFD runs: picks the axis coordinates
// (body velocity components or disturbance parameters) and the outputs (force
// components) out of each run, and builds a gridded table when the runs fill
// a grid, or an RBF surface from scattered runs (optionally resampled onto a
// grid), with leave-one-out quality figures.
//
// Signs: outputs are forces on the body (SignConvention::OnBody); a force
// stored as a damping magnitude (OpposingMotion) is negated. Units: axes in
// their SI unit, outputs in N or N m.
//
// Leave-one-out (LOO) error of a run: its output minus what the surface built
// without it predicts there.
//  - RBF: exact, for the same kernel, polynomial and smoothing (Rippa's
//    formula; RbfSurface::cross_validation).
//  - Grid: a tensor-product table cannot lose one node, so a node is
//    predicted from its grid lines: along each axis with at least 3
//    breakpoints, the 1-D interpolant of the same method (linear when a cubic
//    method is left with 2 points) through the other nodes of that line,
//    continued by its own end polynomial at the line's ends; the prediction
//    is the mean over those axes. A node on no such line has no LOO error.
//  - RBF resampled onto a grid: the RBF's LOO errors (the grid is a
//    tabulation of that RBF), and the grid points far from every run.
//  - GP: the surface built again without the run, with the same
//    hyperparameters (they are not searched again), evaluated at the run;
//    up to 400 runs (above, no LOO error: n refits of O(n^3) each).
//
// Uncertainty. A grid or RBF surface states a standard deviation at a point
// (CoefficientSurface::with_run_uncertainty has the formula): from its runs'
// standard uncertainties (StoredForce::standard_uncertainty) interpolated as
// the surface interpolates their values, and its leave-one-out RMS error.
// A resampled grid carries at its nodes the RBF of the runs' uncertainties
// there. When no run has a leave-one-out error (a grid whose every axis has
// 2 breakpoints, an RBF whose polynomial needs every run) the surface states
// none (has_standard_deviation() false) rather than one without that part.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/store/database.hpp"
#include "src/surface/coefficient_surface.hpp"

namespace hydrocoef {

struct SurfaceSpec {
  /// Axis names: "u".."r" or disturbance names as in the runs' keys; 1 to 6, distinct.
  std::vector<std::string> axes;
  /// Output names: "X".."N"; at least one, distinct.
  std::vector<std::string> outputs;
  /// interpolation_name of a grid method ("nearest", "linear", "pchip",
  /// "makima", "natural-spline"), or "rbf" or "gp" for scattered runs.
  std::string method = "linear";
  /// Out-of-range policy per axis (one entry: for every axis), by name:
  /// grid: "error", "clamp", "linear", "method"; rbf and gp: "error",
  /// "clamp", "extrapolate". Empty: "error" everywhere.
  std::vector<std::string> out_of_range;
  /// RBF only: kernel, polynomial degree, smoothing (axis names and
  /// out-of-range policies are set from the fields above).
  RbfOptions rbf;
  /// GP only: kernel, mean degree, optimiser starts and seed. Each run's
  /// noise is the standard uncertainty of its force component (the standard
  /// error of a mean over a force history and any uncertainty given at
  /// import, StoredForce::standard_uncertainty; 0 when neither is known).
  GpOptions gp;
  /// RBF only: when set, the RBF is tabulated on these breakpoints (one list
  /// per axis) and stored as a grid table of resample_method.
  std::optional<std::vector<std::vector<double>>> resample;
  std::string resample_method = "linear";
  /// A mirror symmetry imposed on the surface (src/surface/surface_symmetry.hpp;
  /// the runs' images are among the runs given). Empty: none.
  SurfaceSymmetry symmetry;
  /// Grid points farther than this from every run (in the RBF's scaled units:
  /// a fraction of the runs' range per axis) are reported as far from data.
  double far_threshold = 0.25;
};

/// Leave-one-out figures per output, in the output's unit.
struct SurfaceQuality {
  std::string method;           ///< "rbf-exact" or "grid-lines" (see the file comment)
  std::vector<double> loo_max;  ///< max |error| over runs where it is defined
  std::vector<double> loo_rms;  ///< RMS over the same runs
  std::size_t loo_defined = 0;  ///< runs with a LOO error
  /// Per run: its id and its leave-one-out error per output (run-major;
  /// NaN where undefined), so that the worst run can be named.
  std::vector<std::int64_t> loo_runs;
  std::vector<double> loo_errors;
  std::size_t runs = 0;  ///< runs the surface was built from
  /// Resampled grids: grid points (axis 0 fastest) far from every run, and the threshold used.
  std::vector<std::size_t> far_from_data;
  double far_threshold = 0.0;
  std::size_t grid_points = 0;
  /// Physical problems (src/surface/surface_checks.hpp): one line each.
  std::vector<std::string> physical;

  /// As stored in SurfaceRecord::quality.
  std::string to_json(const std::vector<std::string>& outputs) const;
};

/// How a quality method's leave-one-out errors were found, for people:
/// "exact, RBF", "along grid lines", "GP refitted without each run", ...
std::string loo_method_description(std::string_view method);

struct BuiltSurface {
  CoefficientSurface surface;
  SurfaceQuality quality;
  std::vector<std::int64_t> run_ids;  ///< the runs used, increasing
  std::size_t runs_skipped = 0;       ///< runs lacking one of the outputs
  /// RBF surfaces: the samples, as RbfSurface took them (for storing).
  std::vector<double> rbf_points;
  std::vector<double> rbf_values;
  /// RBF surfaces stating an uncertainty: the runs' standard uncertainties,
  /// as rbf_values (CoefficientSurface::with_run_uncertainty); else empty.
  std::vector<double> rbf_sigma;

  /// The record to store (name and body set; kind, method, definition, data,
  /// quality, run_ids filled).
  SurfaceRecord record(const std::string& name, const std::string& body) const;
};

/// Builds a surface from runs (typically one body's, filtered by the caller).
/// Runs that lack one of the outputs are skipped (counted). Throws InputError
/// when a name is unknown or repeated, a run lacks an axis's disturbance
/// (naming the run), two runs share the same axis coordinates (naming both:
/// another velocity component or disturbance varies and must be fixed with a
/// filter), a grid method is asked of runs that do not fill a grid (listing
/// missing nodes), or there are too few runs for the method.
BuiltSurface build_surface(const std::vector<StoredRun>& runs, const SurfaceSpec& spec);

}  // namespace hydrocoef
