#include "src/surface/grid_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/surface/grid_kernel.hpp"
#include "src/surface/pchip.hpp"

namespace hydrocoef {

namespace {

using namespace grid_kernel;

// The enums are the shared kernel's codes (runtime/src/grid_kernel.h) and the runtime file's.
static_assert(static_cast<int>(Interpolation::Nearest) == HC_KERNEL_NEAREST &&
              static_cast<int>(Interpolation::Linear) == HC_KERNEL_LINEAR &&
              static_cast<int>(Interpolation::Pchip) == HC_KERNEL_PCHIP &&
              static_cast<int>(Interpolation::Akima) == HC_KERNEL_MAKIMA &&
              static_cast<int>(Interpolation::NaturalSpline) == HC_KERNEL_NATURAL_SPLINE);
static_assert(static_cast<int>(Extrapolation::Error) == HC_KERNEL_ERROR &&
              static_cast<int>(Extrapolation::Clamp) == HC_KERNEL_CLAMP &&
              static_cast<int>(Extrapolation::Linear) == HC_KERNEL_EXTRAPOLATE_LINEAR &&
              static_cast<int>(Extrapolation::Method) == HC_KERNEL_METHOD);

bool is_cubic(Interpolation method) {
  return method == Interpolation::Pchip || method == Interpolation::Akima || method == Interpolation::NaturalSpline;
}

std::string in_quotes(std::string_view name) { return "'" + std::string(name) + "'"; }

// ---- 1-D slope rules: y at breakpoints x (n >= 3) -> slope d at every breakpoint.

void pchip_slopes(std::span<const double> x, std::span<const double> y, std::span<double> d, std::span<double> h,
                  std::span<double> del) {
  const std::size_t n = x.size();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = x[i + 1] - x[i];
    del[i] = (y[i + 1] - y[i]) / h[i];
  }
  for (std::size_t i = 1; i + 1 < n; ++i) d[i] = pchip_interior_slope(h[i - 1], h[i], del[i - 1], del[i]);
  d[0] = pchip_end_slope(h[0], h[1], del[0], del[1]);
  d[n - 1] = pchip_end_slope(h[n - 2], h[n - 3], del[n - 2], del[n - 3]);
}

// Modified Akima. ext holds the n - 1 secants with two extrapolated ones on each side:
// ext[j + 2] is the secant of interval j, j = -2 .. n.
void makima_slopes(std::span<const double> x, std::span<const double> y, std::span<double> d, std::span<double> ext) {
  const std::size_t n = x.size();
  for (std::size_t i = 0; i + 1 < n; ++i) ext[i + 2] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  ext[1] = 2.0 * ext[2] - ext[3];
  ext[0] = 2.0 * ext[1] - ext[2];
  ext[n + 1] = 2.0 * ext[n] - ext[n - 1];
  ext[n + 2] = 2.0 * ext[n + 1] - ext[n];
  for (std::size_t i = 0; i < n; ++i) {
    const double far_left = ext[i];       // secant i - 2
    const double left = ext[i + 1];       // secant i - 1
    const double right = ext[i + 2];      // secant i
    const double far_right = ext[i + 3];  // secant i + 1
    const double w_left = std::abs(left - far_left) + 0.5 * std::abs(left + far_left);
    const double w_right = std::abs(far_right - right) + 0.5 * std::abs(far_right + right);
    const double sum = w_left + w_right;
    d[i] = sum == 0.0 ? 0.0 : (w_right * left + w_left * right) / sum;
  }
}

// Natural cubic spline: second derivatives m with m[0] = m[n-1] = 0 from the
// tridiagonal continuity equations (Thomas algorithm), then the end slopes of
// each cubic piece.
void natural_spline_slopes(std::span<const double> x, std::span<const double> y, std::span<double> d,
                           std::span<double> m, std::span<double> c_prime) {
  const std::size_t n = x.size();
  // Unknowns m[1..n-2]: h[i-1] m[i-1] + 2 (h[i-1] + h[i]) m[i] + h[i] m[i+1] = 6 (del[i] - del[i-1]).
  m[0] = 0.0;
  m[n - 1] = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h_left = x[i] - x[i - 1];
    const double h_right = x[i + 1] - x[i];
    const double rhs = 6.0 * ((y[i + 1] - y[i]) / h_right - (y[i] - y[i - 1]) / h_left);
    const double sub = i > 1 ? h_left : 0.0;
    const double diag = 2.0 * (h_left + h_right) - sub * (i > 1 ? c_prime[i - 1] : 0.0);
    c_prime[i] = h_right / diag;
    m[i] = (rhs - sub * m[i - 1]) / diag;
  }
  for (std::size_t i = n - 2; i >= 1; --i) {
    if (i + 2 < n) m[i] -= c_prime[i] * m[i + 1];
  }
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double h = x[i + 1] - x[i];
    d[i] = (y[i + 1] - y[i]) / h - h * (2.0 * m[i] + m[i + 1]) / 6.0;
  }
  const double h_last = x[n - 1] - x[n - 2];
  d[n - 1] = (y[n - 1] - y[n - 2]) / h_last + h_last * (m[n - 2] + 2.0 * m[n - 1]) / 6.0;
}

