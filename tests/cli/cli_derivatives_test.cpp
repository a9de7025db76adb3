// hydrocoef derivatives from the command line: captive-like runs generated
// from a known sway-force model of six cross-coupled terms over (u, v, r,
// delta), written as a force table and imported, are fitted back to 1e-9 by
// `derivatives fit` (text and --json), stored with their runs, listed, shown
// in the prime form equal to the normalisation library's conversion (and
// refused naming the reference values a form lacks), evaluated with the
// model's value at a point, and deleted; runs that state an uncertainty are
// fitted weighted, and --select loo drops a term the runs do not need. A term
// the parser does not know, fewer runs than terms and terms the runs cannot
// tell apart exit 2 with one line naming them, and leave the database as it
// was.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>

#include "src/derivatives/normalisation.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

// Y = Y_v v + Y_r r + Y_v|v| v|v| + Y_uv u v + Y_vvr v^2 r + Y_uud u^2 delta [N], SI.
constexpr const char* kTerms = "v, r, v*|v|, u*v, v^2*r, u^2*delta";
const std::vector<double> kTrue{-120.0, 35.0, -480.0, -60.0, 210.0, -25.0};

double model(double u, double v, double r, double delta) {
  return kTrue[0] * v + kTrue[1] * r + kTrue[2] * v * std::abs(v) + kTrue[3] * u * v + kTrue[4] * v * v * r +
         kTrue[5] * u * u * delta;
}

void write_runs(const std::filesystem::path& path) {
  std::ofstream out(path);
  out << std::setprecision(17) << "u [m s^-1],v [m s^-1],r [rad s^-1],delta [rad],Y [N]\n";
  for (const double u : {1.0, 1.5, 2.0})
    for (const double v : {-0.3, -0.15, 0.0, 0.15, 0.3})
      for (const double r : {-0.1, 0.0, 0.1})
        for (const double delta : {-0.2, 0.0, 0.2})
          out << u << "," << v << "," << r << "," << delta << "," << model(u, v, r, delta) << "\n";
}

class CliDerivatives : public ::testing::Test {
 protected:
  void SetUp() override {
    write_runs(dir_ / "captive.csv");
    const auto imported = run_cli(
        {"import", "captive.csv", "--body", "ship", "--disturbance", "delta", "--sign", "on-body"}, dir_.path());
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
  }
  test::CliResult fit(std::vector<std::string> extra) {
    std::vector<std::string> args{"derivatives", "fit", "--body", "ship", "--output", "Y"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli(args, dir_.path());
  }
  TempDir dir_;
};

TEST_F(CliDerivatives, AKnownModelIsRecoveredStoredListedAndEvaluated) {
  const auto fitted = fit({"--terms", kTerms, "--name", "sway", "--json"});
  ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
  const auto out = nlohmann::json::parse(fitted.out);
  ASSERT_EQ(out.at("coefficients").size(), kTrue.size());
  for (std::size_t k = 0; k < kTrue.size(); ++k)
    EXPECT_NEAR(out.at("coefficients")[k].at("value").get<double>(), kTrue[k], 1e-9 * std::abs(kTrue[k])) << k;
  EXPECT_EQ(out.at("coefficients")[2].at("term"), "v*|v|");
  EXPECT_EQ(out.at("coefficients")[2].at("unit"), "N/(m/s)^2");
  EXPECT_EQ(out.at("n"), 135);
  EXPECT_EQ(out.at("runs").size(), 135u);
  EXPECT_LT(out.at("rmse").get<double>(), 1e-9);
  EXPECT_GT(out.at("id").get<int>(), 0);

  const auto text = run_cli({"derivatives", "show", "sway"}, dir_.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("derivative model 'sway' of body 'ship': Y [N]"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("u^2*delta"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("form: dimensional (SI)"), std::string::npos) << text.out;

  const auto list = nlohmann::json::parse(run_cli({"derivatives", "list", "--json"}, dir_.path()).out);
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0].at("name"), "sway");
  EXPECT_EQ(list[0].at("terms"), kTerms);

  const auto at = run_cli({"derivatives", "evaluate", "sway", "--at", "u=1.2", "--at", "v=0.1", "--at", "r=-0.05",
                           "--at", "delta=0.1", "--json"},
                          dir_.path());
  ASSERT_EQ(at.exit_code, 0) << at.err;
  const auto value = nlohmann::json::parse(at.out);
  EXPECT_NEAR(value.at("value").get<double>(), model(1.2, 0.1, -0.05, 0.1), 1e-9);
  EXPECT_LT(value.at("std_error").get<double>(), 1e-9);

  const auto removed = run_cli({"derivatives", "delete", "sway"}, dir_.path());
  ASSERT_EQ(removed.exit_code, 0) << removed.err;
  EXPECT_EQ(run_cli({"derivatives", "list", "--json"}, dir_.path()).out, "[]\n");
}

TEST_F(CliDerivatives, ThePrimeFormIsTheNormalisationLibrarysConversion) {
  ASSERT_EQ(fit({"--terms", kTerms, "--name", "sway"}).exit_code, 0);
  const auto shown = run_cli({"derivatives", "show", "sway", "--form", "prime", "--length", "3", "--speed", "1.5",
                              "--density", "1025", "--json"},
                             dir_.path());
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  const auto out = nlohmann::json::parse(shown.out);
  EXPECT_EQ(out.at("form"), "prime");
  NormalisationReference reference;
  reference.length = 3.0;
  reference.speed = 1.5;
  reference.density = 1025.0;
  const DerivativeFactor v{QuantityKind::LinearVelocity, 1}, r{QuantityKind::AngularVelocity, 1};
  const std::vector<DerivativeKind> kinds{
      {QuantityKind::Force, {v}},
      {QuantityKind::Force, {r}},
      {QuantityKind::Force, {{QuantityKind::LinearVelocity, 2}}},
      {QuantityKind::Force, {{QuantityKind::LinearVelocity, 2}}},
      {QuantityKind::Force, {{QuantityKind::LinearVelocity, 2}, r}},
      {QuantityKind::Force, {{QuantityKind::LinearVelocity, 2}, {QuantityKind::Angle, 1}}}};
  for (std::size_t k = 0; k < kTrue.size(); ++k) {
    const auto& c = out.at("coefficients")[k];
    const double expected = to_nondimensional(kTrue[k], kinds[k], NormalisationSystem::Prime, reference);
    EXPECT_NEAR(c.at("value").get<double>(), expected, 1e-9 * std::abs(expected)) << k;
    EXPECT_NE(c.at("normalisation").get<std::string>().find("prime (SNAME 1950)"), std::string::npos) << c;
    EXPECT_EQ(c.at("unit"), "1");
  }
  const auto text = run_cli(
      {"derivatives", "show", "sway", "--form", "prime", "--length", "3", "--speed", "1.5", "--density", "1025"},
      dir_.path());
  EXPECT_NE(text.out.find("v*|v|: prime (SNAME 1950): Y_v|v|' = Y_v|v| / (1/2 rho L^2)"), std::string::npos)
      << text.out;
  const auto missing = run_cli({"derivatives", "show", "sway", "--form", "mmg", "--length", "3"}, dir_.path());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("give --speed, --density and --draft"), std::string::npos) << missing.err;
}

