// End-to-end tests of hydrocoef surface build|rebuild|list|show and query:
// a table of runs over (u, v) whose forces are known functions, surfaces built
// from it, single and batch queries checked against those functions, stale
// surfaces after a re-import, and refusals that leave the database as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"

namespace hydrocoef {
namespace {

using nlohmann::json;
using test::dump_database;
using test::run_cli;
using test::TempDir;

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Forces on the body, multilinear in (u, v): a linear surface reproduces them.
double force_x(double u, double v) { return -0.3 - 11.0 * u + 2.0 * v + 4.0 * u * v; }
double moment_n(double u, double v) { return 0.01 * u - 0.2 * v - 0.5 * u * v; }

const std::vector<double> kU{0.0, 0.1, 0.2, 0.3, 0.5};
const std::vector<double> kV{-0.1, 0.0, 0.05, 0.1};

std::string grid_table(double scale_x = 1.0) {
  std::ostringstream out;
  out.precision(17);
  out << "u [m s^-1],v [m s^-1],X [N],N [N m]\n";
  for (double v : kV)
    for (double u : kU) out << u << "," << v << "," << scale_x * force_x(u, v) << "," << moment_n(u, v) << "\n";
  return out.str();
}

class SurfaceCli : public ::testing::Test {
 protected:
  void SetUp() override {
    write(dir_ / "grid.csv", grid_table());
    ASSERT_EQ(cli({"import", "grid.csv", "--body", "boat"}).exit_code, 0);
  }
  test::CliResult cli(std::vector<std::string> args, const std::filesystem::path& in = "/dev/null") {
    args.insert(args.begin(), {"--db", "runs.db"});
    return run_cli(args, dir_.path(), in);
  }
  TempDir dir_;
};

TEST_F(SurfaceCli, EveryCommandHasHelpWithJson) {
  for (const std::vector<std::string>& command : {std::vector<std::string>{"surface", "build", "--help"},
                                                  {"surface", "list", "--help"},
                                                  {"surface", "show", "--help"},
                                                  {"surface", "rebuild", "--help"},
                                                  {"query", "--help"}}) {
    const auto result = run_cli(command, dir_.path());
    EXPECT_EQ(result.exit_code, 0) << command[0];
    EXPECT_NE(result.out.find("--json"), std::string::npos) << command[0];
  }
}

TEST_F(SurfaceCli, LinearSurfaceAnswersTheTabulatedFunctionAndItsGradient) {
  const auto build = cli({"surface", "build", "xn", "--body", "boat", "--outputs", "X,N", "--axes", "u,v", "--method",
                          "linear", "--json"});
  ASSERT_EQ(build.exit_code, 0) << build.err;
  const json built = json::parse(build.out);
  EXPECT_EQ(built["kind"], "grid");
  EXPECT_EQ(built["runs"].size(), kU.size() * kV.size());
  EXPECT_EQ(built["axes"][0]["breakpoints"], kU.size());
  EXPECT_EQ(built["outputs"][1]["unit"], "N m");

  const auto query = cli({"query", "xn", "u=0.27", "v=-0.033", "--gradient", "--json"});
  ASSERT_EQ(query.exit_code, 0) << query.err;
  const json answer = json::parse(query.out);
  const double u = 0.27, v = -0.033;
  EXPECT_NEAR(answer["values"]["X"].get<double>(), force_x(u, v), 1e-12);
  EXPECT_NEAR(answer["values"]["N"].get<double>(), moment_n(u, v), 1e-12);
  EXPECT_NEAR(answer["gradient"]["X"]["u"].get<double>(), -11.0 + 4.0 * v, 1e-11);
  EXPECT_NEAR(answer["gradient"]["X"]["v"].get<double>(), 2.0 + 4.0 * u, 1e-11);
  EXPECT_NEAR(answer["gradient"]["N"]["v"].get<double>(), -0.2 - 0.5 * u, 1e-11);

  const auto text = cli({"query", "xn", "v=-0.033", "u=0.27"});
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("N m"), std::string::npos);

