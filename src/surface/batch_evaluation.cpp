#include "src/surface/batch_evaluation.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "src/core/error.hpp"
#include "src/core/parallel.hpp"
#include "src/surface/grid_kernel.hpp"

namespace hydrocoef {
namespace {

using namespace grid_kernel;

// Points per chunk: large enough that taking a chunk (one atomic add) costs
// nothing beside it, small enough that two threads finish close together.
constexpr std::size_t kChunkPoints = 8192;

// ---- The fast path of gridded tables ----------------------------------------
//
// A gridded table's linear or cubic Hermite interpolant at a point inside
// every axis's range, with the axis count N and the terms per axis K (2:
// linear; 4: pchip, makima, natural spline) fixed at compile time and the
// table's layout read once per batch from its documented data (values(),
// hermite_data(), see grid_table.hpp), so that a point costs its arithmetic
// and no call. It is GridTable::evaluate's own computation, done in the same
// order (the cell, the weights, the product of the weights of axes 0..N-2,
// then per output the sum over the last axis's terms of partial sums), so it
// gives the same numbers bit for bit; tests/surface/batch_evaluation_test.cpp
// checks that for every method and axis count. A point outside a range, or
// NaN, goes to CoefficientSurface::evaluate: its extrapolation policy or its
// message.

struct GridLayout {
  std::size_t n_out = 0;
  const double* data = nullptr;  // values() (linear) or hermite_data() (cubic)
  std::array<const double*, kMaxGridAxes> x{};
  std::array<std::size_t, kMaxGridAxes> stride{};   // data elements between neighbouring nodes along the axis
  std::array<hc_kernel_axis, kMaxGridAxes> axis{};  // the shared kernel's lookup (range, even spacing)
  std::vector<std::size_t> term_offsets;            // of the K^N terms from the cell's base, axis 0's term fastest
};

GridLayout grid_layout(const GridTable& table, std::size_t terms_per_axis) {
  const std::size_t n = table.axis_count(), n_out = table.output_count();
  const bool cubic = terms_per_axis == 4;
  GridLayout g;
  g.n_out = n_out;
  g.data = cubic ? table.hermite_data().data() : table.values().data();
  const std::size_t node_block = cubic ? (std::size_t{1} << n) * n_out : n_out;
  std::size_t nodes = 1;
  std::array<std::size_t, kMaxGridAxes> node_strides{};
  for (std::size_t a = 0; a < n; ++a) {
    const auto& x = table.axes()[a].breakpoints;
    g.x[a] = x.data();
    g.stride[a] = nodes * node_block;
    node_strides[a] = nodes;
    hc_kernel_axis_setup(x.data(), x.size(), &g.axis[a]);  // as GridTable's (evenly_spaced)
    g.axis[a].node_stride = nodes;
    nodes *= x.size();
  }
  g.term_offsets.assign(power(terms_per_axis, n), 0);
  hc_kernel_term_offsets(n, static_cast<int>(table.method()), n_out, node_block, node_strides.data(),
                         g.term_offsets.data());
  return g;
}

/// The axes of a GridLayout with N known at compile time, copied where each
/// thread's loop keeps them: stores to the output columns (doubles) cannot
/// alias a local copy, so its numbers stay in registers.
template <std::size_t N>
struct LocalAxes {
  std::array<const double*, N> x;
  std::array<std::size_t, N> stride;
  std::array<hc_kernel_axis, N> axis;

