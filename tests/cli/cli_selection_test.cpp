// The one selection language on the command line (src/core/run_selection):
// runs, fit and surface build take --where with = != < <= > >= and ranges,
// several combined with AND, and --exclude-run; a bad clause is named.
// Leave-one-out by hand is one command: surface build --exclude-run, then
// query at the left-out run.
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/csv_record.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

const std::string kSurge = HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-surge-damping.csv";

class Selection : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto imported = run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing"}, dir_.path());
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    all_ = nlohmann::json::parse(run_cli({"runs", "--json"}, dir_.path()).out);
    ASSERT_EQ(all_.size(), 20u);
  }
  nlohmann::json runs(const std::vector<std::string>& options) {
    std::vector<std::string> args = {"runs", "--json"};
    args.insert(args.end(), options.begin(), options.end());
    const auto result = run_cli(args, dir_.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return nlohmann::json::parse(result.out);
  }
  TempDir dir_;
  nlohmann::json all_;
};

TEST_F(Selection, ClausesCombineWithAndAndRunsCanBeLeftOut) {
  std::size_t expected = 0;
  for (const auto& run : all_) {
    const double u = run.at("u").get<double>();
    expected += (u >= 0.1 - 1e-12 && u < 0.3) ? 1 : 0;
  }
  EXPECT_EQ(runs({"--where", "u>=0.1", "--where", "u<0.3"}).size(), expected);
  EXPECT_EQ(runs({"--where", "u=0.1:0.3"}).size(), expected + 1);  // the range includes 0.3
  EXPECT_EQ(runs({"--where", "u!=0"}).size(), all_.size() - 1);
  const auto first = all_[0].at("id").get<std::int64_t>();
  const auto without = runs({"--exclude-run", std::to_string(first)});
  EXPECT_EQ(without.size(), all_.size() - 1);
  for (const auto& run : without) EXPECT_NE(run.at("id").get<std::int64_t>(), first);

  const auto bad = run_cli({"runs", "--where", "u>=fast"}, dir_.path());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("u>=fast"), std::string::npos) << bad.err;
}

TEST_F(Selection, LeaveOneOutByHandIsOneBuildAndOneQuery) {
  // The run at u = 0.2 (an interior run), left out of a linear table.
  std::int64_t left_out = 0;
  double below = 0, above = 0, own = 0;
  for (const auto& run : all_) {
    const double u = run.at("u").get<double>();
    const double x = run.at("forces").at("X").at("total").get<double>();
    if (std::abs(u - 0.2) < 1e-12) {
      left_out = run.at("id").get<std::int64_t>();
      own = x;
    }
    if (std::abs(u - 0.18) < 1e-12) below = x;
    if (std::abs(u - 0.22) < 1e-12) above = x;
  }
  ASSERT_NE(left_out, 0);
  const auto built = run_cli({"surface", "build", "loo", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method",
                              "linear", "--exclude-run", std::to_string(left_out)},
                             dir_.path());
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const auto query = run_cli({"query", "loo", "u=0.2", "--json"}, dir_.path());
  ASSERT_EQ(query.exit_code, 0) << query.err;
  const double predicted = nlohmann::json::parse(query.out).at("values").at("X").get<double>();
  // Without its own run, the table interpolates the neighbours (forces on the body: negated magnitudes).
  ASSERT_NE(below, 0.0);
  ASSERT_NE(above, 0.0);
  EXPECT_NEAR(predicted, -(below + above) / 2, 1e-12 * std::abs(predicted));
  EXPECT_GT(std::abs(predicted + own), 1e-4);  // and not the left-out run's own value
  const auto shown = nlohmann::json::parse(run_cli({"surface", "show", "loo", "--json"}, dir_.path()).out);
  EXPECT_EQ(shown.at("runs").size(), all_.size() - 1);
  // The name is taken: building it again needs --replace.
  const std::vector<std::string> again = {"surface", "build",  "loo", "--body",   "asr-v", "--outputs",
                                          "X",       "--axes", "u",   "--method", "linear"};
  const auto refused = run_cli(again, dir_.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("a surface named 'loo' exists"), std::string::npos) << refused.err;
  auto replacing = again;
  replacing.push_back("--replace");
  EXPECT_EQ(run_cli(replacing, dir_.path()).exit_code, 0);
  const auto whole = nlohmann::json::parse(run_cli({"surface", "show", "loo", "--json"}, dir_.path()).out);
  EXPECT_EQ(whole.at("runs").size(), all_.size());
  // The stored per-run leave-one-out errors: the one of the run at u = 0.2 is
  // what the build without it predicted there, minus its own value.
  const auto& quality = whole.at("quality");
  const auto runs = quality.at("loo_runs").get<std::vector<std::int64_t>>();
  const auto& errors = quality.at("outputs").at("X").at("loo_errors");
  ASSERT_EQ(errors.size(), runs.size());
  const auto at = std::find(runs.begin(), runs.end(), left_out);
  ASSERT_NE(at, runs.end());
  EXPECT_NEAR(std::abs(errors[static_cast<std::size_t>(at - runs.begin())].get<double>()), std::abs(predicted + own),
              1e-12);
  // The worst run is named, and its error is the stored maximum.
  const auto& worst = whole.at("loo_worst").at("X");
  EXPECT_NEAR(std::abs(worst.at("error").get<double>()), quality.at("outputs").at("X").at("loo_max").get<double>(),
              1e-15);
  const auto text = run_cli({"surface", "show", "loo"}, dir_.path());
  EXPECT_NE(text.out.find("(worst: run " + std::to_string(worst.at("run").get<std::int64_t>())), std::string::npos)
      << text.out;
}

// runs --csv: one well-formed row per selected run, forces on the body.
TEST_F(Selection, RunsAsCsvHaveOneRowPerRunWithForcesOnTheBody) {
  const auto csv = run_cli({"runs", "--csv", "--where", "u>0"}, dir_.path());
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  std::istringstream lines(csv.out);
  std::string line;
  std::vector<std::vector<std::string>> rows;
  while (std::getline(lines, line)) {
    const auto record = test::csv_record(line);
    ASSERT_TRUE(record) << line;
    rows.push_back(*record);
  }
  ASSERT_EQ(rows.size(), 1 + all_.size() - 1);  // the header, every run but the one at rest
  EXPECT_EQ(rows[0][2], "u");
  EXPECT_EQ(rows[0][8], "X");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), rows[0].size());
    EXPECT_LT(std::stod(rows[i][8]), 0.0);  // drag on a body moving forward: X < 0
  }
}

}  // namespace
}  // namespace hydrocoef
