// Statistics of one stretch of a correlated series: its mean, spread, the
// standard error of the mean corrected for autocorrelation, and its drift.
//
// Standard error. Successive samples of a CFD history are correlated, so the
// mean of n samples varies like that of n / tau independent ones, tau being the
// integrated autocorrelation time tau = 1 + 2 sum_{t >= 1} rho(t) (in samples).
// tau is estimated with Sokal's automatic window: the sum runs over lags
// t = 1..M for the smallest M with M >= c tau(M), c = 5 (A. D. Sokal, "Monte
// Carlo methods in statistical mechanics: foundations and new algorithms",
// Cargese lectures 1996, section 3; the convention of emcee, Foreman-Mackey
// et al. 2013, PASP 125, 306). The autocovariances are the usual biased ones
// (divided by n) about the window mean.
//   Bias: the window truncates the tail of rho (for an exponential decay the
//   lost part is about exp(-c) of tau, under 1 %); subtracting the estimated
//   mean lowers every autocovariance by about Var(mean), so tau comes out low
//   by about (2M + 1) / n relative (1 % for M = 50, n = 10^4).
//   Scatter: the relative variance of tau is about 2 (2M + 1) / n (Sokal).
//   Floor: tau is never taken below 1. Anti-correlated samples would justify
//   a smaller value; no credit is given for them, so the error stays
//   conservative there. A periodic force (vortex shedding) stops the window
//   within its first period, with tau of the order of a fraction of the
//   period: the error of a mean over many whole periods, which cancel, is
//   overstated, again on the safe side.
// Cost, and coarse graining. Summing lags costs O(n M). To keep that bounded
// the series is first averaged in blocks of B consecutive samples so that at
// most max_blocks blocks remain, and B is doubled whenever the window would
// need more than max_lag lags. The variance of the mean of the whole series
// equals that of the mean of its block means, so coarse graining does not bias
// the error (it only discards the last n mod B samples from the estimate of
// tau, not from the mean). Total cost: O(n) for the blocking plus at most
// about 2 max_blocks max_lag multiply-adds, whatever n and tau are.
//   When even the coarsest blocking (fewer than kMinBlocksForAutocorrelation
//   blocks would remain) does not satisfy the window, tau is not resolved: the
//   record holds too few independent samples. tau(M) at the largest window
//   tried is then reported (a lower bound for positively correlated data) and
//   `autocorrelation_resolved` is false.
//
// Drift. The least-squares slope of the values against the abscissa; `drift`
// is that slope times the window's span (the change the trend makes across
// the window). Its standard error is Var(slope) ~ s2 / sum (t_i - mean t)^2,
// with s2 the long-run variance (estimated as above) of the residuals about
// the line: detrended, so that a trend does not pass for slow fluctuation and
// widen its own error bar. For stationary noise s2 = n SE^2, which for evenly
// spaced samples makes SE(drift) ~ sqrt(12) SE(mean): a drift a few times the
// standard error of the mean is what noise alone gives, so compare the drift
// with drift_standard_error, not with standard_error. (The standard error of
// the mean is not detrended: a trend in the window widens it, which is the
// honest error of a mean taken over a drifting record.)
#pragma once

#include <cstddef>
#include <span>
#include <string>

namespace hydrocoef {

/// The blocked series must keep at least this many blocks to estimate tau.
inline constexpr std::size_t kMinBlocksForAutocorrelation = 64;

struct StatisticsOptions {
  double window_factor = 5.0;      ///< Sokal's c
  std::size_t max_blocks = 65536;  ///< coarse-grain longer series into at most this many blocks
  std::size_t max_lag = 200;       ///< double the block size rather than sum more lags
};

/// One line naming the estimator and its settings, for storing with a result.
std::string standard_error_method(const StatisticsOptions& options = {});

struct SeriesStatistics {
  std::size_t count = 0;
  double mean = 0.0;
  /// Population standard deviation over the window (the root-mean-square
  /// deviation from `mean`; numpy's default), in the series' unit.
  double std_dev = 0.0;
  /// Standard error of `mean`, corrected for autocorrelation (see above).
  double standard_error = 0.0;
  /// Integrated autocorrelation time in samples (>= 1).
  double autocorrelation_time = 1.0;
  double effective_samples = 0.0;  ///< count / autocorrelation_time
  bool autocorrelation_resolved = true;
  std::size_t block_size = 1;              ///< coarse graining used for tau
  std::size_t autocorrelation_window = 0;  ///< lags summed, in blocks
  double drift_slope = 0.0;                ///< per abscissa unit
  double drift = 0.0;                      ///< drift_slope times the window's abscissa span
  double drift_standard_error = 0.0;
  bool constant = false;  ///< every value equal: standard error and drift 0
};

/// Statistics of `values` sampled at `abscissa` (same size, at least 1,
/// abscissa strictly increasing, all finite; std::invalid_argument
/// otherwise). Allocates O(n) scratch.
SeriesStatistics series_statistics(std::span<const double> values, std::span<const double> abscissa,
                                   const StatisticsOptions& options = {});

}  // namespace hydrocoef
