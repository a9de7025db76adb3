// hydrocoef body set / body show and runs --coefficients on the OpenFOAM
// sphere runs (data/openfoam-sphere/cases, R = 0.15 m): the reference data
// set and shown as text and JSON; bad values refused with exit 2, one line
// and the database unchanged; each run's C_X..C_N, Re and Fn equal to the
// formulas worked here from the run's own forces, speed, rho and nu (the
// area chosen by name, moments moved to the body's moment reference point);
// a run at rest and a run without rho or nu have no coefficient (or Re) and
// say why; the text, JSON and CSV name the reference used; `plot
// coefficient` draws the same numbers against Re.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/plot_data.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/sphere_cases.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using nlohmann::json;
using test::CliResult;
using test::TempDir;

constexpr double kFrontal = M_PI * 0.15 * 0.15;  // pi R^2 [m^2]

class CliBodyReference : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(test::import_sphere_cases(dir_.path()).exit_code, 0); }

  CliResult cli(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", "hydrocoef.db"});
    return test::run_cli(args, dir_.path());
  }
  std::string out(const std::vector<std::string>& args) {
    const auto result = cli(args);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return result.out;
  }
  json json_of(std::vector<std::string> args) {
    args.push_back("--json");
    return json::parse(out(args));
  }
  /// exit 2 and one line naming each piece, the database unchanged.
  void refused(const std::vector<std::string>& args, const std::vector<std::string>& pieces) {
    SCOPED_TRACE(testing::PrintToString(args));
    const std::string before = test::dump_database(dir_ / "hydrocoef.db");
    const auto result = cli(args);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    for (const auto& piece : pieces) EXPECT_NE(result.err.find(piece), std::string::npos) << result.err;
    EXPECT_EQ(test::dump_database(dir_ / "hydrocoef.db"), before);
  }
  void set_sphere() {
    out({"body", "set", "sphere", "--length", "0.3", "--area", "frontal=" + number(kFrontal), "--area", "L*d=0.09",
         "--default-area", "frontal", "--volume", "0.0141371669", "--draft", "0.15"});
  }
  static std::string number(double x) {
    std::ostringstream text;
    text.precision(17);
    text << x;
    return text.str();
  }

  TempDir dir_;
};

TEST_F(CliBodyReference, SetAndShownAsTextAndJson) {
  EXPECT_NE(out({"body", "show", "sphere"}).find("body 'sphere': no reference data"), std::string::npos);
  set_sphere();
  const std::string text = out({"body", "show", "sphere"});
  for (const std::string piece :
       {"body 'sphere', reference data", "reference length L: 0.3 m", "'frontal' 0.070685835 m^2 (default)",
        "'L*d' 0.09 m^2", "draft: 0.15 m", "displaced volume: 0.014137167 m^3",
        "moment reference point: not given (moments about each run's own reference point)"})
    EXPECT_NE(text.find(piece), std::string::npos) << piece << " in\n" << text;
  const json shown = json_of({"body", "show"});
  ASSERT_EQ(shown.at("bodies").size(), 1u);
  const json& sphere = shown["bodies"][0];
  EXPECT_EQ(sphere.at("length"), 0.3);
  EXPECT_EQ(sphere.at("areas").at("frontal"), kFrontal);
  EXPECT_EQ(sphere.at("areas").at("L*d"), 0.09);
  EXPECT_EQ(sphere.at("default_area"), "frontal");
  EXPECT_EQ(sphere.at("displaced_volume"), 0.0141371669);
  EXPECT_TRUE(sphere.at("moment_reference_point").is_null());
  // A change keeps what it does not name; --json prints the body's record.
  const json changed =
      json_of({"body", "set", "sphere", "--moment-point", "0.1,0,-0.05", "--remove-area", "L*d", "--unset", "draft"});
  EXPECT_EQ(changed.at("length"), 0.3);
  EXPECT_EQ(changed.at("areas").size(), 1u);
  EXPECT_TRUE(changed.at("draft").is_null());
  EXPECT_EQ(changed.at("moment_reference_point"), json::parse("[0.1, 0, -0.05]"));
  EXPECT_EQ(json_of({"body", "show", "sphere"}).at("bodies")[0], changed);
}

