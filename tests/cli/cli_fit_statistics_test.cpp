// Fits whose statistics are undefined, and per-level fits over a sweep with a
// sparse level, from the command line: a constant force (a symmetric body's
// side force) fits with R^2 shown and stored as n/a instead of failing; fit
// --by stores every level's fit in one transaction, skips a level with too
// few runs with a note, or refuses the whole fit with --strict leaving the
// database as it was; names that break the name rule are refused.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

// Sway-current sweep: X(u) at vc = 0 (4 runs), 0.1 (4 runs), 0.2 (1 run); Y = 0 everywhere.
void write_sweep(const std::filesystem::path& path) {
  std::ofstream out(path);
  out << "u [m s^-1],vc [m s^-1],X [N],Y [N]\n";
  for (const double vc : {0.0, 0.1})
    for (const double u : {0.1, 0.2, 0.3, 0.4}) out << u << "," << vc << "," << -(1.0 + vc) * 11.0 * u * u << ",0\n";
  out << "0.25,0.2,-0.8,0\n";
}

class FitStatistics : public ::testing::Test {
 protected:
  void SetUp() override {
    write_sweep(dir_ / "sweep.csv");
    const auto imported =
        run_cli({"import", "sweep.csv", "--body", "b", "--disturbance", "vc", "--sign", "on-body"}, dir_.path());
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
  }
  TempDir dir_;
};

TEST_F(FitStatistics, AConstantForceFitsWithRSquaredNotAvailable) {
  const auto text = run_cli({"fit", "--body", "b", "--dof", "Y", "--terms", "u", "--where", "vc=0"}, dir_.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("R^2 = n/a (the force does not vary"), std::string::npos) << text.out;
  const auto fits = run_cli({"fits", "--json"}, dir_.path());
  ASSERT_EQ(fits.exit_code, 0) << fits.err;
  const auto list = nlohmann::json::parse(fits.out);
  ASSERT_EQ(list.size(), 1u);
  EXPECT_TRUE(list[0].at("r2").is_null()) << fits.out;
  EXPECT_NE(run_cli({"fits"}, dir_.path()).out.find("R^2=n/a"), std::string::npos);
}

TEST_F(FitStatistics, PerLevelFitsSkipASparseLevelOrRefuseWithStrict) {
  const auto before = test::dump_database(dir_ / "hydrocoef.db");
  const auto strict = run_cli(
      {"fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--by", "vc", "--curve", "polynomial:1", "--strict"},
      dir_.path());
  EXPECT_EQ(strict.exit_code, 2);
  EXPECT_NE(strict.err.find("disturbance level 0.2 has 1 run"), std::string::npos) << strict.err;
  EXPECT_EQ(test::dump_database(dir_ / "hydrocoef.db"), before);

  const auto skipping = run_cli(
      {"fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--by", "vc", "--curve", "polynomial:1", "--json"},
      dir_.path());
  ASSERT_EQ(skipping.exit_code, 0) << skipping.err;
  const auto out = nlohmann::json::parse(skipping.out);
  EXPECT_EQ(out.at("levels").size(), 2u);
  ASSERT_EQ(out.at("skipped_levels").size(), 1u);
  EXPECT_EQ(out.at("skipped_levels")[0].at("level").get<double>(), 0.2);
  EXPECT_EQ(out.at("skipped_levels")[0].at("runs").get<int>(), 1);
  // The two levels' fits are stored, with their runs.
  const auto fits = nlohmann::json::parse(run_cli({"fits", "--json"}, dir_.path()).out);
  EXPECT_EQ(fits.size(), 2u);
  // u|u| at vc = 0.1 is -(1.1)(11) exactly: the data are exact.
  for (const auto& level : out.at("levels")) {
    if (level.at("level").get<double>() == 0.1) {
      EXPECT_NEAR(level.at("coefficients").at("u|u|").get<double>(), -12.1, 1e-9);
    }
  }

  const auto text = run_cli(
      {"fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--by", "vc", "--curve", "polynomial:1", "--no-store"},
      dir_.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("note: level vc=0.2 skipped: 1 run"), std::string::npos) << text.out;
}

TEST_F(FitStatistics, NamesThatBreakTheRuleAreRefused) {
  const auto before = test::dump_database(dir_ / "hydrocoef.db");
  const auto fit =
      run_cli({"fit", "--body", "b", "--dof", "X", "--terms", "u", "--name", "a\nsystem(\"x\")"}, dir_.path());
  EXPECT_EQ(fit.exit_code, 2);
  EXPECT_NE(fit.err.find("fit name from --name"), std::string::npos) << fit.err;
  const auto surface =
      run_cli({"surface", "build", "s\x01", "--body", "b", "--outputs", "X", "--axes", "u"}, dir_.path());
  EXPECT_EQ(surface.exit_code, 2);
  EXPECT_NE(surface.err.find("surface name"), std::string::npos) << surface.err;
  EXPECT_EQ(test::dump_database(dir_ / "hydrocoef.db"), before);
}

// A sway law fitted to a noisy side force that pushes along the motion: the
// fit warns, export-gazebo refuses it unless --allow-unphysical.
TEST(PhysicalChecks, AnEnergyProducingLawIsAWarningOnFitAndARefusalOnExport) {
  TempDir dir;
  {
    std::ofstream out(dir / "sway.csv");
    out << "v [m s^-1],Y [N]\n";
    for (const double v : {-0.3, -0.2, -0.1, 0.1, 0.2, 0.3}) out << v << "," << 3.4 * v << "\n";
  }
  ASSERT_EQ(run_cli({"import", "sway.csv", "--body", "b", "--sign", "on-body"}, dir.path()).exit_code, 0);
  const auto fit = run_cli({"fit", "--body", "b", "--dof", "Y", "--terms", "v"}, dir.path());
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  EXPECT_NE(fit.out.find("warning (energy-producing)"), std::string::npos) << fit.out;
  const auto refused = run_cli(
      {"export-gazebo", "b", "--flavor", "uuv", "-o", "b.xml", "--allow-missing", "--added-mass", "1,1,1,0.1,0.1,0.1"},
      dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("pushes the body along its motion"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "b.xml"));
  const auto allowed = run_cli({"export-gazebo", "b", "--flavor", "uuv", "-o", "b.xml", "--allow-missing",
                                "--added-mass", "1,1,1,0.1,0.1,0.1", "--allow-unphysical"},
                               dir.path());
  EXPECT_EQ(allowed.exit_code, 0) << allowed.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "b.xml"));
}

}  // namespace
}  // namespace hydrocoef
