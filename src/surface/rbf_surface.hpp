// Scattered-sample coefficient surfaces: a smooth function of 1 to 6 axes (for
// example X(u, v) or the coefficients of a damping law over (u, r)) built from
// CFD runs that do not fill a grid, by radial basis function (RBF)
// interpolation or smoothing.
//
// The surface is
//     s_k(x) = sum_i w_ik phi(|z(x) - z_i|) + sum_j c_jk p_j(z(x))
// for each output k, with z_i the samples, phi a polyharmonic kernel and p_j
// the monomials of a polynomial of degree 0, 1 or 2; the weights solve the
// saddle-point system
//     [ A + lambda I   P ] [w]   [y]
//     [ P^T            0 ] [c] = [0],   A_il = phi(|z_i - z_l|), P_ij = p_j(z_i),
// factorized once (LU with partial pivoting) for all outputs.
//
// Axis scaling. Distances are taken in scaled coordinates
//     z_a = (x_a - m_a) / L_a,
// m_a being the midpoint of the samples' range on axis a and L_a a length
// scale: by default the samples' range (max - min) on that axis, so that every
// axis spans 1; or one the caller gives, in the axis's own unit. Without this a
// distance would add m/s to rad/s and the axis with the larger numbers would
// decide which samples are "near". With default scales the surface is the same
// whatever unit each axis is given in (m/s or mm/s, rad/s or deg/s). Distances
// this module reports (nearest sample, far-from-data threshold) are in these
// scaled units: 0.1 is a tenth of the samples' range along an axis.
//
// A built surface never changes. evaluate() and evaluate_with_gradient() are
// const, thread-safe and allocate nothing: callers pass spans, scratch space
// is fixed-size on the stack.
//
// Units: an axis value is in its SI unit (m/s, rad/s, or a disturbance's SI
// unit); outputs are in whatever unit the sample values were given in; a
// gradient entry is the output's unit per axis unit. Sample indices in error
// messages and results are 0-based, as in the arrays the caller passed.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace hydrocoef {

/// The radial function phi(r), r the distance in scaled coordinates.
enum class RbfKernel {
  Cubic,      ///< r^3 (polyharmonic); needs polynomial degree >= 1
  ThinPlate,  ///< r^2 log r (thin-plate spline); needs polynomial degree >= 1
  Linear      ///< -r (piecewise linear along rays; kinks at the samples); needs degree >= 0.
              ///< The minus sign makes the kernel conditionally positive definite, so that
              ///< smoothing acts as a penalty (as in SciPy's RBFInterpolator); it does not
              ///< change the interpolant.
};

/// What evaluation does with a coordinate outside the samples' range [min, max] on its axis.
enum class RbfOutOfRange {
  Error,       ///< throw InputError naming the axis, the value and the range
  Clamp,       ///< evaluate at the nearest end of the range; the gradient along that axis is 0
  Extrapolate  ///< evaluate the RBF there as it stands: unchecked, a guess away from the samples
};

struct RbfOptions {
  RbfKernel kernel = RbfKernel::Cubic;
  /// Degree of the polynomial added to the kernel sum: 0, 1 or 2. With degree
  /// 1 (2) the surface reproduces linear (quadratic) functions exactly. Cubic
  /// and ThinPlate need degree >= 1 for the system to be uniquely solvable
  /// (InputError otherwise).
  int polynomial_degree = 1;
  /// lambda >= 0 added to the kernel matrix's diagonal: 0 interpolates the
  /// samples; larger values give a smoother surface that misses sample i by
  /// lambda * w_i. Dimensionless (the kernel is evaluated in scaled
  /// coordinates) and independent of the outputs' units.
  double smoothing = 0.0;
  /// Empty: each axis is scaled by its samples' range. Otherwise one length
  /// scale per axis, finite and > 0, in the axis's unit.
  std::vector<double> length_scales;
  /// Empty: Error on every axis. Otherwise one policy per axis.
  std::vector<RbfOutOfRange> out_of_range;
  /// Empty: axes are called "axis 0", "axis 1", ... in messages. Otherwise one
  /// name per axis, e.g. {"u", "r"}.
  std::vector<std::string> axis_names;
};