TEST_F(CliBodyReference, BadValuesAreRefusedWithOneLineAndNothingChanged) {
  set_sphere();
  refused({"body", "set", "sphere", "--length", "-1"}, {"--length must be a positive finite number [m], not -1"});
  refused({"body", "set", "sphere", "--volume", "0"}, {"--volume must be a positive finite number [m^3], not 0"});
  refused({"body", "set", "sphere", "--area", "wetted=-0.2"}, {"--area wetted=...", "positive finite", "-0.2"});
  refused({"body", "set", "sphere", "--area", "wetted=big"}, {"--area", "expected a finite number"});
  refused({"body", "set", "sphere", "--area", "=1"}, {"--area", "expected NAME=VALUE"});
  refused({"body", "set", "sphere", "--moment-point", "1,2"}, {"--moment-point", "three comma-separated numbers"});
  refused({"body", "set", "sphere", "--default-area", "side"},
          {"--default-area 'side' is not an area of body 'sphere'", "'L*d', 'frontal'"});
  out({"body", "set", "sphere", "--area", "wetted=0.28"});
  refused({"body", "set", "sphere", "--remove-area", "frontal"}, {"removes the default area 'frontal'"});
  refused({"body", "set", "sphere", "--remove-area", "side"}, {"body 'sphere' has no such area"});
  refused({"body", "set", "sphere", "--unset", "speed"}, {"--unset 'speed'", "length, draft, volume or moment-point"});
  refused({"body", "set", "sphere"}, {"nothing to set"});
  refused({"body", "set", "ghost", "--length", "1"}, {"no body named 'ghost'", "bodies: 'sphere'"});
  refused({"body", "show", "ghost"}, {"no body named 'ghost'"});
  refused({"body", "set", "sphere", "--area", "a\x01=1"}, {"the area name", "control or formatting character"});
  refused({"runs", "--area", "frontal"}, {"--coefficients"});
}

TEST_F(CliBodyReference, CoefficientsEqualTheFormulasWorkedFromEachRun) {
  refused({"runs", "--coefficients"}, {"body 'sphere' has no reference length", "hydrocoef body set NAME --length L"});
  set_sphere();
  out({"body", "set", "sphere", "--moment-point", "0.1,0,0"});
  const json runs = json_of({"runs"});
  const json table = json_of({"runs", "--coefficients"});
  ASSERT_EQ(runs.size(), 4u);
  ASSERT_EQ(table.at("runs").size(), 4u);
  EXPECT_EQ(table.at("gravity"), 9.80665);
  EXPECT_NE(table.at("axes").get<std::string>().find("body axes (x forward, y starboard, z down), forces on the body"),
            std::string::npos);
  const json& reference = table.at("references").at(0);
  EXPECT_EQ(reference.at("area_name"), "frontal");
  EXPECT_EQ(reference.at("area"), kFrontal);
  EXPECT_EQ(reference.at("length"), 0.3);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const json& run = runs[i];
    const json& c = table["runs"][i];
    SCOPED_TRACE(run.dump());
    ASSERT_EQ(c.at("id"), run.at("id"));
    const double u = run["u"], v = run["v"], w = run["w"];
    const double rho = run["density"], nu = run["kinematic_viscosity"];
    EXPECT_EQ(rho, 998.2);
    const double U = std::sqrt(u * u + v * v + w * w), q = 0.5 * rho * U * U;
    const auto force = [&](const char* name) { return run["forces"][name]["total"].get<double>(); };
    EXPECT_NEAR(c["coefficients"]["C_X"].get<double>(), force("X") / (q * kFrontal), 1e-14);
    EXPECT_LT(c["coefficients"]["C_X"].get<double>(), -0.15);  // a drag, on the body: along -x
    EXPECT_NEAR(c["coefficients"]["C_Y"].get<double>(), force("Y") / (q * kFrontal), 1e-14);
    EXPECT_NEAR(c["coefficients"]["C_K"].get<double>(), force("K") / (q * kFrontal * 0.3), 1e-14);
    // About P = (0.1, 0, 0) from the run's O = (0, 0, 0): d = O - P = (-0.1, 0, 0),
    // M_P = M_O + d x F: M' = M - dx Fz = M + 0.1 Z, N' = N + dx Fy = N - 0.1 Y.
    EXPECT_NEAR(c["coefficients"]["C_M"].get<double>(), (force("M") + 0.1 * force("Z")) / (q * kFrontal * 0.3), 1e-14);
    EXPECT_NEAR(c["coefficients"]["C_N"].get<double>(), (force("N") - 0.1 * force("Y")) / (q * kFrontal * 0.3), 1e-14);
    EXPECT_DOUBLE_EQ(c["reynolds"].get<double>(), U * 0.3 / nu);
    EXPECT_DOUBLE_EQ(c["froude"].get<double>(), U / std::sqrt(9.80665 * 0.3));
    EXPECT_EQ(c["speed"].get<double>(), U);
    EXPECT_EQ(c["note"], "");
  }
  // Another area by name: the force coefficients scale by the ratio of the areas.
  const json by_ld = json_of({"runs", "--coefficients", "--area", "L*d"});
  EXPECT_EQ(by_ld["references"][0]["area_name"], "L*d");
  EXPECT_NEAR(by_ld["runs"][0]["coefficients"]["C_X"].get<double>(),
              table["runs"][0]["coefficients"]["C_X"].get<double>() * kFrontal / 0.09, 1e-14);
  refused({"runs", "--coefficients", "--area", "wetted"},
          {"--area 'wetted': body 'sphere' has no such area (areas: 'L*d', 'frontal')"});

  const std::string text = out({"runs", "--coefficients", "--where", "u=0.1"});
  for (const std::string piece :
       {"coefficients of 2 runs",
        "body 'sphere': area 'frontal' A = 0.070685835 m^2, L = 0.3 m, moments about (0.1, 0, 0) m", "C_X", "Re", "Fn",
        "C_F = F / (1/2 rho U^2 A)", "g = 9.80665 m/s^2", "forces on the body"})
    EXPECT_NE(text.find(piece), std::string::npos) << piece << " in\n" << text;
  const std::string csv = out({"runs", "--coefficients", "--csv"});
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "id,body,u,v,w,p,q,r,U,rho,nu,area_name,A,L,Re,Fn,C_X,C_Y,C_Z,C_K,C_M,C_N,note");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  EXPECT_NE(csv.find(",998.2,1.004e-06,frontal,0.07068583470577035,0.3,"), std::string::npos) << csv;
}

