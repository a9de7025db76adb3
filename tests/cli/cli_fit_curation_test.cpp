// Fits a database can be curated with (issue: a database you can correct):
// a fit name is not reused without --replace, a stale fit is made again with
// fit --refit, `fits` says what each fit was built from, per-level fits have
// names of their own shape, and --mirror lets each run stand for its mirror
// image without storing it.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/run_cli.hpp"
#include "tests/support/sphere_cases.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

const std::string kSurge = HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-surge-damping.csv";

class FitCuration : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto imported = run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing"}, dir_.path());
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
  }
  nlohmann::json fits() {
    const auto result = run_cli({"fits", "--json"}, dir_.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return nlohmann::json::parse(result.out);
  }
  TempDir dir_;
};

TEST_F(FitCuration, ANameIsReusedOnlyWithReplace) {
  const std::vector<std::string> fit = {"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|"};
  ASSERT_EQ(run_cli(fit, dir_.path()).exit_code, 0);
  const auto before = test::dump_database(dir_ / "hydrocoef.db");
  std::vector<std::string> other = fit;
  other.insert(other.end(), {"--where", "u>=0.1", "--name", "asr-v:X(u,u|u|)"});
  const auto refused = run_cli(other, dir_.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("a fit named 'asr-v:X(u,u|u|)' exists"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--replace"), std::string::npos) << refused.err;
  EXPECT_EQ(test::dump_database(dir_ / "hydrocoef.db"), before);

  other.push_back("--replace");
  ASSERT_EQ(run_cli(other, dir_.path()).exit_code, 0);
  const auto stored = fits();
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].at("where"), "u>=0.1");
  // `fits` says what each fit was built from.
  const auto text = run_cli({"fits"}, dir_.path());
  EXPECT_NE(text.out.find("from " + std::to_string(stored[0].at("runs").size()) + " runs where u>=0.1"),
            std::string::npos)
      << text.out;
}

TEST_F(FitCuration, AStaleFitIsMadeAgainWithRefit) {
  ASSERT_EQ(run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--where", "u>=0.1"}, dir_.path())
                .exit_code,
            0);
  const auto first = fits()[0];
  EXPECT_FALSE(first.at("stale").get<bool>());
  // Nothing is stale: --refit says so and changes nothing.
  const auto before = test::dump_database(dir_ / "hydrocoef.db");
  const auto nothing = run_cli({"fit", "--refit"}, dir_.path());
  EXPECT_EQ(nothing.exit_code, 0) << nothing.err;
  EXPECT_NE(nothing.out.find("no stale fits"), std::string::npos) << nothing.out;
  EXPECT_EQ(test::dump_database(dir_ / "hydrocoef.db"), before);

  // The fastest run is deleted: the fit goes stale, and --refit makes it from the rest.
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json", "--where", "u>=0.1"}, dir_.path()).out);
  std::int64_t fastest = 0;
  double top = -1;
  for (const auto& run : runs)
    if (run.at("u").get<double>() > top) {
      top = run.at("u").get<double>();
      fastest = run.at("id").get<std::int64_t>();
    }
  ASSERT_EQ(run_cli({"runs", "delete", std::to_string(fastest)}, dir_.path()).exit_code, 0);
  EXPECT_TRUE(fits()[0].at("stale").get<bool>());
  const auto refit = run_cli({"fit", "--refit", "--json"}, dir_.path());
  ASSERT_EQ(refit.exit_code, 0) << refit.err;
  const auto made = nlohmann::json::parse(refit.out);
  ASSERT_EQ(made.size(), 1u);
  EXPECT_EQ(made[0].at("runs").size(), runs.size() - 1);
  const auto after = fits()[0];
  EXPECT_FALSE(after.at("stale").get<bool>());
  EXPECT_EQ(after.at("name"), first.at("name"));
  EXPECT_EQ(after.at("where"), "u>=0.1");
  // The same as fitting the remaining runs by hand.
  const auto by_hand = run_cli(
      {"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--where", "u>=0.1", "--no-store", "--json"},
      dir_.path());
  const auto expected = nlohmann::json::parse(by_hand.out);
  for (const char* term : {"u", "u|u|"}) {
    EXPECT_NEAR(after.at("coefficients").at(term).get<double>(), expected.at("coefficients").at(term).get<double>(),
                1e-12);
    EXPECT_NE(after.at("coefficients").at(term).get<double>(), first.at("coefficients").at(term).get<double>());
  }
  // --refit takes no law or selection of its own.
  const auto mixed = run_cli({"fit", "--refit", "--dof", "X"}, dir_.path());
  EXPECT_EQ(mixed.exit_code, 2);
  EXPECT_NE(mixed.err.find("--refit"), std::string::npos) << mixed.err;
}

