#include "src/history/steady_window.hpp"

#include <stdexcept>
#include <vector>

namespace hydrocoef {

MserResult mser_truncation(std::span<const double> values, std::size_t batch_size) {
  if (batch_size == 0) throw std::invalid_argument("MSER batch size must be at least 1");
  MserResult result;
  result.batch_size = batch_size;
  const std::size_t k = values.size() / batch_size;
  result.batches = k;
  if (k < kMserMinBatches) return result;
  result.applicable = true;

  std::vector<double> means(k);
  for (std::size_t j = 0; j < k; ++j) {
    double sum = 0.0;
    for (std::size_t i = 0; i < batch_size; ++i) sum += values[j * batch_size + i];
    means[j] = sum / static_cast<double>(batch_size);
  }

  // Backward Welford: after adding batch d, `mean` and `m2` describe batches
  // d..k-1, so MSER(d) = m2 / (k - d)^2. Candidates d = 0..k - tail.
  const std::size_t last_candidate = k - kMserMinTailBatches;
  const std::size_t half = k / 2;
  double mean = 0.0;
  double m2 = 0.0;
  std::size_t count = 0;
  double best_first_half = 0.0;
  std::size_t best_first_half_d = 0;
  double best_all = 0.0;
  std::size_t best_all_d = 0;
  bool have_all = false;
  for (std::size_t step = 0; step < k; ++step) {
    const std::size_t d = k - 1 - step;
    ++count;
    const double delta = means[d] - mean;
    mean += delta / static_cast<double>(count);
    m2 += delta * (means[d] - mean);
    if (d > last_candidate) continue;
    const double c = static_cast<double>(count);
    const double statistic = m2 / (c * c);
    // Walking backwards, "<=" keeps the earliest d among equal values.
    if (!have_all || statistic <= best_all) {
      best_all = statistic;
      best_all_d = d;
      have_all = true;
    }
    if (d <= half && (d == half || statistic <= best_first_half)) {
      best_first_half = statistic;
      best_first_half_d = d;
    }
  }
  result.truncation = best_first_half_d * batch_size;
  result.unrestricted_truncation = best_all_d * batch_size;
  result.settled = best_all_d <= half;
  result.statistic = best_first_half;
  return result;
}

}  // namespace hydrocoef
