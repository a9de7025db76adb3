// Where to run CFD next (src/pipeline/next_runs.hpp): the suggested keys
// lie in the bounds, the first is where the surface is least sure, each next
// one is no surer than the one before (sequential maximum variance), the
// runs lower the largest standard deviation, and the manifest written is
// one the sweep importer reads back with the same keys.
#include "src/pipeline/next_runs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
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

// Each coordinate of a key proposed at resolution m * 10^-p is the decimal
// k m e-p itself (as the manifest writes it): read back from that text.
bool is_decimal_multiple(double x, long mantissa, int power) {
  const double steps = x / (static_cast<double>(mantissa) * std::pow(10.0, -power));
  const long k = std::lround(steps);
  return std::abs(steps - static_cast<double>(k)) < 1e-9 &&
         x == std::stod(std::to_string(k * mantissa) + "e-" + std::to_string(power));
}

TEST(NextRuns, SequentialMaximumVarianceOverTheRoundedKeys) {
  const CoefficientSurface surface = surface_of_runs(15);
  NextRunsRequest request;
  request.count = 4;
  request.bounds = {"u=0.1:0.3", "current_v = -0.05 : 0.1"};
  request.round = {"u=0.01", "current_v=0.005"};
  const NextRuns next = suggest_next_runs(surface, request);
  ASSERT_EQ(next.runs.size(), 4u);
  EXPECT_EQ(next.output, "X");
  EXPECT_EQ(next.lower, (std::vector<double>{0.1, -0.05}));
  EXPECT_EQ(next.upper, (std::vector<double>{0.3, 0.1}));
  EXPECT_EQ(next.resolution, (std::vector<double>{0.01, 0.005}));
  EXPECT_EQ(next.candidates, 21u * 31u);  // the whole lattice: 21 x 31 keys
  for (const auto& run : next.runs) {
    EXPECT_GE(run.point[0], 0.1);
    EXPECT_LE(run.point[0], 0.3);
    EXPECT_GE(run.point[1], -0.05);
    EXPECT_LE(run.point[1], 0.1);
    EXPECT_TRUE(is_decimal_multiple(run.point[0], 1, 2)) << run.point[0];
    EXPECT_TRUE(is_decimal_multiple(run.point[1], 5, 3)) << run.point[1];
  }
  // The first is the largest standard deviation over every key of the lattice.
  const GpSurface& gp = surface.gp()->output(0);
  GpSurface::Workspace workspace(gp);
  double largest = 0.0;
  std::vector<double> where;
  for (int i = 10; i <= 30; ++i)
    for (int j = -10; j <= 20; ++j) {
      const double p[2] = {std::stod(std::to_string(i) + "e-2"), std::stod(std::to_string(5 * j) + "e-3")};
      double sd = 0.0;
      gp.evaluate(p, workspace, &sd);
      if (sd > largest) largest = sd, where = {p[0], p[1]};
    }
  EXPECT_EQ(next.runs[0].point, where);
  EXPECT_EQ(next.runs[0].standard_deviation, largest);
  for (std::size_t i = 1; i < next.runs.size(); ++i)
    EXPECT_LE(next.runs[i].standard_deviation, next.runs[i - 1].standard_deviation * (1 + 1e-12));
  EXPECT_LT(next.largest_sd_after, next.runs.back().standard_deviation);
}

// Without --round each axis gets 1/100 of its bounds' width rounded down to
// a 1-2-5 step; with the Halton candidates of a lattice too large to list.
TEST(NextRuns, DefaultResolutionIsAOneTwoFiveStep) {
  const CoefficientSurface surface = surface_of_runs(15);
  NextRunsRequest request;
  request.count = 6;
  request.bounds = {"u=0:0.4", "current_v=-0.05:0.1"};  // widths 0.4 and 0.15
  const NextRuns next = suggest_next_runs(surface, request);
  EXPECT_EQ(next.resolution, (std::vector<double>{0.002, 0.001}));
  EXPECT_EQ(next.resolution_given, (std::vector<bool>{false, false}));
  EXPECT_LT(next.candidates, 201u * 151u);
  for (const auto& run : next.runs) {
    EXPECT_TRUE(is_decimal_multiple(run.point[0], 2, 3)) << run.point[0];
    EXPECT_TRUE(is_decimal_multiple(run.point[1], 1, 3)) << run.point[1];
  }
}

// A lattice of exactly `count` keys: rounding never gives one key twice, so
// every key is proposed once; one more than it holds is refused.
TEST(NextRuns, RoundingNeverProposesOneKeyTwice) {
  const CoefficientSurface surface = surface_of_runs(15);
  NextRunsRequest request;
  request.count = 6;
  request.bounds = {"u=0.3:0.4", "current_v=-0.1:0.1"};
  request.round = {"u=0.05", "current_v=0.1"};  // 3 x 3 keys
  request.candidates = 4;                       // fewer than the lattice: Halton points, rounded
  std::set<std::vector<double>> keys;
  for (const auto& run : suggest_next_runs(surface, request).runs) keys.insert(run.point);
  EXPECT_EQ(keys.size(), 6u);
  request.count = 9;
  request.candidates = 4096;
  keys.clear();
  for (const auto& run : suggest_next_runs(surface, request).runs) keys.insert(run.point);
  EXPECT_EQ(keys.size(), 9u);
  request.count = 10;
  try {
    (void)suggest_next_runs(surface, request);
    ADD_FAILURE() << "10 keys proposed from 9";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hold 9 new keys"), std::string::npos) << e.what();
  }
}

