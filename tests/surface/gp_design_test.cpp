// Suggested runs: the first goes where the surface is least sure, each run
// suggested lowers the largest uncertainty left, suggestions stay in their
// bounds and do not repeat, and bad requests are refused.
#include "src/surface/gp_design.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

GpSurface surface_on_the_left_half() {
  // Runs fill u in [0, 0.2] of a domain [0, 0.4]: the right half is unknown.
  std::vector<double> x, y;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const double u = 0.05 * i, v = -0.1 + 0.05 * j;
      x.push_back(u), x.push_back(v), y.push_back(-11.0 * u * u + 0.3 * v);
    }
  return GpSurface::fit(x, 2, y, {}, {.mean_degree = 1, .fixed_hyperparameters = {0.5, 0.1, 0.1}});
}

TEST(SuggestRuns, GoWhereTheSurfaceIsLeastSure) {
  const GpSurface gp = surface_on_the_left_half();
  const auto runs = suggest_gp_runs(gp, {0.0, -0.1}, {0.4, 0.1}, 5, 1024);
  ASSERT_EQ(runs.size(), 5u);
  EXPECT_GT(runs[0].point[0], 0.3);  // far from every run
  for (std::size_t k = 0; k < runs.size(); ++k) {
    EXPECT_GE(runs[k].point[0], 0.0);
    EXPECT_LE(runs[k].point[0], 0.4);
    EXPECT_GE(runs[k].point[1], -0.1);
    EXPECT_LE(runs[k].point[1], 0.1);
    if (k > 0) {
      EXPECT_LE(runs[k].standard_deviation, runs[k - 1].standard_deviation + 1e-12);
    }
    for (std::size_t j = 0; j < k; ++j) {
      EXPECT_NE(runs[k].point, runs[j].point);
    }
  }
  // The largest uncertainty left after the suggestions is below the first.
  GpSurface after = gp;
  for (const auto& run : runs) after.add_pseudo_run(run.point.data());
  GpSurface::Workspace ws(after);
  double largest = 0.0;
  for (std::size_t i = 0; i < 2000; ++i) {
    const auto h = halton_point(i, 2);
    const double p[2] = {0.4 * h[0], -0.1 + 0.2 * h[1]};
    double sd = 0.0;
    after.evaluate(p, ws, &sd);
    largest = std::max(largest, sd);
  }
  EXPECT_LT(largest, runs[0].standard_deviation);
}

TEST(SuggestRuns, HaltonPointsFillTheUnitBox) {
  EXPECT_EQ(halton_point(0, 2), (std::vector<double>{0.5, 1.0 / 3.0}));
  EXPECT_EQ(halton_point(1, 2), (std::vector<double>{0.25, 2.0 / 3.0}));
  EXPECT_DOUBLE_EQ(halton_point(2, 1)[0], 0.75);
}

TEST(SuggestRuns, RefusesBadRequests) {
  const GpSurface gp = surface_on_the_left_half();
  EXPECT_THROW(suggest_gp_runs(gp, {0.0}, {0.4}, 3), InputError);
  EXPECT_THROW(suggest_gp_runs(gp, {0.4, -0.1}, {0.0, 0.1}, 3), InputError);
  EXPECT_THROW(suggest_gp_runs(gp, {0.0, -0.1}, {0.4, 0.1}, 0), InputError);
  EXPECT_THROW(suggest_gp_runs(gp, {0.0, -0.1}, {0.4, 0.1}, 10, 5), InputError);
}

}  // namespace
}  // namespace hydrocoef