  explicit LocalAxes(const GridLayout& g) {
    for (std::size_t a = 0; a < N; ++a) {
      x[a] = g.x[a];
      stride[a] = g.stride[a];
      axis[a] = g.axis[a];
    }
  }
};

/// Every output at a point inside every axis's range; false (nothing
/// written) when a coordinate is outside its range or NaN.
template <std::size_t N, std::size_t K, std::size_t kOutputs>
inline bool grid_inside(const LocalAxes<N>& g, const double* data, const std::size_t* offsets, std::size_t n_out,
                        const double* point, double* out) {
  // The shared kernel (runtime/src/grid_kernel.h): the cell and weights of
  // each axis, the product of the weights of axes 0..N-2, the sums.
  std::array<double, 4 * N> w;
  std::size_t base = 0;
#pragma GCC unroll 6
  for (std::size_t a = 0; a < N; ++a) {
    const double value = point[a];
    const hc_kernel_axis& axis = g.axis[a];
    if (!(value >= axis.lo && value <= axis.hi)) return false;
    const double* x = g.x[a];
    const std::size_t cell = hc_kernel_cell_inside(&axis, x, value);
    const double h = x[cell + 1] - x[cell];
    const double t = (value - x[cell]) / h;
    base += cell * g.stride[a];
    hc_kernel_cell_weights(K, 0, t, h, w.data() + 4 * a, nullptr);
  }
  constexpr std::size_t kInner = power(K, N - 1);
  std::array<double, kInner> inner;
  hc_kernel_inner_weights(N, K, w.data(), kMaxGridAxes, nullptr, inner.data());
  const double* cell_data = data + base;
  const double* last = w.data() + 4 * (N - 1);
  if constexpr (kOutputs > 0) {
    accumulate<kOutputs, kInner, K>(inner.data(), last, offsets, cell_data, out, 1);
    return true;
  }
  std::size_t j = 0;
  for (; j + 6 <= n_out; j += 6) accumulate<6, kInner, K>(inner.data(), last, offsets, cell_data + j, out + j, 1);
  if (n_out - j >= 4) {
    accumulate<4, kInner, K>(inner.data(), last, offsets, cell_data + j, out + j, 1);
    j += 4;
  }
  if (n_out - j >= 2) {
    accumulate<2, kInner, K>(inner.data(), last, offsets, cell_data + j, out + j, 1);
    j += 2;
  }
  if (j < n_out) accumulate<1, kInner, K>(inner.data(), last, offsets, cell_data + j, out + j, 1);
  return true;
}

// ---- The batch ------------------------------------------------------------------

/// The columns and the scratch space of one thread.
struct Work {
  const CoefficientSurface& surface;
  std::span<const StridedInput> inputs;
  std::span<const StridedOutput> outputs;
  std::span<const StridedOutput> gradients;
  std::span<const StridedOutput> deviations;  ///< standard deviations (GP surfaces), or none
  const GridLayout* grid = nullptr;
  std::vector<double> point, values, gradient, deviation;
};

/// Points [i, end) on the fast path; i is where an exception left it.
template <std::size_t N, std::size_t K, std::size_t kOutputs>
void grid_points(Work& w, std::size_t& i, std::size_t end) {
  // Everything the loop reads is a local copy (stores to the output columns
  // cannot change it), so that it stays in registers.
  const LocalAxes<N> axes(*w.grid);
  const double* data = w.grid->data;
  constexpr std::size_t kTerms = power(K, N);
  constexpr bool kLocalOffsets = kTerms <= 64;
  std::array<std::size_t, kLocalOffsets ? kTerms : 1> local_offsets{};
  if constexpr (kLocalOffsets) std::copy_n(w.grid->term_offsets.data(), kTerms, local_offsets.begin());
  const std::size_t* offsets = kLocalOffsets ? local_offsets.data() : w.grid->term_offsets.data();
  std::array<const double*, N> in;
  std::array<std::ptrdiff_t, N> in_stride;
  for (std::size_t a = 0; a < N; ++a) {
    in[a] = w.inputs[a].data;
    in_stride[a] = w.inputs[a].stride;
  }
  const std::size_t n_out = w.values.size();
  double* const out0 = w.outputs[0].data;
  const std::ptrdiff_t out0_stride = w.outputs[0].stride;
  std::array<double, kOutputs == 1 ? 1 : 0> one{};
  double* const values = kOutputs == 1 ? one.data() : w.values.data();
  std::size_t index = i;  // a local: i itself would be stored at every point
  try {
    for (; index < end; ++index) {
      const auto at = static_cast<std::ptrdiff_t>(index);
      std::array<double, N> point;
      for (std::size_t a = 0; a < N; ++a) point[a] = in[a][at * in_stride[a]];
      if (!grid_inside<N, K, kOutputs>(axes, data, offsets, n_out, point.data(), values)) [[unlikely]] {
        std::copy(point.begin(), point.end(), w.point.begin());
        w.surface.evaluate(w.point, w.values);
        if constexpr (kOutputs == 1) values[0] = w.values[0];
      }
      if constexpr (kOutputs == 1) {
        out0[at * out0_stride] = values[0];
      } else {
        for (std::size_t k = 0; k < n_out; ++k) w.outputs[k].data[at * w.outputs[k].stride] = values[k];
      }
    }
  } catch (...) {
    i = index;
    throw;
  }
  i = index;
}

/// Points [i, end) through CoefficientSurface (gradients, RBF, nearest).
void any_points(Work& w, std::size_t& i, std::size_t end) {
  const std::size_t n_axes = w.point.size(), n_out = w.values.size();
  const bool with_gradient = !w.gradients.empty();
  for (; i < end; ++i) {
    const auto at = static_cast<std::ptrdiff_t>(i);
    for (std::size_t a = 0; a < n_axes; ++a) w.point[a] = w.inputs[a].data[at * w.inputs[a].stride];
    if (!w.deviations.empty()) {
      w.surface.evaluate_with_standard_deviation(w.point, w.values, w.deviation,
                                                 with_gradient ? std::span<double>(w.gradient) : std::span<double>());
      for (std::size_t k = 0; k < n_out; ++k) w.deviations[k].data[at * w.deviations[k].stride] = w.deviation[k];
    } else if (with_gradient) {
      w.surface.evaluate_with_gradient(w.point, w.values, w.gradient);
    } else {
      w.surface.evaluate(w.point, w.values);
    }
    if (with_gradient)
      for (std::size_t g = 0; g < w.gradient.size(); ++g)
        w.gradients[g].data[at * w.gradients[g].stride] = w.gradient[g];
    for (std::size_t k = 0; k < n_out; ++k) w.outputs[k].data[at * w.outputs[k].stride] = w.values[k];
  }
}

using PointsFunction = void (*)(Work&, std::size_t&, std::size_t);

// Per axis count: any number of outputs, and one output (the common case, with its sum unrolled).
template <std::size_t K, std::size_t kOutputs, std::size_t... N>
constexpr std::array<PointsFunction, sizeof...(N)> grid_functions(std::index_sequence<N...>) {
  return {&grid_points<N + 1, K, kOutputs>...};
}

/// How the batch evaluates its points: the fast path for a gridded table with
/// linear or cubic Hermite interpolation (without gradients), else the surface's own calls.
PointsFunction points_function(const CoefficientSurface& surface, bool with_gradient, std::optional<GridLayout>& grid) {
  const GridTable* table = surface.symmetry().empty() ? surface.grid() : nullptr;
  if (with_gradient || !table || table->axis_count() < 1 || table->axis_count() > kMaxGridAxes ||
      table->method() == Interpolation::Nearest)
    return &any_points;
  static constexpr auto kLinear = grid_functions<2, 0>(std::make_index_sequence<kMaxGridAxes>());
  static constexpr auto kCubic = grid_functions<4, 0>(std::make_index_sequence<kMaxGridAxes>());
  static constexpr auto kLinearOne = grid_functions<2, 1>(std::make_index_sequence<kMaxGridAxes>());
  static constexpr auto kCubicOne = grid_functions<4, 1>(std::make_index_sequence<kMaxGridAxes>());
  const bool cubic = table->method() != Interpolation::Linear, one = table->output_count() == 1;
  grid = grid_layout(*table, cubic ? 4 : 2);
  return (cubic ? (one ? kCubicOne : kCubic) : (one ? kLinearOne : kLinear))[table->axis_count() - 1];
}

void check_columns(const char* what, std::size_t expected, std::size_t given, std::size_t count, auto columns) {
  if (given != expected)
    throw std::invalid_argument("evaluate_batch: " + std::to_string(given) + " " + what + " columns; expected " +
                                std::to_string(expected));
  if (count > 0)
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (!columns[c].data)
        throw std::invalid_argument(std::string("evaluate_batch: ") + what + " column " + std::to_string(c) +
                                    " has no data");
}

}  // namespace

void evaluate_batch(const CoefficientSurface& surface, std::size_t count, std::span<const StridedInput> inputs,
                    std::span<const StridedOutput> outputs, std::span<const StridedOutput> gradients, unsigned threads,
                    std::span<const StridedOutput> standard_deviations) {
  const std::size_t n_axes = surface.axis_count(), n_out = surface.output_count();
  check_columns("input", n_axes, inputs.size(), count, inputs);
  check_columns("output", n_out, outputs.size(), count, outputs);
  if (!gradients.empty()) check_columns("gradient", n_out * n_axes, gradients.size(), count, gradients);
  if (!standard_deviations.empty()) {
    check_columns("standard deviation", n_out, standard_deviations.size(), count, standard_deviations);
    if (!surface.has_standard_deviation())
      throw InputError("the surface (method '" + surface.method_name() +
                       "') states no standard deviation (stored without its runs' uncertainty: rebuild it with "
                       "hydrocoef surface rebuild); expected a GP surface or a grid or RBF surface built by this "
                       "hydrocoef");
  }
  if (count == 0) return;

  // Chunks in index order on every core; a point that fails stops the batch
  // with its index, and parallel_for rethrows the failure of the lowest
  // chunk, so the error names the first failing point whatever the timing.
  const std::size_t chunks = (count + kChunkPoints - 1) / kChunkPoints;
  std::optional<GridLayout> grid;
  const PointsFunction points = points_function(surface, !gradients.empty() || !standard_deviations.empty(), grid);
  std::vector<Work> scratch;
  const unsigned workers = parallel_threads(chunks, threads);
  scratch.reserve(workers);
  for (unsigned w = 0; w < workers; ++w)
    scratch.push_back(Work{surface, inputs, outputs, gradients, standard_deviations, grid ? &*grid : nullptr,
                           std::vector<double>(n_axes), std::vector<double>(n_out),
                           std::vector<double>(gradients.empty() ? 0 : n_out * n_axes), std::vector<double>(n_out)});
  parallel_for(chunks, workers, [&](std::size_t chunk, unsigned worker) {
    std::size_t i = chunk * kChunkPoints;
    try {
      points(scratch[worker], i, std::min(count, i + kChunkPoints));
    } catch (const InputError& error) {
      throw InputError("point " + std::to_string(i) + ": " + error.what());
    }
  });
}

}  // namespace hydrocoef
