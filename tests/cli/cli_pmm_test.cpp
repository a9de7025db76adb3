// hydrocoef pmm and added-mass through the command line, on synthetic force
// histories with a known answer: a 6x6 added-mass matrix and damping matrix
// recovered from one run per DOF (CSV histories with a start-up transient),
// an oscillating stream with its Froude-Krylov force removed, quadratic
// damping from three amplitudes, the motion read from an OpenFOAM case's
// dynamicMeshDict (and refused when the options contradict it), bad input
// refused on one line with exit code 2 and the database unchanged, hostile
// body names printed as data, and a vehicle whose added mass comes from the
// database simulating.
#include <gtest/gtest.h>

#include <sqlite3.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <tuple>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "tests/support/hostile_names.hpp"
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
constexpr double kPeriod = 1.6, kOmega = 2.0 * kPi / kPeriod;
constexpr const char* kDofs[] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};

/// A symmetric positive definite M_A and a damping matrix, entry (i, j).
double true_added_mass(std::size_t i, std::size_t j) {
  if (i == j) return 5.0 + 2.0 * static_cast<double>(i);
  return 0.3 * std::cos(static_cast<double>(i + j));  // symmetric, diagonally dominant
}
double true_damping(std::size_t i, std::size_t j) {
  return i == j ? 1.5 + 0.25 * static_cast<double>(i)
                : 0.05 * static_cast<double>(i + 1) - 0.02 * static_cast<double>(j);
}

/// A CSV history (time, body-axis X..N) of DOF j moved as A sin(omega t),
/// the force F_i = mean_i - M[i][j] x'' - D[i][j] x' - c x'|x'| (c on the
/// diagonal) plus a start-up transient that dies out within a few periods.
fs::path write_history(const fs::path& dir, const std::string& name, std::size_t j, double amplitude,
                       double quadratic = 0.0, bool stream = false, double froude_krylov = 0.0,
                       std::size_t components = 6) {
  const fs::path path = dir / name;
  std::ofstream out(path);
  // All six components, or (components == 1) the in-line X alone.
  out << std::setprecision(17)
      << (components == 1 ? "Time [s],X [N]\n" : "Time [s],X [N],Y [N],Z [N],K [N m],M [N m],N [N m]\n");
  for (int k = 0; k <= 3200; ++k) {
    const double t = 0.02 * k;
    const double x_dot = amplitude * kOmega * std::cos(kOmega * t);
    const double x_ddot = -amplitude * kOmega * kOmega * std::sin(kOmega * t);
    const double transient = 2.0 * std::exp(-t / 1.5) + std::exp(-t / 2.0) * std::sin(5.3 * t);
    out << t;
    for (std::size_t i = 0; i < components; ++i) {
      double f = 0.1 * static_cast<double>(i) - true_added_mass(i, j) * x_ddot - true_damping(i, j) * x_dot;
      if (i == j) f -= quadratic * x_dot * std::abs(x_dot);
      if (stream)
        f = (i == j ? froude_krylov : 0.0) * x_ddot + true_added_mass(i, j) * x_ddot +
            true_damping(i, j) * x_dot;  // a held body in a stream x_s = A sin(omega t)
      out << ',' << f + transient;
    }
    out << '\n';
  }
  return path;
}

std::vector<std::string> motion_options(std::size_t j, double amplitude) {
  std::ostringstream a, p;
  a << std::setprecision(17) << amplitude;
  p << std::setprecision(17) << kPeriod;
  return {"--motion", kDofs[j], "--amplitude", a.str(), "--period", p.str()};
}

int pmm(const TempDir& dir, const fs::path& history, std::size_t j, double amplitude, const std::string& body,
        std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"pmm", history.string(), "--body", body, "--json"};
  for (const auto& o : motion_options(j, amplitude)) args.push_back(o);
  for (const auto& o : extra) args.push_back(o);
  const auto result = run_cli(args, dir.path());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return result.exit_code;
}