TEST(FitCurationMirror, AMirroredFitOverHalfThePlaneIsTheFitOverTheWholePlane) {
  TempDir dir;
  // Sway force of a port-starboard symmetric body over v >= 0 only, and the
  // same runs with their mirror images written out.
  std::ostringstream half, whole;
  half << "v [m s^-1],Y [N],N [N m]\n";
  whole << "v [m s^-1],Y [N],N [N m]\n";
  const std::vector<double> vs = {0.0, 0.05, 0.1, 0.2, 0.3};
  for (std::size_t i = 0; i < vs.size(); ++i) {
    const double v = vs[i];
    const double y = -2.0 * v - 30.0 * v * std::abs(v) + 0.004 * std::sin(3.0 * static_cast<double>(i) + 1.0);
    half << v << "," << y << "," << 0.1 * y << "\n";
    whole << v << "," << y << "," << 0.1 * y << "\n";
    if (v != 0.0) whole << -v << "," << -y << "," << -0.1 * y << "\n";
  }
  std::ofstream(dir / "half.csv") << half.str();
  std::ofstream(dir / "whole.csv") << whole.str();
  ASSERT_EQ(run_cli({"--db", "half.db", "import", "half.csv", "--body", "b"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli({"--db", "whole.db", "import", "whole.csv", "--body", "b"}, dir.path()).exit_code, 0);
  const auto mirrored =
      run_cli({"--db", "half.db", "fit", "--body", "b", "--dof", "Y", "--terms", "1,v,v|v|", "--mirror", "v", "--json"},
              dir.path());
  ASSERT_EQ(mirrored.exit_code, 0) << mirrored.err;
  const auto explicit_runs =
      run_cli({"--db", "whole.db", "fit", "--body", "b", "--dof", "Y", "--terms", "1,v,v|v|", "--json"}, dir.path());
  ASSERT_EQ(explicit_runs.exit_code, 0) << explicit_runs.err;
  const auto a = nlohmann::json::parse(mirrored.out), b = nlohmann::json::parse(explicit_runs.out);
  EXPECT_EQ(a.at("mirror_images").get<int>(), 4);
  EXPECT_EQ(a.at("n").get<int>(), 9);
  for (const char* term : {"1", "v", "v|v|"})
    EXPECT_NEAR(a.at("coefficients").at(term).get<double>(), b.at("coefficients").at(term).get<double>(),
                1e-9 * (1.0 + std::abs(b.at("coefficients").at(term).get<double>())))
        << term;
  // The images are not stored as runs; the fit remembers its mirror and refits with it.
  EXPECT_EQ(nlohmann::json::parse(run_cli({"--db", "half.db", "runs", "--json"}, dir.path()).out).size(), 5u);
  const auto stored = nlohmann::json::parse(run_cli({"--db", "half.db", "fits", "--json"}, dir.path()).out);
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].at("mirror"), "v");
  const auto again = run_cli({"--db", "half.db", "fit", "--refit", "--name", "b:Y(1,v,v|v|)", "--json"}, dir.path());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NEAR(nlohmann::json::parse(again.out)[0].at("coefficients").at("v").get<double>(),
              b.at("coefficients").at("v").get<double>(),
              1e-9 * (1.0 + std::abs(b.at("coefficients").at("v").get<double>())));

  // A surface over v from half the plane covers the whole plane.
  const auto surface = run_cli({"--db", "half.db", "surface", "build", "side", "--body", "b", "--outputs", "Y",
                                "--axes", "v", "--method", "pchip", "--mirror", "v", "--json"},
                               dir.path());
  ASSERT_EQ(surface.exit_code, 0) << surface.err;
  const auto built = nlohmann::json::parse(surface.out);
  EXPECT_EQ(built.at("mirror_images").get<int>(), 4);
  EXPECT_EQ(built.at("axes")[0].at("lower").get<double>(), -0.3);
  EXPECT_EQ(built.at("axes")[0].at("upper").get<double>(), 0.3);
  // surface list says what each surface was built from.
  const auto list = run_cli({"--db", "half.db", "surface", "list"}, dir.path());
  EXPECT_NE(list.out.find("all runs, mirror v"), std::string::npos) << list.out;
}

