// GP surfaces through the hydrocoef binary: surface build --method gp, query
// --uncertainty at a point and in a batch, surface show, rebuild, suggest
// with its manifest, and the runs' own standard errors as the noise of real
// OpenFOAM runs (data/openfoam-sphere/cases).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>

#include "src/core/numbers.hpp"
#include "src/store/connection.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/sphere_cases.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using nlohmann::json;
using test::run_cli;
using test::TempDir;

double force_x(double u, double v) { return -20.0 * u * std::abs(u) + 3.0 * v * v - 0.5; }
double moment_n(double u, double v) { return 0.4 * std::sin(4.0 * v) * (1.0 + u); }

class GpSurfaceCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(0.0, 0.5), v(-0.2, 0.2);
    std::ostringstream table;
    table.precision(17);
    table << "u [m s^-1],v [m s^-1],X [N],N [N m]\n";
    for (int i = 0; i < 30; ++i) {
      const double a = u(random), b = v(random);
      runs_.push_back({a, b, force_x(a, b)});
      table << a << "," << b << "," << force_x(a, b) << "," << moment_n(a, b) << "\n";
    }
    std::ofstream(dir_ / "scattered.csv") << table.str();
    ASSERT_EQ(cli({"import", "scattered.csv", "--body", "blob"}).exit_code, 0);
  }
  test::CliResult cli(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", "runs.db"});
    return run_cli(args, dir_.path());
  }
  json build_gp() {
    const auto build = cli({"surface", "build", "gpxn", "--body", "blob", "--outputs", "X,N", "--axes", "u,v",
                            "--method", "gp", "--starts", "2", "--json"});
    EXPECT_EQ(build.exit_code, 0) << build.err;
    return json::parse(build.out);
  }
  std::vector<std::array<double, 3>> runs_;  // u, v, X
  TempDir dir_;
};

TEST_F(GpSurfaceCli, BuildsStoresAndStatesItsQuality) {
  const json built = build_gp();
  EXPECT_EQ(built["kind"], "gp");
  EXPECT_EQ(built["method"], "matern52");
  EXPECT_EQ(built["runs"].size(), 30u);
  EXPECT_EQ(built["quality"]["loo_method"], "gp-refit");
  EXPECT_EQ(built["quality"]["loo_defined"], 30);
  // X is smooth: the left-out runs are predicted to a small part of its spread.
  EXPECT_LT(built["quality"]["outputs"]["X"]["loo_rms"].get<double>(), 0.05 * 5.5);
  EXPECT_EQ(built["gp"]["outputs"]["X"]["largest_sd"].size(), 3u);
  EXPECT_EQ(built["build_spec"]["gp"]["kernel"], "matern52");
  const auto show = cli({"surface", "show", "gpxn"});
  ASSERT_EQ(show.exit_code, 0) << show.err;
  EXPECT_NE(show.out.find("Gaussian process: matern52 kernel"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("GP refitted without each run"), std::string::npos) << show.out;
  // Not a table: an export says how to make one.
  const auto exported = cli({"export", "gpxn", "--format", "csv", "-o", "gp.csv"});
  EXPECT_EQ(exported.exit_code, 2);
  EXPECT_NE(exported.err.find("is a GP surface"), std::string::npos) << exported.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "gp.csv"));
  // Rebuilt from its stored specification, it is the same surface.
  const auto rebuild = cli({"surface", "rebuild", "gpxn", "--json"});
  ASSERT_EQ(rebuild.exit_code, 0) << rebuild.err;
  const json again = json::parse(rebuild.out)[0];
  EXPECT_EQ(again["kind"], "gp");
  EXPECT_EQ(again["gp"], built["gp"]);
}

