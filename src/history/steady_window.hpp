// Where the start-up of a CFD history ends: the MSER-5 truncation rule.
//
// MSER (marginal standard error rule; White 1997) truncates the first d
// observations of an output series at the d that minimises
//     MSER(d) = 1/(n - d)^2 * sum_{i > d} (x_i - mean_{i > d} x)^2,
// the squared standard error of the mean of what is kept, uncorrected for
// autocorrelation: cutting more start-up bias lowers it, cutting steady data
// raises it through the 1/(n - d)^2. MSER-5 applies the rule to the means of
// consecutive batches of 5 observations, which smooths the statistic and
// makes it more reliable (White, Cobb & Spratt 2000; Franklin & White 2008).
//   K. P. White Jr., "An effective truncation heuristic for bias reduction in
//     simulation output", Simulation 69(6), 323-334, 1997.
//   K. P. White Jr., M. J. Cobb, S. C. Spratt, "A comparison of five
//     steady-state truncation heuristics for simulation", Proc. 2000 Winter
//     Simulation Conference, 755-760.
//   W. W. Franklin, K. P. White Jr., "Stationarity tests and MSER-5: exploring
//     the intuition behind mean-squared-error-reduction in detecting and
//     correcting initialization bias", Proc. 2008 Winter Simulation Conference.
//
// A minimum in the second half of the record means the series has not
// settled (or is too short to tell): the rule is then said to fail, and the
// truncation is taken from the first half only (White & Robinson 2010, "The
// problem of the initial transient (again), or why MSER works", J. Simulation
// 4, 268-272). The last kMserMinTailBatches batches are never candidates: a
// tail of two or three batches can have a tiny variance by chance, and a
// minimum there would call a steady record unsettled a few per cent of the
// time.
//
// Cost: O(n) time (one pass for the batch means, one backward pass with
// Welford's update for the statistic), O(n / batch size) memory.
#pragma once

#include <cstddef>
#include <span>

namespace hydrocoef {

inline constexpr std::size_t kMserBatchSize = 5;
/// Fewest batches for the rule to say anything; shorter series are "too short".
inline constexpr std::size_t kMserMinBatches = 20;
/// Batches at the end of the record never chosen as the kept tail's start.
inline constexpr std::size_t kMserMinTailBatches = 10;

struct MserResult {
  std::size_t batch_size = kMserBatchSize;
  std::size_t batches = 0;  ///< n / batch_size (a partial last batch is left out of the statistic)
  /// The rule could be applied (at least kMserMinBatches batches).
  bool applicable = false;
  /// Samples to discard from the start: batch_size times the minimising
  /// batch index within the first half of the batches.
  std::size_t truncation = 0;
  /// The minimiser over all candidates (the first half and the second, up to
  /// the last kMserMinTailBatches), in samples.
  std::size_t unrestricted_truncation = 0;
  /// The unrestricted minimiser lies in the first half: the series settled.
  bool settled = false;
  double statistic = 0.0;  ///< MSER at `truncation`, in the series' unit squared
};

/// MSER-`batch_size` on a series (batch_size >= 1; 5 is MSER-5). Ties go to
/// the earlier truncation, so a constant series keeps everything. Values must
/// be finite.
MserResult mser_truncation(std::span<const double> values, std::size_t batch_size = kMserBatchSize);

}  // namespace hydrocoef
