// Where to run CFD next (src/pipeline/next_runs.hpp): the suggested keys
// lie in the bounds, the first is where the surface is least sure, each next
// one is no surer than the one before (sequential maximum variance), the
// runs lower the largest standard deviation, and the manifest written is
// one the sweep importer reads back with the same keys.
#include "src/pipeline/next_runs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <variant>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/pipeline/sweep_keys.hpp"
#include "tests/support/hostile_names.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

CoefficientSurface surface_of_runs(std::size_t n) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(0.0, 0.4), disturbance(-0.1, 0.1);
  std::vector<double> x, y;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = u(random), b = disturbance(random);
    x.insert(x.end(), {a, b});
    y.push_back(-15.0 * a * a + 2.0 * b);
  }
  GpOptions options;
  options.starts = 2;
  return CoefficientSurface(GpSurfaces(2, x, 1, y, {}, options, {"u", "current_v"}, {}), {"u", "current_v"}, {"X"});
}

TEST(NextRuns, SequentialMaximumVarianceInsideTheBounds) {
  const CoefficientSurface surface = surface_of_runs(15);
  NextRunsRequest request;
  request.count = 4;
  request.bounds = {"u=0.1:0.3", "current_v = -0.05 : 0.1"};
  const NextRuns next = suggest_next_runs(surface, request);
  ASSERT_EQ(next.runs.size(), 4u);
  EXPECT_EQ(next.output, "X");
  EXPECT_EQ(next.lower, (std::vector<double>{0.1, -0.05}));
  EXPECT_EQ(next.upper, (std::vector<double>{0.3, 0.1}));
  for (const auto& run : next.runs) {
    EXPECT_GE(run.point[0], 0.1);
    EXPECT_LE(run.point[0], 0.3);
    EXPECT_GE(run.point[1], -0.05);
    EXPECT_LE(run.point[1], 0.1);
  }
  // The first is the largest standard deviation among the same candidates.
  const auto largest = largest_standard_deviations(surface.gp()->output(0), next.lower, next.upper, 1, 4096);
  EXPECT_EQ(next.runs[0].point, largest[0].point);
  EXPECT_EQ(next.runs[0].standard_deviation, largest[0].standard_deviation);
  for (std::size_t i = 1; i < next.runs.size(); ++i)
    EXPECT_LE(next.runs[i].standard_deviation, next.runs[i - 1].standard_deviation * (1 + 1e-12));
  EXPECT_LT(next.largest_sd_after, next.runs.back().standard_deviation);
}

TEST(NextRuns, RefusalsNameWhatIsWrong) {
  const CoefficientSurface surface = surface_of_runs(10);
  const auto refused = [&](NextRunsRequest request, const std::string& expected) {
    try {
      (void)suggest_next_runs(surface, request);
      ADD_FAILURE() << "accepted; expected " << expected;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  NextRunsRequest request;
  request.count = 0;
  refused(request, "--count 0");
  request.count = 2;
  request.bounds = {"u=0.3:0.1"};
  refused(request, "expected FROM < TO");
  request.bounds = {"u=0.1"};
  refused(request, "expected AXIS=FROM:TO");
  request.bounds = {"w=0:1"};
  refused(request, "'w'");
  request.bounds = {"u=0:nan"};
  refused(request, "expected AXIS=FROM:TO");
  request.bounds = {"u=0:0.1", "u=0.1:0.2"};
  refused(request, "twice");
  request.bounds = {};
  request.output = "N";
  refused(request, "'N'");
  const GridTable table({{"u", {0.0, 1.0}, Extrapolation::Error}}, {"X"}, {1.0, 2.0}, Interpolation::Linear);
  try {
    (void)suggest_next_runs(CoefficientSurface(table), NextRunsRequest{});
    ADD_FAILURE() << "a grid was given suggestions";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected a GP surface"), std::string::npos) << e.what();
  }
}

TEST(NextRuns, TheManifestIsReadBackByTheSweepImporter) {
  const CoefficientSurface surface = surface_of_runs(12);
  NextRunsRequest request;
  request.count = 3;
  const NextRuns next = suggest_next_runs(surface, request);
  test::TempDir dir;
  write_next_runs_manifest(next, "sphere", dir / "next.csv");
  const Manifest manifest = Manifest::read(dir / "next.csv");
  ASSERT_EQ(manifest.rows(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const SettingsLayer* row = manifest.find(dir / ("next-0" + std::to_string(i + 1)) / "case.foam");
    ASSERT_NE(row, nullptr) << i;
    EXPECT_EQ(std::get<double>(row->values.at("u").value), next.runs[i].point[0]);
    EXPECT_EQ(std::get<double>(row->values.at("disturbance.current_v").value), next.runs[i].point[1]);
    EXPECT_EQ(std::get<std::string>(row->values.at("body").value), "sphere");
  }
}

// A body's name goes into the manifest's CSV through escape::csv_field:
// every hostile name a body may have comes back from Manifest::read as it was.
TEST(NextRuns, HostileBodyNamesSurviveTheManifest) {
  const CoefficientSurface surface = surface_of_runs(8);
  NextRunsRequest request;
  request.count = 1;
  const NextRuns next = suggest_next_runs(surface, request);
  test::TempDir dir;
  std::size_t tried = 0;
  for (const std::string& name : test::hostile_names()) {
    try {
      check_name(NameKind::Body, name, {}, "test");
    } catch (const InputError&) {
      continue;  // a name no body can have
    }
    ++tried;
    write_next_runs_manifest(next, name, dir / "next.csv");
    const Manifest manifest = Manifest::read(dir / "next.csv");
    const SettingsLayer* row = manifest.find(dir / "next-01");
    ASSERT_NE(row, nullptr) << name;
    EXPECT_EQ(std::get<std::string>(row->values.at("body").value), name);
  }
  EXPECT_GT(tried, 20u);
}

}  // namespace
}  // namespace hydrocoef