TEST(FitCurationHistories, RunsShowTheirHistoryStatisticsAndFitsWarnOfUnconvergedOnes) {
  TempDir dir;
  ASSERT_EQ(test::import_sphere_cases(dir.path()).exit_code, 0);
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 4u);
  std::size_t flagged = 0;
  std::vector<std::string> where_v0;
  for (const auto& run : runs) {
    for (const char* c : {"X", "Y", "Z", "K", "M", "N"}) {
      const auto& st = run.at("forces").at(c).at("statistics");
      EXPECT_GT(st.at("standard_error").get<double>(), 0.0);
      EXPECT_GT(st.at("samples").get<int>(), 1);
      EXPECT_LT(st.at("window")[0].get<double>(), st.at("window")[1].get<double>());
      EXPECT_EQ(st.at("abscissa"), "iteration");  // steady runs: pseudo-time
    }
    if (!run.at("flags").empty()) ++flagged;
  }
  const auto table = run_cli({"runs"}, dir.path());
  EXPECT_NE(table.out.find("history"), std::string::npos) << table.out;
  EXPECT_EQ(table.out.find("* = as tabulated"), std::string::npos) << table.out;  // no row has one
  const auto fit = run_cli({"fit", "--body", "sphere", "--dof", "X", "--terms", "u|u|", "--json"}, dir.path());
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  bool warned = false;
  const auto fitted = nlohmann::json::parse(fit.out);
  for (const auto& warning : fitted.at("warnings")) warned = warned || warning.at("kind") == "unconverged-runs";
  EXPECT_EQ(warned, flagged > 0);
  // A table's runs have no history: no column, no warning.
  TempDir other;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing"}, other.path()).exit_code, 0);
  const auto plain = run_cli({"runs"}, other.path());
  EXPECT_EQ(plain.out.find("history"), std::string::npos) << plain.out;
  EXPECT_NE(plain.out.find("* = as tabulated"), std::string::npos) << plain.out;
}

