// Uncertainty given at import (import --uncertainty): stored with each value,
// absolute or relative, combined with a history's standard error in
// quadrature, used to weight fits; malformed values refused naming the
// option; a re-import with another uncertainty is another reading of the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using nlohmann::json;
using test::run_cli;
using test::TempDir;

const std::string kSurge = HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-surge-damping.csv";

TEST(GivenUncertainty, IsStoredAndWeightsTheFit) {
  TempDir dir;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--uncertainty", "X=0.002"}, dir.path())
                .exit_code,
            0);
  const auto runs = json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  std::size_t n = 0;
  for (const auto& run : runs) {
    if (!run["forces"].contains("X")) continue;
    ++n;
    EXPECT_EQ(run["forces"]["X"]["given_uncertainty"], 0.002);
    EXPECT_EQ(run["forces"]["X"]["standard_uncertainty"], 0.002);
  }
  ASSERT_GT(n, 3u);
  const auto weighted = json::parse(
      run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--no-store", "--json"}, dir.path()).out);
  const auto plain = json::parse(
      run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--no-store", "--unweighted", "--json"},
              dir.path())
          .out);
  EXPECT_EQ(weighted["weighting"], "uncertainty");
  EXPECT_EQ(plain["weighting"], "none");
  // One uncertainty for every run: the unweighted coefficients, and
  // chi^2 / (n - k) = SSR / s^2 / (n - k) with SSR = n RMSE^2.
  for (const char* term : {"u", "u|u|"})
    EXPECT_NEAR(weighted["coefficients"][term].get<double>(), plain["coefficients"][term].get<double>(),
                1e-9 * std::abs(plain["coefficients"][term].get<double>()));
  const double rmse = plain["rmse"], runs_fitted = plain["n"];
  EXPECT_NEAR(weighted["chi2_reduced"].get<double>(), runs_fitted * rmse * rmse / (0.002 * 0.002) / (runs_fitted - 2),
              1e-8 * weighted["chi2_reduced"].get<double>());
}

TEST(GivenUncertainty, ARelativeValueIsAFractionOfEachValue) {
  TempDir dir;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--uncertainty", "X=10%"}, dir.path())
                .exit_code,
            0);
  for (const auto& run : json::parse(run_cli({"runs", "--json"}, dir.path()).out)) {
    if (!run["forces"].contains("X")) continue;
    const double total = run["forces"]["X"]["total"];
    EXPECT_NEAR(run["forces"]["X"]["given_uncertainty"].get<double>(), 0.1 * std::abs(total), 1e-15);
  }
}

TEST(GivenUncertainty, CombinesWithAHistorysStandardErrorInQuadrature) {
  TempDir dir;
  std::filesystem::path cases = HYDROCOEF_SOURCE_DIR "/data/openfoam-sphere/cases";
  std::vector<std::string> args = {"import"};
  for (const auto& entry : std::filesystem::directory_iterator(cases)) args.push_back(entry.path().string());
  args.insert(args.end(), {"--body", "sphere", "--axes=-x,y,-z", "--quiet", "--uncertainty", "X=0.001"});
  ASSERT_EQ(run_cli(args, dir.path()).exit_code, 0);
  for (const auto& run : json::parse(run_cli({"runs", "--json"}, dir.path()).out)) {
    const auto& x = run["forces"]["X"];
    const double se = x["statistics"]["standard_error"];
    EXPECT_NEAR(x["standard_uncertainty"].get<double>(), std::hypot(se, 0.001), 1e-15);
    EXPECT_TRUE(run["forces"]["Y"]["given_uncertainty"].is_null());
  }
}

TEST(GivenUncertainty, MalformedValuesAreRefusedAndNothingIsWritten) {
  TempDir dir;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing"}, dir.path()).exit_code, 0);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  for (const std::string bad : {"Q=1", "X=-1", "X=abc", "X=2000%", "X", "X=1,X=2", "X=nan"}) {
    const auto result =
        run_cli({"import", kSurge, "--body", "other", "--sign", "opposing", "--uncertainty", bad}, dir.path());
    EXPECT_EQ(result.exit_code, 2) << bad;
    EXPECT_NE(result.err.find("--uncertainty"), std::string::npos) << bad << ": " << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  }
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
}