// ---- Per-axis weights of the local sum.

// ---- The local sum, with the axis count N and the terms per axis K known at compile time.

template <std::size_t N, std::size_t K>
void sum_terms(const double* axis_weights, std::size_t replaced, const double* replacement, const std::size_t* offsets,
               const double* data, std::size_t count, double* out, std::size_t out_stride) {
  // hc_kernel_sum's steps, the shared kernel's, with N, K and K^(N-1) known
  // here at compile time (so the sums over the K^(N-1) inner terms unroll).
  constexpr std::size_t kInner = power(K, N - 1);
  std::array<double, kInner> inner;
  hc_kernel_inner_weights(N, K, axis_weights, replaced, replacement, inner.data());
  const double* last = N - 1 == replaced ? replacement : axis_weights + 4 * (N - 1);
  std::size_t k = 0;
  for (; k + 6 <= count; k += 6)
    accumulate<6, kInner, K>(inner.data(), last, offsets, data + k, out + k * out_stride, out_stride);
  if (count - k >= 4) {
    accumulate<4, kInner, K>(inner.data(), last, offsets, data + k, out + k * out_stride, out_stride);
    k += 4;
  }
  if (count - k >= 2) {
    accumulate<2, kInner, K>(inner.data(), last, offsets, data + k, out + k * out_stride, out_stride);
    k += 2;
  }
  if (k < count) accumulate<1, kInner, K>(inner.data(), last, offsets, data + k, out + k * out_stride, out_stride);
}

template <std::size_t K, std::size_t... N>
constexpr std::array<void (*)(const double*, std::size_t, const double*, const std::size_t*, const double*, std::size_t,
                              double*, std::size_t),
                     sizeof...(N)>
kernels_for(std::index_sequence<N...>) {
  return {&sum_terms<N + 1, K>...};
}

}  // namespace

std::string_view interpolation_name(Interpolation method) {
  switch (method) {
    case Interpolation::Nearest: return "nearest";
    case Interpolation::Linear: return "linear";
    case Interpolation::Pchip: return "pchip";
    case Interpolation::Akima: return "makima";
    case Interpolation::NaturalSpline: return "natural-spline";
  }
  return "?";
}

Interpolation parse_interpolation(std::string_view text) {
  for (Interpolation method : {Interpolation::Nearest, Interpolation::Linear, Interpolation::Pchip,
                               Interpolation::Akima, Interpolation::NaturalSpline}) {
    if (text == interpolation_name(method)) return method;
  }
  throw InputError("unknown interpolation method " + in_quotes(text) +
                   "; expected nearest, linear, pchip, makima or natural-spline");
}

std::string_view extrapolation_name(Extrapolation policy) {
  switch (policy) {
    case Extrapolation::Error: return "error";
    case Extrapolation::Clamp: return "clamp";
    case Extrapolation::Linear: return "linear";
    case Extrapolation::Method: return "method";
  }
  return "?";
}

