// hydrocoef export-gazebo end to end: the ASR-V surge and yaw tables
// imported and fitted, then written for gz-sim and uuv_simulator; the files,
// parsed back, hold the fitted coefficients in on-body sign (the surge table
// is "opposing", so negated) and the sphere's added mass; refusals exit 2
// with one line on stderr and write nothing.
#include <gtest/gtest.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/xml_numbers.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

const std::string kSurge = HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-surge-damping.csv";
const std::string kYaw = HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-yaw-damping.csv";

struct Fits {
  nlohmann::json surge;  // X in u, stored opposing
  nlohmann::json yaw;    // N in r with a constant, stored on-body
};

Fits make_database(const TempDir& dir) {
  Fits fits;
  const auto surge = run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--rho", "998.2"}, dir.path());
  EXPECT_EQ(surge.exit_code, 0) << surge.err;
  const auto yaw = run_cli({"import", kYaw, "--body", "asr-v", "--sign", "on-body", "--rho", "998.2"}, dir.path());
  EXPECT_EQ(yaw.exit_code, 0) << yaw.err;
  const auto x = run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--json"}, dir.path());
  EXPECT_EQ(x.exit_code, 0) << x.err;
  fits.surge = nlohmann::json::parse(x.out);
  const auto n = run_cli({"fit", "--body", "asr-v", "--dof", "N", "--terms", "1,r,r|r|", "--json"}, dir.path());
  EXPECT_EQ(n.exit_code, 0) << n.err;
  fits.yaw = nlohmann::json::parse(n.out);
  EXPECT_EQ(fits.surge.at("sign_convention"), "opposing");
  EXPECT_EQ(fits.yaw.at("sign_convention"), "on-body");
  return fits;
}

