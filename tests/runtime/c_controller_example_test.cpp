// The C controller example (examples/c-controller/controller.c) compiles as
// C99 with -pedantic -Werror against the static runtime library and runs on
// the runtime file of the ASR-V example (vehicle.json): with its gains at
// zero and the pool test's constant yaw torque (0.0027 N m, 60 s) it logs
// `hydrocoef simulate`'s trajectory bit for bit at every 0.1 s (position,
// attitude, velocities); with its PD gains it turns the vehicle to a heading
// of 0.5 rad and holds it there (within 5 mrad and 1 mrad/s after 30 s, no
// overshoot beyond 0.1 rad); a file the runtime refuses and a file without a
// vehicle end it with the runtime's message and exit status 1.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_cli.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::same_bits;
using test::shell_quote;
using test::TempDir;

const std::string kExample = HYDROCOEF_SOURCE_DIR "/examples/asr-v/";

// Whitespace- or comma-separated rows of numbers, after one header line.
std::vector<std::vector<double>> rows_of(const std::string& text, char separator) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, separator))
      if (!cell.empty()) row.push_back(std::strtod(cell.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

struct Outcome {
  int status = 0;
  std::string out, err;
};

class CController : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    const auto imported = run_cli({"import", kExample + "asr-v-surge-damping.csv", "--body", "asr-v", "--sign",
                                   "opposing", "--rho", "998.2", "--nu", "1.004e-6"},
                                  dir_->path());
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    const auto exported =
        run_cli({"export", "asr-v", "--format", "runtime", "--vehicle", kExample + "vehicle.json", "-o", "asr-v.hcrt"},
                dir_->path());
    ASSERT_EQ(exported.exit_code, 0) << exported.err;
    const auto surface =
        run_cli({"surface", "build", "surge", "--body", "asr-v", "--outputs", "X", "--axes", "u"}, dir_->path());
    ASSERT_EQ(surface.exit_code, 0) << surface.err;
    const auto surfaces_only = run_cli({"export", "surge", "--format", "runtime", "-o", "surge.hcrt"}, dir_->path());
    ASSERT_EQ(surfaces_only.exit_code, 0) << surfaces_only.err;
    const std::string exe = (*dir_ / "controller").string(), log = (*dir_ / "cc.log").string();
    const std::string cc = shell_quote(HYDROCOEF_C_COMPILER) + " -std=c99 -pedantic -Wall -Wextra -Werror " +
                           HYDROCOEF_RUNTIME_CONSUMER_FLAGS + " -I" + shell_quote(HYDROCOEF_RUNTIME_INCLUDE) + " " +
                           shell_quote(HYDROCOEF_SOURCE_DIR "/examples/c-controller/controller.c") + " -o " +
                           shell_quote(exe) + " " + shell_quote(HYDROCOEF_RUNTIME_STATIC) + " -lm >" +
                           shell_quote(log) + " 2>&1";
    ASSERT_EQ(std::system(cc.c_str()), 0) << test::read_text(log);
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static Outcome controller(const std::vector<std::string>& args) {
    std::string command = shell_quote((*dir_ / "controller").string());
    for (const auto& a : args) command += " " + shell_quote(a);
    const std::string out = (*dir_ / "run.out").string(), err = (*dir_ / "run.err").string();
    const int status = std::system((command + " >" + shell_quote(out) + " 2>" + shell_quote(err)).c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::read_text(out), test::read_text(err)};
  }
  static TempDir* dir_;
};
TempDir* CController::dir_ = nullptr;

TEST_F(CController, WithoutGainsItIsSimulateOfThePoolTestBitForBit) {
  const auto simulated = run_cli({"simulate", "--vehicle", kExample + "vehicle.json", "--scenario",
                                  kExample + "scenario-yaw-0.0027.json", "--out", "pool.csv"},
                                 dir_->path());
  ASSERT_EQ(simulated.exit_code, 0) << simulated.err;
  const auto expected = rows_of(test::read_text((*dir_ / "pool.csv").string()), ',');
  const Outcome run = controller({(*dir_ / "asr-v.hcrt").string(), "--seconds", "60", "--torque", "0.0027"});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto logged = rows_of(run.out, ' ');
  ASSERT_EQ(logged.size(), 601u);
  ASSERT_EQ(expected.size(), 601u);
  // The log's columns (t, x_n y_n z_n, q, u..r) and the CSV's (t, x_n y_n z_n, phi theta psi, q, u..r).
  std::size_t mismatches = 0, attitude_ulps = 0;
  for (std::size_t k = 0; k < logged.size(); ++k) {
    ASSERT_EQ(logged[k].size(), 16u);
    mismatches += !same_bits(logged[k][0], expected[k][0]);
    for (std::size_t i = 0; i < 3; ++i) mismatches += !same_bits(logged[k][1 + i], expected[k][1 + i]);
    for (std::size_t i = 0; i < 6; ++i) mismatches += !same_bits(logged[k][8 + i], expected[k][11 + i]);
    // The log states the state's attitude (normalised by the step); simulate's sample normalises it once more.
    for (std::size_t i = 0; i < 4; ++i) attitude_ulps += std::abs(logged[k][4 + i] - expected[k][7 + i]) > 2.3e-16;
    EXPECT_EQ(logged[k][15], 0.0027);
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(attitude_ulps, 0u);
  EXPECT_GT(logged.back()[13], 0.01);  // the yaw rate near its root: the run went somewhere
}

TEST_F(CController, ItsGainsHoldTheHeadingSetPoint) {
  const Outcome run = controller(
      {(*dir_ / "asr-v.hcrt").string(), "--seconds", "30", "--heading", "0.5", "--kp", "0.02", "--kd", "0.05"});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto logged = rows_of(run.out, ' ');
  ASSERT_EQ(logged.size(), 301u);
  double largest = 0.0;
  for (const auto& row : logged) largest = std::max(largest, row[14]);
  EXPECT_LT(largest, 0.6);  // no overshoot beyond 0.1 rad
  const auto& last = logged.back();
  EXPECT_NEAR(last[14], 0.5, 5e-3);
  EXPECT_LT(std::abs(last[13]), 1e-3);
  EXPECT_GT(logged[50][14], 0.1);  // turning by 5 s
}

TEST_F(CController, TheRuntimesErrorsEndItWithTheirMessage) {
  const Outcome missing = controller({(*dir_ / "no-such.hcrt").string()});
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("no-such.hcrt"), std::string::npos) << missing.err;
  EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
  const Outcome surfaces = controller({(*dir_ / "surge.hcrt").string()});
  EXPECT_EQ(surfaces.status, 1);
  EXPECT_NE(surfaces.err.find("holds no vehicle"), std::string::npos) << surfaces.err;
  const Outcome bad = controller({(*dir_ / "asr-v.hcrt").string(), "--kp", "fast"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--kp 'fast' is not a finite number"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace hydrocoef
