// The brief of a force history a run keeps (src/history/history_trace): whole
// when short, binned with every sample in exactly one bin when long, each
// bin's extremes and last abscissa exact, and a damaged trace named.
#include "src/history/history_trace.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace hydrocoef {
namespace {

ForceHistory history_of(std::size_t n, bool with_moment) {
  ForceHistory h;
  h.abscissa = HistoryAbscissa::Iteration;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i + 1);
    h.abscissa_values.push_back(t);
    h.values(ForcePart::Total, HistoryComponent::Fx).push_back(-1.0 + std::exp(-t / 50.0) * std::sin(t));
    if (with_moment) h.values(ForcePart::Total, HistoryComponent::Mz).push_back(0.01 * std::cos(0.1 * t));
  }
  return h;
}

TEST(HistoryTrace, AShortRecordIsKeptWhole) {
  const auto h = history_of(100, false);
  const HistoryTrace trace = trace_of(h);
  EXPECT_EQ(trace.samples, 100u);
  EXPECT_EQ(trace.abscissa_name, "iteration");
  EXPECT_EQ(trace.abscissa, h.abscissa_values);
  EXPECT_EQ(trace.low[0], h.values(ForcePart::Total, HistoryComponent::Fx));
  EXPECT_EQ(trace.high[0], trace.low[0]);
  EXPECT_TRUE(trace.low[5].empty());
  EXPECT_EQ(trace_problem(trace), "");
}

TEST(HistoryTrace, ALongRecordKeepsEachBinsExtremesAndEndsAtItsLastSample) {
  const std::size_t n = 1000;  // 256 bins: the first 232 of 4 samples, the other 24 of 3
  const auto h = history_of(n, true);
  const HistoryTrace trace = trace_of(h);
  ASSERT_EQ(trace.abscissa.size(), HistoryTrace::kMaxBins);
  EXPECT_EQ(trace.abscissa.back(), static_cast<double>(n));
  EXPECT_EQ(trace.abscissa[0], 4.0);
  EXPECT_EQ(trace.abscissa[231], 928.0);
  EXPECT_EQ(trace.abscissa[232], 931.0);
  const auto& x = h.values(ForcePart::Total, HistoryComponent::Fx);
  // Over the whole record the extremes are the bins' extremes.
  EXPECT_EQ(*std::min_element(trace.low[0].begin(), trace.low[0].end()), *std::min_element(x.begin(), x.end()));
  EXPECT_EQ(*std::max_element(trace.high[0].begin(), trace.high[0].end()), *std::max_element(x.begin(), x.end()));
  // Bin 1 holds samples 1..4.
  EXPECT_EQ(trace.low[0][0], *std::min_element(x.begin(), x.begin() + 4));
  EXPECT_EQ(trace.high[0][0], *std::max_element(x.begin(), x.begin() + 4));
  EXPECT_EQ(trace.low[5].size(), HistoryTrace::kMaxBins);
  EXPECT_EQ(trace_problem(trace), "");
}

TEST(HistoryTrace, ADamagedTraceIsNamed) {
  const HistoryTrace good = trace_of(history_of(1000, false));
  HistoryTrace t = good;
  t.abscissa.pop_back();
  EXPECT_NE(trace_problem(t).find("bins of 1000 samples"), std::string::npos) << trace_problem(t);
  t = good;
  t.high[0][7] = t.low[0][7] - 1.0;
  EXPECT_NE(trace_problem(t).find("low <= high"), std::string::npos);
  t = good;
  t.low[0][3] = NAN;
  EXPECT_NE(trace_problem(t).find("bin 4"), std::string::npos);
  t = good;
  std::swap(t.abscissa[2], t.abscissa[3]);
  EXPECT_NE(trace_problem(t).find("increasing"), std::string::npos);
  t = good;
  t.low[3] = {1.0};
  EXPECT_NE(trace_problem(t).find("component 4"), std::string::npos);
  t = good;
  t.abscissa_name = "days";
  EXPECT_NE(trace_problem(t).find("time or iteration"), std::string::npos);
}

}  // namespace
}  // namespace hydrocoef
