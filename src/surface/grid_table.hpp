// Gridded lookup surfaces: one or several coefficients tabulated on a
// rectilinear grid of 1 to 6 axes (for example X, Y, Z, K, M, N over u, v, r
// from a CFD campaign) and evaluated anywhere on, and optionally beyond, the
// grid, with the exact gradient of the interpolant. This is what a dynamics
// model or a controller queries at every time step.
//
// A GridTable is built once and never changes; evaluation is const,
// thread-safe, allocates nothing and writes into spans the caller owns. All
// outputs share one breakpoint search and one set of weights per query, so
// six outputs cost far less than six one-output queries (in 2-D, under twice
// one; in 4-D cubic the 256 coefficients read per output dominate instead).
//
// N-D interpolation is the tensor product of a 1-D method. Every method is
// written as a cubic (or linear, or constant) Hermite form: for the cubic
// methods the nodal derivatives the method needs are computed once, at
// construction, along each axis, and so are the mixed derivatives (d^2/dx dy
// and so on), by applying the same 1-D slope rule along each further axis in
// increasing axis order. Evaluation is then a fixed local sum over the cell's
// 2^n corners and their 2^n derivative combinations (4^n terms per output; 16
// in 2-D, 256 in 4-D). The price is memory: a cubic table keeps 2^n numbers
// per tabulated value (4x in 2-D, 16x in 4-D, 64x in 6-D).
//
// For the natural spline (linear in the data) this is exactly the
// tensor-product natural spline. PCHIP's and makima's slope rules are
// nonlinear, so their N-D extension is a choice: the one here reproduces
// multilinear functions, equals G(x) H(y) or G(x) + H(y) (G, H the 1-D
// interpolants) on data g(x) h(y) or g(x) + h(y), and is the 1-D method
// exactly along every grid line. PCHIP's monotonicity therefore holds along
// grid lines and for such separable data; between grid lines of general
// monotone N-D data it is not guaranteed (nor is it by the other common
// construction, successive 1-D pchip along one axis after another).
//
// Units: breakpoints are in their axis variable's SI unit (m/s for u, v, w;
// rad/s for p, q, r; rad for angles), values in their output's SI unit (N,
// N m, or 1 for a non-dimensional coefficient), in whatever sign convention
// they were given. A gradient entry is in output unit per axis unit.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/src/grid_kernel.h"

namespace hydrocoef {

/// The 1-D method; N-D is its tensor product (see the file comment). The
/// values are the runtime file's method codes (runtime/src/grid_kernel.h).
enum class Interpolation {
  /// Value of the nearest breakpoint along each axis (a tie goes to the upper
  /// breakpoint). Piecewise constant: the gradient is 0.
  Nearest,
  /// Piecewise linear along each axis (multilinear in a cell). Continuous; the
  /// gradient is the cell's slope, one-sided at breakpoints.
  Linear,
  /// Monotone piecewise cubic Hermite, slopes as MATLAB pchip and SciPy
  /// PchipInterpolator: interior slopes are the Fritsch–Butland weighted
  /// harmonic mean of the neighbouring secants (0 where they differ in sign
  /// or one is 0), end slopes the shape-preserving three-point formula. C1;
  /// no overshoot on monotone 1-D data. Needs >= 3 breakpoints per axis.
  Pchip,
  /// Modified Akima ("makima", as MATLAB makima): slopes are a weighted mean
  /// of the two neighbouring secants, the weights |d(i+1) - d(i)| +
  /// |d(i+1) + d(i)| / 2 damping wiggles next to flat or kinked data. End
  /// rule: two secants are added beyond each end by linear extrapolation of
  /// the secants (d(-1) = 2 d(0) - d(1), d(-2) = 2 d(-1) - d(0), likewise on
  /// the right); where all four secants are 0 the slope is 0. C1. Needs >= 3
  /// breakpoints per axis.
  Akima,
  /// Natural cubic spline (second derivative 0 at both ends) along each
  /// axis: C2, global (every value influences every cell along its axis).
  /// Needs >= 3 breakpoints per axis.
  NaturalSpline
};

/// What happens at a query coordinate outside an axis's breakpoint range.
/// The values are the runtime file's policy codes (runtime/src/grid_kernel.h).
enum class Extrapolation {
  /// Throw InputError naming the axis, the value and the valid range.
  Error,
  /// Use the nearest end of the range; the gradient along this axis is 0.
  Clamp,
  /// Continue linearly from the end value with the interpolant's slope along
  /// this axis at that end: f(b) + (x - b) df/dx(b). With several axes
  /// outside, the tensor product of these 1-D continuations (so a
  /// multilinear function is continued exactly). For Nearest, as Clamp.
  Linear,
  /// Continue the end cell's own polynomial (the end cubic for cubic methods,
  /// the end segment for Linear). For Linear interpolation this equals
  /// Extrapolation::Linear; for Nearest, Clamp.
  Method
};

/// One axis of a grid.
struct GridAxis {
  std::string name;                 ///< e.g. "u"; non-empty, unique within a table
  std::vector<double> breakpoints;  ///< finite, strictly increasing; >= 2 (>= 3 for cubic methods)
  Extrapolation extrapolation = Extrapolation::Error;
};

/// The most axes a table may have.
inline constexpr std::size_t kMaxGridAxes = 6;

/// The lowercase name used in files and on the command line: "nearest",
/// "linear", "pchip", "makima", "natural-spline".
std::string_view interpolation_name(Interpolation method);
/// Reads interpolation_name's spelling back; throws InputError listing the accepted names.
Interpolation parse_interpolation(std::string_view text);
/// "error", "clamp", "linear", "method".
std::string_view extrapolation_name(Extrapolation policy);
/// Reads extrapolation_name's spelling back; throws InputError listing the accepted names.
Extrapolation parse_extrapolation(std::string_view text);

/// An immutable gridded surface of one or more outputs over 1 to 6 axes.
class GridTable {
 public:
  /// axes: 1 to kMaxGridAxes axes, as described at GridAxis.
  /// outputs: output names, at least one, non-empty and unique (e.g. "X", "Y", "N").
  /// values: one finite value per node and output, outputs interleaved
  ///   fastest, then axis 0, then axis 1 and so on. With n_a breakpoints on
  ///   axis a, n_out outputs and node index (i_0, ..., i_{n-1}):
  ///     values[((i_{n-1} * n_{n-2} + ... + i_1) * n_0 + i_0) * n_out + k]
  ///   is output k at that node; values.size() == n_0 * ... * n_{n-1} * n_out.
  /// method: the interpolation method, the same along every axis.
  /// Throws InputError naming the axis or output, the index, what was found
  /// and what was expected when any of this does not hold.
  GridTable(std::vector<GridAxis> axes, std::vector<std::string> outputs, std::vector<double> values,
            Interpolation method);

