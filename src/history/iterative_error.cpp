#include "src/history/iterative_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace hydrocoef {
namespace {

constexpr int kTimeConstants = 40;

/// Least-squares slope of y_i against i, i = 0..n-1.
double slope_of(std::span<const double> y) {
  const std::size_t n = y.size();
  if (n < 2) return 0.0;
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
  return sxy / sxx;
}

struct ExponentialFit {
  double limit = 0.0, time_constant = 0.0, rms = 0.0;
};

/// y_i = a + b exp(-i / tau) by least squares in (a, b) at one tau (i from
/// the window's first sample, so e_i is in (0, 1]).
ExponentialFit fit_at(std::span<const double> y, double tau, double& ssr) {
  const std::size_t n = y.size();
  // Normal equations of [1, e_i] with e_i = exp(-i / tau).
  double se = 0.0, see = 0.0, sy = 0.0, sey = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double e = std::exp(-static_cast<double>(i) / tau);
    se += e, see += e * e, sy += y[i], sey += e * y[i];
  }
  const double nn = static_cast<double>(n);
  const double det = nn * see - se * se;
  ssr = std::numeric_limits<double>::infinity();
  if (!(det > 1e-12 * nn * see)) return {};  // e nearly constant: no information on the limit
  const double b = (nn * sey - se * sy) / det;
  const double a = (sy - b * se) / nn;
  ssr = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - a - b * std::exp(-static_cast<double>(i) / tau);
    ssr += r * r;
  }
  return {a, tau, std::sqrt(ssr / nn)};
}

/// The best tau of a log-spaced grid from 2 to `longest`, refined by a
/// golden-section search on log tau between its neighbours. y holds at
/// least 4 values.
ExponentialFit fit_exponential(std::span<const double> y, double longest) {
  const double shortest = 2.0;
  longest = std::max(longest, shortest * 1.01);
  const double step = std::log(longest / shortest) / (kTimeConstants - 1);
  int best_k = -1;
  double best_ssr = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kTimeConstants; ++k) {
    double ssr = 0.0;
    fit_at(y, shortest * std::exp(step * k), ssr);
    if (ssr < best_ssr) best_ssr = ssr, best_k = k;
  }
  if (best_k < 0) return {};
  double lo = std::log(shortest) + step * std::max(0, best_k - 1);
  double hi = std::log(shortest) + step * std::min(kTimeConstants - 1, best_k + 1);
  constexpr double kGolden = 0.6180339887498949;
  const auto cost = [&](double log_tau) {
    double ssr = 0.0;
    fit_at(y, std::exp(log_tau), ssr);
    return ssr;
  };
  double c = hi - kGolden * (hi - lo), d = lo + kGolden * (hi - lo);
  double fc = cost(c), fd = cost(d);
  for (int i = 0; i < 60; ++i) {
    if (fc <= fd) {
      hi = d, d = c, fd = fc;
      c = hi - kGolden * (hi - lo), fc = cost(c);
    } else {
      lo = c, c = d, fc = fd;
      d = lo + kGolden * (hi - lo), fd = cost(d);
    }
  }
  double ssr = 0.0;
  const ExponentialFit refined = fit_at(y, std::exp(0.5 * (lo + hi)), ssr);
  if (ssr <= best_ssr) return refined;
  return fit_at(y, shortest * std::exp(step * best_k), ssr);
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
  return std::exp(slope_of(logs));
}

IterativeError iterative_error(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("iterative_error: no values");
  const std::size_t n = values.size();
  IterativeError out;
  out.value = values.back();
  out.extrapolated = out.value;
  if (n < 2) return out;
  const std::size_t quarter = std::max<std::size_t>(1, n / 4);
  out.recent_change = std::abs(values[n - 1] - values[n - 1 - quarter]);
  const std::size_t tail = std::min<std::size_t>(n, std::clamp<std::size_t>(n / 20, 5, 20));
  out.change_per_iteration = slope_of(values.subspan(n - tail));
  const std::size_t half = n / 2;
  double fitted_error = 0.0;
  if (n - half >= 4) {
    const ExponentialFit fit = fit_exponential(values.subspan(half), static_cast<double>(n) / 2.0);
    if (fit.time_constant > 0.0 && std::isfinite(fit.limit)) {
      out.extrapolated = fit.limit;
      out.time_constant = fit.time_constant;
      out.fluctuation = fit.rms;
      fitted_error = std::abs(out.value - fit.limit);
    }
  }
  out.standard_uncertainty = std::max(out.recent_change, fitted_error);
  return out;
}

}  // namespace hydrocoef
