#include "src/history/iterative_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace hydrocoef {
namespace {

/// Least-squares line through (i, y_i), i = 0..n-1: slope and the RMS of the
/// residuals.
struct Line {
  double slope = 0.0;
  double rms = 0.0;
};

Line fit_line(std::span<const double> y) {
  const std::size_t n = y.size();
  if (n < 2) return {};
  const double mean_i = static_cast<double>(n - 1) / 2.0;
  double mean_y = 0.0;
  for (const double v : y) mean_y += v;
  mean_y /= static_cast<double>(n);
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double di = static_cast<double>(i) - mean_i;
    sxy += di * (y[i] - mean_y);
    sxx += di * di;
  }
  Line line;
  line.slope = sxy / sxx;
  double ss = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - (mean_y + line.slope * (static_cast<double>(i) - mean_i));
    ss += r * r;
  }
  line.rms = std::sqrt(ss / static_cast<double>(n));
  return line;
}

}  // namespace

double decay_rate(std::span<const double> series) {
  const std::size_t n = series.size();
  const std::size_t tail = std::max<std::size_t>(10, n / 4);
  if (n < 10) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> logs;
  logs.reserve(tail);
  for (std::size_t i = n - tail; i < n; ++i) {
    const double v = series[i];
    if (!(v > 0.0) || !std::isfinite(v)) return std::numeric_limits<double>::quiet_NaN();
    logs.push_back(std::log(v));
  }
  return std::exp(fit_line(logs).slope);
}

IterativeError iterative_error(std::span<const double> values, double residual_rate) {
  if (values.empty()) throw std::invalid_argument("iterative_error: no values");
  const std::size_t n = values.size();
  IterativeError out;
  out.value = values.back();
  out.tail = std::min<std::size_t>(n, std::clamp<std::size_t>(n / 20, 5, 20));
  const Line line = fit_line(values.subspan(n - out.tail));
  out.change_per_iteration = line.slope;
  out.fluctuation = line.rms;

  double rate = residual_rate;
  out.rate_from_residuals = std::isfinite(rate) && rate > 0.0;
  if (!out.rate_from_residuals) {
    // The component's own changes, where they decay geometrically.
    std::vector<double> changes;
    changes.reserve(n);
    for (std::size_t i = 1; i < n; ++i) changes.push_back(std::abs(values[i] - values[i - 1]));
    rate = decay_rate(changes);
    if (!std::isfinite(rate)) rate = kMaxIterationRate;
  }
  out.rate = std::clamp(rate, 0.0, kMaxIterationRate);
  out.extrapolated_error = std::abs(out.change_per_iteration) * out.rate / (1.0 - out.rate);
  out.standard_uncertainty = std::hypot(out.extrapolated_error, out.fluctuation);
  return out;
}

}  // namespace hydrocoef