TEST(Pmm, SixRunsGiveTheWholeAddedMassAndDampingMatrices) {
  TempDir dir;
  for (std::size_t j = 0; j < 6; ++j) {
    const double amplitude = j < 3 ? 0.05 : 0.2;
    ASSERT_EQ(
        pmm(dir, write_history(dir.path(), "run" + std::to_string(j) + ".csv", j, amplitude), j, amplitude, "hull"), 0);
  }
  const auto result = run_cli({"added-mass", "hull", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto assembly = json::parse(result.out);
  EXPECT_EQ(assembly["records"], 6);
  EXPECT_TRUE(assembly["missing"].empty());
  EXPECT_TRUE(assembly["positive_definite"].get<bool>());
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j) {
      const double m = assembly["added_mass_b"][i][j].get<double>();
      const double d = assembly["damping_b"][i][j].get<double>();
      // To 1e-6 of the column's in-line coefficient: the start-up transient,
      // the same in every component, leaves a few 1e-7 N s/m after MSER.
      EXPECT_NEAR(m, true_added_mass(i, j), 1e-6 * true_added_mass(j, j)) << i << " " << j;
      EXPECT_NEAR(d, true_damping(i, j), 1e-6 * true_damping(j, j)) << i << " " << j;
    }
  // The readable form names the matrix and its check.
  const auto text = run_cli({"added-mass", "hull"}, dir.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("positive definite"), std::string::npos) << text.out;
}

TEST(Pmm, OneRunLeavesTheOtherEntriesMissingUntilStated) {
  TempDir dir;
  ASSERT_EQ(pmm(dir, write_history(dir.path(), "surge.csv", 0, 0.05), 0, 0.05, "ball"), 0);
  auto result = run_cli({"added-mass", "ball", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  auto assembly = json::parse(result.out);
  // Column surge is measured; M_A[sway][sway] and the rest are missing.
  EXPECT_FALSE(assembly["missing"].empty());
  bool names_sway = false;
  for (const auto& m : assembly["missing"])
    names_sway = names_sway || m.get<std::string>().find("M_A[sway][sway]") == 0;
  EXPECT_TRUE(names_sway) << result.out;
  // A symmetric body: sway and heave as surge, no rotational added mass.
  // The synthetic surge run couples to the rotations stated zero, so the
  // whole matrix is indefinite: refused unless --allow-indefinite.
  const std::vector<std::string> stated = {"added-mass", "ball",        "--same", "sway=surge",
                                           "--same",     "heave=surge", "--zero", "roll,pitch,yaw"};
  result = run_cli(stated, dir.path());
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_NE(result.err.find("not positive definite"), std::string::npos) << result.err;
  auto allowed = stated;
  for (const char* a : {"--allow-indefinite", "--json"}) allowed.push_back(a);
  result = run_cli(allowed, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  assembly = json::parse(result.out);
  EXPECT_FALSE(assembly["positive_definite"].get<bool>());
  EXPECT_TRUE(assembly["missing"].empty()) << result.out;
  EXPECT_NEAR(assembly["added_mass_b"][1][1].get<double>(), true_added_mass(0, 0), 1e-6 * true_added_mass(0, 0));
  EXPECT_NEAR(assembly["added_mass_b"][2][2].get<double>(), true_added_mass(0, 0), 1e-6 * true_added_mass(0, 0));
  EXPECT_EQ(assembly["added_mass_b"][3][3].get<double>(), 0.0);

  // A vehicle whose added mass comes from the database simulates, and one
  // that leaves entries missing is refused naming them.
  const auto write_vehicle =
      [&](const std::string& added_mass) {
        std::ofstream(dir / "vehicle.json")
            << R"({"mass": 14.0, "inertia": [0.13, 0.13, 0.13], "center_of_gravity": [0, 0, 0.02],
      "neutrally_buoyant": true, "added_mass": )"
            << added_mass << R"(,
      "damping": {"X": {"law": {"u": -2.0, "u|u|": -10.0}, "sign": "on-body"}, "N": {"law": {"r": -0.05}, "sign": "on-body"}}})";
      };
  std::ofstream(dir / "scenario.json") << R"({"duration": 2.0, "integrator": {"method": "rk4", "step": 0.01},
      "segments": [{"start": 0.0, "tau": {"X": 5.0}}]})";
  write_vehicle(
      R"({"from_database": "ball", "same": {"sway": "surge", "heave": "surge"}, "zero": ["roll", "pitch", "yaw"]})");
  const auto simulated =
      run_cli({"simulate", "--vehicle", "vehicle.json", "--scenario", "scenario.json", "--json"}, dir.path());
  ASSERT_EQ(simulated.exit_code, 0) << simulated.err;
  write_vehicle(R"({"from_database": "ball"})");
  const auto refused = run_cli({"simulate", "--vehicle", "vehicle.json", "--scenario", "scenario.json"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("M_A[sway][sway]"), std::string::npos) << refused.err;
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
}

