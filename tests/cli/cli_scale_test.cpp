// hydrocoef scale from the command line:
// - the worked model-to-ship example of tests/derivatives/scaling_test.cpp
//   (computed there to 30 digits from the ITTC-1957 line and the form-factor
//   method) comes out of `scale --json` to the same 7 significant digits,
//   with the method's citation and the assumptions printed;
// - a submerged body with a given form factor, and Prohaska's plot over
//   points generated from a known (1 + k) and slope, give what the library
//   gives;
// - a stored surge law X = a u + b u|u| scaled through --fit gives the
//   coefficients the library's scale_damping_law gives for the same law;
// - each refusal is one line, exit 2, the database unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "src/derivatives/scaling.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

double relative_error(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

// Model (fresh water, 15 C) and ship (sea water, 15 C), as scaling_test.cpp.
const std::vector<std::string> kModelToShip{
    "--from-length", "5",   "--from-area", "4",    "--from-viscosity", "1.13902e-6", "--from-density", "999.1",
    "--to-length",   "125", "--to-area",   "2500", "--to-viscosity",   "1.18831e-6", "--to-density",   "1025.9"};

class CliScale : public ::testing::Test {
 protected:
  test::CliResult scale(std::vector<std::string> args, bool ship = true) {
    args.insert(args.begin(), "scale");
    if (ship) args.insert(args.end(), kModelToShip.begin(), kModelToShip.end());
    return run_cli(args, dir_.path());
  }
  nlohmann::json scale_json(std::vector<std::string> args, bool ship = true) {
    args.emplace_back("--json");
    const auto result = scale(args, ship);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return nlohmann::json::parse(result.out);
  }
  TempDir dir_;
};

TEST_F(CliScale, TheWorkedModelToShipExample) {
  const auto out =
      scale_json({"--point", "1.5,-30", "--to-roughness", "150e-6", "--wave", "froude", "--form-factor", "1.15"});
  ASSERT_EQ(out.at("points").size(), 1u);
  const auto& p = out.at("points")[0];
  const double digits = 5e-7;
  EXPECT_LT(relative_error(p.at("froude_from").get<double>(), 0.2142130), digits);
  EXPECT_LT(relative_error(p.at("froude_to").get<double>(), 0.2142130), digits);
  EXPECT_LT(relative_error(p.at("reynolds_from").get<double>(), 6.584608e6), digits);
  EXPECT_LT(relative_error(p.at("friction_from").get<double>(), 3.230220e-3), digits);
  EXPECT_LT(relative_error(p.at("total_from").get<double>(), 6.672672e-3), digits);
  EXPECT_LT(relative_error(p.at("wave").get<double>(), 2.957919e-3), digits);
  EXPECT_DOUBLE_EQ(p.at("speed_to").get<double>(), 7.5);
  EXPECT_LT(relative_error(p.at("reynolds_to").get<double>(), 7.889355e8), digits);
  EXPECT_LT(relative_error(p.at("friction_to").get<double>(), 1.576651e-3), digits);
  EXPECT_LT(relative_error(p.at("total_to").get<double>(), 5.246859e-3), digits);
  EXPECT_LT(relative_error(p.at("resistance_to").get<double>(), 378474.8), digits);
  EXPECT_LT(relative_error(p.at("force_to").get<double>(), -378474.8), digits);
  EXPECT_EQ(out.at("one_plus_k"), 1.15);
  EXPECT_EQ(out.at("form_factor_method"), "given");
  EXPECT_EQ(out.at("wave"), "C_W at equal Froude number");

  // The text names the method, its sources and the assumptions, and tabulates U and R at scale 2.
  const auto text =
      scale({"--point", "1.5,-30", "--to-roughness", "150e-6", "--wave", "froude", "--form-factor", "1.15"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  for (const char* expected :
       {"ITTC-1957 friction line C_F = 0.075/(log10 Re - 2)^2 (8th ITTC, Madrid 1957; ITTC 7.5-02-02-01 and "
        "7.5-02-03-01.4)",
        "C_W equal at equal Froude number", "1+k = 1.15 (given), independent of scale and Reynolds number",
        "scale 2: roughness allowance dC_F = 0.000475791", "R2 [N]", "378474.8", "-378474.8"})
    EXPECT_NE(text.out.find(expected), std::string::npos) << expected << "\n" << text.out;

  // Resistance magnitudes in: the same coefficients, a positive force out.
  const auto opposing = scale_json({"--point", "1.5,30", "--sign", "opposing", "--to-roughness", "150e-6", "--wave",
                                    "froude", "--form-factor", "1.15"});
  EXPECT_EQ(opposing.at("points")[0].at("total_to"), p.at("total_to"));
  EXPECT_EQ(opposing.at("points")[0].at("force_to").get<double>(), -p.at("force_to").get<double>());
}

TEST_F(CliScale, SubmergedAndProhaskaAreTheLibrarys) {
  // Runs of a body with 1 + k = 1.3 exactly, no waves: the mean ratio recovers 1.3.
  const ScaleConditions model{1.0, 1.2, 1.0e-6, 998.0, 0.0, 0.0};
  const auto line = [](double re) { return 0.075 / std::pow(std::log10(re) - 2.0, 2); };
  std::vector<std::string> args{"--wave",       "submerged", "--target-speeds",  "2,4",  "--from-length",  "1",
                                "--from-area",  "1.2",       "--from-viscosity", "1e-6", "--from-density", "998",
                                "--to-length",  "4",         "--to-area",        "19.2", "--to-viscosity", "1e-6",
                                "--to-density", "1025"};
  std::vector<ResistanceRun> runs;
  for (const double u : {0.5, 1.0}) {
    const double force = -0.5 * model.density * model.wetted_area * u * u * 1.3 * line(u * model.length / 1e-6);
    runs.push_back({u, force});
    std::ostringstream point;
    point << std::setprecision(17) << u << "," << force;
    args.insert(args.end(), {"--point", point.str()});
  }
  const auto out = scale_json(args, false);
  EXPECT_NEAR(out.at("one_plus_k").get<double>(), 1.3, 1e-13);
  EXPECT_EQ(out.at("form_factor_method"), "mean ratio");
  ScalingOptions options;
  options.from = model;
  options.to = {4.0, 19.2, 1.0e-6, 1025.0, 0.0, 0.0};
  options.wave = {WaveStatement::Submerged, 0.0};
  options.target_speeds = {2.0, 4.0};
  const ScalingResult library = scale_resistance(runs, options);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(out.at("points")[k].at("force_to").get<double>(), library.points[k].force_to);
    EXPECT_NEAR(out.at("points")[k].at("total_to").get<double>() / out.at("points")[k].at("friction_to").get<double>(),
                1.3, 1e-12);
  }

  // Prohaska's plot: C_T = 1.12 C_F + 0.9 Fn^4 at four low speeds of the tank model.
  std::vector<std::string> prohaska{"--wave", "froude", "--form-factor", "prohaska", "--json"};
  for (const double froude : {0.08, 0.10, 0.12, 0.14}) {
    const double u = froude * std::sqrt(9.80665 * 5.0);
    const double total = 1.12 * line(u * 5.0 / 1.13902e-6) + 0.9 * std::pow(froude, 4);
    std::ostringstream point;
    point << std::setprecision(17) << u << "," << -0.5 * 999.1 * 4.0 * u * u * total;
    prohaska.insert(prohaska.end(), {"--point", point.str()});
  }
  const auto fitted = scale_json(prohaska);
  EXPECT_NEAR(fitted.at("one_plus_k").get<double>(), 1.12, 1e-10);
  EXPECT_NEAR(fitted.at("prohaska_slope").get<double>(), 0.9, 1e-10);
  EXPECT_EQ(fitted.at("form_factor_method"), "prohaska");
}

TEST_F(CliScale, AStoredSurgeLawIsTheLibrarysScaledLaw) {
  {
    std::ofstream out(dir_ / "surge.csv");
    out << std::setprecision(17) << "u [m s^-1],X [N]\n";
    for (const double u : {0.3, 0.6, 0.9, 1.2, 1.5, 1.8, 2.1}) out << u << "," << -2 * u - 12 * u * std::abs(u) << "\n";
  }
  ASSERT_EQ(run_cli({"import", "surge.csv", "--body", "m", "--sign", "on-body"}, dir_.path()).exit_code, 0);
  ASSERT_EQ(
      run_cli({"fit", "--body", "m", "--dof", "X", "--terms", "u,u|u|", "--name", "surge"}, dir_.path()).exit_code, 0);
  const std::string before = test::read_bytes(dir_ / "hydrocoef.db");
  const auto out =
      scale_json({"--fit", "surge", "--speeds", "0.6,0.9,1.2,1.5,1.8,2.1", "--wave", "froude", "--form-factor", "1.1"});
  const auto fits = nlohmann::json::parse(run_cli({"fits", "--json"}, dir_.path()).out);
  ASSERT_EQ(fits.size(), 1u);
  const std::vector<double> stored{fits.at(0).at("coefficients").at("u").get<double>(),
                                   fits.at(0).at("coefficients").at("u|u|").get<double>()};
  EXPECT_NEAR(stored[0], -2.0, 1e-9);

  ScalingOptions options;
  options.from = {5.0, 4.0, 1.13902e-6, 999.1, 0.0, 0.0};
  options.to = {125.0, 2500.0, 1.18831e-6, 1025.9, 0.0, 0.0};
  options.wave = {WaveStatement::FroudeMatched, 0.0};
  options.form_factor = given_form_factor(1.1);
  const std::vector<double> speeds{0.6, 0.9, 1.2, 1.5, 1.8, 2.1};
  const ScaledLaw law = scale_damping_law(parse_damping_terms("u,u|u|"), stored, speeds, options);
  const auto& scaled = out.at("law");
  EXPECT_EQ(scaled.at("fit"), "surge");
  EXPECT_EQ(scaled.at("coefficients_from").get<std::vector<double>>(), stored);
  EXPECT_EQ(scaled.at("coefficients_to").get<std::vector<double>>(), law.coefficients);
  EXPECT_EQ(scaled.at("max_relative_deviation").get<double>(), law.max_relative_deviation);
  EXPECT_EQ(scaled.at("units"), nlohmann::json({"N/(m/s)", "N/(m/s)^2"}));
  EXPECT_EQ(out.at("points").size(), speeds.size());
  EXPECT_EQ(test::read_bytes(dir_ / "hydrocoef.db"), before);
}

TEST_F(CliScale, RefusalsAreOneLineExitTwo) {
  std::ofstream(dir_ / "surge.csv") << "u [m s^-1],X [N]\n0.5,-4\n1,-14\n";
  ASSERT_EQ(run_cli({"import", "surge.csv", "--body", "m", "--sign", "on-body"}, dir_.path()).exit_code, 0);
  const std::string before = test::read_bytes(dir_ / "hydrocoef.db");
  const auto refused = [&](std::vector<std::string> args, const std::string& expected, bool ship = true) {
    const auto result = scale(args, ship);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_EQ(result.out, "");
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
  };
  refused({"--point", "1.5,-30", "--form-factor", "1.15"}, "scale: expected --wave submerged");
  refused({"--point", "1.5,-30", "--wave", "froude"}, "form factor");
  refused({"--point", "1.5,-30", "--wave", "waves", "--form-factor", "1.1"}, "waves");
  refused({"--point", "1.5", "--wave", "froude", "--form-factor", "1.1"}, "--point '1.5': expected U,X");
  refused({"--wave", "froude", "--form-factor", "1.1"}, "expected either --point U,X (repeatable) or --fit NAME");
  refused({"--point", "1.5,-30", "--wave", "froude", "--form-factor", "-1"}, "--form-factor '-1'");
  refused({"--point", "1.5,-30", "--wave", "froude", "--form-factor", "1.1", "--sign", "up"}, "--sign 'up'");
  std::vector<std::string> zero_length{"--point", "1.5,-30", "--wave", "froude", "--form-factor", "1.1"};
  zero_length.insert(zero_length.end(), kModelToShip.begin(), kModelToShip.end());
  zero_length[std::find(zero_length.begin(), zero_length.end(), "--from-length") - zero_length.begin() + 1] = "0";
  refused(zero_length, "--from-length must be a finite number above 0, not 0", false);
  refused({"--point", "1.5,-30", "--wave", "froude"}, "scale: expected --from-length", false);
  refused({"--point", "0.01,-0.001", "--wave", "froude", "--form-factor", "1.1"},
          "the Reynolds number U L / nu = 43897.4 is below 100000");
  refused({"--point", "1.5,30", "--wave", "froude", "--form-factor", "1.1"}, "oppose");
  refused({"--point", "1.5,-30", "--wave", "submerged"}, "target");
  refused({"--fit", "nosuch", "--speeds", "1,2", "--wave", "froude", "--form-factor", "1.1"},
          "--fit 'nosuch': no fit of that name; expected a stored surge law, a fit of X in u");
  refused({"--fit", "nosuch", "--wave", "froude", "--form-factor", "1.1"}, "needs --speeds");
  EXPECT_EQ(test::read_bytes(dir_ / "hydrocoef.db"), before);
}

}  // namespace
}  // namespace hydrocoef