TEST(GivenUncertainty, AnotherUncertaintyIsAnotherReadingOfTheFile) {
  TempDir dir;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--uncertainty", "X=0.002"}, dir.path())
                .exit_code,
            0);
  const auto again =
      run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--uncertainty", "X=0.003"}, dir.path());
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("uncertainty"), std::string::npos) << again.err;
  ASSERT_EQ(
      run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--uncertainty", "X=0.003", "--replace"},
              dir.path())
          .exit_code,
      0);
  for (const auto& run : json::parse(run_cli({"runs", "--json"}, dir.path()).out)) {
    if (run["forces"].contains("X")) {
      EXPECT_EQ(run["forces"]["X"]["given_uncertainty"], 0.003);
    }
  }
}

TEST(GivenUncertainty, AGridSurfaceStatesItThroughQueryBatchShowAndExport) {
  // One given uncertainty for every run: a linear table's interpolated runs'
  // part is that number everywhere, so sd = sqrt(0.002^2 + loo_rms^2).
  TempDir dir;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--uncertainty", "X=0.002"}, dir.path())
                .exit_code,
            0);
  const auto build =
      run_cli({"surface", "build", "surge", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method", "linear"},
              dir.path());
  ASSERT_EQ(build.exit_code, 0) << build.err;
  EXPECT_NE(build.out.find("uncertainty: sd^2"), std::string::npos) << build.out;
  const auto show = json::parse(run_cli({"surface", "show", "surge", "--json"}, dir.path()).out);
  const double loo = show["quality"]["outputs"]["X"]["loo_rms"];
  ASSERT_GT(loo, 0.0);
  const double expected = std::hypot(0.002, loo);
  EXPECT_EQ(show["uncertainty"]["outputs"]["X"]["loo_sd"], loo);
  ASSERT_EQ(show["uncertainty"]["outputs"]["X"]["largest_sd"].size(), 3u);
  EXPECT_NEAR(show["uncertainty"]["outputs"]["X"]["largest_sd"][0]["sd"].get<double>(), expected, 1e-12);
  // Three distinct points: at least 1% of the range apart (a node and the lattice point on it are one).
  const auto& largest = show["uncertainty"]["outputs"]["X"]["largest_sd"];
  const double range = show["axes"][0]["upper"].get<double>() - show["axes"][0]["lower"].get<double>();
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = i + 1; j < 3; ++j)
      EXPECT_GT(std::abs(largest[i]["point"]["u"].get<double>() - largest[j]["point"]["u"].get<double>()),
                0.01 * range);

  const auto point = json::parse(run_cli({"query", "surge", "u=0.05", "--uncertainty", "--json"}, dir.path()).out);
  EXPECT_NEAR(point["standard_deviation"]["X"].get<double>(), expected, 1e-12);

  std::ofstream(dir.path() / "points.csv") << "u\n0.05\n0.1\n";
  const auto batch = run_cli({"query", "surge", "--input", "points.csv", "--uncertainty"}, dir.path());
  ASSERT_EQ(batch.exit_code, 0) << batch.err;
  std::istringstream lines(batch.out);
  std::string header, row;
  std::getline(lines, header);
  EXPECT_EQ(header, "u,X,sigma_X");
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(std::getline(lines, row));
    EXPECT_NEAR(std::stod(row.substr(row.rfind(',') + 1)), expected, 1e-9 * expected) << row;
  }

  ASSERT_EQ(run_cli({"export", "surge", "--format", "json", "-o", "surge.json"}, dir.path()).exit_code, 0);
  std::ifstream file(dir.path() / "surge.json");
  const auto exported = json::parse(file);
  ASSERT_TRUE(exported.contains("sigma"));
  EXPECT_EQ(exported["sigma"]["X"].size(), exported["values"]["X"].size());
  for (const auto& sd : exported["sigma"]["X"]) EXPECT_NEAR(sd.get<double>(), expected, 1e-12);
}

}  // namespace
}  // namespace hydrocoef
