// hydrocoef derivatives pmm through the command line: pure sway and pure yaw
// force histories made from the Mariner's published derivatives (Chislett
// and Strom-Tejsen 1965, as printed in the MSS toolbox's mariner.m; see
// tests/pmm/pmm_derivatives_test.cpp) imported with `hydrocoef pmm` give the
// printed prime values back with omega' = omega L / U; the real OpenFOAM
// sphere run of examples/openfoam-sphere/pmm, read as a sway run, gives
// Y_vdot = -M_A[sway][sway] of `hydrocoef added-mass` on the same database;
// bad input is one line, exit code 2, the database unchanged.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using nlohmann::json;
using test::run_cli;
using test::TempDir;
namespace fs = std::filesystem;

constexpr double kPi = std::numbers::pi;
constexpr double kLength = 160.93, kSpeed = 7.7175, kDensity = 1025.0;
constexpr double kOmegaPrime = 1.5, kOmega = kOmegaPrime * kSpeed / kLength;

// Prime values times 1e5 (mariner.m): Y velocity, Y acceleration, N velocity, N acceleration.
constexpr std::array<double, 4> kSwayPrime{-1160.0, -748.0, -264.0, 4.646};
constexpr std::array<double, 4> kYawPrime{-499.0, -9.354, -166.0, -43.8};
constexpr const char* kSwayNames[] = {"Y_v", "Y_vdot", "N_v", "N_vdot"};
constexpr const char* kYawNames[] = {"Y_r", "Y_rdot", "N_r", "N_rdot"};

std::string number(double value) {
  std::ostringstream text;
  text << std::setprecision(17) << value;
  return text.str();
}

/// SI from prime: Y_v' (1/2 rho U L^2), Y_vdot' (1/2 rho L^3), N_v' (1/2 rho U L^3),
/// N_vdot' (1/2 rho L^4); yaw: Y_r' (1/2 rho U L^3), Y_rdot' (1/2 rho L^4), N_r' (1/2 rho U L^4),
/// N_rdot' (1/2 rho L^5). Written out here, apart from the library's normalisation.
std::array<double, 4> dimensional(bool sway) {
  const auto& p = sway ? kSwayPrime : kYawPrime;
  const double h = 0.5 * kDensity, L = kLength, U = kSpeed;
  const double extra = sway ? 1.0 : L;
  return {p[0] * 1e-5 * h * U * L * L * extra, p[1] * 1e-5 * h * L * L * L * extra,
          p[2] * 1e-5 * h * U * L * L * L * extra, p[3] * 1e-5 * h * L * L * L * L * extra};
}

/// A CSV history of Y and N of a pure sway (or yaw) run y = A sin(omega t) with 12 periods.
fs::path write_run(const fs::path& dir, const std::string& name, bool sway, double amplitude) {
  const std::array<double, 4> d = dimensional(sway);
  const fs::path path = dir / name;
  std::ofstream out(path);
  out << std::setprecision(17) << "Time [s],Y [N],N [N m]\n";
  const double dt = 2.0 * kPi / kOmega / 200.0;
  for (int n = 0; n <= 2400; ++n) {
    const double t = dt * n;
    const double x1 = amplitude * kOmega * std::cos(kOmega * t);
    const double x2 = -amplitude * kOmega * kOmega * std::sin(kOmega * t);
    out << t << ',' << 30.0 + d[0] * x1 + d[1] * x2 << ',' << -12.0 + d[2] * x1 + d[3] * x2 << '\n';
  }
  return path;
}

