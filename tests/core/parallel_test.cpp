// The parallel loop (src/core/parallel.hpp): every index runs exactly once
// whatever the thread count, per-worker scratch is never shared by two
// running iterations, and of several failing iterations the lowest index's
// exception is the one rethrown, every time, with every index below it run.
#include "src/core/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace hydrocoef {
namespace {

TEST(ParallelThreads, AtLeastOneAtMostTheWork) {
  EXPECT_EQ(parallel_threads(10, 4), 4u);
  EXPECT_EQ(parallel_threads(3, 8), 3u);
  EXPECT_EQ(parallel_threads(0, 8), 1u);
  EXPECT_EQ(parallel_threads(1, 0), 1u);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  EXPECT_EQ(parallel_threads(1000000, 0), cores);
}

TEST(ParallelFor, RunsEveryIndexExactlyOnce) {
  for (const std::size_t count : {0u, 1u, 2u, 7u, 1000u}) {
    for (const unsigned threads : {0u, 1u, 2u, 3u, 16u}) {
      std::vector<std::atomic<int>> runs(count);
      parallel_for(count, threads, [&](std::size_t i) { ++runs[i]; });
      for (std::size_t i = 0; i < count; ++i)
        ASSERT_EQ(runs[i].load(), 1) << "index " << i << " of " << count << " on " << threads << " threads";
    }
  }
}

TEST(ParallelFor, OneThreadRunsInOrderOnTheCaller) {
  std::vector<std::size_t> order;
  const auto caller = std::this_thread::get_id();
  bool elsewhere = false;
  parallel_for(50, 1, [&](std::size_t i) {
    order.push_back(i);
    elsewhere = elsewhere || std::this_thread::get_id() != caller;
  });
  ASSERT_EQ(order.size(), 50u);
  for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], i);
  EXPECT_FALSE(elsewhere);
}

TEST(ParallelFor, AWorkerRunsOneIterationAtATime) {
  constexpr unsigned kThreads = 4;
  const unsigned workers = parallel_threads(2000, kThreads);
  std::vector<std::atomic<int>> busy(workers);
  std::vector<std::size_t> done(workers, 0);  // written only by its worker
  std::atomic<bool> shared{false}, out_of_range{false};
  parallel_for(2000, kThreads, [&](std::size_t, unsigned worker) {
    if (worker >= workers) {
      out_of_range = true;
      return;
    }
    if (busy[worker].fetch_add(1) != 0) shared = true;
    ++done[worker];
    std::this_thread::yield();
    busy[worker].fetch_sub(1);
  });
  EXPECT_FALSE(out_of_range);
  EXPECT_FALSE(shared);
  std::size_t total = 0;
  for (std::size_t n : done) total += n;
  EXPECT_EQ(total, 2000u);
}

TEST(ParallelFor, RethrowsTheLowestFailingIndexWhateverTheTiming) {
  // Indices 300, 301 and 900 fail; a slow 300 lets the others fail first.
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<std::atomic<int>> runs(1000);
    try {
      parallel_for(1000, 4, [&](std::size_t i) {
        ++runs[i];
        if (i == 300) {
          std::this_thread::sleep_for(std::chrono::microseconds(trial % 5 * 200));
          throw std::runtime_error("index 300");
        }
        if (i == 301 || i == 900) throw std::invalid_argument("index " + std::to_string(i));
      });
      FAIL() << "no exception";
    } catch (const std::runtime_error& error) {
      EXPECT_EQ(std::string(error.what()), "index 300");
    } catch (const std::exception& error) {
      FAIL() << "trial " << trial << " rethrew '" << error.what() << "', expected the lowest failing index 300";
    }
    for (std::size_t i = 0; i < 300; ++i) ASSERT_EQ(runs[i].load(), 1) << "index " << i << ", trial " << trial;
    for (std::size_t i = 0; i < runs.size(); ++i) ASSERT_LE(runs[i].load(), 1) << "index " << i;
  }
}

TEST(ParallelFor, StopsStartingIterationsAfterAFailure) {
  std::atomic<std::size_t> ran{0};
  EXPECT_THROW(parallel_for(10000000, 2,
                            [&](std::size_t i) {
                              ++ran;
                              if (i == 0) throw std::runtime_error("first");
                            }),
               std::runtime_error);
  EXPECT_LT(ran.load(), 10000000u);
}

TEST(ParallelFor, ExceptionOfASingleThreadLoop) {
  std::vector<std::size_t> seen;
  EXPECT_THROW(parallel_for(10, 1,
                            [&](std::size_t i) {
                              seen.push_back(i);
                              if (i == 4) throw std::out_of_range("4");
                            }),
               std::out_of_range);
  EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
}

}  // namespace
}  // namespace hydrocoef