Extrapolation parse_extrapolation(std::string_view text) {
  for (Extrapolation policy :
       {Extrapolation::Error, Extrapolation::Clamp, Extrapolation::Linear, Extrapolation::Method}) {
    if (text == extrapolation_name(policy)) return policy;
  }
  throw InputError("unknown extrapolation policy " + in_quotes(text) + "; expected error, clamp, linear or method");
}

// Where a query falls: the base offset of its cell (or node, for Nearest) in
// the evaluated array and the per-axis term weights and their derivatives.
// Only the first K entries of each used axis's weights are written and read.
struct GridTable::Location {
  std::size_t base;
  std::array<double, 4 * kMaxGridAxes> weights;
  std::array<double, 4 * kMaxGridAxes> derivative_weights;
};

template <std::size_t K, std::size_t... N>
constexpr std::array<GridTable::PointKernel, sizeof...(N)> GridTable::point_kernels(std::index_sequence<N...>) {
  return {&GridTable::evaluate_point<N + 1, K>...};
}

GridTable::GridTable(std::vector<GridAxis> axes, std::vector<std::string> outputs, std::vector<double> values,
                     Interpolation method)
    : axes_(std::move(axes)), outputs_(std::move(outputs)), values_(std::move(values)), method_(method) {
  const std::size_t n = axes_.size();
  if (n < 1 || n > kMaxGridAxes) {
    throw InputError("a grid table has " + std::to_string(n) + " axes; expected 1 to " + std::to_string(kMaxGridAxes));
  }
  const bool cubic = is_cubic(method_);
  const std::size_t min_points = cubic ? 3 : 2;
  node_count_ = 1;
  for (std::size_t a = 0; a < n; ++a) {
    const GridAxis& axis = axes_[a];
    if (axis.name.empty()) throw InputError("axis " + std::to_string(a) + " has an empty name; expected a name");
    for (std::size_t b = 0; b < a; ++b) {
      if (axes_[b].name == axis.name) {
        throw InputError("axis name " + in_quotes(axis.name) + " is used by axes " + std::to_string(b) + " and " +
                         std::to_string(a) + "; expected unique axis names");
      }
    }
    const std::vector<double>& x = axis.breakpoints;
    if (x.size() < min_points) {
      throw InputError("axis " + in_quotes(axis.name) + " has " + std::to_string(x.size()) +
                       " breakpoints; expected at least " + std::to_string(min_points) + " for " +
                       std::string(interpolation_name(method_)) + " interpolation" +
                       (cubic ? " (cubic methods need 3)" : ""));
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (!std::isfinite(x[i])) {
        throw InputError("axis " + in_quotes(axis.name) + " breakpoint " + std::to_string(i) + " is " +
                         shortest_number(x[i]) + "; expected a finite number");
      }
      if (i > 0 && !(x[i] > x[i - 1])) {
        throw InputError("axis " + in_quotes(axis.name) + " breakpoint " + std::to_string(i) + " (" +
                         shortest_number(x[i]) + ") is not greater than breakpoint " + std::to_string(i - 1) + " (" +
                         shortest_number(x[i - 1]) + "); expected strictly increasing breakpoints");
      }
    }
    AxisLookup& lookup = lookup_[a];
    hc_kernel_axis_setup(x.data(), x.size(), &lookup);  // lo, hi, count, even, inv_step
    lookup.node_stride = node_count_;
    lookup.offset = breakpoints_.size();
    breakpoints_.insert(breakpoints_.end(), x.begin(), x.end());
    lookup.extrapolation = static_cast<int>(axis.extrapolation);
    if (node_count_ > values_.max_size() / x.size()) {
      throw InputError("a grid table of this size has too many nodes; expected fewer breakpoints");
    }
    node_count_ *= x.size();
  }

  if (outputs_.empty()) throw InputError("a grid table has no outputs; expected at least one output name");
  for (std::size_t k = 0; k < outputs_.size(); ++k) {
    if (outputs_[k].empty()) {
      throw InputError("output " + std::to_string(k) + " has an empty name; expected a name");
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (outputs_[j] == outputs_[k]) {
        throw InputError("output name " + in_quotes(outputs_[k]) + " is used by outputs " + std::to_string(j) +
                         " and " + std::to_string(k) + "; expected unique output names");
      }
    }
  }
  const std::size_t n_out = outputs_.size();
  if (values_.size() / n_out != node_count_ || values_.size() % n_out != 0) {
    std::string shape;
    for (std::size_t a = 0; a < n; ++a) shape += (a > 0 ? " x " : "") + std::to_string(lookup_[a].count);
    throw InputError("a grid table has " + std::to_string(values_.size()) + " values; expected " +
                     std::to_string(node_count_ * n_out) + " (" + shape + " nodes x " + std::to_string(n_out) +
                     " outputs)");
  }
  for (std::size_t index = 0; index < values_.size(); ++index) {
    if (std::isfinite(values_[index])) continue;
    std::size_t node = index / n_out;
    std::string at;
    for (std::size_t a = 0; a < n; ++a) {
      at += (a > 0 ? ", " : "") + axes_[a].name + "[" + std::to_string(node % lookup_[a].count) + "]";
      node /= lookup_[a].count;
    }
    throw InputError("value of output " + in_quotes(outputs_[index % n_out]) + " at node (" + at + ") (values index " +
                     std::to_string(index) + ") is " + shortest_number(values_[index]) + "; expected a finite number");
  }

  // Derivative tables for the cubic methods.
  const std::size_t subsets = cubic ? (std::size_t{1} << n) : 1;
  node_block_ = subsets * n_out;
  if (cubic) {
    hermite_.assign(node_count_ * node_block_, 0.0);
    for (std::size_t node = 0; node < node_count_; ++node) {
      std::copy_n(values_.begin() + static_cast<std::ptrdiff_t>(node * n_out), n_out,
                  hermite_.begin() + static_cast<std::ptrdiff_t>(node * node_block_));
    }
    std::size_t longest = 0;
    for (const AxisLookup& lookup : lookup_) longest = std::max(longest, lookup.count);
    std::vector<double> y(longest);
    std::vector<double> d(longest);
    std::vector<double> scratch_a(longest + 3);
    std::vector<double> scratch_b(longest + 3);
    // Subset S gets its derivative along its highest axis from subset S minus that axis.
    for (std::size_t subset = 1; subset < subsets; ++subset) {
      std::size_t a = 0;
      while ((subset >> (a + 1)) != 0) ++a;
      const std::size_t from = subset & ~(std::size_t{1} << a);
      const AxisLookup& lookup = lookup_[a];
      const std::size_t count = lookup.count;
      const std::size_t stride = lookup.node_stride;
      const std::span<const double> x(axes_[a].breakpoints);
      const std::span<double> ys(y.data(), count);
      const std::span<double> ds(d.data(), count);
      for (std::size_t outer = 0; outer < node_count_; outer += stride * count) {
        for (std::size_t inner = 0; inner < stride; ++inner) {
          const std::size_t first = outer + inner;
          for (std::size_t k = 0; k < n_out; ++k) {
            for (std::size_t i = 0; i < count; ++i) {
              ys[i] = hermite_[(first + i * stride) * node_block_ + from * n_out + k];
            }
            switch (method_) {
              case Interpolation::Pchip: pchip_slopes(x, ys, ds, scratch_a, scratch_b); break;
              case Interpolation::Akima: makima_slopes(x, ys, ds, scratch_a); break;
              default: natural_spline_slopes(x, ys, ds, scratch_a, scratch_b); break;
            }
            for (std::size_t i = 0; i < count; ++i) {
              hermite_[(first + i * stride) * node_block_ + subset * n_out + k] = ds[i];
            }
          }
        }
      }
    }
  }

  // Offsets of the local sum's terms from the cell base.
  terms_per_axis_ = hc_kernel_terms_per_axis(static_cast<int>(method_));
  std::array<std::size_t, kMaxGridAxes> node_strides{};
  for (std::size_t a = 0; a < n; ++a) node_strides[a] = lookup_[a].node_stride;
  term_offsets_.assign(hc_kernel_power(terms_per_axis_, n), 0);
  hc_kernel_term_offsets(n, static_cast<int>(method_), n_out, node_block_, node_strides.data(), term_offsets_.data());
  static constexpr auto kNearest = kernels_for<1>(std::make_index_sequence<kMaxGridAxes>());
  static constexpr auto kLinear = kernels_for<2>(std::make_index_sequence<kMaxGridAxes>());
  static constexpr auto kCubic = kernels_for<4>(std::make_index_sequence<kMaxGridAxes>());
  sum_ = (terms_per_axis_ == 1 ? kNearest : (terms_per_axis_ == 2 ? kLinear : kCubic))[n - 1];
  static constexpr auto kNearestPoint = point_kernels<1>(std::make_index_sequence<kMaxGridAxes>());
  static constexpr auto kLinearPoint = point_kernels<2>(std::make_index_sequence<kMaxGridAxes>());
  static constexpr auto kCubicPoint = point_kernels<4>(std::make_index_sequence<kMaxGridAxes>());
  point_kernel_ = (terms_per_axis_ == 1 ? kNearestPoint : (terms_per_axis_ == 2 ? kLinearPoint : kCubicPoint))[n - 1];
}