/// Leave-one-out cross-validation of a surface: how well each sample is
/// predicted by the surface built (with the same options) from all the others.
/// Computed from one factorization (Rippa's formula, extended to the
/// polynomial-augmented and smoothed system: e_i = w_i / (K^-1)_ii).
struct RbfCrossValidation {
  /// Sample-major, errors[i * outputs + k] = y_ik - s_k^(-i)(x_i) [output unit].
  /// NaN for a sample without which the others no longer determine the
  /// polynomial (e.g. the only sample off a line, degree 1 in 2-D).
  std::vector<double> errors;
  std::vector<double> max_abs;      ///< per output: max |error| over samples where it is defined
  std::vector<double> rms;          ///< per output: root mean square over samples where it is defined
  std::size_t undefined_count = 0;  ///< samples whose error is NaN
};

/// A surface resampled onto a rectilinear grid, e.g. to store or export it as a table.
struct RbfGrid {
  std::vector<std::vector<double>> breakpoints;  ///< per axis, strictly increasing [axis unit]
  /// Grid point g = i0 + n0 * (i1 + n1 * (i2 + ...)) (axis 0 fastest), i_a the
  /// breakpoint index on axis a and n_a that axis's breakpoint count.
  /// values[g * outputs + k]: outputs fastest, then axis 0, then axis 1, ...
  /// (the layout GridTable's constructor takes).
  std::vector<double> values;
  /// Per grid point g: distance from it to the nearest sample, in scaled units.
  std::vector<double> nearest_sample_distance;
  /// Grid points (g, increasing) whose nearest sample is farther than
  /// far_threshold: there the values are extrapolated guesses, not data.
  std::vector<std::size_t> far_from_data;
  double far_threshold = 0.0;  ///< in scaled units
};

/// A solved RBF system, as stored with a surface so that loading it costs
/// O(N) instead of a new O(N^3) solve.
struct RbfSolution {
  std::vector<double> kernel_weights;      ///< sample-major, w_ik
  std::vector<double> polynomial_weights;  ///< term-major, c_jk
  std::vector<double> loo_errors;          ///< as RbfCrossValidation::errors (NaN where undefined)
};

class RbfSurface {
 public:
  static constexpr std::size_t kMaxAxes = 6;
  /// The most samples a surface may have (a dense solve of 5000 takes about
  /// 10 s and 0.4 GB); a build or a stored surface with more is refused.
  static constexpr std::size_t kMaxSamples = 5000;

  /// Builds the surface.
  ///   axis_count:   1..6.
  ///   points:       sample-major, points[i * axis_count + a] = sample i's value on axis a.
  ///   output_count: >= 1 outputs per sample (they share one factorization).
  ///   values:       sample-major, values[i * output_count + k] = output k at sample i.
  ///   options:      kernel, polynomial, smoothing, scaling, out-of-range policies, axis names.
  /// Also computes the leave-one-out cross-validation. Cost: O((N + M)^3) time
  /// and O((N + M)^2) memory for N samples and M polynomial terms (one LU and
  /// its inverse), meant for CFD sweeps of up to a few thousand runs; an
  /// evaluation costs O(N (axes + outputs)).
  /// Throws InputError when sizes disagree, a value is not finite, an option is
  /// out of its range, an axis does not vary across the samples, two samples
  /// are at the same point (naming both), there are fewer samples than
  /// polynomial terms or the samples do not determine the polynomial (all on a
  /// line for degree 1 in 2-D), or the system is numerically singular.
  RbfSurface(std::size_t axis_count, std::span<const double> points, std::size_t output_count,
             std::span<const double> values, const RbfOptions& options = {});

  /// The surface from its samples and a stored solution of them, in O(N):
  /// the same checks of the samples and options as the constructor above,
  /// and the solution's sizes and finiteness, but no solve. The caller
  /// vouches that the solution is the samples' (src/surface/stored_surface
  /// keeps a hash of the samples with it).
  RbfSurface(std::size_t axis_count, std::span<const double> points, std::size_t output_count,
             std::span<const double> values, const RbfOptions& options, const RbfSolution& solution);

