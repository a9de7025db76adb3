// The arithmetic of a gridded table's local sum, shared by GridTable's
// evaluation (src/surface/grid_table.cpp), the batch evaluation on many
// points (src/surface/batch_evaluation.cpp) and the C runtime library
// (runtime/src/runtime_evaluate.c), so all give the same numbers bit for
// bit. The arithmetic itself is runtime/src/grid_kernel.h (C11 and C++20,
// static inline); this header gives its C++ callers compile-time sizes.
#pragma once

#include <array>
#include <cstddef>

#include "runtime/src/grid_kernel.h"

namespace hydrocoef::grid_kernel {

// Sizes of compile-time arrays (hc_kernel_power is the same, at run time).
constexpr std::size_t power(std::size_t base, std::size_t exponent) {
  std::size_t result = 1;
  for (std::size_t i = 0; i < exponent; ++i) result *= base;
  return result;
}

// Cubic Hermite basis on a cell of width h at t = (x - x_i) / h, in term order
// (corner 0 value, corner 0 slope, corner 1 value, corner 1 slope); slope
// terms carry h so that they multiply d/dx in axis units.
inline void hermite_weights(double t, double h, double* w) { hc_kernel_hermite_weights(t, h, w); }

// d/dx of hermite_weights.
inline void hermite_derivative_weights(double t, double h, double* dw) {
  hc_kernel_hermite_derivative_weights(t, h, dw);
}

// M outputs at once. The weight of term t = t_inner + e * kInner is
// inner_weights[t_inner] * last[e] (last: the last axis's weights), so
// out[j * out_stride] = sum_e last[e] sum_t_inner inner_weights[t_inner] * data[offsets[t] + j].
template <std::size_t M, std::size_t kInner, std::size_t K>
inline void accumulate(const double* inner_weights, const double* last, const std::size_t* offsets, const double* data,
                       double* out, std::size_t out_stride) {
  static_assert(M >= 1 && M <= 6);
  hc_kernel_accumulate(M, kInner, K, inner_weights, last, offsets, data, out, out_stride);
}

}  // namespace hydrocoef::grid_kernel