TEST_F(CliBodyReference, ARunAtRestOrWithoutRhoOrNuHasNoCoefficientAndSaysWhy) {
  {
    std::ofstream table(dir_ / "hull-known.csv");
    table << "u [m s^-1],X [N]\n0,0.01\n0.5,-2\n";
    std::ofstream bare(dir_ / "hull-bare.csv");
    bare << "u [m s^-1],X [N]\n1.0,-8\n";
  }
  out({"import", "hull-known.csv", "--body", "hull", "--sign", "on-body", "--rho", "1025", "--quiet"});
  out({"import", "hull-bare.csv", "--body", "hull", "--sign", "on-body", "--quiet"});
  out({"body", "set", "hull", "--length", "2", "--area", "L^2=4"});
  const json table = json_of({"runs", "--coefficients", "--body", "hull"});
  ASSERT_EQ(table["runs"].size(), 3u);
  const json& rest = table["runs"][0];
  const json& known = table["runs"][1];
  const json& bare = table["runs"][2];
  EXPECT_EQ(rest["u"], 0.0);
  EXPECT_TRUE(rest["coefficients"]["C_X"].is_null());
  EXPECT_NE(rest["note"].get<std::string>().find("U = 0: no dynamic pressure, no coefficient"), std::string::npos);
  EXPECT_EQ(rest["froude"], 0.0);
  // rho given, nu not: a coefficient (-2 / (1/2 1025 0.25 4) = -0.00780488), no Re.
  EXPECT_DOUBLE_EQ(known["coefficients"]["C_X"].get<double>(), -2.0 / (0.5 * 1025 * 0.25 * 4));
  EXPECT_TRUE(known["reynolds"].is_null());
  EXPECT_EQ(known["note"], "no kinematic viscosity: no Re (import the run with --nu, or nu in its settings)");
  EXPECT_TRUE(bare["coefficients"]["C_X"].is_null());
  EXPECT_TRUE(bare["density"].is_null());
  EXPECT_NE(bare["note"].get<std::string>().find("no density: no coefficient (import the run with --rho"),
            std::string::npos);
  const std::string text = out({"runs", "--coefficients", "--body", "hull"});
  EXPECT_NE(text.find("area 'L^2' A = 4 m^2, L = 2 m"), std::string::npos) << text;
  EXPECT_NE(text.find("U = 0: no dynamic pressure"), std::string::npos) << text;
  // The sphere has no reference data: with every body selected, the command says what to give.
  refused({"runs", "--coefficients"}, {"body 'sphere' has no reference length"});
}

TEST_F(CliBodyReference, APlotOfACoefficientAgainstReDrawsTheTablesNumbers) {
  set_sphere();
  const json table = json_of({"runs", "--coefficients"});
  const json plot = json_of({"plot", "coefficient", "--coefficient", "C_X", "--against", "Re", "-o", "cx.svg"});
  EXPECT_EQ(plot["format"], "svg");
  ASSERT_TRUE(std::filesystem::exists(dir_ / "cx.svg"));
  const auto blocks = test::read_plot_blocks(dir_ / "cx.dat");
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_NE(blocks[0].first.find("body 'sphere': area 'frontal'"), std::string::npos) << blocks[0].first;
  ASSERT_EQ(blocks[0].second.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(blocks[0].second[i].at(0), table["runs"][i]["reynolds"].get<double>());
    EXPECT_EQ(blocks[0].second[i].at(1), table["runs"][i]["coefficients"]["C_X"].get<double>());
  }
  refused({"plot", "coefficient", "--coefficient", "C_Q"}, {"--coefficient 'C_Q': expected C_X, C_Y, C_Z"});
  refused({"plot", "coefficient", "--against", "speed"}, {"--against 'speed': expected Re, Fn or U"});
}

}  // namespace
}  // namespace hydrocoef