TEST_F(GpSurfaceCli, QueriesStateTheStandardDeviation) {
  build_gp();
  const auto& run = runs_[7];
  const auto at_run =
      cli({"query", "gpxn", "u=" + json(run[0]).dump(), "v=" + json(run[1]).dump(), "--uncertainty", "--json"});
  ASSERT_EQ(at_run.exit_code, 0) << at_run.err;
  const json a = json::parse(at_run.out);
  EXPECT_NEAR(a["values"]["X"].get<double>(), run[2], 1e-4);  // exact but for the jitter (gp_surface.hpp)
  const double sd_at_run = a["standard_deviation"]["X"].get<double>();
  EXPECT_GE(sd_at_run, 0.0);
  EXPECT_LT(sd_at_run, 1e-3);
  const auto corner = cli({"query", "gpxn", "u=0.25", "v=0.01", "--uncertainty"});
  ASSERT_EQ(corner.exit_code, 0) << corner.err;
  EXPECT_NE(corner.out.find("+/- "), std::string::npos) << corner.out;

  // The batch gives the same numbers, with a sigma column per output.
  std::ofstream(dir_ / "points.csv") << "v,u\n" << json(run[1]).dump() << "," << json(run[0]).dump() << "\n0.1,0.25\n";
  const auto batch = cli({"query", "gpxn", "--input", "points.csv", "--uncertainty"});
  ASSERT_EQ(batch.exit_code, 0) << batch.err;
  std::istringstream lines(batch.out);
  std::string header, first, second;
  std::getline(lines, header);
  std::getline(lines, first);
  std::getline(lines, second);
  EXPECT_EQ(header, "u,v,X,N,sigma_X,sigma_N");
  const auto mid = json::parse(cli({"query", "gpxn", "u=0.25", "v=0.1", "--uncertainty", "--json"}).out);
  std::vector<double> cells;
  std::stringstream row(second);
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(std::stod(cell));
  ASSERT_EQ(cells.size(), 6u);
  EXPECT_EQ(cells[2], mid["values"]["X"].get<double>());
  EXPECT_EQ(cells[4], mid["standard_deviation"]["X"].get<double>());
  EXPECT_EQ(cells[5], mid["standard_deviation"]["N"].get<double>());

  // Both at once: the standard deviations and the gradient of one pass, as
  // the point queries give them.
  const auto both = cli({"query", "gpxn", "--input", "points.csv", "--uncertainty", "--gradient"});
  ASSERT_EQ(both.exit_code, 0) << both.err;
  std::istringstream both_lines(both.out);
  std::string both_header, both_first, both_second;
  std::getline(both_lines, both_header);
  std::getline(both_lines, both_first);
  std::getline(both_lines, both_second);
  EXPECT_EQ(both_header, "u,v,X,N,sigma_X,sigma_N,dX/du,dX/dv,dN/du,dN/dv");
  const auto slope = json::parse(cli({"query", "gpxn", "u=0.25", "v=0.1", "--gradient", "--json"}).out);
  std::vector<double> both_cells;
  std::stringstream both_row(both_second);
  for (std::string cell; std::getline(both_row, cell, ',');) both_cells.push_back(std::stod(cell));
  ASSERT_EQ(both_cells.size(), 10u);
  EXPECT_EQ(both_cells[2], mid["values"]["X"].get<double>());
  EXPECT_EQ(both_cells[4], mid["standard_deviation"]["X"].get<double>());
  EXPECT_EQ(both_cells[6], slope["gradient"]["X"]["u"].get<double>());
  EXPECT_EQ(both_cells[9], slope["gradient"]["N"]["v"].get<double>());
  const auto point_both =
      json::parse(cli({"query", "gpxn", "u=0.25", "v=0.1", "--uncertainty", "--gradient", "--json"}).out);
  EXPECT_EQ(point_both["gradient"], slope["gradient"]);
  EXPECT_EQ(point_both["standard_deviation"], mid["standard_deviation"]);

  // A surface that states no standard deviation says so, and writes nothing:
  // an RBF stored as an older hydrocoef stored it, without its uncertainty.
  ASSERT_EQ(cli({"surface", "build", "rbfx", "--body", "blob", "--outputs", "X", "--axes", "u,v", "--method", "rbf"})
                .exit_code,
            0);
  {
    auto connection = test::connect_database(dir_ / "runs.db");
    connection.execute(test::on_postgresql()
                           ? "UPDATE surface SET definition = (definition::jsonb - 'uncertainty')::text WHERE name = "
                             "'rbfx'"
                           : "UPDATE surface SET definition = json_remove(definition, '$.uncertainty') WHERE name = "
                             "'rbfx'");
  }
  const auto refused = cli({"query", "rbfx", "--input", "points.csv", "--output", "out.csv", "--uncertainty"});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("states no standard deviation"), std::string::npos) << refused.err;
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out.csv"));
  const auto point = cli({"query", "rbfx", "u=0.2", "v=0", "--uncertainty"});
  EXPECT_EQ(point.exit_code, 2);
  EXPECT_NE(point.err.find("expected a GP surface"), std::string::npos) << point.err;
}

