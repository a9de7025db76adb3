// Test support: synthetic force histories with a known truth. An exponential
// start-up decaying onto a constant mean, plus AR(1) noise
//     e_i = phi e_{i-1} + sigma w_i,   w_i ~ N(0, 1),
// started in its stationary distribution (e_0 ~ N(0, sigma^2 / (1 - phi^2))).
// Its long-run variance is sigma^2 / (1 - phi)^2 and the variance of the mean
// of n consecutive samples is known exactly (ar1_standard_error).
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace hydrocoef::test {

struct SyntheticSeries {
  double mean = 0.0;           ///< the value the series settles on
  double startup = 0.0;        ///< amplitude of the exponential start-up at sample 0
  double startup_decay = 1.0;  ///< its time constant, in samples
  double phi = 0.0;            ///< AR(1) coefficient
  double sigma = 1.0;          ///< innovation standard deviation
  double slope = 0.0;          ///< a linear drift per sample, added to everything
};

inline std::vector<double> make_series(const SyntheticSeries& spec, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> x(n);
  double e = spec.sigma / std::sqrt(1.0 - spec.phi * spec.phi) * normal(random);
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) e = spec.phi * e + spec.sigma * normal(random);
    const double t = static_cast<double>(i);
    x[i] = spec.mean + spec.startup * std::exp(-t / spec.startup_decay) + spec.slope * t + e;
  }
  return x;
}

/// The exact standard error of the mean of n consecutive samples of the
/// stationary AR(1) noise: Var = s_x^2 / n [ (1 + phi) / (1 - phi)
/// - 2 phi (1 - phi^n) / (n (1 - phi)^2) ], s_x^2 = sigma^2 / (1 - phi^2). For
/// large n it tends to sqrt(sigma^2 / (1 - phi)^2 / n), the long-run variance
/// over n.
inline double ar1_standard_error(double phi, double sigma, std::size_t n) {
  const double nd = static_cast<double>(n);
  const double variance_x = sigma * sigma / (1.0 - phi * phi);
  const double factor =
      (1.0 + phi) / (1.0 - phi) - 2.0 * phi * (1.0 - std::pow(phi, nd)) / (nd * (1.0 - phi) * (1.0 - phi));
  return std::sqrt(variance_x / nd * factor);
}

inline std::vector<double> iota_abscissa(std::size_t n, double first = 1.0, double step = 1.0) {
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = first + step * static_cast<double>(i);
  return t;
}

}  // namespace hydrocoef::test
