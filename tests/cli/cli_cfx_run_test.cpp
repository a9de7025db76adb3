// A CFX run imported as the solver left it: the case's settings from the CCL
// echoed in its solver output (STEM.out) and its forces from the cfx5mondata
// monitor CSV beside it (STEM*.csv), with sweep-wide flags only. The free
// stream of the CCL becomes the body velocity with the same frame that turns
// the monitors into body axes.
#include <gtest/gtest.h>

#include <utility>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/backend_under_test.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

const std::filesystem::path kOut = HYDROCOEF_SOURCE_DIR "/tests/data/cfx/tow_u1.5_001.out";

// A steady run's monitors: a start-up that decays over some tens of
// iterations, then small oscillations about the converged forces.
double fx(int i) { return 1.25 + 0.3 * std::exp(-i / 10.0) + 0.002 * std::sin(1.7 * i); }
double fy(int i) { return 0.12 + 0.001 * std::cos(2.3 * i); }
double fz(int i) { return 0.03 - 0.05 * std::exp(-i / 8.0); }

void write_monitors(const std::filesystem::path& path) {
  std::ofstream out(path);
  out << "\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\",\"USER POINT,Fy\",\"USER POINT,Fz\"\n";
  out.precision(17);
  for (int i = 1; i <= 300; ++i) out << i << "," << fx(i) << "," << fy(i) << "," << fz(i) << "\n";
}

double mean_over(double (*f)(int), double first, double last) {
  double sum = 0.0;
  int n = 0;
  for (int i = static_cast<int>(first); i <= static_cast<int>(last); ++i, ++n) sum += f(i);
  return sum / n;
}

