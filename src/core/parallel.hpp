// A loop whose iterations run on several threads: the one way hydrocoef
// spreads independent pieces of work (files of an import, blocks of a
// compressed array, chunks of a force history, slices of a batch query)
// over the cores.
//
// The calling thread is one of the workers; iterations are handed out one
// at a time in increasing index order, so a slow one does not hold up the
// others. Errors behave as in a serial loop as far as the caller can tell:
// once an iteration throws, no further iteration starts, and the exception
// rethrown is the one of the lowest failing index, whatever the timing.
// (Indices are claimed in increasing order and a claimed one always runs, so
// every index below a failing one has run by the time the loop ends.)
#pragma once

#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <type_traits>
#include <vector>

namespace hydrocoef {

/// The number of threads parallel_for(count, threads, ...) runs on: `threads`
/// (0: one per core, std::thread::hardware_concurrency()), at most `count`,
/// at least 1.
inline unsigned parallel_threads(std::size_t count, unsigned threads) {
  if (threads == 0) threads = std::thread::hardware_concurrency();
  if (threads == 0) threads = 1;
  if (count < threads) threads = count == 0 ? 1u : static_cast<unsigned>(count);
  return threads;
}

/// Runs body(i) for every i in [0, count) on parallel_threads(count, threads)
/// threads, the calling thread included, and returns when all are done.
/// body may instead take (i, worker): worker in [0, parallel_threads(count,
/// threads)) names the thread running iteration i, and one worker runs one
/// iteration at a time, so scratch space indexed by worker needs no lock.
/// Exceptions: see the file comment. A helper thread that cannot be started
/// (std::system_error) leaves its share to the others.
template <typename Body>
void parallel_for(std::size_t count, unsigned threads, Body&& body) {
  const unsigned workers = parallel_threads(count, threads);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex error_mutex;
  std::size_t error_index = count;
  std::exception_ptr error;
  auto work = [&](unsigned worker) {
    while (!failed.load(std::memory_order_relaxed)) {
      const std::size_t i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= count) return;
      try {
        if constexpr (std::is_invocable_v<Body&, std::size_t, unsigned>) {
          body(i, worker);
        } else {
          (void)worker;
          body(i);
        }
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (i < error_index) {
          error_index = i;
          error = std::current_exception();
        }
        failed.store(true, std::memory_order_relaxed);
      }
    }
  };
  std::vector<std::thread> helpers;
  helpers.reserve(workers - 1);
  for (unsigned worker = 1; worker < workers; ++worker) {
    try {
      helpers.emplace_back(work, worker);
    } catch (const std::system_error&) {
      break;
    }
  }
  work(0);
  for (std::thread& helper : helpers) helper.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace hydrocoef
