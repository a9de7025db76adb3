#include "src/history/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace hydrocoef {
namespace {

// Four partial sums: independent chains the CPU can overlap, and a smaller
// rounding error than one running sum.
double sum_of(const double* x, std::size_t n) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    s0 += x[i];
    s1 += x[i + 1];
    s2 += x[i + 2];
    s3 += x[i + 3];
  }
  for (; i < n; ++i) s0 += x[i];
  return (s0 + s1) + (s2 + s3);
}

double dot_of(const double* x, const double* y, std::size_t n) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    s0 += x[i] * y[i];
    s1 += x[i + 1] * y[i + 1];
    s2 += x[i + 2] * y[i + 2];
    s3 += x[i + 3] * y[i + 3];
  }
  for (; i < n; ++i) s0 += x[i] * y[i];
  return (s0 + s1) + (s2 + s3);
}

struct AutocorrelationEstimate {
  double long_run_variance = 0.0;  // per sample: n Var(mean)
  double tau_blocks = 1.0;
  std::size_t block_size = 1;
  std::size_t window = 0;
  bool resolved = false;
};

// Sokal's windowed tau on the centred series, coarse-grained as described in
// the header. `centred` has zero mean (up to rounding).
AutocorrelationEstimate estimate_autocorrelation(const std::vector<double>& centred, const StatisticsOptions& options) {
  const std::size_t n = centred.size();
  const std::size_t max_blocks = std::max<std::size_t>(options.max_blocks, kMinBlocksForAutocorrelation);
  const std::size_t max_lag = std::max<std::size_t>(options.max_lag, 1);
  std::size_t block = (n + max_blocks - 1) / max_blocks;
  std::vector<double> blocks(n / block);
  for (std::size_t j = 0; j < blocks.size(); ++j)
    blocks[j] = sum_of(centred.data() + j * block, block) / static_cast<double>(block);

  AutocorrelationEstimate estimate;
  for (;;) {
    const std::size_t nb = blocks.size();
    const double shift = sum_of(blocks.data(), nb) / static_cast<double>(nb);
    std::vector<double> y(nb);
    for (std::size_t j = 0; j < nb; ++j) y[j] = blocks[j] - shift;
    const double c0 = dot_of(y.data(), y.data(), nb) / static_cast<double>(nb);
    estimate.block_size = block;
    if (!(c0 > 0.0)) {
      // Every block mean equal: nothing left to correlate at this scale.
      estimate.long_run_variance = 0.0;
      estimate.tau_blocks = 1.0;
      estimate.window = 0;
      estimate.resolved = true;
      return estimate;
    }
    const std::size_t lag_limit = std::min(max_lag, nb - 1);
    double tau = 1.0;
    std::size_t lag = 1;
    bool met = false;
    for (; lag <= lag_limit; ++lag) {
      tau += 2.0 * dot_of(y.data(), y.data() + lag, nb - lag) / (static_cast<double>(nb) * c0);
      if (static_cast<double>(lag) >= options.window_factor * tau) {
        met = true;
        break;
      }
    }
    const bool can_coarsen = nb / 2 >= kMinBlocksForAutocorrelation;
    if (met || !can_coarsen) {
      estimate.tau_blocks = tau;
      estimate.window = met ? lag : lag_limit;
      estimate.resolved = met;
      estimate.long_run_variance = static_cast<double>(block) * c0 * tau;
      return estimate;
    }
    // Too few lags for the window at this scale: average pairs of blocks.
    std::vector<double> coarser(nb / 2);
    for (std::size_t j = 0; j < coarser.size(); ++j) coarser[j] = 0.5 * (blocks[2 * j] + blocks[2 * j + 1]);
    blocks = std::move(coarser);
    block *= 2;
  }
}

}  // namespace

std::string standard_error_method(const StatisticsOptions& options) {
  char factor[32];
  std::snprintf(factor, sizeof factor, "%g", options.window_factor);
  return std::string("Sokal integrated autocorrelation time, automatic window M >= ") + factor +
         " tau, coarse-grained to at most " + std::to_string(options.max_blocks) + " blocks and " +
         std::to_string(options.max_lag) + " lags; tau floored at 1";
}

SeriesStatistics series_statistics(std::span<const double> values, std::span<const double> abscissa,
                                   const StatisticsOptions& options) {
  const std::size_t n = values.size();
  if (n == 0) throw std::invalid_argument("series statistics of an empty series");
  if (abscissa.size() != n) throw std::invalid_argument("series statistics: values and abscissa differ in size");
  if (!(options.window_factor > 0.0)) throw std::invalid_argument("series statistics: window factor must be positive");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(values[i]) || !std::isfinite(abscissa[i]))
      throw std::invalid_argument("series statistics: a value is not finite");
    if (i > 0 && !(abscissa[i] > abscissa[i - 1]))
      throw std::invalid_argument("series statistics: abscissa not strictly increasing");
  }

  SeriesStatistics s;
  s.count = n;
  // Summing values - values[0] keeps a large common offset out of the sums and
  // gives exactly values[0] for a constant series.
  const double shift = values[0];
  std::vector<double> centred(n);
  for (std::size_t i = 0; i < n; ++i) centred[i] = values[i] - shift;
  s.mean = shift + sum_of(centred.data(), n) / static_cast<double>(n);
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  if (*low == *high) {
    s.mean = values[0];
    s.constant = true;
    s.effective_samples = static_cast<double>(n);
    return s;
  }
  const double offset = s.mean - shift;
  for (double& x : centred) x -= offset;
  const double c0 = dot_of(centred.data(), centred.data(), n) / static_cast<double>(n);
  s.std_dev = std::sqrt(c0);

  double long_run_variance = c0;  // a single sample: nothing to correlate
  if (n >= 2) {
    const AutocorrelationEstimate estimate = estimate_autocorrelation(centred, options);
    s.block_size = estimate.block_size;
    s.autocorrelation_window = estimate.window;
    s.autocorrelation_resolved = estimate.resolved;
    long_run_variance = std::max(estimate.long_run_variance, c0);  // tau >= 1
  }
  s.autocorrelation_time = long_run_variance / c0;
  s.effective_samples = static_cast<double>(n) / s.autocorrelation_time;
  s.standard_error = std::sqrt(long_run_variance / static_cast<double>(n));

  if (n >= 2) {
    const double t0 = abscissa[0];
    double t_mean = 0.0;
    for (std::size_t i = 0; i < n; ++i) t_mean += abscissa[i] - t0;
    t_mean /= static_cast<double>(n);
    double stt = 0.0;
    double stx = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double dt = abscissa[i] - t0 - t_mean;
      stt += dt * dt;
      stx += dt * centred[i];
    }
    const double span = abscissa[n - 1] - abscissa[0];
    s.drift_slope = stx / stt;
    s.drift = s.drift_slope * span;
    // The noise about the line, not about the mean: a trend would otherwise
    // pass for slow fluctuation and widen its own error bar.
    std::vector<double>& residuals = centred;
    for (std::size_t i = 0; i < n; ++i) residuals[i] -= s.drift_slope * (abscissa[i] - t0 - t_mean);
    const double r0 = dot_of(residuals.data(), residuals.data(), n) / static_cast<double>(n);
    double residual_variance = r0;
    if (r0 > 0.0) residual_variance = std::max(estimate_autocorrelation(residuals, options).long_run_variance, r0);
    s.drift_standard_error = span * std::sqrt(residual_variance / stt);
  }
  return s;
}

}  // namespace hydrocoef
