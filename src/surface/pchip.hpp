// The slopes of PCHIP, the monotone piecewise cubic Hermite interpolant
// (Fritsch-Carlson with Fritsch-Butland weights and the shape-preserving
// three-point end rule, as MATLAB pchip and SciPy PchipInterpolator). One
// definition for every place that interpolates monotone data: gridded
// tables along each axis and coefficient curves across a disturbance.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>

namespace hydrocoef {

/// End slope from the end interval (width h0, secant del0) and its
/// neighbour (h1, del1), limited so the curve stays monotone next to the end.
inline double pchip_end_slope(double h0, double h1, double del0, double del1) {
  const auto sign = [](double v) { return (v > 0.0) - (v < 0.0); };
  double d = ((2.0 * h0 + h1) * del0 - h0 * del1) / (h0 + h1);
  if (sign(d) != sign(del0)) {
    d = 0.0;
  } else if (sign(del0) != sign(del1) && std::abs(d) > std::abs(3.0 * del0)) {
    d = 3.0 * del0;
  }
  return d;
}

/// Interior slope between an interval (h_left, del_left) and the next one
/// (h_right, del_right): 0 at a local extremum or next to a flat piece,
/// else the weighted harmonic mean of the secants, the weights favouring the
/// shorter interval's secant.
inline double pchip_interior_slope(double h_left, double h_right, double del_left, double del_right) {
  if (del_left == 0.0 || del_right == 0.0 || (del_left > 0.0) != (del_right > 0.0)) return 0.0;
  const double w_left = h_left + 2.0 * h_right;
  const double w_right = 2.0 * h_left + h_right;
  return (w_left + w_right) / (w_left / del_left + w_right / del_right);
}

/// The slope at knot i of data (x, y), x strictly increasing, n >= 2 (with
/// two points the curve is the straight line through them).
inline double pchip_slope(std::span<const double> x, std::span<const double> y, std::size_t i) {
  const std::size_t n = x.size();
  const auto h = [&](std::size_t k) { return x[k + 1] - x[k]; };
  const auto del = [&](std::size_t k) { return (y[k + 1] - y[k]) / (x[k + 1] - x[k]); };
  if (n == 2) return del(0);
  if (i == 0) return pchip_end_slope(h(0), h(1), del(0), del(1));
  if (i == n - 1) return pchip_end_slope(h(n - 2), h(n - 3), del(n - 2), del(n - 3));
  return pchip_interior_slope(h(i - 1), h(i), del(i - 1), del(i));
}

}  // namespace hydrocoef