// Runs averaged over force histories state a standard error: fits weight
// them by 1/s^2 by default, report the reduced chi^2 and the covariance,
// store how they were weighted, and a refit weights them again.
TEST(FitCurationHistories, FitsAreWeightedByTheRunsStandardErrors) {
  TempDir dir;
  ASSERT_EQ(test::import_sphere_cases(dir.path()).exit_code, 0);
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  // The weighted least-squares slope of X = c u|u| through the origin:
  // c = sum(w h y) / sum(w h^2), var(c) = 1 / sum(w h^2), h = u|u|, w = 1/s^2.
  double swhy = 0.0, swhh = 0.0;
  std::vector<std::pair<double, double>> points;
  for (const auto& run : runs) {
    const double u = run.at("u"), y = run.at("forces").at("X").at("total");
    const double s = run.at("forces").at("X").at("statistics").at("standard_error");
    const double h = u * std::abs(u), w = 1.0 / (s * s);
    swhy += w * h * y;
    swhh += w * h * h;
    points.push_back({h, y});
  }
  const double c = swhy / swhh;
  double chi2 = 0.0;
  for (const auto& run : runs) {
    const double u = run.at("u"), y = run.at("forces").at("X").at("total");
    const double s = run.at("forces").at("X").at("statistics").at("standard_error");
    chi2 += std::pow((y - c * u * std::abs(u)) / s, 2);
  }
  chi2 /= static_cast<double>(runs.size() - 1);

  const auto fit =
      run_cli({"fit", "--body", "sphere", "--dof", "X", "--terms", "u|u|", "--name", "drag", "--json"}, dir.path());
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const auto fitted = nlohmann::json::parse(fit.out);
  EXPECT_EQ(fitted.at("weighting"), "uncertainty");
  EXPECT_NEAR(fitted.at("coefficients").at("u|u|").get<double>(), c, 1e-9 * std::abs(c));
  // The runs scatter far more than their standard errors say (chi^2/(n-k) in
  // the thousands): the covariance is scaled by it (the Birge ratio squared).
  const double scale = std::max(1.0, chi2);
  EXPECT_GT(chi2, 100.0);
  EXPECT_NEAR(fitted.at("std_errors").at("u|u|").get<double>(), std::sqrt(scale / swhh),
              1e-7 * std::sqrt(scale / swhh));
  EXPECT_NEAR(fitted.at("chi2_reduced").get<double>(), chi2, 1e-8 * chi2);
  EXPECT_NEAR(fitted.at("covariance")[0].get<double>(), scale / swhh, 1e-7 * scale / swhh);
  const auto text = run_cli({"fit", "--body", "sphere", "--dof", "X", "--terms", "u|u|", "--no-store"}, dir.path());
  EXPECT_NE(text.out.find("reduced chi^2 = "), std::string::npos) << text.out;

  const auto stored = nlohmann::json::parse(run_cli({"fits", "--json"}, dir.path()).out);
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].at("weighting"), "uncertainty");
  EXPECT_EQ(stored[0].at("chi2_reduced"), fitted.at("chi2_reduced"));
  EXPECT_EQ(stored[0].at("covariance"), fitted.at("covariance"));
  // Made again, it is weighted again.
  const auto refit = run_cli({"fit", "--refit", "--name", "drag", "--json"}, dir.path());
  ASSERT_EQ(refit.exit_code, 0) << refit.err;
  const auto again = nlohmann::json::parse(run_cli({"fits", "--json"}, dir.path()).out);
  EXPECT_EQ(again[0].at("weighting"), "uncertainty");
  EXPECT_EQ(again[0].at("coefficients"), stored[0].at("coefficients"));

  // --unweighted: ordinary least squares, no chi^2.
  const auto plain = run_cli(
      {"fit", "--body", "sphere", "--dof", "X", "--terms", "u|u|", "--unweighted", "--no-store", "--json"}, dir.path());
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const auto unweighted = nlohmann::json::parse(plain.out);
  EXPECT_EQ(unweighted.at("weighting"), "none");
  EXPECT_TRUE(unweighted.at("chi2_reduced").is_null());
  double shy = 0.0, shh = 0.0;
  for (const auto& [h, y] : points) shy += h * y, shh += h * h;
  EXPECT_NEAR(unweighted.at("coefficients").at("u|u|").get<double>(), shy / shh, 1e-9 * std::abs(shy / shh));

  // A table's values state no standard error: unweighted, without a word.
  TempDir other;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing"}, other.path()).exit_code, 0);
  const auto table = nlohmann::json::parse(
      run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--no-store", "--json"}, other.path()).out);
  EXPECT_EQ(table.at("weighting"), "none");
  for (const auto& warning : table.at("warnings")) EXPECT_NE(warning.at("kind"), "unweighted");
}

}  // namespace
}  // namespace hydrocoef
