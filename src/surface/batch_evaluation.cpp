#include "src/surface/batch_evaluation.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

// Points per chunk: large enough that taking a chunk (one atomic add) costs
// nothing beside it, small enough that two threads finish close together.
constexpr std::size_t kChunkPoints = 8192;

/// What the threads share: the columns, the next chunk to take, and the first
/// failure found so far.
class Batch {
 public:
  Batch(const CoefficientSurface& surface, std::size_t count, std::span<const StridedInput> inputs,
        std::span<const StridedOutput> outputs, std::span<const StridedOutput> gradients)
      : surface_(surface), count_(count), inputs_(inputs), outputs_(outputs), gradients_(gradients),
        first_failure_(count) {}

  /// Takes chunks until none is left or every chunk left starts after a
  /// failure already found (chunks are taken in index order, so none of them
  /// can hold the first failing point).
  void work() {
    const std::size_t n_axes = surface_.axis_count(), n_out = surface_.output_count();
    std::vector<double> point(n_axes), values(n_out), gradient(gradients_.empty() ? 0 : n_out * n_axes);
    for (;;) {
      const std::size_t begin = next_chunk_.fetch_add(1, std::memory_order_relaxed) * kChunkPoints;
      if (begin >= count_ || begin >= first_failure_.load(std::memory_order_relaxed)) return;
      run(begin, std::min(count_, begin + kChunkPoints), point, values, gradient);
    }
  }

  /// Throws what the batch found, if anything: a bug first, else the first failing point.
  void finish() const {
    if (bug_) std::rethrow_exception(bug_);
    if (failure_point_ < count_) throw InputError("point " + std::to_string(failure_point_) + ": " + failure_message_);
  }

 private:
  void run(std::size_t begin, std::size_t end, std::vector<double>& point, std::vector<double>& values,
           std::vector<double>& gradient) {
    const std::size_t n_axes = point.size(), n_out = values.size();
    const bool with_gradient = !gradient.empty();
    std::size_t i = begin;
    try {
      for (; i < end; ++i) {
        const auto at = static_cast<std::ptrdiff_t>(i);
        for (std::size_t a = 0; a < n_axes; ++a) point[a] = inputs_[a].data[at * inputs_[a].stride];
        if (with_gradient) {
          surface_.evaluate_with_gradient(point, values, gradient);
          for (std::size_t g = 0; g < gradient.size(); ++g) gradients_[g].data[at * gradients_[g].stride] = gradient[g];
        } else {
          surface_.evaluate(point, values);
        }
        for (std::size_t k = 0; k < n_out; ++k) outputs_[k].data[at * outputs_[k].stride] = values[k];
      }
    } catch (const InputError& error) {
      record_failure(i, error.what());
    } catch (...) {
      const std::lock_guard lock(mutex_);
      if (!bug_) bug_ = std::current_exception();
      first_failure_.store(0, std::memory_order_relaxed);  // everyone stops
    }
  }

  void record_failure(std::size_t point, const char* message) {
    const std::lock_guard lock(mutex_);
    if (point >= failure_point_) return;
    failure_point_ = point;
    failure_message_ = message;
    if (point < first_failure_.load(std::memory_order_relaxed)) first_failure_.store(point, std::memory_order_relaxed);
  }

  const CoefficientSurface& surface_;
  const std::size_t count_;
  const std::span<const StridedInput> inputs_;
  const std::span<const StridedOutput> outputs_;
  const std::span<const StridedOutput> gradients_;
  std::atomic<std::size_t> next_chunk_{0};
  std::atomic<std::size_t> first_failure_;  // a hint for skipping chunks; failure_point_ is the answer
  std::mutex mutex_;
  std::size_t failure_point_ = static_cast<std::size_t>(-1);
  std::string failure_message_;
  std::exception_ptr bug_;
};

void check_columns(const char* what, std::size_t expected, std::size_t given, std::size_t count,
                   auto columns) {
  if (given != expected)
    throw std::invalid_argument("evaluate_batch: " + std::to_string(given) + " " + what + " columns; expected " +
                                std::to_string(expected));
  if (count > 0)
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (!columns[c].data)
        throw std::invalid_argument(std::string("evaluate_batch: ") + what + " column " + std::to_string(c) +
                                    " has no data");
}

}  // namespace

void evaluate_batch(const CoefficientSurface& surface, std::size_t count, std::span<const StridedInput> inputs,
                    std::span<const StridedOutput> outputs, std::span<const StridedOutput> gradients,
                    unsigned threads) {
  const std::size_t n_axes = surface.axis_count(), n_out = surface.output_count();
  check_columns("input", n_axes, inputs.size(), count, inputs);
  check_columns("output", n_out, outputs.size(), count, outputs);
  if (!gradients.empty()) check_columns("gradient", n_out * n_axes, gradients.size(), count, gradients);
  if (count == 0) return;

  const std::size_t chunks = (count + kChunkPoints - 1) / kChunkPoints;
  std::size_t workers = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
  workers = std::min(workers, chunks);
  Batch batch(surface, count, inputs, outputs, gradients);
  {
    std::vector<std::jthread> pool;
    pool.reserve(workers - 1);
    for (std::size_t t = 1; t < workers; ++t) pool.emplace_back([&batch] { batch.work(); });
    batch.work();  // the calling thread is one of the workers
  }  // joined
  batch.finish();
}

}  // namespace hydrocoef
