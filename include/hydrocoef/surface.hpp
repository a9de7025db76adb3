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
#include <memory>
#include <string>
#include <vector>

#include "hydrocoef/error.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
// The public API lives in an inline namespace: users write hydrocoef::Surface;
// inside the library it keeps these classes apart from the internal ones of
// the same name (the store's Database).
inline namespace api {

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

  /// Made by Database::surface(); Impl is the library's own.
  struct Impl;
  explicit Surface(std::shared_ptr<const Impl> impl);

 private:
  std::shared_ptr<const Impl> impl_;
};

}  // namespace api
}  // namespace hydrocoef
