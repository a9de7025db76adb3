// A coefficient surface read from a run database: named axes, named outputs,
// each with its unit, evaluated at one point or at many points at once.
//
// Axes are body velocity components or disturbance parameters, in SI units:
// u, v, w [m/s] and p, q, r [rad/s] in body axes (Fossen/SNAME: x forward, y
// starboard, z down), a disturbance in its own SI unit (axis_units() says
// which). Outputs are generalized forces on the body in body axes, X, Y, Z [N]
// and K, M, N [N m] about the runs' reference point, signed as the force the
// fluid exerts on the body (a damping force is negative along the motion), or
// any other coefficient in the unit output_units() gives.
//
// A Surface is immutable and self-contained: it keeps its table after the
// Database it came from is closed, copies are cheap (they share the table),
// and every member may be called from any number of threads at once.
//
// Out of range: each axis has the policy the surface was built with
// (`hydrocoef surface build --extrapolate`): "error" refuses a coordinate
// outside [lower(a), upper(a)] with an InputError naming the axis, the value
// and the range; "clamp", "linear" and "method" answer there. A NaN or
// infinite coordinate is always an InputError. The messages are the ones
// `hydrocoef query` prints.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hydrocoef/error.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
// The public API lives in an inline namespace: users write hydrocoef::Surface;
// inside the library it keeps these classes apart from the internal ones of
// the same name (the store's Database).
inline namespace api {

class Database;              // hydrocoef/database.hpp
struct SurfaceBuildOptions;  // hydrocoef/database.hpp

/// A column of input numbers for Surface::evaluate_batch: point i's value is
/// data[i * stride]. stride is in elements (doubles), not bytes; it may be 0
/// (the same value for every point) or negative. The caller owns the memory.
struct ConstColumn {
  const double* data = nullptr;
  std::ptrdiff_t stride = 1;
};

/// A column of output numbers for Surface::evaluate_batch: point i's result
/// goes to data[i * stride] (stride in elements, not 0). The caller owns the memory.
struct Column {
  double* data = nullptr;
  std::ptrdiff_t stride = 1;
};

/// One of the points of a surface's range where an output's standard
/// deviation is largest (Surface::largest_standard_deviations).
struct SigmaPeak {
  std::vector<double> point;        ///< one coordinate per axis, in Surface::axes() order and axis units
  double standard_deviation = 0.0;  ///< of the output there, in its unit
};

/// A surface tabulated on breakpoints (Surface::tabulate, or a gridded
/// surface's own nodes): what a controller's lookup table needs.
///
/// Layout: node (i_0, ..., i_{d-1}), i_a the index into breakpoints[a], has
/// the flat index  i_0 + n_0 * (i_1 + n_1 * (i_2 + ...))  (the first axis
/// varies fastest); values[k][flat] is output k there.
struct SurfaceTable {
  std::vector<std::string> axes;                 ///< as Surface::axes()
  std::vector<std::string> axis_units;           ///< as Surface::axis_units()
  std::vector<std::string> outputs;              ///< as Surface::outputs()
  std::vector<std::string> output_units;         ///< as Surface::output_units()
  std::vector<std::vector<double>> breakpoints;  ///< per axis, increasing [axis unit]
  std::vector<std::vector<double>> values;       ///< per output, one per node [output unit]
  /// Per output, one per node, the surface's standard deviation there [output
  /// unit] (as Surface::evaluate_with_standard_deviation); empty when the
  /// surface states none (Surface::has_standard_deviation() false).
  std::vector<std::vector<double>> standard_deviation;

  std::size_t node_count() const noexcept { return values.empty() ? 0 : values.front().size(); }
};

class HYDROCOEF_EXPORT Surface {
 public:
  /// A surface and its gradient at one point.
  struct ValueAndGradient {
    std::vector<double> values;    ///< one per output, in outputs() order
    std::vector<double> gradient;  ///< gradient[k * axes().size() + a] = d output_k / d axis_a
  };

  /// The surface's name in its database.
  const std::string& name() const;
  /// The body whose runs it was built from.
  const std::string& body() const;
  /// "nearest", "linear", "pchip", "makima", "natural-spline" (gridded tables),
  /// "rbf" or "gp" (scattered samples; a GP states a standard deviation).
  const std::string& method() const;
  /// True when forces of the body changed in the database since the surface
  /// was built (`hydrocoef surface rebuild` makes it again).
  bool stale() const;

  /// Axis names, in the order evaluate() takes the coordinates.
  const std::vector<std::string>& axes() const;
  /// Output names, in the order evaluate() returns the values.
  const std::vector<std::string>& outputs() const;
  /// One unit per axis ("m/s", "rad/s", or a disturbance's unit; "" when unknown).
  const std::vector<std::string>& axis_units() const;
  /// One unit per output ("N", "N m", or a coefficient's unit).
  const std::vector<std::string>& output_units() const;
  /// The range the surface was built over on an axis [axis unit]: its first
  /// and last breakpoint, or the range of its samples. std::out_of_range for
  /// axis >= axes().size().
  double lower(std::size_t axis) const;
  double upper(std::size_t axis) const;
  /// The out-of-range policy of an axis: "error", "clamp", "linear" or
  /// "method" (gridded tables), "error", "clamp" or "extrapolate" (rbf, gp).
  std::string out_of_range(std::size_t axis) const;

  /// Every output at one point (one coordinate per axis, in axes() order and
  /// axis units). InputError when point has the wrong size, a coordinate is
  /// NaN or infinite, or a coordinate is outside its axis under "error".
  std::vector<double> evaluate(const std::vector<double>& point) const;
  /// As evaluate, with the exact gradient of the interpolant [output unit per axis unit].
  ValueAndGradient evaluate_with_gradient(const std::vector<double>& point) const;

  /// Whether the surface states a standard deviation at a point: GP surfaces
  /// (the posterior's), and grid and RBF surfaces built by this version (the
  /// runs' standard uncertainty interpolated as the surface interpolates
  /// their values, and the leave-one-out RMS error, in quadrature; README,
  /// "Uncertainty of grid and RBF surfaces"). A surface stored by an older
  /// version without it states none (false) until it is rebuilt.
  bool has_standard_deviation() const;
  /// The outputs and their standard deviations at one point.
  struct ValueAndDeviation {
    std::vector<double> values;              ///< one per output
    std::vector<double> standard_deviation;  ///< one per output, in its unit
  };
  /// As evaluate, with each output's standard deviation. InputError as
  /// evaluate, or for a surface without one (has_standard_deviation() false).
  ValueAndDeviation evaluate_with_standard_deviation(const std::vector<double>& point) const;

  /// Evaluates `count` points at once, on `threads` threads (0: every core),
  /// allocating nothing per point.
  ///   inputs:    one column per axis, in axes() order.
  ///   outputs:   one column per output, in outputs() order.
  ///   gradients: empty, or one column per (output, axis) pair, entry
  ///              [k * axes().size() + a] receiving d output_k / d axis_a.
  /// Every output column must be distinct memory from every input column.
  /// A point that cannot be evaluated (NaN, outside an axis under "error")
  /// stops the batch: the first such point in index order is reported as
  /// InputError "point I: MESSAGE" (I 0-based, MESSAGE as evaluate's). Then
  /// every point before it has been written and the outputs of that point and
  /// the points after it are unspecified (some may have been written).
  /// std::invalid_argument when the number of columns is wrong or a column
  /// with count > 0 has no data.
  ///   standard_deviations: empty, or one column per output receiving its
  ///              standard deviation (InputError for a surface without one).
  void evaluate_batch(std::size_t count, const std::vector<ConstColumn>& inputs, const std::vector<Column>& outputs,
                      const std::vector<Column>& gradients, unsigned threads = 0,
                      const std::vector<Column>& standard_deviations = {}) const;

  /// True for a gridded table: methods nearest, linear, pchip, makima and
  /// natural-spline, and an RBF surface resampled on a grid (`surface build
  /// --resample`). GP surfaces and plain RBF surfaces are not gridded.
  bool gridded() const;
  /// A gridded surface's own table: its breakpoints per axis, its node values
  /// as stored and, when it states one, the standard deviation at each node (the runs'
  /// uncertainty there, with the leave-one-out RMS in quadrature). InputError
  /// for a surface that is not gridded (tabulate() gives any surface on
  /// breakpoints of one's choosing).
  SurfaceTable table() const;
  /// The surface evaluated at every node of the grid the breakpoints make
  /// (one list per axis, in axes() order, each finite and strictly
  /// increasing), with its standard deviation when it states one: a GP (or
  /// any) surface made into a lookup table for a controller. On `threads`
  /// threads (0: every core). InputError for a wrong number of lists, an
  /// empty, non-finite or unordered list, more than 10^8 nodes, or a node the
  /// surface refuses (outside an axis under "error"): "point I: MESSAGE" as
  /// evaluate_batch says it, I the node's flat index.
  SurfaceTable tabulate(const std::vector<std::vector<double>>& breakpoints, unsigned threads = 0) const;
  /// Per output (outputs() order), the `count` points of the surface's range
  /// where its standard deviation is largest, largest first, as `hydrocoef
  /// surface show` lists them. GP: the posterior's, searched over a space-
  /// filling set of candidates (1024 up to 200 runs, fewer for more runs, at
  /// least 64). Grid and RBF surfaces: every grid node (up to 100000) and a
  /// lattice of about 4096 points over the range, the points at least 1% of
  /// the range apart. Empty when the surface states no standard deviation.
  std::vector<std::vector<SigmaPeak>> largest_standard_deviations(std::size_t count = 3) const;

  /// Made by Database::surface(); Impl is the library's own.
  struct Impl;
  explicit Surface(std::shared_ptr<const Impl> impl);

 private:
  std::shared_ptr<const Impl> impl_;
};

// ---------------------------------------------------------------------------
// The surface commands as library calls: `hydrocoef surface build | rebuild |
// list | show` and `hydrocoef query` are these functions and print their
// results' text() or json(). Each takes a Database (hydrocoef/database.hpp):
// writes need one opened ReadWrite or Create (InputError for a read-only one,
// the file untouched).

/// One axis of a stored surface, as `surface show` describes it.
struct SurfaceAxisReport {
  std::string name;
  std::string unit;                 ///< "" when unknown (SI)
  double lower = 0.0, upper = 0.0;  ///< the range it was built over [unit]
  std::string out_of_range;         ///< the policy, as Surface::out_of_range
  std::vector<double> breakpoints;  ///< gridded surfaces: the table's breakpoints; empty otherwise
};

/// One output of a stored surface, with its quality figures.
struct SurfaceOutputReport {
  std::string name;
  std::string unit;
  /// Leave-one-out error of the runs [unit]: largest magnitude and RMS; NaN
  /// when not known (too few runs, or stored before it was kept).
  double loo_max = 0.0, loo_rms = 0.0;
  /// The run with the largest leave-one-out error and that error; 0 and NaN when not known.
  std::int64_t worst_run = 0;
  double worst_error = 0.0;
  /// Where the standard deviation is largest (Surface::largest_standard_deviations); empty when none is stated.
  std::vector<SigmaPeak> largest_sd;
};

/// A stored surface described whole: `hydrocoef surface show` (and, one per
/// surface, `surface list --json`).
struct SurfaceReport {
  std::string name;
  std::string body;
  std::string kind;                ///< "grid", "rbf" or "gp"
  std::string method;              ///< as Surface::method()
  std::string created_at;          ///< UTC, ISO 8601
  bool stale = false;              ///< forces of the body changed since it was built
  std::vector<std::int64_t> runs;  ///< the runs it was built from
  std::string built_from;          ///< the selection, in the selection language ("all runs", "u>=0.1, mirror v")
  std::vector<SurfaceAxisReport> axes;
  std::vector<SurfaceOutputReport> outputs;

  HYDROCOEF_EXPORT std::string text() const;  ///< what `surface show` prints
  HYDROCOEF_EXPORT std::string json() const;  ///< what `surface show --json` prints (breakpoint values included)
  struct Access;                              ///< the library's own

 private:
  std::string text_, json_;
};

/// The stored surfaces: `hydrocoef surface list`.
struct SurfaceList {
  std::vector<SurfaceReport> surfaces;  ///< by name

  HYDROCOEF_EXPORT std::string text() const;  ///< the table `surface list` prints
  HYDROCOEF_EXPORT std::string json() const;  ///< what `surface list --json` prints
  struct Access;

 private:
  std::string text_, json_;
};

/// A surface built and stored: `hydrocoef surface build` (one of `surface rebuild`).
struct SurfaceBuildReport {
  SurfaceReport surface;           ///< as stored (its text() and json() are show's)
  std::int64_t id = 0;             ///< its id in the database
  std::size_t runs_measured = 0;   ///< selected runs of the body
  std::size_t mirror_images = 0;   ///< images added beside them (never stored as runs)
  std::size_t images_skipped = 0;  ///< images left out at the key of a measured run
  std::size_t runs_skipped = 0;    ///< runs (or images) without every output
  std::string mirror;              ///< the mirror ("v", "v,w/current_v"), "" for none

  HYDROCOEF_EXPORT std::string text() const;  ///< what `surface build` prints
  HYDROCOEF_EXPORT std::string json() const;  ///< what `surface build --json` prints
  struct Access;

 private:
  std::string text_, json_;
};

/// Which stored surfaces `surface rebuild` builds again.
struct SurfaceRebuildOptions {
  std::string name;                        ///< one surface ("" : every surface, of `body` when given)
  std::string body;                        ///< only this body's surfaces ("" : every body)
  bool stale_only = false;                 ///< only surfaces whose runs changed (--stale)
  HYDROCOEF_EXPORT void validate() const;  ///< nothing to refuse today; called first
};

/// Surfaces built again: `hydrocoef surface rebuild`.
struct SurfaceRebuildReport {
  std::vector<SurfaceBuildReport> rebuilt;

  HYDROCOEF_EXPORT std::string text() const;  ///< each build's text, or "no surface to rebuild"
  HYDROCOEF_EXPORT std::string json() const;  ///< a JSON array of the builds' JSON
};

/// Builds a surface from the selected runs and stores it with its build
/// specification, as `hydrocoef surface build` (options.validate() first).
HYDROCOEF_EXPORT SurfaceBuildReport surface_build(Database& db, const SurfaceBuildOptions& options);
/// Builds stored surfaces again from the current runs with the specification
/// each was built with, as `hydrocoef surface rebuild`.
HYDROCOEF_EXPORT SurfaceRebuildReport surface_rebuild(Database& db, const SurfaceRebuildOptions& options);
/// The stored surfaces (of one body, or all when body is ""), as `hydrocoef surface list`.
HYDROCOEF_EXPORT SurfaceList surface_list(const Database& db, const std::string& body = "");
/// One stored surface described, as `hydrocoef surface show NAME`. InputError
/// listing the stored names when there is none of that name.
HYDROCOEF_EXPORT SurfaceReport surface_show(const Database& db, const std::string& name);

/// A query of a stored surface: the options of `hydrocoef query`. Either a
/// point (one value per axis) or a CSV file of points (`input`).
struct SurfaceQueryOptions {
  std::string name;  ///< the surface
  /// The point: (axis, value) pairs [axis unit], each axis of the surface once, any order.
  std::vector<std::pair<std::string, double>> point;
  /// A CSV of points whose header names the axes ("-" : standard input); "" for a point.
  std::string input;
  /// With input: where the CSV of results goes ("-" : standard output).
  std::string output = "-";
  bool gradient = false;     ///< also d output / d axis [output unit per axis unit]
  bool uncertainty = false;  ///< also each output's standard deviation (--uncertainty)
  /// Called with a warning before the surface is evaluated (a stale surface);
  /// the CLI prints it on standard error. Unset: warnings are only in the result.
  std::function<void(const std::string&)> warning;
  /// InputError "give either a point (AXIS=VALUE ...) or --input, not both"
  /// or "no point; ..." as the CLI says.
  HYDROCOEF_EXPORT void validate() const;
};

/// The answer of `hydrocoef query`.
struct SurfaceQueryResult {
  std::string surface;  ///< its name
  bool stale = false;
  std::vector<std::string> warnings;  ///< as given to SurfaceQueryOptions::warning
  // A point (options.point):
  std::vector<std::string> axes;     ///< the surface's axes
  std::vector<double> point;         ///< one per axis, in axes order
  std::vector<std::string> outputs;  ///< the surface's outputs
  std::vector<std::string> units;    ///< one per output
  std::vector<double> values;        ///< one per output [unit]
  /// With uncertainty: one per output [unit]; empty otherwise.
  std::vector<double> standard_deviation;
  /// With uncertainty on a GP surface: a new run's standard deviation there (the
  /// discrepancy added); empty otherwise.
  std::vector<double> new_run_standard_deviation;
  /// With gradient: gradient[k * axes.size() + a] = d output_k / d axis_a; empty otherwise.
  std::vector<double> gradient;
  // A batch (options.input):
  std::size_t points = 0;  ///< rows answered
  std::string output;      ///< where they were written ("-" : standard output)

  /// A point: what `query` prints; a batch: "" (the CSV is the output).
  HYDROCOEF_EXPORT std::string text() const;
  /// A point: what `query --json` prints; a batch written to a file: its
  /// summary {"surface", "points", "output"}; a batch to standard output: "".
  HYDROCOEF_EXPORT std::string json() const;
  /// A batch written to a file: "N points of surface 'S' written to FILE"
  /// (the CLI prints it on standard error); "" otherwise.
  HYDROCOEF_EXPORT std::string note() const;
  struct Access;

 private:
  std::string text_, json_, note_;
};

/// Evaluates a stored surface at a point, or at every row of a CSV, as
/// `hydrocoef query` (options.validate() first). InputError as the CLI's.
HYDROCOEF_EXPORT SurfaceQueryResult query_surface(const Database& db, const SurfaceQueryOptions& options);

}  // namespace api
}  // namespace hydrocoef