bool GridTable::evenly_spaced(std::size_t axis) const {
  if (axis >= axes_.size()) {
    throw std::out_of_range("GridTable::evenly_spaced: axis " + std::to_string(axis) +
                            " is out of range; the table has " + std::to_string(axes_.size()) + " axes");
  }
  return lookup_[axis].even;
}

std::size_t GridTable::output_index(std::string_view name) const {
  for (std::size_t k = 0; k < outputs_.size(); ++k) {
    if (outputs_[k] == name) return k;
  }
  std::string names;
  for (std::size_t k = 0; k < outputs_.size(); ++k) names += (k > 0 ? ", " : "") + outputs_[k];
  throw InputError("no output named " + in_quotes(name) + "; expected one of " + names);
}

void GridTable::check_point(std::span<const double> point) const {
  if (point.size() != axes_.size()) {
    throw InputError("a query point has " + std::to_string(point.size()) + " coordinates; expected " +
                     std::to_string(axes_.size()) + " (one per axis)");
  }
}

void GridTable::throw_outside(std::size_t axis, double value) const {
  if (!std::isfinite(value)) {
    throw InputError("axis " + in_quotes(axes_[axis].name) + " = " + shortest_number(value) +
                     " is not a number; expected a finite value");
  }
  throw InputError("axis " + in_quotes(axes_[axis].name) + " = " + shortest_number(value) + " is outside [" +
                   shortest_number(lookup_[axis].lo) + ", " + shortest_number(lookup_[axis].hi) +
                   "]; expected a value in range (or an extrapolation policy)");
}