  /// The solved weights and leave-one-out errors, to store.
  RbfSolution solution() const;

  std::size_t axis_count() const noexcept { return axis_count_; }
  std::size_t output_count() const noexcept { return output_count_; }
  std::size_t sample_count() const noexcept { return sample_count_; }
  RbfKernel kernel() const noexcept { return kernel_; }
  int polynomial_degree() const noexcept { return polynomial_degree_; }
  double smoothing() const noexcept { return smoothing_; }
  /// The samples' range on an axis [axis unit]. These per-axis accessors
  /// throw std::out_of_range when axis >= axis_count().
  double lower(std::size_t axis) const { return lower_[checked(axis)]; }
  double upper(std::size_t axis) const { return upper_[checked(axis)]; }
  /// The length scale L_a that axis is divided by [axis unit].
  double length_scale(std::size_t axis) const { return scale_[checked(axis)]; }
  RbfOutOfRange out_of_range(std::size_t axis) const { return policy_[checked(axis)]; }
  const RbfCrossValidation& cross_validation() const noexcept { return cross_validation_; }

  /// out[k] = s_k(point).
  ///   point: axis_count values [axis units].
  ///   out:   output_count values, overwritten.
  /// Throws InputError when point does not have axis_count values, a
  /// coordinate is NaN or infinite (naming the axis), or a coordinate is out of
  /// range on an axis whose policy is Error; std::invalid_argument when out
  /// has the wrong size. Allocates nothing (except an exception's message).
  void evaluate(std::span<const double> point, std::span<double> out) const;

  /// As evaluate, and gradient[k * axis_count + a] = d s_k / d x_a [output unit
  /// per axis unit] (output-major). gradient has output_count * axis_count
  /// values (std::invalid_argument otherwise). The linear kernel has kinks at
  /// the samples; there the kernel's contribution to the gradient is taken as 0.
  void evaluate_with_gradient(std::span<const double> point, std::span<double> out, std::span<double> gradient) const;

  /// Distance from point to the nearest sample in scaled units (no range
  /// policy applies: any finite point is accepted).
  double nearest_sample_distance(std::span<const double> point) const;

  /// The surface on a grid.
  ///   breakpoints:   one strictly increasing, finite, non-empty list per axis [axis unit];
  ///                  each axis's out-of-range policy applies to its breakpoints.
  ///   far_threshold: >= 0, scaled units; grid points farther than this from
  ///                  every sample are listed in far_from_data.
  RbfGrid resample(const std::vector<std::vector<double>>& breakpoints, double far_threshold) const;

 private:
  /// Checks sizes, options and samples; sets ranges, scales and centres.
  void prepare(std::span<const double> points, std::span<const double> values, const RbfOptions& options);
  /// Solves the system for the weights and the leave-one-out errors.
  void solve(std::span<const double> values);
  void evaluate_at(std::span<const double> point, std::span<double> out, double* gradient) const;
  std::size_t checked(std::size_t axis) const;

  std::size_t axis_count_ = 0;
  std::size_t output_count_ = 0;
  std::size_t sample_count_ = 0;
  std::size_t polynomial_terms_ = 0;
  RbfKernel kernel_ = RbfKernel::Cubic;
  int polynomial_degree_ = 1;
  double smoothing_ = 0.0;
  std::array<double, kMaxAxes> lower_{};
  std::array<double, kMaxAxes> upper_{};
  std::array<double, kMaxAxes> midpoint_{};
  std::array<double, kMaxAxes> scale_{};
  std::array<RbfOutOfRange, kMaxAxes> policy_{};
  std::vector<std::string> axis_labels_;    ///< "axis 'u'" or "axis 0", for messages
  std::vector<double> centers_;             ///< sample-major, scaled coordinates
  std::vector<double> kernel_weights_;      ///< sample-major, w_ik
  std::vector<double> polynomial_weights_;  ///< term-major, c_jk
  RbfCrossValidation cross_validation_;
};

}  // namespace hydrocoef