TEST_F(GpSurfaceCli, SuggestProposesRunsInsideTheBoundsAndWritesAManifest) {
  build_gp();
  const auto suggest = cli({"suggest", "gpxn", "--count", "3", "--bounds", "u=0.1:0.4,v=-0.1:0.1", "--for", "N",
                            "--manifest", "next.csv", "--json"});
  ASSERT_EQ(suggest.exit_code, 0) << suggest.err;
  const json out = json::parse(suggest.out);
  EXPECT_EQ(out["output"], "N");
  ASSERT_EQ(out["runs"].size(), 3u);
  for (const auto& run : out["runs"]) {
    EXPECT_GE(run["key"]["u"].get<double>(), 0.1);
    EXPECT_LE(run["key"]["u"].get<double>(), 0.4);
    EXPECT_GE(run["key"]["v"].get<double>(), -0.1);
    EXPECT_LE(run["key"]["v"].get<double>(), 0.1);
  }
  EXPECT_LT(out["largest_sd_after"].get<double>(), out["runs"][0]["sd_before"].get<double>());
  std::ifstream manifest(dir_ / "next.csv");
  std::string header;
  std::getline(manifest, header);
  EXPECT_EQ(header, "path,body,u,v");
  const auto text = cli({"suggest", "gpxn", "--count", "2"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("largest sd in the bounds"), std::string::npos) << text.out;
  for (const std::vector<std::string>& bad : {std::vector<std::string>{"suggest", "gpxn", "--bounds", "u=1:0"},
                                              {"suggest", "gpxn", "--count", "0"},
                                              {"suggest", "nothing"}}) {
    const auto refused = cli(bad);
    EXPECT_EQ(refused.exit_code, 2) << bad.back();
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  }
  EXPECT_EQ(run_cli({"suggest", "--help"}, dir_.path()).exit_code, 0);
  EXPECT_NE(run_cli({"suggest", "--help"}, dir_.path()).out.find("--json"), std::string::npos);
}

// Through the database: keys where the body has a run (at a coarse
// resolution, the runs round onto lattice keys) are never proposed, a
// surface built with --mirror v gets keys with v >= 0 only, keys listed in a
// --running manifest are not proposed again, and bounds of infinite width
// are refused with one line.
TEST_F(GpSurfaceCli, SuggestSkipsRunKeysAndRunningKeysInTheMirrorsDomain) {
  build_gp();
  std::set<std::pair<long, long>> covered;  // lattice keys (u / 0.1, v / 0.1) with a run
  for (const auto& run : runs_) covered.insert({std::lround(run[0] / 0.1), std::lround(run[1] / 0.1)});
  const std::size_t free = 6 * 5 - covered.size();
  ASSERT_GT(free, 0u);
  const auto all = cli({"suggest", "gpxn", "--count", std::to_string(free), "--bounds", "u=0:0.5,v=-0.2:0.2", "--round",
                        "u=0.1,v=0.1", "--json"});
  ASSERT_EQ(all.exit_code, 0) << all.err;
  const json out = json::parse(all.out);
  EXPECT_EQ(out["skipped"]["imported"].get<std::size_t>(), covered.size());
  for (const auto& run : out["runs"]) {
    const double u = run["key"]["u"], v = run["key"]["v"];
    EXPECT_EQ(covered.count({std::lround(u / 0.1), std::lround(v / 0.1)}), 0u) << u << " " << v;
    EXPECT_EQ(shortest_number(u).size() <= 4, true) << u;  // "0.3", "-0.1": decimals, not round-off
  }
  const auto more = cli({"suggest", "gpxn", "--count", std::to_string(free + 1), "--bounds", "u=0:0.5,v=-0.2:0.2",
                         "--round", "u=0.1,v=0.1"});
  EXPECT_EQ(more.exit_code, 2);
  EXPECT_NE(more.err.find("new keys"), std::string::npos) << more.err;

  ASSERT_EQ(cli({"surface", "build", "gpm", "--body", "blob", "--outputs", "X", "--axes", "u,v", "--method", "gp",
                 "--starts", "2", "--mirror", "v"})
                .exit_code,
            0);
  const auto first = cli({"suggest", "gpm", "--count", "4", "--manifest", "next.csv", "--json"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const json mirrored = json::parse(first.out);
  EXPECT_EQ(mirrored["domain"], "v >= 0");
  std::set<std::pair<double, double>> proposed;
  for (const auto& run : mirrored["runs"]) {
    EXPECT_GE(run["key"]["v"].get<double>(), 0.0);
    proposed.insert({run["key"]["u"].get<double>(), run["key"]["v"].get<double>()});
  }
  const auto second = cli({"suggest", "gpm", "--count", "4", "--running", "next.csv", "--json"});
  ASSERT_EQ(second.exit_code, 0) << second.err;
  const json after = json::parse(second.out);
  EXPECT_EQ(after["skipped"]["running"].get<std::size_t>(), 4u);
  for (const auto& run : after["runs"])
    EXPECT_EQ(proposed.count({run["key"]["u"].get<double>(), run["key"]["v"].get<double>()}), 0u);

  const auto huge = cli({"suggest", "gpxn", "--bounds", "u=-1e308:1e308", "--manifest", "huge.csv"});
  EXPECT_EQ(huge.exit_code, 2);
  EXPECT_EQ(std::count(huge.err.begin(), huge.err.end(), '\n'), 1) << huge.err;
  EXPECT_NE(huge.err.find("not a finite number"), std::string::npos) << huge.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "huge.csv"));
}

// Real OpenFOAM runs: each force is a mean over its history with a standard
// error; the GP takes it, with the discrepancy sd tau it estimates on top, as
// the run's noise, so at a run its standard deviation is no larger than that
// noise times the surface's sd factor: the kriging predictor is the best
// linear unbiased one, and the run's own value is a linear unbiased
// predictor of mean square error s^2 + tau^2 + j, s the standard error and j
// the jitter 1e-10 sigma^2 on the diagonal (gp_surface.hpp).
TEST(GpSurfaceCliOpenFoam, TheRunsStandardErrorsAreTheNoise) {
  TempDir dir;
  ASSERT_EQ(test::import_sphere_cases(dir.path()).exit_code, 0);
  const auto build = run_cli({"surface", "build", "drag", "--body", "sphere", "--outputs", "X", "--axes", "u,v",
                              "--method", "gp", "--degree", "0", "--json"},
                             dir.path());
  ASSERT_EQ(build.exit_code, 0) << build.err;
  const json built = json::parse(build.out);
  const auto& gp = built["gp"]["outputs"]["X"];
  const double sigma = gp["signal_sd"], tau = gp["discrepancy_sd"], factor = gp["sd_factor"];
  EXPECT_GE(factor, 1.0);
  const auto runs = json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 4u);
  for (const auto& run : runs) {
    const double u = run["u"], v = run["v"];
    const double standard_error = run["forces"]["X"]["statistics"]["standard_error"];
    const auto q =
        run_cli({"query", "drag", "u=" + json(u).dump(), "v=" + json(v).dump(), "--uncertainty", "--json"}, dir.path());
    ASSERT_EQ(q.exit_code, 0) << q.err;
    const double sd = json::parse(q.out)["standard_deviation"]["X"];
    EXPECT_LE(sd, factor * std::sqrt(standard_error * standard_error + tau * tau + 1e-10 * sigma * sigma) * (1 + 1e-6))
        << u << "," << v;
    EXPECT_GT(sd, 0.5 * standard_error);  // and it does take the run's noise: not near 0
  }
}

}  // namespace
}  // namespace hydrocoef