// A surface of X(u, v) built with --mirror v (runs and their images): keys
// with v >= 0 only, never two that are images of each other, never the image
// of a run that is imported or running.
CoefficientSurface mirrored_surface() {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(0.0, 0.4), v(0.0, 0.1);
  std::vector<double> x, y;
  for (int i = 0; i < 12; ++i) {
    const double a = u(random), b = v(random);
    for (const double side : {1.0, -1.0}) {
      x.insert(x.end(), {a, side * b});
      y.push_back(-15.0 * a * a - 4.0 * b * b);
    }
  }
  GpOptions options;
  options.starts = 2;
  return CoefficientSurface(GpSurfaces(2, x, 1, y, {}, options, {"u", "v"}, {}), {"u", "v"}, {"X"});
}

TEST(NextRuns, KeysLieInTheFundamentalDomainOfTheMirror) {
  const CoefficientSurface surface = mirrored_surface();
  NextRunsRequest request;
  request.count = 12;
  request.bounds = {"u=0:0.4", "v=-0.1:0.1"};
  request.mirror = make_mirror_spec({"v"}, {});
  const NextRuns next = suggest_next_runs(surface, request);
  EXPECT_EQ(next.domain, "v >= 0");
  ASSERT_EQ(next.runs.size(), 12u);
  for (std::size_t i = 0; i < next.runs.size(); ++i) {
    EXPECT_GE(next.runs[i].point[1], 0.0) << i;
    for (std::size_t j = 0; j < next.runs.size(); ++j) {
      if (i == j) continue;
      EXPECT_NE(next.runs[i].point, next.runs[j].point);
      EXPECT_NE(next.runs[i].point, (std::vector<double>{next.runs[j].point[0], -next.runs[j].point[1]}));
    }
  }
  // Without the mirror the same surface is offered both sides (it is
  // symmetric, so what the mirror prevents happens).
  NextRunsRequest blind = request;
  blind.mirror = {};
  const NextRuns both = suggest_next_runs(surface, blind);
  EXPECT_TRUE(std::any_of(both.runs.begin(), both.runs.end(), [](const SuggestedRun& r) { return r.point[1] < 0; }));
  // A run imported at the image of the first key: that key is not proposed
  // again (nor its image), and neither is one listed as running.
  NextRunsRequest again = request;
  again.imported = {{next.runs[0].point[0], -next.runs[0].point[1]}};
  again.running = {next.runs[1].point};
  const NextRuns after = suggest_next_runs(surface, again);
  EXPECT_EQ(after.imported_skipped, 1u);
  EXPECT_EQ(after.running_skipped, 1u);
  for (const auto& run : after.runs) {
    EXPECT_NE(run.point, next.runs[0].point);
    EXPECT_NE(run.point, next.runs[1].point);
    EXPECT_GE(run.point[1], 0.0);
  }
}

// Keys already imported are never proposed: with every key of a small
// lattice but three imported (some within round-off of the key), the three
// are what is proposed.
TEST(NextRuns, KeysAlreadyImportedAreNeverProposed) {
  const CoefficientSurface surface = surface_of_runs(15);
  NextRunsRequest request;
  request.count = 3;
  request.bounds = {"u=0.2:0.4", "current_v=0:0.1"};
  request.round = {"u=0.1", "current_v=0.05"};  // 3 x 3 keys
  const std::set<std::vector<double>> left = {{0.3, 0.05}, {0.4, 0.0}, {0.2, 0.1}};
  for (const double a : {0.2, 0.3, 0.4})
    for (const double b : {0.0, 0.05, 0.1})
      if (!left.count({a, b})) request.imported.push_back({a + 1e-7, b - 1e-7});
  const NextRuns next = suggest_next_runs(surface, request);
  EXPECT_EQ(next.imported_skipped, 6u);
  std::set<std::vector<double>> proposed;
  for (const auto& run : next.runs) proposed.insert(run.point);
  EXPECT_EQ(proposed, left);
  request.count = 4;
  EXPECT_THROW((void)suggest_next_runs(surface, request), InputError);
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
  // Bounds must be finite in width and hold distinct keys (issue 34, item 15).
  request.bounds = {"u=-1e308:1e308"};
  refused(request, "not a finite number");
  request.bounds = {"u=0.1:0.10000000000000002"};
  refused(request, "wider than the round-off");
  request.bounds = {"u=0:0.05"};
  request.round = {"u=0.1"};
  refused(request, "not wider than the resolution 0.1 of u");
  request.round = {"u=0"};
  refused(request, "expected AXIS=STEP with STEP > 0");
  request.round = {"u=1e-16"};
  refused(request, "too fine");
  request.round = {};
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

// A body's name goes into the manifest's CSV through escape::csv_text:
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