TEST(CliCfxRun, TheSolverOutputAndItsMonitorsGiveOneRunInBodyAxes) {
  TempDir dir;
  std::filesystem::create_directories(dir / "sweep");
  std::filesystem::copy_file(kOut, dir / "sweep" / "tow_u1.5_001.out");
  write_monitors(dir / "sweep" / "tow_u1.5_001_monitors.csv");
  // Named directly: the .out stands for its run.
  const auto result =
      run_cli({"import", "sweep/tow_u1.5_001.out", "--body", "hull", "--axes=-x,y,-z", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 1u);
  const auto& run = runs[0];
  // Free stream (1.5, 0.1, 0) m/s in CFD axes; the body moves at its negative; CFD -> body: (-x, y, -z).
  EXPECT_DOUBLE_EQ(run.at("u").get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(run.at("v").get<double>(), -0.1);
  EXPECT_DOUBLE_EQ(run.at("w").get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(run.at("density").get<double>(), 997.0);
  EXPECT_NEAR(run.at("kinematic_viscosity").get<double>(), 8.899e-4 / 997.0, 1e-18);
  // The monitors are a force history: the mean over the steady window the
  // analysis found (after the start-up), with its standard error. Drag opposes
  // the motion: the monitor's +x force is -X in body axes.
  const auto& statistics = run.at("forces").at("X").at("statistics");
  const double first = statistics.at("window")[0].get<double>(), last = statistics.at("window")[1].get<double>();
  EXPECT_GT(first, 20.0);  // the start-up is left out
  EXPECT_EQ(last, 300.0);
  EXPECT_GT(statistics.at("standard_error").get<double>(), 0.0);
  EXPECT_NEAR(run.at("forces").at("X").at("total").get<double>(), -mean_over(fx, first, last), 1e-12);
  // Each component over its own window.
  const auto window_of = [&](const char* c) {
    const auto& w = run.at("forces").at(c).at("statistics").at("window");
    return std::pair{w[0].get<double>(), w[1].get<double>()};
  };
  const auto [y_first, y_last] = window_of("Y");
  const auto [z_first, z_last] = window_of("Z");
  EXPECT_NEAR(run.at("forces").at("Y").at("total").get<double>(), mean_over(fy, y_first, y_last), 1e-12);
  EXPECT_NEAR(run.at("forces").at("Z").at("total").get<double>(), -mean_over(fz, z_first, z_last), 1e-12);
  // The provenance says where each setting came from: the .out's line.
  const auto shown = nlohmann::json::parse(
      run_cli({"runs", "show", std::to_string(run.at("id").get<int>()), "--json"}, dir.path()).out);
  const auto settings = shown.at("imports")[0].at("settings");
  EXPECT_EQ(settings.at("flow").at("source"), "case files") << settings.dump();
  EXPECT_NE(settings.at("flow").at("where").get<std::string>().find("tow_u1.5_001.out:72"), std::string::npos)
      << settings.dump();
  EXPECT_EQ(settings.at("axes").at("source"), "command line");

  // The same run from a folder walk: the monitor CSV takes the .out beside it (same bytes, same settings: nothing
  // added).
  const auto again = run_cli({"import", "sweep", "--body", "hull", "--axes=-x,y,-z"}, dir.path());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out).size(), 1u);

  // --average-last N: the last N iterations, a second reading of the same file.
  const auto averaged = run_cli({"--db", "last.db", "import", "sweep/tow_u1.5_001.out", "--body", "hull",
                                 "--axes=-x,y,-z", "--average-last", "10"},
                                dir.path());
  ASSERT_EQ(averaged.exit_code, 0) << averaged.err;
  const auto tail = nlohmann::json::parse(run_cli({"--db", "last.db", "runs", "--json"}, dir.path()).out);
  EXPECT_NEAR(tail[0].at("forces").at("X").at("total").get<double>(), -mean_over(fx, 291, 300), 1e-12);
}

TEST(CliCfxRun, ACaseFileWithoutItsMonitorsOrSummaryIsRefused) {
  TempDir dir;
  std::filesystem::copy_file(kOut, dir / "tow_u1.5_001.out");
  const auto result = run_cli({"import", "tow_u1.5_001.out", "--body", "hull"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("no monitor file beside it"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("no wall force summary in it"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("cfx5mondata"), std::string::npos) << result.err;
  EXPECT_FALSE(test::database_exists(dir / "hydrocoef.db") &&
               nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out).size() > 0);
}

TEST(CliCfxRun, ANormalSpeedWithoutADirectionIsRefusedAndTakesAGivenOne) {
  TempDir dir;
  std::string ccl;
  {
    std::ifstream in(kOut);
    ccl.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto at = ccl.find("Option = Cartesian Velocity Components");
  ASSERT_NE(at, std::string::npos);
  const auto end = ccl.find("W = 0 [m s^-1]", at);
  ccl.replace(at, end + 14 - at, "Option = Normal Speed\n           Normal Speed = 1.5 [m s^-1]");
  std::ofstream(dir / "run.out") << ccl;
  write_monitors(dir / "run.csv");
  const auto refused = run_cli({"import", "run.out", "--body", "hull", "--axes=-x,y,-z"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("normal speed, 1.5 m/s"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--flow"), std::string::npos) << refused.err;
  const auto given =
      run_cli({"import", "run.out", "--body", "hull", "--axes=-x,y,-z", "--flow", "1.5,0,0"}, dir.path());
  ASSERT_EQ(given.exit_code, 0) << given.err;
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_DOUBLE_EQ(runs[0].at("u").get<double>(), 1.5);
}

const std::filesystem::path kSummaryOut = HYDROCOEF_SOURCE_DIR "/tests/data/cfx/hull_u1.5_001.out";

// A run with only its .out: the solver's wall force summary (the numbers of
// tests/data/cfx/hull_u1.5_001.out's own table), the domain group's totals by
// default, one boundary with --location.
TEST(CliCfxRun, AnOutWithoutMonitorsImportsItsWallForceSummary) {
  TempDir dir;
  std::filesystem::copy_file(kSummaryOut, dir / "hull_u1.5_001.out");
  const auto result = run_cli({"import", "hull_u1.5_001.out", "--body", "hull", "--axes=-x,y,-z"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("wall force and moment summary"), std::string::npos) << result.out;
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_DOUBLE_EQ(runs[0].at("u").get<double>(), 1.5);
  const auto& x = runs[0].at("forces").at("X");
  EXPECT_DOUBLE_EQ(x.at("pressure").get<double>(), -13.25);  // -(12.5 + 0.75): hull and rudder
  EXPECT_DOUBLE_EQ(x.at("viscous").get<double>(), -3.75);
  EXPECT_DOUBLE_EQ(x.at("total").get<double>(), -17.0);

  const auto hull = run_cli(
      {"--db", "hull.db", "import", "hull_u1.5_001.out", "--body", "hull", "--axes=-x,y,-z", "--location", "hull"},
      dir.path());
  ASSERT_EQ(hull.exit_code, 0) << hull.err;
  const auto one = nlohmann::json::parse(run_cli({"--db", "hull.db", "runs", "--json"}, dir.path()).out);
  EXPECT_DOUBLE_EQ(one[0].at("forces").at("X").at("pressure").get<double>(), -12.5);
  EXPECT_DOUBLE_EQ(one[0].at("forces").at("X").at("viscous").get<double>(), -3.5);
  const auto unknown = run_cli({"--db", "keel.db", "import", "hull_u1.5_001.out", "--location", "keel"}, dir.path());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("no location 'keel'"), std::string::npos) << unknown.err;
}

// A pressure-driven case (an opening, no inlet velocity): refused without a
// flow, completed by --flow or by a sidecar.
TEST(CliCfxRun, APressureDrivenCaseTakesTheFlowFromTheCommandLineOrASidecar) {
  TempDir dir;
  std::string text;
  {
    std::ifstream in(kSummaryOut);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string inlet = "       Boundary Type = INLET\n";
  text.replace(text.find(inlet), inlet.size(), "       Boundary Type = OPENING\n");
  const auto at = text.find("Option = Cartesian Velocity Components");
  const auto end = text.find("W = 0 [m s^-1]", at);
  text.replace(at, end + 14 - at, "Option = Opening Pressure and Direction\n           Relative Pressure = 0 [Pa]");
  std::ofstream(dir / "channel.out") << text;
  const auto refused = run_cli({"import", "channel.out", "--body", "hull", "--axes=-x,y,-z"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("channel.out:"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("driven by a pressure"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--flow"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "hydrocoef.db"));

  const auto flow =
      run_cli({"--db", "flow.db", "import", "channel.out", "--body", "hull", "--axes=-x,y,-z", "--flow", "1.2,0,0"},
              dir.path());
  ASSERT_EQ(flow.exit_code, 0) << flow.err;
  EXPECT_DOUBLE_EQ(
      nlohmann::json::parse(run_cli({"--db", "flow.db", "runs", "--json"}, dir.path()).out)[0].at("u").get<double>(),
      1.2);
  std::ofstream(dir / "channel.out.json") << R"({"flow": [0.9, 0, 0]})";
  const auto sidecar =
      run_cli({"--db", "sidecar.db", "import", "channel.out", "--body", "hull", "--axes=-x,y,-z"}, dir.path());
  ASSERT_EQ(sidecar.exit_code, 0) << sidecar.err;
  EXPECT_DOUBLE_EQ(
      nlohmann::json::parse(run_cli({"--db", "sidecar.db", "runs", "--json"}, dir.path()).out)[0].at("u").get<double>(),
      0.9);
}

}  // namespace
}  // namespace hydrocoef
