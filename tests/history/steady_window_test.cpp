// MSER-5 truncation (src/history/steady_window): a step in the mean is cut
// exactly at the step; an exponential start-up is cut where it has sunk into
// the noise; steady noise keeps (almost) everything; a constant keeps
// everything; a series still moving at its end, or a trend, is called
// unsettled; a record under 20 batches is too short; the minimum is never
// taken in the last 10 batches.
#include "src/history/steady_window.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "tests/history/synthetic_history.hpp"

namespace hydrocoef {
namespace {

using test::make_series;

TEST(MserTruncation, CutsAStepInTheMeanAtTheStep) {
  // 300 samples at 5 then 2000 at 1, small noise: the first 300 must go.
  auto x = make_series({.mean = 1.0, .phi = 0.0, .sigma = 0.01}, 2300, 1);
  for (std::size_t i = 0; i < 300; ++i) x[i] += 4.0;
  const MserResult r = mser_truncation(x);
  EXPECT_TRUE(r.applicable);
  EXPECT_TRUE(r.settled);
  EXPECT_EQ(r.batch_size, 5u);
  EXPECT_EQ(r.batches, 460u);
  EXPECT_EQ(r.truncation, 300u);
  EXPECT_EQ(r.unrestricted_truncation, 300u);
}

TEST(MserTruncation, CutsAnExponentialStartUpWhereItSinksIntoTheNoise) {
  // Start-up 20 sigma, time constant 100: below 0.1 sigma after ~530 samples.
  const double sigma = 1.0;
  const auto x =
      make_series({.mean = 0.0, .startup = 20.0, .startup_decay = 100.0, .phi = 0.0, .sigma = sigma}, 10000, 2);
  const MserResult r = mser_truncation(x);
  EXPECT_TRUE(r.settled);
  EXPECT_GE(r.truncation, 250u);  // 20 exp(-t/100) is still 1.6 sigma at 250
  EXPECT_LE(r.truncation, 1500u);
  EXPECT_EQ(r.truncation % 5, 0u);
}

TEST(MserTruncation, SteadyNoiseKeepsAlmostEverything) {
  int late = 0;
  for (int seed = 0; seed < 50; ++seed) {
    const auto x = make_series({.mean = 2.0, .phi = 0.5, .sigma = 1.0}, 5000, 100 + seed);
    const MserResult r = mser_truncation(x);
    EXPECT_TRUE(r.settled) << "seed " << seed;
    if (r.truncation > 1000) ++late;
  }
  EXPECT_LE(late, 3);
}

TEST(MserTruncation, ConstantSeriesKeepsEverything) {
  const std::vector<double> x(1000, 0.1);
  const MserResult r = mser_truncation(x);
  EXPECT_TRUE(r.applicable);
  EXPECT_TRUE(r.settled);
  EXPECT_EQ(r.truncation, 0u);
  EXPECT_EQ(r.statistic, 0.0);
}

TEST(MserTruncation, AStartUpLastingTheWholeRecordIsUnsettled) {
  // Time constant 2000 on 3000 samples: still moving at the end.
  const auto x =
      make_series({.mean = 0.0, .startup = 10.0, .startup_decay = 2000.0, .phi = 0.3, .sigma = 0.01}, 3000, 3);
  const MserResult r = mser_truncation(x);
  EXPECT_TRUE(r.applicable);
  EXPECT_FALSE(r.settled);
  EXPECT_GT(r.unrestricted_truncation, 1500u);
  EXPECT_LE(r.truncation, 1500u);  // the first-half choice is still given
}

TEST(MserTruncation, ALinearTrendIsUnsettled) {
  const auto x = make_series({.mean = 0.0, .phi = 0.0, .sigma = 0.1, .slope = 0.01}, 4000, 4);
  EXPECT_FALSE(mser_truncation(x).settled);
}

TEST(MserTruncation, TooShortRecordsAreNotJudged) {
  const std::vector<double> x(99, 1.0);  // 19 batches of 5
  const MserResult r = mser_truncation(x);
  EXPECT_FALSE(r.applicable);
  EXPECT_FALSE(r.settled);
  EXPECT_EQ(r.batches, 19u);
  EXPECT_TRUE(mser_truncation(std::vector<double>(100, 1.0)).applicable);
}

TEST(MserTruncation, TheLastTenBatchesAreNeverChosen) {
  // Noise, then the last 45 samples (9 batches) exactly constant: a tail of
  // zero variance that MSER without the guard would pick.
  auto x = make_series({.mean = 0.0, .phi = 0.0, .sigma = 1.0}, 1000, 5);
  for (std::size_t i = 955; i < 1000; ++i) x[i] = 0.0;
  const MserResult r = mser_truncation(x);
  EXPECT_LE(r.unrestricted_truncation, 1000u - 50u);
  EXPECT_TRUE(r.settled);
}

TEST(MserTruncation, OtherBatchSizes) {
  auto x = make_series({.mean = 1.0, .phi = 0.0, .sigma = 0.01}, 2000, 6);
  for (std::size_t i = 0; i < 210; ++i) x[i] += 4.0;
  const MserResult one = mser_truncation(x, 1);
  EXPECT_EQ(one.truncation, 210u);
  const MserResult ten = mser_truncation(x, 10);
  EXPECT_EQ(ten.truncation, 210u);  // the batch straddling no step
  EXPECT_THROW(mser_truncation(x, 0), std::invalid_argument);
}

}  // namespace
}  // namespace hydrocoef