TEST(Pmm, GazeboExportTakesTheAssembledAddedMass) {
  TempDir dir;
  const std::string surge = HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-surge-damping.csv";
  ASSERT_EQ(run_cli({"import", surge, "--body", "asr-v", "--sign", "opposing", "--quiet"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|"}, dir.path()).exit_code, 0);
  ASSERT_EQ(pmm(dir, write_history(dir.path(), "surge.csv", 0, 0.05, 0.0, false, 0.0, 1), 0, 0.05, "asr-v"), 0);
  const std::vector<std::string> args = {
      "export-gazebo", "asr-v", "--flavor", "uuv", "-o", "asr-v.xml", "--allow-missing", "--added-mass-from-database",
      "asr-v"};
  // Entries no run gives are refused, named.
  const auto refused = run_cli(args, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("M_A[sway][sway]"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "asr-v.xml"));
  auto stated = args;
  for (const char* a : {"--same", "sway=surge", "--same", "heave=surge", "--zero", "roll,pitch,yaw", "--json"})
    stated.push_back(a);
  const auto result = run_cli(stated, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto exported = json::parse(result.out);
  const auto& m = exported.at("added_mass_b");
  EXPECT_NEAR(m[0].get<double>(), true_added_mass(0, 0), 1e-6 * true_added_mass(0, 0));  // row-major (0, 0)
  EXPECT_NEAR(m[7].get<double>(), true_added_mass(0, 0), 1e-6 * true_added_mass(0, 0));  // (1, 1)
  EXPECT_NE(exported.at("added_mass_source").get<std::string>().find("forced-oscillation"), std::string::npos);
}

TEST(Pmm, QuadraticDampingFromThreeAmplitudes) {
  TempDir dir;
  const double b2 = 40.0;
  for (const double amplitude : {0.02, 0.05, 0.1})
    ASSERT_EQ(pmm(dir, write_history(dir.path(), "a" + std::to_string(amplitude) + ".csv", 0, amplitude, b2), 0,
                  amplitude, "hull"),
              0);
  const auto result = run_cli({"added-mass", "hull", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto assembly = json::parse(result.out);
  ASSERT_EQ(assembly["quadratic_damping"].size(), 1u) << result.out;
  const auto& q = assembly["quadratic_damping"][0];
  EXPECT_EQ(q["dof"], "surge");
  EXPECT_NEAR(q["quadratic"].get<double>(), b2, 1e-6 * b2);
  EXPECT_NEAR(q["linear"].get<double>(), true_damping(0, 0), 1e-6 * true_damping(0, 0));
  // The added mass does not depend on the amplitude.
  EXPECT_NEAR(assembly["added_mass_b"][0][0].get<double>(), true_added_mass(0, 0), 1e-6 * true_added_mass(0, 0));
}

TEST(Pmm, AnOscillatingStreamHasItsFroudeKrylovForceRemoved) {
  TempDir dir;
  const double rho = 1000.0, volume = 0.004;  // rho V = 4 kg
  const auto history = write_history(dir.path(), "stream.csv", 0, 0.05, 0.0, true, rho * volume);
  const auto result =
      run_cli({"pmm", history.string(), "--body", "hull", "--motion", "surge", "--amplitude", "0.05", "--period",
               "1.6000000000000001", "--stream", "--rho", "1000", "--volume", "0.004", "--json", "--no-store"},
              dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto run = json::parse(result.out)["runs"][0];
  EXPECT_EQ(run["medium"], "oscillating stream");
  const auto& x = run["components"][0];
  EXPECT_NEAR(x["added_mass"].get<double>(), true_added_mass(0, 0), 1e-6 * true_added_mass(0, 0));
  EXPECT_NEAR(x["damping"].get<double>(), true_damping(0, 0), 1e-6 * true_damping(0, 0));
  EXPECT_NEAR(x["added_mass_coefficient"].get<double>(), true_added_mass(0, 0) / (rho * volume), 1e-6);
  // Without the volume the Froude-Krylov force cannot be removed.
  const auto refused = run_cli({"pmm", history.string(), "--motion", "surge", "--amplitude", "0.05", "--period", "1.6",
                                "--stream", "--rho", "1000"},
                               dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("displaced volume"), std::string::npos) << refused.err;
}

/// A case folder whose dynamicMeshDict moves the mesh and whose forces
/// function object wrote force.dat and moment.dat (OpenFOAM v1912 layout).
fs::path write_openfoam_case(const fs::path& root, double amplitude_x, double omega) {
  const fs::path dir = root / "osc";
  fs::create_directories(dir / "constant");
  fs::create_directories(dir / "system");
  fs::create_directories(dir / "postProcessing/forces/0");
  std::ofstream(dir / "constant/dynamicMeshDict")
      << R"(FoamFile { version 2.0; format ascii; class dictionary; object dynamicMeshDict; }
dynamicFvMesh   dynamicMotionSolverFvMesh;
motionSolverLibs ("libfvMotionSolvers.so");
motionSolver    solidBody;
solidBodyCoeffs
{
    solidBodyMotionFunction oscillatingLinearMotion;
    oscillatingLinearMotionCoeffs
    {
        amplitude       ()"
      << std::setprecision(17) << amplitude_x << R"( 0 0);
        omega           )"
      << omega << R"(;
    }
}
)";
  std::ofstream(dir / "system/controlDict")
      << R"(FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application pimpleFoam;
functions { forces { type forces; libs ("libforces.so"); patches (sphere); rho rhoInf; rhoInf 998.2; CofR (0 0 0); } }
)";
  std::ofstream force(dir / "postProcessing/forces/0/force.dat");
  std::ofstream moment(dir / "postProcessing/forces/0/moment.dat");
  force << "# Force\n# CofR                : (0.000000e+00 0.000000e+00 0.000000e+00)\n#\n"
        << "# Time                    total_x      total_y      total_z      pressure_x   pressure_y   pressure_z   "
           "viscous_x    viscous_y    viscous_z\n";
  moment << "# Moment\n# CofR                : (0.000000e+00 0.000000e+00 0.000000e+00)\n#\n"
         << "# Time                    total_x      total_y      total_z      pressure_x   pressure_y   pressure_z   "
            "viscous_x    viscous_y    viscous_z\n";
  force << std::setprecision(17);
  moment << std::setprecision(17);
  for (int k = 1; k <= 2000; ++k) {
    const double t = 0.005 * k;
    // The potential-flow sphere of added mass 7.0 kg: F = -7 x''.
    const double fx = 7.0 * amplitude_x * omega * omega * std::sin(omega * t);
    force << t << "\t(" << fx << " 0 0)\t(" << fx << " 0 0)\t(0 0 0)\n";
    moment << t << "\t(0 0 0)\t(0 0 0)\t(0 0 0)\n";
  }
  return dir;
}

TEST(Pmm, TheMotionIsReadFromTheOpenFoamCaseAndCheckedAgainstTheOptions) {
  TempDir dir;
  const fs::path case_dir = write_openfoam_case(dir.path(), 0.02, kPi);
  // Body axes with x forward: the case's +x is the body's -x (a phase of pi),
  // which leaves the added mass as it is.
  auto result = run_cli({"pmm", case_dir.string(), "--body", "ball", "--axes", "-x,-y,z", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  auto run = json::parse(result.out)["runs"][0];
  EXPECT_EQ(run["motion"]["dof"], "surge");
  EXPECT_NEAR(run["motion"]["amplitude"].get<double>(), 0.02, 1e-15);
  EXPECT_NEAR(run["motion"]["period_s"].get<double>(), 2.0, 1e-12);
  EXPECT_NE(run["motion"]["source"].get<std::string>().find("dynamicMeshDict"), std::string::npos);
  EXPECT_NEAR(run["components"][0]["added_mass"].get<double>(), 7.0, 1e-6);
  // Options that contradict the case are refused, naming both.
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  result =
      run_cli({"pmm", case_dir.string(), "--body", "ball", "--motion", "surge", "--amplitude", "0.03", "--period", "2"},
              dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("dynamicMeshDict"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("0.03"), std::string::npos) << result.err;
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
  // The same analysis again replaces the stored one.
  result = run_cli({"pmm", case_dir.string(), "--body", "ball", "--axes", "-x,-y,z", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(json::parse(result.out)["runs"][0]["stored"]["replaced"].get<bool>());
  const auto assembled = json::parse(run_cli({"added-mass", "ball", "--json"}, dir.path()).out);
  EXPECT_EQ(assembled["records"], 1);
}

TEST(Pmm, AFrequencyTooHighForTheSamplingIsOneLine) {
  // omega 1e20 in dynamicMeshDict, or --period 1e-20 / 1e-18 / 1e-9: a
  // SIGSEGV or "internal error" before; now one line naming the input, exit
  // 2, the database unchanged.
  TempDir dir;
  ASSERT_EQ(pmm(dir, write_history(dir.path(), "surge.csv", 0, 0.05), 0, 0.05, "hull"), 0);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  const fs::path case_dir = write_openfoam_case(dir.path(), 0.02, 1e20);
  const auto refused = [&](const std::vector<std::string>& args, const std::string& input) {
    const auto result = run_cli(args, dir.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(input), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("shorter than 4 sampling steps"), std::string::npos) << result.err;
    EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
  };
  refused({"pmm", case_dir.string(), "--body", "ball"}, "osc");
  for (const char* period : {"1e-20", "1e-18", "1e-9"})
    refused({"pmm", "surge.csv", "--body", "hull", "--motion", "surge", "--amplitude", "0.05", "--period", period},
            "surge.csv");
}

TEST(Pmm, TheOpenFoamSphereRunGivesHalfTheDisplacedMass) {
  // examples/openfoam-sphere/pmm: OpenFOAM v1912, the whole mesh of a
  // R = 0.15 m sphere moved as x = A sin(pi t) (PROVENANCE.md there). In
  // potential flow M_A = rho V / 2; the Stokes boundary layer adds 9 delta /
  // (2 R) = 2.4 % at this frequency (delta = sqrt(2 nu / omega) = 0.8 mm).
  TempDir dir;
  const double rho = 998.2, radius = 0.15, volume = 4.0 / 3.0 * kPi * radius * radius * radius;
  std::ostringstream v;
  v << std::setprecision(17) << volume;
  const std::string root = HYDROCOEF_SOURCE_DIR "/examples/openfoam-sphere/pmm/";
  const auto result =
      run_cli({"pmm", root + "surge-A0.015-T2", root + "surge-A0.045-T2", "--body", "sphere", "--axes=-x,y,-z", "--rho",
               "998.2", "--nu", "1.004e-6", "--volume", v.str(), "--size", "0.3", "--json"},
              dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto runs = json::parse(result.out)["runs"];
  ASSERT_EQ(runs.size(), 2u);
  for (const auto& run : runs) {
    EXPECT_EQ(run["motion"]["dof"], "surge");
    EXPECT_NEAR(run["motion"]["period_s"].get<double>(), 2.0, 1e-12);
    EXPECT_GE(run["periods"].get<int>(), 3);
    const auto& x = run["components"][0];
    ASSERT_EQ(x["component"], "X");
    const double coefficient = x["added_mass_coefficient"].get<double>();
    EXPECT_NEAR(coefficient, 0.5, 0.05) << run["path"];  // within 10 %
    EXPECT_NEAR(x["added_mass"].get<double>(), coefficient * rho * volume, 1e-9);
    EXPECT_GE(x["explained"].get<double>(), 0.99) << run["path"];
    EXPECT_GT(x["damping"].get<double>(), 0.0);  // the boundary layer dissipates
    // The periods agree: their in-phase parts spread by well under 1 % of it.
    EXPECT_LT(x["cycle_spread"]["in_phase"].get<double>(), 0.01 * std::abs(x["harmonics_sin_cos"][0].get<double>()));
  }
  EXPECT_NEAR(runs[0]["keulegan_carpenter"].get<double>(), 2.0 * kPi * 0.015 / 0.3, 1e-12);
  // The assembled matrix of a sphere: sway and heave as surge, no rotational added mass.
  const auto assembled = run_cli(
      {"added-mass", "sphere", "--same", "sway=surge", "--same", "heave=surge", "--zero", "roll,pitch,yaw", "--json"},
      dir.path());
  ASSERT_EQ(assembled.exit_code, 0) << assembled.err;
  const auto a = json::parse(assembled.out);
  EXPECT_TRUE(a["positive_definite"].get<bool>());
  EXPECT_NEAR(a["added_mass_b"][0][0].get<double>() / (rho * volume), 0.5, 0.05);
  EXPECT_EQ(a["quadratic_damping"].size(), 1u);  // two amplitudes at one frequency
}

TEST(Pmm, BadInputIsOneLineWithTheDatabaseUnchanged) {
  TempDir dir;
  ASSERT_EQ(pmm(dir, write_history(dir.path(), "surge.csv", 0, 0.05), 0, 0.05, "hull"), 0);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  std::ofstream(dir / "short.csv") << "Time [s],X [N]\n0,1\n0.1,2\n0.2,1\n";
  std::ofstream(dir / "steady.csv") << "Iteration,X [N]\n1,1\n2,2\n3,1\n";
  std::ofstream(dir / "table.csv") << "u [m s^-1],X [N]\n0.1,1\n0.2,2\n";
  const std::vector<std::vector<std::string>> cases = {
      {"pmm", "surge.csv", "--motion", "surge", "--amplitude", "0.05"},  // --period missing
      {"pmm", "surge.csv"},                                              // no motion anywhere
      {"pmm", "surge.csv", "--motion", "twist", "--amplitude", "1", "--period", "1"},
      {"pmm", "surge.csv", "--motion", "surge", "--amplitude", "-1", "--period", "1"},
      {"pmm", "short.csv", "--motion", "surge", "--amplitude", "0.05", "--period", "1.6"},  // < 3 periods
      {"pmm", "steady.csv", "--motion", "surge", "--amplitude", "0.05", "--period", "1.6"},
      {"pmm", "table.csv", "--motion", "surge", "--amplitude", "0.05", "--period", "1.6"},  // not a history
      {"pmm", "surge.csv", "--motion", "surge", "--amplitude", "0.05", "--period", "1.6", "--harmonics", "11"},
      {"added-mass", "nobody"},
      {"added-mass", "hull", "--zero", "surge"},
      {"added-mass", "hull", "--same", "sway=roll"},
  };
  for (const auto& args : cases) {
    const auto result = run_cli(args, dir.path());
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    EXPECT_EQ(result.exit_code, 2) << joined << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << joined << result.err;
    EXPECT_EQ(result.err.find("internal error"), std::string::npos) << joined << result.err;
    EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before) << joined;
  }
}

TEST(Pmm, HostileBodyNamesAreDataInTheOutput) {
  TempDir dir;
  const auto history = write_history(dir.path(), "surge.csv", 0, 0.05);
  std::size_t tried = 0;
  for (const std::string& name : test::hostile_names()) {
    try {
      check_name(NameKind::Body, name, {}, "test");
    } catch (const InputError&) {
      continue;
    }
    if (++tried > 6) break;
    ASSERT_EQ(pmm(dir, history, 0, 0.05, name), 0) << name;
    const auto result = run_cli({"added-mass", name, "--json"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << name << ": " << result.err;
    EXPECT_EQ(json::parse(result.out)["body"], name);
    for (const auto& args : {std::vector<std::string>{"added-mass", name},
                             std::vector<std::string>{"pmm", "surge.csv", "--body", name, "--motion", "surge",
                                                      "--amplitude", "0.05", "--period", "1.6", "--no-store"}}) {
      const auto text = run_cli(args, dir.path());
      ASSERT_EQ(text.exit_code, 0) << name << ": " << text.err;
      EXPECT_TRUE(test::terminal_safe(text.out)) << name << ": a control character in " << text.out;
    }
  }
  EXPECT_GT(tried, 5u);
}

/// A CSV history (time, body-axis X..N) of DOF j moved as A sin(2 pi t / T)
/// for 40 periods: F_i = -m[i] x'' - d[i] x' on every component, and the
/// restoring force -c x on the moved DOF's own component.
fs::path write_run(const fs::path& dir, const std::string& name, std::size_t j, double amplitude, double period,
                   const std::array<double, 6>& m, const std::array<double, 6>& d, double c = 0.0) {
  const fs::path path = dir / name;
  std::ofstream out(path);
  out << std::setprecision(17) << "Time [s],X [N],Y [N],Z [N],K [N m],M [N m],N [N m]\n";
  const double omega = 2.0 * kPi / period, dt = period / 80.0;
  for (int k = 0; k <= 40 * 80; ++k) {
    const double t = dt * k;
    const double x = amplitude * std::sin(omega * t), x_dot = amplitude * omega * std::cos(omega * t);
    const double x_ddot = -omega * omega * x;
    out << t;
    for (std::size_t i = 0; i < 6; ++i) out << ',' << -m[i] * x_ddot - d[i] * x_dot - (i == j ? c * x : 0.0);
    out << '\n';
  }
  return path;
}

std::string number_text(double value) {
  std::ostringstream text;
  text << std::setprecision(17) << value;
  return text.str();
}

/// One refusal: exit 2, one line, no "internal error", the database as it was.
void expect_refused(const TempDir& dir, const std::vector<std::string>& args, const std::string& before,
                    const std::vector<std::string>& words = {}) {
  const auto result = run_cli(args, dir.path());
  std::string joined;
  for (const auto& a : args) joined += a + " ";
  EXPECT_EQ(result.exit_code, 2) << joined << result.out << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << joined << result.err;
  EXPECT_EQ(result.err.find("internal error"), std::string::npos) << joined << result.err;
  for (const auto& word : words) EXPECT_NE(result.err.find(word), std::string::npos) << joined << result.err;
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before) << joined;
}

TEST(Pmm, AReversedAxisGivesTheSameAddedMassAsTheCaseAxes) {
  // The sphere's runs with the README's --axes=-x,y,-z (the motion's phase
  // becomes pi) and with the case's own axes: the periods are counted from
  // the window start either way, so the fits see the same samples.
  TempDir dir;
  const std::string root = HYDROCOEF_SOURCE_DIR "/examples/openfoam-sphere/pmm/";
  std::map<std::string, json> by_axes;
  for (const std::string axes : {"x,y,z", "-x,y,-z"}) {
    const auto result = run_cli({"pmm", root + "surge-A0.015-T2", root + "surge-A0.045-T2", "--body", "sphere",
                                 "--axes=" + axes, "--no-store", "--json"},
                                dir.path());
    ASSERT_EQ(result.exit_code, 0) << axes << ": " << result.err;
    by_axes[axes] = json::parse(result.out)["runs"];
  }
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& forward = by_axes["x,y,z"][k];
    const auto& reversed = by_axes["-x,y,-z"][k];
    EXPECT_NEAR(reversed["motion"]["phase_rad"].get<double>(), kPi, 1e-15);
    EXPECT_EQ(forward["motion"]["phase_rad"].get<double>(), 0.0);
    EXPECT_EQ(reversed["window_s"], forward["window_s"]);
    EXPECT_EQ(reversed["periods"], forward["periods"]);
    const double m_forward = forward["components"][0]["added_mass"].get<double>();
    const double m_reversed = reversed["components"][0]["added_mass"].get<double>();
    EXPECT_NEAR(m_reversed, m_forward, 1e-12 * m_forward) << forward["path"];
    const double d_forward = forward["components"][0]["damping"].get<double>();
    EXPECT_NEAR(reversed["components"][0]["damping"].get<double>(), d_forward, 1e-12 * d_forward);
    std::cout << forward["path"].get<std::string>() << ": M_A " << std::setprecision(17) << m_forward << " (x,y,z) "
              << m_reversed << " (-x,y,-z)\n";
  }
}

TEST(Pmm, ARestoringForceIsRemovedBeforeTheAddedMass) {
  // A floating body's heave: F_z = -M_A z'' - D z' - C z. Without --restoring
  // the fit sees M_A - C / w^2 = 5 - 64.8 kg, and that is refused.
  TempDir dir;
  const double m = 5.0, d = 1.5, c = 1000.0, period = 1.6, amplitude = 0.04;
  const auto history = write_run(dir.path(), "heave.csv", 2, amplitude, period, {0.1, 0.0, m, 0.0, 0.2, 0.0},
                                 {0.0, 0.0, d, 0.0, 0.05, 0.0}, c);
  const std::vector<std::string> args = {
      "pmm",         history.string(),      "--body", "buoy", "--motion", "heave", "--period", number_text(period),
      "--amplitude", number_text(amplitude)};
  ASSERT_EQ(run_cli({"pmm", "--help"}, dir.path()).exit_code, 0);
  ASSERT_EQ(pmm(dir, write_history(dir.path(), "surge.csv", 0, 0.05), 0, 0.05, "hull"), 0);  // a database to keep
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  expect_refused(dir, args, before, {"M_A[heave][heave] = -", "negative", "--restoring", "--axes"});
  auto restored = args;
  for (const char* a : {"--restoring", "1000", "--json"}) restored.push_back(a);
  const auto result = run_cli(restored, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto run = json::parse(result.out)["runs"][0];
  EXPECT_EQ(run["restoring"].get<double>(), c);
  EXPECT_EQ(run["restoring_unit"], "N/m");
  const auto& z = run["components"][2];
  ASSERT_EQ(z["component"], "Z");
  EXPECT_NEAR(z["added_mass"].get<double>(), m, 1e-6 * m);
  EXPECT_NEAR(z["damping"].get<double>(), d, 1e-6 * d);
  // The coupled X and M are not touched by the heave restoring force.
  EXPECT_NEAR(run["components"][0]["added_mass"].get<double>(), 0.1, 1e-6 * m);
  EXPECT_NEAR(run["components"][4]["added_mass"].get<double>(), 0.2, 1e-6 * m);
  // Stored with the record: pmm-runs shows it, readable and as JSON.
  const auto listed = run_cli({"pmm-runs", "--body", "buoy", "--json"}, dir.path());
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  ASSERT_EQ(json::parse(listed.out).size(), 1u) << listed.out;
  EXPECT_EQ(json::parse(listed.out)[0]["restoring"].get<double>(), c);
  const auto text = run_cli({"pmm-runs"}, dir.path());
  EXPECT_NE(text.out.find("restoring 1000 N/m"), std::string::npos) << text.out;
  // A restoring coefficient that is not a number, or given for a held body in a stream, is refused.
  const std::string stored = test::dump_database(dir / "hydrocoef.db");
  auto nan = args;
  for (const char* a : {"--restoring", "nan"}) nan.push_back(a);
  expect_refused(dir, nan, stored, {"--restoring"});
  auto stream = args;
  for (const char* a : {"--restoring", "1000", "--stream", "--rho", "1000", "--volume", "0.01"}) stream.push_back(a);
  expect_refused(dir, stream, stored, {"--restoring", "--stream"});
}

TEST(Pmm, NumbersThatWouldPoisonTheDatabaseAreRefused) {
  TempDir dir;
  const std::array<double, 6> m = {7.0, 0.0, 0.0, 0.0, 0.0, 0.0}, d = {0.7, 0.0, 0.0, 0.0, 0.0, 0.0};
  const auto history = write_run(dir.path(), "surge.csv", 0, 0.03, 2.0, m, d);  // steps of 0.025 s
  const auto with = [&](const std::string& amplitude, const std::string& period) {
    return std::vector<std::string>{"pmm",   history.string(), "--body",  "ball",     "--motion",
                                    "surge", "--amplitude",    amplitude, "--period", period};
  };
  ASSERT_EQ(run_cli(with("0.03", "2"), dir.path()).exit_code, 0);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  expect_refused(dir, with("5e-324", "2"), before, {"amplitude"});  // M_A was infinite
  expect_refused(dir, with("1e-12", "2"), before, {"round-off"});   // below the positions' round-off
  expect_refused(dir, with("1e308", "2"), before, {"A w^2"});       // M_A was 0, "100 % explained"
  expect_refused(dir, with("0.03", "0.025"), before);               // one sampling step: M_A was -2.6e8 kg
  expect_refused(dir, with("0.03", "0.05"), before);                // two
  // --size sets the scale of the round-off: 1e-8 m is fine for a 1 m body, not for a 100 m one.
  auto large = with("1e-8", "2");
  for (const char* a : {"--size", "100", "--no-store"}) large.push_back(a);
  expect_refused(dir, large, before, {"round-off", "1e-07 m"});
}

TEST(Pmm, PmmRunsListsAndDeletesRecordsEvenOnesNoReaderAccepts) {
  TempDir dir;
  const std::array<double, 6> m = {7.0, 0.5, 0.0, 0.0, 0.0, 0.0}, d = {0.7, 0.0, 0.0, 0.0, 0.0, 0.0};
  ASSERT_EQ(pmm(dir, write_run(dir.path(), "a.csv", 0, 0.03, kPeriod, m, d), 0, 0.03, "ball"), 0);
  ASSERT_EQ(pmm(dir, write_run(dir.path(), "b.csv", 0, 0.05, kPeriod, m, d), 0, 0.05, "ball"), 0);
  ASSERT_EQ(run_cli({"pmm-runs", "--help"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli({"pmm-runs", "delete", "--help"}, dir.path()).exit_code, 0);
  auto listed = run_cli({"pmm-runs", "--json"}, dir.path());
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  auto records = json::parse(listed.out);
  ASSERT_EQ(records.size(), 2u);
  const std::int64_t first = records[0]["id"].get<std::int64_t>(), second = records[1]["id"].get<std::int64_t>();
  EXPECT_NEAR(records[0]["added_mass"].get<double>(), 7.0, 1e-6 * 7.0);
  // An id that is not stored deletes nothing, not even the ids beside it.
  std::string before = test::dump_database(dir / "hydrocoef.db");
  expect_refused(dir, {"pmm-runs", "delete", std::to_string(first), "999"}, before, {"no forced-oscillation run 999"});
  // A record no reader accepts (an infinite added mass, as pmm once stored)
  // makes added-mass refuse the database; pmm-runs delete still removes it.
  // (The record is tampered with through SQLite's own API.)
  if (test::on_postgresql()) GTEST_SKIP() << "the rest tampers with an SQLite file";
  {
    sqlite3* raw = nullptr;
    ASSERT_EQ(sqlite3_open((dir / "hydrocoef.db").string().c_str(), &raw), SQLITE_OK);
    const std::string sql = "UPDATE pmm_coefficient SET added_mass = 9e999 WHERE pmm_run_id = " + std::to_string(first);
    ASSERT_EQ(sqlite3_exec(raw, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(raw);
  }
  before = test::dump_database(dir / "hydrocoef.db");
  expect_refused(dir, {"added-mass", "ball"}, before, {"pmm_coefficient"});
  const auto deleted = run_cli({"pmm-runs", "delete", std::to_string(first), "--json"}, dir.path());
  ASSERT_EQ(deleted.exit_code, 0) << deleted.err;
  const auto outcome = json::parse(deleted.out);
  ASSERT_EQ(outcome["deleted"].size(), 1u);
  EXPECT_EQ(outcome["deleted"][0]["id"], first);
  EXPECT_EQ(outcome["deleted"][0]["body"], "ball");
  EXPECT_EQ(outcome["deleted"][0]["dof"], "surge");
  listed = run_cli({"pmm-runs", "--json"}, dir.path());
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  records = json::parse(listed.out);
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0]["id"], second);
  const auto assembled = run_cli({"added-mass", "ball", "--json"}, dir.path());
  ASSERT_EQ(assembled.exit_code, 0) << assembled.err;
  EXPECT_EQ(json::parse(assembled.out)["records"], 1);
  // Readable output names what went.
  const auto text = run_cli({"pmm-runs", "delete", std::to_string(second)}, dir.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("deleted 1 forced-oscillation run"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("b.csv"), std::string::npos) << text.out;
  EXPECT_NE(run_cli({"pmm-runs"}, dir.path()).out.find("No forced-oscillation runs"), std::string::npos);
  // The coefficients went with their runs.
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db").find("INSERT INTO pmm_coefficient"), std::string::npos);
}

TEST(Pmm, AddedMassKeepsFrequenciesApart) {
  TempDir dir;
  const std::array<double, 6> m16 = {7.0, 0.0, 0.0, 0.0, 0.0, 0.0}, d16 = {0.7, 0.0, 0.0, 0.0, 0.0, 0.0};
  const std::array<double, 6> m20 = {7.5, 0.0, 0.0, 0.0, 0.0, 0.0}, d20 = {1.9, 0.0, 0.0, 0.0, 0.0, 0.0};
  const auto run = [&](const std::string& name, double amplitude, double period, const std::array<double, 6>& m,
                       const std::array<double, 6>& d) {
    const auto path = write_run(dir.path(), name, 0, amplitude, period, m, d);
    const auto result = run_cli({"pmm", path.string(), "--body", "hull", "--motion", "surge", "--amplitude",
                                 number_text(amplitude), "--period", number_text(period)},
                                dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
  };
  run("a.csv", 0.03, 1.6, m16, d16);
  run("b.csv", 0.05, 1.6, m16, d16);
  run("c.csv", 0.03, 2.0, m20, d20);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  // Several frequencies and none chosen: refused, listing them.
  expect_refused(dir, {"added-mass", "hull"}, before, {"1.6 s (2 runs)", "2 s (1 run)", "--period"});
  expect_refused(dir, {"added-mass", "hull", "--period", "3"}, before, {"period 3 s", "1.6 s (2 runs)"});
  for (const auto& [period, m, d, records] : {std::tuple{"1.6", 7.0, 0.7, 2}, std::tuple{"2", 7.5, 1.9, 1}}) {
    const auto result = run_cli({"added-mass", "hull", "--period", period, "--json"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const auto a = json::parse(result.out);
    EXPECT_EQ(a["records"], records);
    EXPECT_EQ(a["other_frequency_records"], 3 - records);
    EXPECT_NEAR(a["period_s"].get<double>(), std::stod(period), 1e-12);
    EXPECT_NEAR(a["added_mass_b"][0][0].get<double>(), m, 1e-6 * m);
    EXPECT_NEAR(a["damping_b"][0][0].get<double>(), d, 1e-6 * d);  // not the mean of the two frequencies
    // The damping at each frequency, a row each, whatever the period used.
    ASSERT_EQ(a["by_frequency"].size(), 2u) << result.out;
    EXPECT_NEAR(a["by_frequency"][0]["period_s"].get<double>(), 2.0, 1e-12);  // the lower frequency first
    EXPECT_EQ(a["by_frequency"][0]["runs"], 1);
    EXPECT_NEAR(a["by_frequency"][0]["damping"].get<double>(), 1.9, 1e-6);
    EXPECT_NEAR(a["by_frequency"][1]["period_s"].get<double>(), 1.6, 1e-12);
    EXPECT_EQ(a["by_frequency"][1]["runs"], 2);
    EXPECT_NEAR(a["by_frequency"][1]["damping"].get<double>(), 0.7, 1e-6);
  }
  const auto text = run_cli({"added-mass", "hull", "--period", "1.6"}, dir.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("at period 1.6 s"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("1 run at other periods left out"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("T 2 s"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("D = 1.9"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("* surge"), std::string::npos) << text.out;
}

TEST(Pmm, AddedMassRefusesAMatrixThatIsNotPositiveDefinite) {
  // Surge and sway runs whose couplings outweigh the diagonal: M_A =
  // [[1, 5], [5, 1]] has eigenvalue -4.
  TempDir dir;
  const auto surge = write_run(dir.path(), "surge.csv", 0, 0.03, kPeriod, {1.0, 5.0, 0, 0, 0, 0}, {0.1, 0, 0, 0, 0, 0});
  const auto sway = write_run(dir.path(), "sway.csv", 1, 0.03, kPeriod, {5.0, 1.0, 0, 0, 0, 0}, {0, 0.1, 0, 0, 0, 0});
  ASSERT_EQ(pmm(dir, surge, 0, 0.03, "hull"), 0);
  ASSERT_EQ(pmm(dir, sway, 1, 0.03, "hull"), 0);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  expect_refused(dir, {"added-mass", "hull"}, before, {"not positive definite", "-4", "--allow-indefinite"});
  const auto allowed = run_cli({"added-mass", "hull", "--allow-indefinite", "--json"}, dir.path());
  ASSERT_EQ(allowed.exit_code, 0) << allowed.err;
  const auto a = json::parse(allowed.out);
  EXPECT_FALSE(a["positive_definite"].get<bool>());
  EXPECT_NEAR(a["smallest_eigenvalue"].get<double>(), -4.0, 1e-5);
}

}  // namespace
}  // namespace hydrocoef
