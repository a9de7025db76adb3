// The arithmetic of a gridded table's local sum, shared by GridTable's
// evaluation (src/surface/grid_table.cpp) and the batch evaluation on many
// points (src/surface/batch_evaluation.cpp), so both give the same numbers
// bit for bit: the cubic Hermite weights of an axis, and the sum over a
// cell's K^N terms of weight times node value, outputs M at a time.
#pragma once

#include <array>
#include <cstddef>

namespace hydrocoef::grid_kernel {

constexpr std::size_t power(std::size_t base, std::size_t exponent) {
  std::size_t result = 1;
  for (std::size_t i = 0; i < exponent; ++i) result *= base;
  return result;
}

// Cubic Hermite basis on a cell of width h at t = (x - x_i) / h, in term order
// (corner 0 value, corner 0 slope, corner 1 value, corner 1 slope); slope
// terms carry h so that they multiply d/dx in axis units.
inline void hermite_weights(double t, double h, double* w) {
  const double t2 = t * t;
  const double t3 = t2 * t;
  w[0] = 2.0 * t3 - 3.0 * t2 + 1.0;
  w[1] = h * (t3 - 2.0 * t2 + t);
  w[2] = 3.0 * t2 - 2.0 * t3;
  w[3] = h * (t3 - t2);
}

// d/dx of hermite_weights.
inline void hermite_derivative_weights(double t, double h, double* dw) {
  const double t2 = t * t;
  dw[0] = 6.0 * (t2 - t) / h;
  dw[1] = 3.0 * t2 - 4.0 * t + 1.0;
  dw[2] = 6.0 * (t - t2) / h;
  dw[3] = 3.0 * t2 - 2.0 * t;
}

// M outputs at once. The weight of term t = t_inner + e * kInner is
// inner_weights[t_inner] * last[e] (last: the last axis's weights), so
// out[j * out_stride] = sum_e last[e] sum_t_inner inner_weights[t_inner] * data[offsets[t] + j].
template <std::size_t M, std::size_t kInner, std::size_t K>
inline void accumulate(const double* inner_weights, const double* last, const std::size_t* offsets, const double* data,
                       double* out, std::size_t out_stride) {
  std::array<double, M> total{};
  for (std::size_t e = 0; e < K; ++e) {
    std::array<double, M> part{};
    const std::size_t* term_offsets = offsets + e * kInner;
    for (std::size_t t = 0; t < kInner; ++t) {
      const double* row = data + term_offsets[t];
      const double w = inner_weights[t];
      for (std::size_t j = 0; j < M; ++j) part[j] += w * row[j];
    }
    for (std::size_t j = 0; j < M; ++j) total[j] += last[e] * part[j];
  }
  for (std::size_t j = 0; j < M; ++j) out[j * out_stride] = total[j];
}

}  // namespace hydrocoef::grid_kernel