  const auto shown = cli({"surface", "show", "xn", "--json"});
  ASSERT_EQ(shown.exit_code, 0);
  EXPECT_EQ(json::parse(shown.out)["axes"][1]["breakpoint_values"].get<std::vector<double>>(), kV);
  const auto listed = cli({"surface", "list", "--json"});
  ASSERT_EQ(listed.exit_code, 0);
  EXPECT_EQ(json::parse(listed.out).size(), 1u);
}

TEST_F(SurfaceCli, BatchQueriesFromAFileAndFromStdinMatchThePointwiseAnswers) {
  ASSERT_EQ(cli({"surface", "build", "xn", "--body", "boat", "--outputs", "X,N", "--axes", "u,v"}).exit_code, 0);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> du(0.0, 0.5), dv(-0.1, 0.1);
  std::ostringstream points;
  points.precision(17);
  points << "v, u\r\n";  // columns in any order, CRLF accepted
  std::vector<std::pair<double, double>> expected;
  for (int i = 0; i < 500; ++i) {
    const double u = du(rng), v = dv(rng);
    points << v << ", " << u << "\r\n";
    expected.emplace_back(u, v);
  }
  write(dir_ / "points.csv", points.str());
  const auto to_file = cli({"query", "xn", "--input", "points.csv", "--output", "out.csv", "--gradient"});
  ASSERT_EQ(to_file.exit_code, 0) << to_file.err;
  const auto from_stdin = cli({"query", "xn", "--input", "-", "--gradient"}, dir_ / "points.csv");
  ASSERT_EQ(from_stdin.exit_code, 0) << from_stdin.err;
  EXPECT_EQ(from_stdin.out, test::read_text(dir_ / "out.csv"));

  std::istringstream lines(from_stdin.out);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "u,v,X,N,dX/du,dX/dv,dN/du,dN/dv");
  for (const auto& [u, v] : expected) {
    ASSERT_TRUE(std::getline(lines, line));
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    ASSERT_EQ(row.size(), 8u);
    EXPECT_EQ(row[0], u);
    EXPECT_EQ(row[1], v);
    EXPECT_NEAR(row[2], force_x(u, v), 1e-12);
    EXPECT_NEAR(row[3], moment_n(u, v), 1e-12);
    EXPECT_NEAR(row[5], 2.0 + 4.0 * u, 1e-11);
  }
}

TEST_F(SurfaceCli, BadBatchInputIsLocatedAndWritesNoFile) {
  ASSERT_EQ(cli({"surface", "build", "xn", "--body", "boat", "--outputs", "X", "--axes", "u,v"}).exit_code, 0);
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
      {"u,v\n0.1,0.0\n0.2,abc\n", {"points.csv:3:5", "'abc'", "column 'v'"}},
      {"u,v\n0.1,0.0,7\n", {"points.csv:2", "more than 2 numbers"}},
      {"u,w\n0.1,0.0\n", {"points.csv:1:3", "column 'w'", "expected the axes u, v"}},
      {"u\n0.1\n", {"no column for axis 'v'"}},
      {"u,v\n0.1,nan\n", {"points.csv:2:5", "finite number"}},
      {"u,v\n0.1,0.0\n0.9,0.0\n", {"points.csv:3", "'u' = 0.9", "[0, 0.5]"}},
      {"", {"points.csv", "empty"}}};
  for (const auto& [text, pieces] : cases) {
    write(dir_ / "points.csv", text);
    const auto result = cli({"query", "xn", "--input", "points.csv", "--output", "out.csv"});
    EXPECT_EQ(result.exit_code, 2) << text;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    for (const auto& piece : pieces) EXPECT_NE(result.err.find(piece), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "out.csv")) << text;
    // Nothing is left beside it either (no temporary).
    for (const auto& entry : std::filesystem::directory_iterator(dir_.path()))
      EXPECT_EQ(entry.path().filename().string().find("out.csv"), std::string::npos) << entry.path();
  }
}