  std::size_t axis_count() const noexcept { return axes_.size(); }
  std::size_t output_count() const noexcept { return outputs_.size(); }
  /// Number of grid nodes, n_0 * ... * n_{n-1}.
  std::size_t node_count() const noexcept { return node_count_; }
  const std::vector<GridAxis>& axes() const noexcept { return axes_; }
  const std::vector<std::string>& outputs() const noexcept { return outputs_; }
  /// The tabulated values, laid out as in the constructor.
  const std::vector<double>& values() const noexcept { return values_; }
  Interpolation method() const noexcept { return method_; }
  /// For the cubic methods (Pchip, Akima, NaturalSpline): what evaluation
  /// reads, per node the value and every mixed derivative of every output,
  ///   hermite_data()[(node * 2^n + S) * output_count() + k],
  /// node as in the values layout, S a bit set over the axes (bit a set: one
  /// derivative along axis a, in output unit per axis unit; S = 0 the value).
  /// In a cell, along each axis, the interpolant is the cubic Hermite form of
  /// the two end nodes' values and slopes; N-D is the tensor product. An
  /// exporter that writes these numbers reproduces the table exactly. Empty
  /// for Nearest and Linear, which read values().
  const std::vector<double>& hermite_data() const noexcept { return hermite_; }
  /// True when the axis's breakpoints were found evenly spaced (to 1e-12 of
  /// their magnitude) and are located by direct index rather than by search.
  /// A performance detail only: both ways give the same cell. Throws
  /// std::out_of_range if axis >= axis_count().
  bool evenly_spaced(std::size_t axis) const;
  /// Position of an output by name; throws InputError listing the outputs if there is none.
  std::size_t output_index(std::string_view name) const;

  /// Evaluates every output at a point.
  /// point: one coordinate per axis, in axis order and axis units.
  /// out: receives output_count() values, in output order.
  /// Throws InputError if point.size() != axis_count(), a coordinate is NaN or
  /// infinite, or a coordinate is outside its axis under Extrapolation::Error;
  /// std::invalid_argument if out has the wrong size. Allocates nothing
  /// (except to build an exception's message).
  void evaluate(std::span<const double> point, std::span<double> out) const;

  /// As evaluate, and the exact gradient of the interpolant:
  /// gradient[k * axis_count() + a] = d output_k / d axis_a, so gradient has
  /// output_count() * axis_count() entries. At a breakpoint of a Linear table
  /// the derivative along that axis is the upper cell's (the lower cell's at
  /// the last breakpoint); Nearest gives 0, and so does a clamped axis.
  void evaluate_with_gradient(std::span<const double> point, std::span<double> out, std::span<double> gradient) const;

  /// evaluate() of a one-axis table at `value`, without the span checks:
  /// `out` receives output_count() values, the same numbers evaluate gives.
  /// The dynamics model's hot path (src/dynamics/damping.cpp). Throws as
  /// evaluate, and InputError for a table of more than one axis.
  void evaluate_one_axis(double value, double* out) const;