/// `hydrocoef pmm` of a run at forward speed u with the Mariner's density (or, at_rest, at u = 0 without one).
void import_run(const TempDir& dir, const fs::path& csv, bool sway, double amplitude, bool at_rest = false) {
  std::vector<std::string> args = {"pmm",         csv.string(),
                                   "--body",      "mariner",
                                   "--motion",    sway ? "sway" : "yaw",
                                   "--amplitude", number(amplitude),
                                   "--period",    number(2.0 * kPi / kOmega)};
  if (!at_rest)
    for (const std::string& a : {std::string("--set"), "u=" + number(kSpeed), std::string("--rho"), number(kDensity)})
      args.push_back(a);
  const auto result = run_cli(args, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
}

double relative_error(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

TEST(PmmDerivativesCli, MarinerPureSwayAndPureYawGiveThePrintedPrimeDerivatives) {
  TempDir dir;
  import_run(dir, write_run(dir.path(), "sway-a.csv", true, 0.05 * kLength), true, 0.05 * kLength);
  import_run(dir, write_run(dir.path(), "sway-b.csv", true, 0.1 * kLength), true, 0.1 * kLength);
  import_run(dir, write_run(dir.path(), "yaw.csv", false, 0.1), false, 0.1);
  ASSERT_EQ(run_cli({"body", "set", "mariner", "--length", number(kLength)}, dir.path()).exit_code, 0);
  const auto result = run_cli({"derivatives", "pmm", "mariner", "--prime", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const json out = json::parse(result.out);
  EXPECT_EQ(out["length_from"], "body reference");
  EXPECT_EQ(out["density_from"], "the runs");
  ASSERT_EQ(out["sets"].size(), 2u);
  for (const bool sway : {true, false}) {
    const json& set = out["sets"][sway ? 0 : 1];
    EXPECT_EQ(set["motion"], sway ? "pure sway" : "pure yaw");
    EXPECT_EQ(set["runs"], sway ? 2 : 1);
    EXPECT_NEAR(set["omega_prime"].get<double>(), kOmegaPrime, 1e-12);
    EXPECT_NEAR(set["speed_m_s"].get<double>(), kSpeed, 0.0);
    const auto& printed = sway ? kSwayPrime : kYawPrime;
    const std::array<double, 4> si = dimensional(sway);
    for (std::size_t k = 0; k < 4; ++k) {
      const json& d = set["derivatives"][k];
      EXPECT_EQ(d["name"], (sway ? kSwayNames : kYawNames)[k]);
      EXPECT_LE(relative_error(d["value"].get<double>(), si[k]), 1e-9) << d;
      EXPECT_LE(relative_error(d["prime"].get<double>(), printed[k] * 1e-5), 1e-9) << d;
      EXPECT_NE(d["normalisation"].get<std::string>().find("prime (SNAME 1950)"), std::string::npos) << d;
    }
  }
  // The text: the table with the prime column and omega'.
  const auto text = run_cli({"derivatives", "pmm", "mariner"}, dir.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("pure sway, U = 7.7175 m/s"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("omega' = omega L / U = 1.5"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("derivative         value   std error  unit             prime   std error"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("  Y_vdot      -1.59774e+07"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("kg            -0.00748"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("prime (SNAME 1950): N_rdot' = N_rdot / (1/2 rho L^5)"), std::string::npos) << text.out;
}

TEST(PmmDerivativesCli, TheOpenFoamSphereSwayRunGivesMinusTheAddedMass) {
  // examples/openfoam-sphere/pmm: the sphere moved along the case's x axis,
  // read here with body y = case x (--axes y,x,-z) as a sway run. At zero
  // speed Y_vdot = -M_A[sway][sway]: about -0.514 rho V (potential flow 0.5
  // plus the Stokes layer).
  TempDir dir;
  const double rho = 998.2, volume = 4.0 / 3.0 * kPi * 0.15 * 0.15 * 0.15;
  const std::string root = HYDROCOEF_SOURCE_DIR "/examples/openfoam-sphere/pmm/";
  const auto imported = run_cli({"pmm", root + "surge-A0.015-T2", root + "surge-A0.045-T2", "--body", "sphere",
                                 "--axes", "y,x,-z", "--rho", "998.2", "--nu", "1.004e-6", "--size", "0.3"},
                                dir.path());
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  const auto matrix = run_cli({"added-mass", "sphere", "--json"}, dir.path());
  ASSERT_EQ(matrix.exit_code, 0) << matrix.err;
  const json a = json::parse(matrix.out);
  const auto result = run_cli({"derivatives", "pmm", "sphere", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const json out = json::parse(result.out);
  ASSERT_EQ(out["sets"].size(), 1u);
  const json& set = out["sets"][0];
  EXPECT_EQ(set["motion"], "pure sway");
  EXPECT_EQ(set["runs"], 2);
  EXPECT_EQ(set["speed_m_s"].get<double>(), 0.0);
  EXPECT_TRUE(set["omega_prime"].is_null());  // U = 0
  const json& y_vdot = set["derivatives"][1];
  ASSERT_EQ(y_vdot["name"], "Y_vdot");
  EXPECT_EQ(y_vdot["source"], "-M_A[sway][sway]");
  EXPECT_EQ(y_vdot["value"].get<double>(), -a["added_mass_b"][1][1].get<double>());
  EXPECT_EQ(y_vdot["std_error"].get<double>(), a["added_mass_se"][1][1].get<double>());
  EXPECT_NEAR(y_vdot["value"].get<double>() / (rho * volume), -0.514, 0.01);
  // Y_v = -D[sway][sway]: the boundary layer dissipates, so Y_v < 0.
  EXPECT_EQ(set["derivatives"][0]["value"].get<double>(), -a["damping_b"][1][1].get<double>());
  EXPECT_LT(set["derivatives"][0]["value"].get<double>(), 0.0);
  // Each run's own Y_vdot is the run's stored in-line added mass, negated.
  const json runs = json::parse(run_cli({"pmm-runs", "--json"}, dir.path()).out);
  ASSERT_EQ(out["runs"].size(), 2u);
  for (std::size_t n = 0; n < 2; ++n)
    EXPECT_EQ(out["runs"][n]["derivatives"][1]["value"].get<double>(), -runs[n]["added_mass"].get<double>());
}

TEST(PmmDerivativesCli, BadInputIsOneLineWithExitCodeTwoAndTheDatabaseUnchanged) {
  TempDir dir;
  // A sway run at zero speed without a density, and a surge run (the sphere run as the case states it).
  import_run(dir, write_run(dir.path(), "sway.csv", true, 5.0), true, 5.0, true);
  const std::string root = HYDROCOEF_SOURCE_DIR "/examples/openfoam-sphere/pmm/";
  ASSERT_EQ(run_cli({"pmm", root + "surge-A0.015-T2", "--body", "sphere", "--axes=-x,y,-z"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli({"pmm", root + "surge-A0.015-T2", "--body", "mariner", "--axes=-x,y,-z"}, dir.path()).exit_code, 0);
  const json stored = json::parse(run_cli({"pmm-runs", "--json"}, dir.path()).out);
  ASSERT_EQ(stored.size(), 3u);
  std::string surge_id;
  for (const json& run : stored)
    if (run["body"] == "mariner" && run["dof"] == "surge") surge_id = std::to_string(run["id"].get<std::int64_t>());
  ASSERT_FALSE(surge_id.empty()) << stored;
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  const auto refused = [&](const std::vector<std::string>& args, const std::string& expected) {
    const auto result = run_cli(args, dir.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
    EXPECT_EQ(result.err.find("internal error"), std::string::npos) << result.err;
    EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
  };
  // A run that is not a sway or yaw oscillation.
  refused({"derivatives", "pmm", "mariner", "--run", surge_id},
          "pmm run " + surge_id + " (" + root + "surge-A0.015-T2");
  refused({"derivatives", "pmm", "mariner", "--run", surge_id}, "moves surge; expected a sway (pure sway) or yaw");
  // A body with no such runs, and a body with none at all.
  refused({"derivatives", "pmm", "sphere"},
          "body 'sphere' has no sway or yaw forced-oscillation runs (it has 1 surge)");
  refused({"derivatives", "pmm", "nothing"}, "body 'nothing' has no stored forced-oscillation runs");
  refused({"derivatives", "pmm", "mariner", "--run", "999"}, "pmm run 999: not a stored forced-oscillation run");
  // omega' and the prime form without the forward speed (the runs' u is 0), length or density.
  refused({"derivatives", "pmm", "mariner", "--prime", "--length", "160", "--density", "1000"},
          "have no forward speed (U > 0) for omega' = omega L / U");
  refused({"derivatives", "pmm", "mariner", "--prime", "--speed", "7"}, "have no reference length L; give --length");
  refused({"derivatives", "pmm", "mariner", "--prime", "--speed", "7", "--length", "160"},
          "have no density rho; give --density");
  refused({"derivatives", "pmm", "mariner", "--length", "-1"}, "--length -1: expected a finite number > 0 (m)");
  refused({"derivatives", "pmm", "mariner", "--density", "0"}, "--density 0: expected a finite number > 0");
  // Without --prime, what is known is given and the rest named in a note.
  const auto ok = run_cli({"derivatives", "pmm", "mariner", "--speed", "7"}, dir.path());
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("note: 1 run of another DOF left out"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("note: no reference length: no omega' or prime form"), std::string::npos) << ok.out;
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
}

TEST(PmmDerivativesCli, RunsOfDifferentDensitiesNeedTheDensityGiven) {
  TempDir dir;
  const double period = 2.0 * kPi / kOmega;
  // Two runs (of two amplitudes: a file of the same contents would replace the first) at two densities.
  for (const auto& [rho, amplitude] : {std::pair{"1000", 5.0}, std::pair{"1025", 6.0}}) {
    const fs::path csv = write_run(dir.path(), std::string("sway-") + rho + ".csv", true, amplitude);
    ASSERT_EQ(run_cli({"pmm", csv.string(), "--body", "twin", "--motion", "sway", "--amplitude", number(amplitude),
                       "--period", number(period), "--set", "u=2", "--rho", rho},
                      dir.path())
                  .exit_code,
              0);
  }
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  const auto refused = run_cli({"derivatives", "pmm", "twin", "--length", "10"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("body 'twin': the sway and yaw runs state densities 1000 and 1025 kg/m^3; expected one "
                             "(give --density)"),
            std::string::npos)
      << refused.err;
  const auto given =
      run_cli({"derivatives", "pmm", "twin", "--length", "10", "--density", "1010", "--json"}, dir.path());
  ASSERT_EQ(given.exit_code, 0) << given.err;
  const json out = json::parse(given.out);
  EXPECT_EQ(out["density_from"], "--density");
  // Y_vdot' = Y_vdot / (1/2 rho L^3) with the density given.
  const json& y_vdot = out["sets"][0]["derivatives"][1];
  EXPECT_NEAR(y_vdot["prime"].get<double>(), y_vdot["value"].get<double>() / (0.5 * 1010.0 * 1000.0),
              1e-12 * std::abs(y_vdot["prime"].get<double>()));
  EXPECT_NEAR(out["sets"][0]["omega_prime"].get<double>(), kOmega * 10.0 / 2.0, 1e-12);
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
}

TEST(PmmDerivativesCli, HelpNamesTheOptions) {
  TempDir dir;
  const auto help = run_cli({"derivatives", "pmm", "--help"}, dir.path());
  ASSERT_EQ(help.exit_code, 0) << help.err;
  for (const char* option : {"--run", "--speed", "--length", "--density", "--prime", "--json"})
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
  EXPECT_NE(help.out.find("Y_vdot = -M_A[sway][sway]"), std::string::npos) << help.out;
}

}  // namespace
}  // namespace hydrocoef