template <std::size_t K, bool WithGradient>
inline std::size_t GridTable::axis_cell(std::size_t a, double value, double* w, double* dw) const {
  // The shared kernel: the cell search inside the range, the extrapolation
  // policy outside it (out of line), the weights of the method.
  const AxisLookup& axis = lookup_[a];
  std::size_t node = 0;
  if (hc_kernel_axis_cell(&axis, breakpoints_.data() + axis.offset, K, WithGradient, value, w, dw, &node) !=
      HC_KERNEL_OK) [[unlikely]]
    throw_outside(a, value);
  return node;
}

template <std::size_t K, bool WithGradient>
void GridTable::locate(std::span<const double> point, Location& location) const {
  std::size_t base_node = 0;
  for (std::size_t a = 0; a < point.size(); ++a) {
    base_node += axis_cell<K, WithGradient>(a, point[a], location.weights.data() + 4 * a,
                                            location.derivative_weights.data() + 4 * a) *
                 lookup_[a].node_stride;
  }
  location.base = base_node * node_block_;
}

template <bool WithGradient>
void GridTable::locate_any(std::span<const double> point, Location& location) const {
  switch (terms_per_axis_) {
    case 1: locate<1, WithGradient>(point, location); break;
    case 2: locate<2, WithGradient>(point, location); break;
    default: locate<4, WithGradient>(point, location); break;
  }
}