TEST_F(SurfaceCli, PointQueriesNameWhatIsMissingOrOutOfRange) {
  ASSERT_EQ(
      cli({"surface", "build", "xn", "--body", "boat", "--outputs", "X", "--axes", "u,v", "--extrapolate", "v=clamp"})
          .exit_code,
      0);
  auto result = cli({"query", "xn", "u=0.1"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("no value for axis 'v'"), std::string::npos) << result.err;
  result = cli({"query", "xn", "u=0.1", "w=0"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("no axis 'w'"), std::string::npos) << result.err;
  result = cli({"query", "xn", "u=-0.5", "v=0"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("'u' = -0.5"), std::string::npos) << result.err;
  // v is clamped: v = 0.4 answers as v = 0.1.
  const auto clamped = cli({"query", "xn", "u=0.2", "v=0.4", "--json"});
  ASSERT_EQ(clamped.exit_code, 0) << clamped.err;
  EXPECT_NEAR(json::parse(clamped.out)["values"]["X"].get<double>(), force_x(0.2, 0.1), 1e-12);
  result = cli({"query", "nope", "u=0"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("nope"), std::string::npos);
}

TEST_F(SurfaceCli, FailedBuildsLeaveTheDatabaseAsItWas) {
  ASSERT_EQ(cli({"surface", "build", "xn", "--body", "boat", "--outputs", "X", "--axes", "u,v"}).exit_code, 0);
  const auto before = dump_database(dir_ / "runs.db");
  // One more run off the grid breaks the grid.
  write(dir_ / "extra.csv", "u [m s^-1],v [m s^-1],X [N]\n0.4,0.02,-4.0\n");
  ASSERT_EQ(cli({"import", "extra.csv", "--body", "other"}).exit_code, 0);
  const auto with_other = dump_database(dir_ / "runs.db");
  write(dir_ / "extra2.csv", "u [m s^-1],v [m s^-1],X [N]\n0.4,0.02,-4.0\n");
  const std::vector<std::vector<std::string>> bad{
      {"surface", "build", "x2", "--body", "other", "--outputs", "X", "--axes", "u,v", "--method", "pchip"},
      {"surface", "build", "x2", "--body", "boat", "--outputs", "F", "--axes", "u,v"},
      {"surface", "build", "x2", "--body", "boat", "--outputs", "X", "--axes", "u,q2"},
      {"surface", "build", "x2", "--body", "boat", "--outputs", "X", "--axes", "u", "--method", "linear"},
      {"surface", "build", "x2", "--body", "boat", "--outputs", "X", "--axes", "u,v", "--method", "cubic"},
      {"surface", "build", "x2", "--body", "boat", "--outputs", "X", "--axes", "u,v", "--resample", "u=0:1:5"},
      {"surface", "build", "x2", "--body", "nobody", "--outputs", "X", "--axes", "u,v"}};
  for (const auto& args : bad) {
    const auto result = cli(args);
    EXPECT_EQ(result.exit_code, 2) << args[6] << " " << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_EQ(dump_database(dir_ / "runs.db"), with_other) << result.err;
  }
  EXPECT_NE(before, with_other);
}

TEST_F(SurfaceCli, ChangedRunsMakeASurfaceStaleUntilRebuilt) {
  ASSERT_EQ(cli({"surface", "build", "xn", "--body", "boat", "--outputs", "X", "--axes", "u,v", "--method", "pchip"})
                .exit_code,
            0);
  auto listed = json::parse(cli({"surface", "list", "--json"}).out);
  EXPECT_FALSE(listed[0]["stale"].get<bool>());
  // The same runs, X doubled, imported over the old values.
  write(dir_ / "grid2.csv", grid_table(2.0));
  ASSERT_EQ(cli({"import", "grid2.csv", "--body", "boat", "--replace"}).exit_code, 0);
  listed = json::parse(cli({"surface", "list", "--json"}).out);
  EXPECT_TRUE(listed[0]["stale"].get<bool>());
  const auto warned = cli({"query", "xn", "u=0.1", "v=0", "--json"});
  EXPECT_EQ(warned.exit_code, 0);
  EXPECT_NE(warned.err.find("stale"), std::string::npos);
  EXPECT_NEAR(json::parse(warned.out)["values"]["X"].get<double>(), force_x(0.1, 0.0), 1e-12);

  const auto rebuilt = cli({"surface", "rebuild", "--stale", "--json"});
  ASSERT_EQ(rebuilt.exit_code, 0) << rebuilt.err;
  EXPECT_EQ(json::parse(rebuilt.out).size(), 1u);
  const auto fresh = cli({"query", "xn", "u=0.1", "v=0", "--json"});
  EXPECT_TRUE(fresh.err.empty()) << fresh.err;
  const json answer = json::parse(fresh.out);
  EXPECT_FALSE(answer["stale"].get<bool>());
  EXPECT_NEAR(answer["values"]["X"].get<double>(), 2.0 * force_x(0.1, 0.0), 1e-12);
  EXPECT_EQ(json::parse(cli({"surface", "show", "xn", "--json"}).out)["build_spec"]["method"], "pchip");
}

TEST_F(SurfaceCli, ScatteredRunsNeedRbfAndResamplingReportsPointsFarFromRuns) {
  // Five runs that fill no grid over (u, v).
  write(dir_ / "scattered.csv",
        "u [m s^-1],v [m s^-1],X [N]\n0,0,-0.3\n0.2,0,-2.5\n0.1,0.1,-1.2\n0.3,-0.1,-3.7\n0.05,-0.05,-0.9\n");
  ASSERT_EQ(cli({"import", "scattered.csv", "--body", "blob"}).exit_code, 0);
  auto result = cli({"surface", "build", "s", "--body", "blob", "--outputs", "X", "--axes", "u,v"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--method rbf"), std::string::npos) << result.err;
  result = cli({"surface",     "build",      "s",         "--body",     "blob",       "--outputs",
                "X",           "--axes",     "u,v",       "--method",   "rbf",        "--extrapolate",
                "extrapolate", "--resample", "u=0:0.9:4", "--resample", "v=-0.1,0.1", "--far-threshold",
                "0.7",         "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const json built = json::parse(result.out);
  EXPECT_EQ(built["kind"], "grid");
  EXPECT_EQ(built["quality"]["grid_points"], 8);
  EXPECT_EQ(built["quality"]["loo_method"], "rbf-exact");
  // Scaled by the runs' ranges (0.3 in u, 0.2 in v), the grid points at u =
  // 0.6 and 0.9 are at least 1 from every run; the others within 0.67.
  EXPECT_EQ(built["quality"]["far_from_data"].get<std::vector<int>>(), (std::vector<int>{2, 3, 6, 7}));
  // As coordinates (axis 0 fastest: node 2 is u = 0.6, v = -0.1), in text and JSON and in every export.
  const json points = built["far_from_data_points"];
  ASSERT_EQ(points.size(), 4u);
  EXPECT_NEAR(points[0]["u"].get<double>(), 0.6, 1e-15);
  EXPECT_EQ(points[0]["v"].get<double>(), -0.1);
  EXPECT_NEAR(points[3]["u"].get<double>(), 0.9, 1e-15);
  EXPECT_EQ(points[3]["v"].get<double>(), 0.1);
  const auto shown = cli({"surface", "show", "s"});
  EXPECT_NE(shown.out.find("(u = 0.6, v = -0.1)"), std::string::npos) << shown.out;
  ASSERT_EQ(cli({"export", "s", "--format", "c", "-o", "s.h"}).exit_code, 0);
  const std::string header = test::read_text(dir_ / "s.h");
  EXPECT_NE(header.find("Far from every CFD run"), std::string::npos);
  EXPECT_NE(header.find("(u = 0.9, v = 0.1)"), std::string::npos) << header.substr(0, 3000);
  ASSERT_EQ(cli({"export", "s", "--format", "json", "-o", "s.json"}).exit_code, 0);
  const json exported = json::parse(test::read_text(dir_ / "s.json"));
  EXPECT_EQ(exported["far_from_data"].size(), 4u);
  EXPECT_EQ(exported["far_from_data"][1]["v"].get<double>(), -0.1);
  const auto query = cli({"query", "s", "u=0.2", "v=0", "--json"});
  ASSERT_EQ(query.exit_code, 0) << query.err;
  EXPECT_NEAR(json::parse(query.out)["values"]["X"].get<double>(), -2.5, 0.2);
}

}  // namespace
}  // namespace hydrocoef