  /// evaluate() without the span checks, for any axis count: `point` holds
  /// axis_count() coordinates and `out` receives output_count() values, the
  /// same numbers evaluate gives (the same weights and the same sum, compiled
  /// for this table's axis count and method). The dynamics model's hot path
  /// (src/dynamics/damping.cpp). Throws as evaluate for a coordinate.
  void evaluate_unchecked(const double* point, double* out) const { point_kernel_(*this, point, out); }

  /// True when `other` has this table's one axis (name, breakpoints and
  /// extrapolation), method and output count, as the draws of one surface on
  /// its nodes have: evaluate_one_axis_lanes may serve both.
  bool shares_axis(const GridTable& other) const;
  /// evaluate_one_axis of N tables that share their axis (shares_axis) at
  /// values[l], lane by lane: out[k * N + l] = tables[l]'s output k at values[l],
  /// the same numbers. The cell search, the division and the weights are done
  /// for every lane at once. Allocates nothing (but to build an exception's
  /// message).
  /// Instantiated for N = 1 and 8 (motion::kLanes).
  template <std::size_t N>
  static void evaluate_one_axis_lanes(const std::array<const GridTable*, N>& tables, const double* values, double* out);

  /// One output at a point (the same number evaluate gives). Throws as
  /// evaluate; std::out_of_range if output >= output_count().
  double evaluate_one(std::span<const double> point, std::size_t output) const;

 private:
  // Per-axis lookup data derived from the breakpoints (the shared kernel's:
  // lo, hi, inv_step, even, extrapolation as its code, count, offset of the
  // first breakpoint in breakpoints_, node_stride).
  using AxisLookup = hc_kernel_axis;
  struct Location;
  // The local sum for one (axis count, terms per axis) pair, with both known
  // at compile time: out[k * out_stride] = sum over the K^n terms of the
  // product of per-axis weights times data[term offset + k], k < count.
  // axis_weights: kMaxGridAxes x 4; axis `replaced` (if < n) uses
  // `replacement` instead (a partial derivative).
  using SumKernel = void (*)(const double* axis_weights, std::size_t replaced, const double* replacement,
                             const std::size_t* term_offsets, const double* data, std::size_t count, double* out,
                             std::size_t out_stride);

  // locate's work along axis a: the weights w (and their derivatives dw) of
  // `value`, and the node along the axis the weights start at.
  // Throws (throw_outside) for a value outside under Extrapolation::Error or
  // not finite. The shared kernel's hc_kernel_axis_cell.
  template <std::size_t K, bool WithGradient>
  std::size_t axis_cell(std::size_t a, double value, double* w, double* dw) const;
  template <std::size_t K, bool WithGradient>
  void locate(std::span<const double> point, Location& location) const;
  // evaluate_one_axis_lanes' sum from each lane's node and weights w[e][lane].
  template <std::size_t N>
  static void sum_lanes(const std::array<const GridTable*, N>& tables, const std::array<std::size_t, N>& node,
                        const std::array<std::array<double, N>, 4>& w, double* out);
  // evaluate_unchecked for N axes and K terms per axis: locate and sum in one.
  using PointKernel = void (*)(const GridTable& table, const double* point, double* out);
  template <std::size_t N, std::size_t K>
  static void evaluate_point(const GridTable& table, const double* point, double* out);
  template <std::size_t K, std::size_t... N>
  static constexpr std::array<PointKernel, sizeof...(N)> point_kernels(std::index_sequence<N...>);
  template <bool WithGradient>
  void locate_any(std::span<const double> point, Location& location) const;
  void check_point(std::span<const double> point) const;
  [[noreturn]] void throw_outside(std::size_t axis, double value) const;

  std::vector<GridAxis> axes_;
  std::vector<std::string> outputs_;
  std::vector<double> values_;
  Interpolation method_;
  std::size_t node_count_ = 0;
  std::array<AxisLookup, kMaxGridAxes> lookup_{};
  // Every axis's breakpoints, one after another, so that the hot path reads
  // them without going through axes_.
  std::vector<double> breakpoints_;
  // For cubic methods: per node, for each subset S of axes (bit a set: one
  // derivative along axis a), the mixed derivative of every output:
  // hermite_[(node * 2^n + S) * n_out + k]. Empty for Nearest and Linear,
  // which read values_.
  std::vector<double> hermite_;
  // Numbers per node in the evaluated array: n_out, or 2^n * n_out (cubic).
  std::size_t node_block_ = 0;
  // Terms per axis in the local sum: 1 (Nearest), 2 (Linear) or 4 (cubic:
  // two corners, each with value and slope), and the offset of every term of
  // the K^n-term sum from the cell's base, axis 0's term fastest.
  std::size_t terms_per_axis_ = 0;
  std::vector<std::size_t> term_offsets_;
  SumKernel sum_ = nullptr;
  PointKernel point_kernel_ = nullptr;
};

}  // namespace hydrocoef