template <std::size_t N, std::size_t K>
void GridTable::evaluate_point(const GridTable& table, const double* point, double* out) {
  // locate<K, false> and sum_terms<N, K> as evaluate() calls them, so the
  // same arithmetic in the same order, with the axis count known here.
  std::array<double, 4 * kMaxGridAxes> weights;  // written before it is read (hot path)
  std::size_t base_node = 0;
  for (std::size_t a = 0; a < N; ++a)
    base_node += table.axis_cell<K, false>(a, point[a], weights.data() + 4 * a, nullptr) * table.lookup_[a].node_stride;
  const double* data =
      (table.hermite_.empty() ? table.values_.data() : table.hermite_.data()) + base_node * table.node_block_;
  sum_terms<N, K>(weights.data(), kMaxGridAxes, nullptr, table.term_offsets_.data(), data, table.outputs_.size(), out,
                  1);
}

void GridTable::evaluate(std::span<const double> point, std::span<double> out) const {
  check_point(point);
  if (out.size() != outputs_.size()) {
    throw std::invalid_argument("GridTable::evaluate: out has " + std::to_string(out.size()) + " entries; expected " +
                                std::to_string(outputs_.size()));
  }
  Location location;
  locate_any<false>(point, location);
  const double* data = (hermite_.empty() ? values_.data() : hermite_.data()) + location.base;
  sum_(location.weights.data(), kMaxGridAxes, nullptr, term_offsets_.data(), data, out.size(), out.data(), 1);
}

void GridTable::evaluate_with_gradient(std::span<const double> point, std::span<double> out,
                                       std::span<double> gradient) const {
  check_point(point);
  const std::size_t n = axes_.size();
  const std::size_t n_out = outputs_.size();
  if (out.size() != n_out || gradient.size() != n_out * n) {
    throw std::invalid_argument("GridTable::evaluate_with_gradient: out has " + std::to_string(out.size()) +
                                " and gradient " + std::to_string(gradient.size()) + " entries; expected " +
                                std::to_string(n_out) + " and " + std::to_string(n_out * n));
  }
  Location location;
  locate_any<true>(point, location);
  const double* data = (hermite_.empty() ? values_.data() : hermite_.data()) + location.base;
  sum_(location.weights.data(), kMaxGridAxes, nullptr, term_offsets_.data(), data, n_out, out.data(), 1);
  for (std::size_t a = 0; a < n; ++a) {
    sum_(location.weights.data(), a, location.derivative_weights.data() + 4 * a, term_offsets_.data(), data, n_out,
         gradient.data() + a, n);
  }
}

void GridTable::evaluate_one_axis(double value, double* out) const { evaluate_one_axis_lanes<1>({this}, &value, out); }

bool GridTable::shares_axis(const GridTable& other) const {
  return axes_.size() == 1 && other.axes_.size() == 1 && axes_[0].name == other.axes_[0].name &&
         method_ == other.method_ && outputs_.size() == other.outputs_.size() && breakpoints_ == other.breakpoints_ &&
         lookup_[0].extrapolation == other.lookup_[0].extrapolation && node_block_ == other.node_block_ &&
         term_offsets_ == other.term_offsets_;
}