TEST_F(CliDerivatives, BadTermsTooFewRunsAndCollinearTermsAreRefusedLeavingTheDatabase) {
  const auto before = test::dump_database(dir_ / "hydrocoef.db");
  const auto unknown = fit({"--terms", "v, v**r"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("v**r"), std::string::npos) << unknown.err;
  const auto few =
      fit({"--terms", "v, r, v*|v|", "--where", "u=1", "--where", "r=0", "--where", "delta=0", "--where", "v>=0.1"});
  EXPECT_EQ(few.exit_code, 2);
  EXPECT_NE(few.err.find("2 runs"), std::string::npos) << few.err;
  const auto collinear = fit({"--terms", "v, u*v", "--where", "u=1.5"});
  EXPECT_EQ(collinear.exit_code, 2);
  EXPECT_NE(collinear.err.find("u*v"), std::string::npos) << collinear.err;
  EXPECT_NE(collinear.err.find("u = 1.5 at every run"), std::string::npos) << collinear.err;
  for (const auto* result : {&unknown, &few, &collinear})
    EXPECT_EQ(std::count(result->err.begin(), result->err.end(), '\n'), 1) << result->err;
  EXPECT_EQ(test::dump_database(dir_ / "hydrocoef.db"), before);
}

TEST_F(CliDerivatives, RunsThatStateAnUncertaintyAreWeighted) {
  write_runs(dir_ / "weighed.csv");  // the same runs, imported for another body with a stated uncertainty
  const auto imported = run_cli({"import", "weighed.csv", "--body", "weighed", "--disturbance", "delta", "--sign",
                                 "on-body", "--uncertainty", "Y=0.5", "--also", "weighed"},
                                dir_.path());
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  const auto fitted =
      run_cli({"derivatives", "fit", "--body", "weighed", "--output", "Y", "--terms", kTerms, "--no-store", "--json"},
              dir_.path());
  ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
  const auto out = nlohmann::json::parse(fitted.out);
  EXPECT_EQ(out.at("weighting"), "uncertainty");
  EXPECT_LT(out.at("chi2_reduced").get<double>(), 1e-12);  // noise-free runs, sigma 0.5 N stated
  EXPECT_NE(out.at("warnings").dump().find("scatter-below-uncertainty"), std::string::npos) << out.at("warnings");
  // The stated uncertainties as they are (never scaled down): the normal quantile 1.96.
  EXPECT_NEAR(out.at("interval_factor").get<double>(), 1.959964, 1e-6);
  for (std::size_t k = 0; k < kTrue.size(); ++k)
    EXPECT_NEAR(out.at("coefficients")[k].at("value").get<double>(), kTrue[k], 1e-9 * std::abs(kTrue[k])) << k;
  const auto unweighted = run_cli({"derivatives", "fit", "--body", "weighed", "--output", "Y", "--terms", kTerms,
                                   "--no-store", "--unweighted", "--json"},
                                  dir_.path());
  EXPECT_EQ(nlohmann::json::parse(unweighted.out).at("weighting"), "none");
}

TEST_F(CliDerivatives, TermsChosenByCrossValidationDropATermTheRunsDoNotNeed) {
  const auto chosen = fit({"--terms", std::string(kTerms) + ", u*r", "--select", "loo", "--no-store", "--json"});
  ASSERT_EQ(chosen.exit_code, 0) << chosen.err;
  const auto out = nlohmann::json::parse(chosen.out);
  EXPECT_EQ(out.at("selection"), "loo");
  EXPECT_EQ(out.at("terms"), kTerms);
  EXPECT_EQ(out.at("id"), 0);
}

}  // namespace
}  // namespace hydrocoef