const std::vector<std::string> kSphere = {"--sphere-radius",  "0.15", "--rho", "998.2", "--added-mass-rotation",
                                          "0.001,0.002,0.003"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

using test::number_of;
using test::numbers_of;
using test::read_xml;

const double kSphereMass = 2.0 / 3.0 * std::numbers::pi * 998.2 * 0.15 * 0.15 * 0.15;

TEST(CliExportGazebo, GzFileHoldsTheAsrVFitsOnBodyAndTheSphereAddedMass) {
  TempDir dir;
  const Fits fits = make_database(dir);
  const auto result = run_cli(
      with({"export-gazebo", "asr-v", "--flavor", "gz", "-o", "asr-v.sdf", "--drop-constant", "--allow-missing"},
           kSphere),
      dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* piece :
       {"wrote asr-v.sdf", "xU = ", "negated to on-body", "dropped", "link axes FLU", "no damping law; written as 0"})
    EXPECT_NE(result.out.find(piece), std::string::npos) << "output lacks '" << piece << "'\n" << result.out;

  const auto root = read_xml(dir / "asr-v.sdf");
  ASSERT_NE(root, nullptr) << test::read_text(dir / "asr-v.sdf");
  const auto& x = fits.surge.at("coefficients");
  const auto& n = fits.yaw.at("coefficients");
  EXPECT_EQ(number_of(root, "xU"), -x.at("u").get<double>());  // opposing -> on-body
  EXPECT_EQ(number_of(root, "xUabsU"), -x.at("u|u|").get<double>());
  EXPECT_LT(number_of(root, "xUabsU"), 0.0);
  EXPECT_EQ(number_of(root, "nR"), n.at("r").get<double>());  // already on-body
  EXPECT_EQ(number_of(root, "nRabsR"), n.at("r|r|").get<double>());
  EXPECT_EQ(number_of(root, "yV"), 0.0);  // no sway law: --allow-missing
  EXPECT_NEAR(number_of(root, "xDotU"), -kSphereMass, 1e-12 * kSphereMass);
  EXPECT_NEAR(number_of(root, "zDotW"), -kSphereMass, 1e-12 * kSphereMass);
  EXPECT_EQ(number_of(root, "kDotP"), -0.001);
  EXPECT_EQ(number_of(root, "nDotR"), -0.003);
  const std::string text = test::read_text(dir / "asr-v.sdf");
  for (const std::string& piece : {std::string("fit '") + fits.yaw.at("name").get<std::string>() + "'",
                                   std::string("runs ["), std::string("dropped on request (drop-constant)")})
    EXPECT_NE(text.find(piece), std::string::npos) << "file lacks '" << piece << "'";
}

TEST(CliExportGazebo, UuvJsonReportsWhatTheFileHolds) {
  TempDir dir;
  const Fits fits = make_database(dir);
  const auto result = run_cli(with({"export-gazebo", "asr-v", "--flavor", "uuv", "-o", "asr-v.xml", "--drop-constant",
                                    "--allow-missing", "--json"},
                                   kSphere),
                              dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto out = nlohmann::json::parse(result.out);
  const double xu = -fits.surge.at("coefficients").at("u").get<double>();
  const double nr = fits.yaw.at("coefficients").at("r").get<double>();
  EXPECT_EQ(out.at("flavor"), "uuv");
  EXPECT_EQ(out.at("sign_convention"), "on-body");
  EXPECT_EQ(out.at("elements").at("linear_damping")[0].get<double>(), xu);
  EXPECT_EQ(out.at("elements").at("linear_damping")[5].get<double>(), nr);
  EXPECT_EQ(out.at("missing"), nlohmann::json({"Y", "Z", "K", "M"}));
  ASSERT_EQ(out.at("fits").size(), 2u);
  EXPECT_EQ(out.at("fits")[0].at("stored_sign"), "opposing");
  EXPECT_EQ(out.at("fits")[1].at("dropped_constant").get<double>(), fits.yaw.at("coefficients").at("1").get<double>());

  const auto root = read_xml(dir / "asr-v.xml");
  ASSERT_NE(root, nullptr);
  const auto linear = numbers_of(root, "linear_damping");
  const auto quadratic = numbers_of(root, "quadratic_damping");
  const auto added = numbers_of(root, "added_mass");
  ASSERT_EQ(linear.size(), 6u);
  ASSERT_EQ(quadratic.size(), 6u);
  ASSERT_EQ(added.size(), 36u);
  EXPECT_EQ(linear[0], xu);
  EXPECT_EQ(quadratic[0], -fits.surge.at("coefficients").at("u|u|").get<double>());
  EXPECT_EQ(linear[5], nr);
  EXPECT_EQ(quadratic[5], fits.yaw.at("coefficients").at("r|r|").get<double>());
  EXPECT_NEAR(added[0], kSphereMass, 1e-12 * kSphereMass);
  EXPECT_EQ(added[35], 0.003);
  EXPECT_EQ(added[1], 0.0);
}

TEST(CliExportGazebo, LinearizeAtWritesTheSlopeAtTheForwardSpeed) {
  TempDir dir;
  const Fits fits = make_database(dir);
  const auto result = run_cli(with({"export-gazebo", "asr-v", "--flavor", "gz", "-o", "lin.sdf", "--drop-constant",
                                    "--allow-missing", "--linearize-at", "0.3"},
                                   kSphere),
                              dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto root = read_xml(dir / "lin.sdf");
  ASSERT_NE(root, nullptr);
  const double a = -fits.surge.at("coefficients").at("u").get<double>();
  const double b = -fits.surge.at("coefficients").at("u|u|").get<double>();
  EXPECT_EQ(number_of(root, "xU"), a + 2.0 * b * 0.3);
  EXPECT_EQ(number_of(root, "xUabsU"), 0.0);
  EXPECT_EQ(number_of(root, "nR"), fits.yaw.at("coefficients").at("r").get<double>());  // r0 = 0
  EXPECT_EQ(number_of(root, "nRabsR"), 0.0);
}

TEST(CliExportGazebo, RefusalsExitTwoWithOneLineAndWriteNothing) {
  TempDir dir;
  make_database(dir);
  // A cubic X law and a second X law in u for the ambiguity case.
  ASSERT_EQ(
      run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u^3", "--name", "cubic"}, dir.path()).exit_code,
      0);
  const std::vector<std::string> base = {"export-gazebo", "asr-v", "-o", "out.sdf"};
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {with(with(base, {"--flavor", "gz", "--fit", "X=asr-v:X(u,u|u|)", "--allow-missing"}), kSphere),
       "constant term '1'"},
      {with(base, {"--flavor", "gz", "--fit", "X=asr-v:X(u,u|u|)", "--drop-constant", "--allow-missing", "--added-mass",
                   "7,7,7,0.001,0.001,-1"}),
       "smallest eigenvalue -1"},
      {with(with(base, {"--flavor", "gz", "--fit", "X=asr-v:X(u,u|u|)", "--drop-constant"}), kSphere),
       "no damping law of Y in v, Z in w, K in p, M in q"},
      {with(with(base, {"--flavor", "uuv", "--fit", "X=cubic", "--drop-constant", "--allow-missing"}), kSphere),
       "term 'u^3'"},
      {with(with(base, {"--flavor", "gz", "--drop-constant", "--allow-missing"}), kSphere),
       "2 fits of X in u ('asr-v:X(u,u|u|)', 'cubic')"},
      {with(with(base, {"--flavor", "gz", "--fit", "X=nope", "--drop-constant", "--allow-missing"}), kSphere),
       "no fit named 'nope'"},
      {with(base, {"--flavor", "gz", "--fit", "X=asr-v:X(u,u|u|)", "--drop-constant", "--allow-missing"}),
       "no added mass given"},
      {with(with(base, {"--flavor", "uuv", "--link", "hull", "--fit", "X=asr-v:X(u,u|u|)", "--drop-constant",
                        "--allow-missing"}),
            kSphere),
       "--link applies to --flavor gz only"},
      {with(with(base, {"--flavor", "sdf"}), kSphere), "unknown Gazebo flavor 'sdf'"},
  };
  for (const auto& [args, expected] : cases) {
    const auto result = run_cli(args, dir.path());
    std::string command;
    for (const auto& arg : args) command += arg + " ";
    EXPECT_EQ(result.exit_code, 2) << command << "\n" << result.out;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << command << "\n" << result.err;
    EXPECT_EQ(result.err.rfind("hydrocoef: error: ", 0), 0u) << result.err;
    EXPECT_NE(result.err.find(expected), std::string::npos) << command << "\nstderr: " << result.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.sdf")) << command;
  }
  // A refusal leaves a file that is already there as it was.
  {
    std::ofstream old(dir / "out.sdf");
    old << "old\n";
  }
  const auto refused = run_cli(with(base, {"--flavor", "gz", "--drop-constant", "--allow-missing"}), dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(test::read_text(dir / "out.sdf"), "old\n");
}

TEST(CliExportGazebo, HelpNamesTheOptions) {
  TempDir dir;
  const auto result = run_cli({"export-gazebo", "--help"}, dir.path());
  EXPECT_EQ(result.exit_code, 0);
  for (const char* piece : {"--flavor", "--fit", "--added-mass-matrix", "--sphere-radius", "--drop-constant",
                            "--linearize-at", "--allow-missing", "--json"})
    EXPECT_NE(result.out.find(piece), std::string::npos) << piece;
}

TEST(CliExportGazebo, ASphereNeedsNoInventedRotationalAddedMassAndWhereChoosesTheFits) {
  TempDir dir;
  const Fits fits = make_database(dir);
  // Fits of the surge runs at u >= 0.1 only, beside the fit of all runs.
  ASSERT_EQ(
      run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--where", "u>=0.1", "--json"}, dir.path())
          .exit_code,
      0);
  const auto fast = nlohmann::json::parse(run_cli({"fits", "--json"}, dir.path()).out);
  double fast_u = 0.0;
  for (const auto& fit : fast)
    if (fit.at("where") == "u>=0.1") fast_u = fit.at("coefficients").at("u").get<double>();
  ASSERT_NE(fast_u, 0.0);
  // Without --where the two X laws are ambiguous; --where picks the one made from those runs.
  const std::vector<std::string> base = {
      "export-gazebo",   "asr-v",           "--flavor",        "gz",   "-o",    "s.sdf",
      "--drop-constant", "--allow-missing", "--sphere-radius", "0.15", "--rho", "998.2"};
  const auto ambiguous = run_cli(base, dir.path());
  EXPECT_EQ(ambiguous.exit_code, 2);
  EXPECT_NE(ambiguous.err.find("2 fits of X in u"), std::string::npos) << ambiguous.err;
  const auto chosen = run_cli(with(base, {"--where", "u>=0.1"}), dir.path());
  ASSERT_EQ(chosen.exit_code, 0) << chosen.err;
  const auto root = read_xml(dir / "s.sdf");
  ASSERT_NE(root, nullptr);
  EXPECT_EQ(number_of(root, "xU"), -fast_u);  // opposing -> on-body
  // No rotational added mass given: a sphere has none, written as 0 with a note.
  EXPECT_NEAR(number_of(root, "xDotU"), -kSphereMass, 1e-12 * kSphereMass);
  EXPECT_EQ(number_of(root, "kDotP"), 0.0);
  EXPECT_EQ(number_of(root, "mDotQ"), 0.0);
  EXPECT_EQ(number_of(root, "nDotR"), 0.0);
  EXPECT_NE(chosen.out.find("Ma is singular"), std::string::npos) << chosen.out;
  const auto none = run_cli(with(base, {"--where", "u>=0.2"}), dir.path());
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("no fits of body 'asr-v' made from the runs where u>=0.2"), std::string::npos) << none.err;
  (void)fits;
}

}  // namespace
}  // namespace hydrocoef