template <std::size_t N>
void GridTable::evaluate_one_axis_lanes(const std::array<const GridTable*, N>& tables, const double* values,
                                        double* out) {
  const GridTable& first = *tables[0];
  const AxisLookup& axis = first.lookup_[0];
  if (first.axes_.size() != 1) [[unlikely]] {
    first.check_point(std::span<const double>(values, 1));  // throws as evaluate does
    throw std::logic_error("GridTable::evaluate_one_axis_lanes: a table of no axis");
  }
  const std::size_t terms = first.terms_per_axis_;
  std::array<std::size_t, N> node;
  std::array<std::array<double, N>, 4> w;  // entries e < terms are written before they are read
  bool inside = true;
  for (std::size_t l = 0; l < N; ++l) inside = inside && values[l] >= axis.lo && values[l] <= axis.hi;
  if (!inside) [[unlikely]] {
    // A value outside the axis (or NaN): locate's work, lane by lane.
    for (std::size_t l = 0; l < N; ++l) {
      std::array<double, 4> lane;
      switch (terms) {
        case 1: node[l] = first.axis_cell<1, false>(0, values[l], lane.data(), nullptr); break;
        case 2: node[l] = first.axis_cell<2, false>(0, values[l], lane.data(), nullptr); break;
        default: node[l] = first.axis_cell<4, false>(0, values[l], lane.data(), nullptr); break;
      }
      for (std::size_t e = 0; e < terms; ++e) w[e][l] = lane[e];
    }
    sum_lanes(tables, node, w, out);
    return;
  }
  // locate's work for one axis inside its range, every lane at once (the
  // cell search, the division and the weights vectorize over the lanes).
  const double* x = first.breakpoints_.data() + axis.offset;
  std::array<double, N> h, t;
  for (std::size_t l = 0; l < N; ++l) node[l] = hc_kernel_cell_inside(&axis, x, values[l]);
  for (std::size_t l = 0; l < N; ++l) {
    h[l] = x[node[l] + 1] - x[node[l]];
    t[l] = (values[l] - x[node[l]]) / h[l];
  }
  if (terms == 1) {
    for (std::size_t l = 0; l < N; ++l) {
      w[0][l] = 1.0;
      if (t[l] >= 0.5) ++node[l];
    }
  } else {
    // The shared kernel's weights, K a constant in each loop.
    const auto weights = [&]<std::size_t K>() {
      for (std::size_t l = 0; l < N; ++l) {
        std::array<double, 4> lane;
        hc_kernel_cell_weights(K, 0, t[l], h[l], lane.data(), nullptr);
        for (std::size_t e = 0; e < K; ++e) w[e][l] = lane[e];
      }
    };
    if (terms == 2)
      weights.template operator()<2>();
    else
      weights.template operator()<4>();
  }
  sum_lanes(tables, node, w, out);
}

template <std::size_t N>
inline void GridTable::sum_lanes(const std::array<const GridTable*, N>& tables, const std::array<std::size_t, N>& node,
                                 const std::array<std::array<double, N>, 4>& w, double* out) {
  // sum_terms<1, K>'s arithmetic: out = sum_e w[e] data[offset_e + k], added
  // in the same order from 0 (its inner weight is 1), so evaluate()'s numbers
  // bit for bit.
  const GridTable& first = *tables[0];
  const std::size_t n_out = first.outputs_.size();
  const std::size_t* offsets = first.term_offsets_.data();
  const auto sum = [&]<std::size_t K>() {
    for (std::size_t l = 0; l < N; ++l) {
      const GridTable& table = *tables[l];
      const double* data =
          (table.hermite_.empty() ? table.values_.data() : table.hermite_.data()) + node[l] * first.node_block_;
      for (std::size_t k = 0; k < n_out; ++k) {
        double total = 0.0;
        for (std::size_t e = 0; e < K; ++e) total += w[e][l] * data[offsets[e] + k];
        out[k * N + l] = total;
      }
    }
  };
  switch (first.terms_per_axis_) {
    case 1: sum.template operator()<1>(); break;
    case 2: sum.template operator()<2>(); break;
    default: sum.template operator()<4>(); break;
  }
}

template void GridTable::evaluate_one_axis_lanes<1>(const std::array<const GridTable*, 1>&, const double*, double*);
template void GridTable::evaluate_one_axis_lanes<8>(const std::array<const GridTable*, 8>&, const double*, double*);

double GridTable::evaluate_one(std::span<const double> point, std::size_t output) const {
  check_point(point);
  if (output >= outputs_.size()) {
    throw std::out_of_range("GridTable::evaluate_one: output " + std::to_string(output) +
                            " is out of range; the table has " + std::to_string(outputs_.size()) + " outputs");
  }
  Location location;
  locate_any<false>(point, location);
  const double* data = (hermite_.empty() ? values_.data() : hermite_.data()) + location.base + output;
  double result = 0.0;
  sum_(location.weights.data(), kMaxGridAxes, nullptr, term_offsets_.data(), data, 1, &result, 1);
  return result;
}

}  // namespace hydrocoef
