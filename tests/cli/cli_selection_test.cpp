// The one selection language on the command line (src/core/run_selection):
// runs, fit and surface build take --where with = != < <= > >= and ranges,
// several combined with AND, and --exclude-run; a bad clause is named.
// Leave-one-out by hand is one command: surface build --exclude-run, then
// query at the left-out run.
#include <gtest/gtest.h>

#include <algorithm>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "tests/support/csv_record.hpp"
#include "tests/support/hostile_names.hpp"
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

// runs --csv with hostile body names (the corpus holds =HYPERLINK(...), +1+1,
// -2+3, @SUM(A1), -0.5): after RFC 4180 parsing no cell starts like a
// formula, each body cell is its name (less the guard quote) and every other
// cell of a run's row is a plain number or empty, negative forces included.
TEST(RunsCsv, HostileBodyNamesAreTextAndNumbersStayNumbers) {
  TempDir dir;
  std::set<std::string> bodies;
  for (const std::string& name : test::hostile_names()) {
    if (name_problem(NameKind::Body, name)) continue;  // a name no body can have
    // Other bytes for each body: the same file again would be another reading of it.
    const auto table = dir / "table.csv";
    std::ofstream(table) << "u [m s^-1],X [N]\n0.5," << 1.0 + static_cast<double>(bodies.size()) << "\n";
    const auto imported = run_cli({"import", table.string(), "--body=" + name, "--sign", "opposing"}, dir.path());
    ASSERT_EQ(imported.exit_code, 0) << name << ": " << imported.err;
    bodies.insert(name);
  }
  ASSERT_GT(bodies.size(), 20u);
  const auto csv = run_cli({"runs", "--csv"}, dir.path());
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  std::istringstream lines(csv.out);
  std::string line;
  std::vector<std::vector<std::string>> rows;
  while (std::getline(lines, line)) {
    const auto record = test::csv_record(line);
    ASSERT_TRUE(record) << line;
    rows.push_back(*record);
  }
  ASSERT_EQ(rows.size(), 1 + bodies.size());
  ASSERT_EQ(rows[0][8], "X");
  std::set<std::string> seen;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    ASSERT_EQ(row.size(), rows[0].size()) << csv.out;
    for (const auto& cell : row) EXPECT_FALSE(test::formula_cell(cell) && !test::number_cell(cell)) << cell;
    seen.insert(escape::csv_text_value(row[1]));
    for (std::size_t j = 2; j + 1 < row.size(); ++j) EXPECT_TRUE(row[j].empty() || test::number_cell(row[j])) << row[j];
    EXPECT_LT(std::stod(row[8]), 0.0);  // drag on the body: X < 0, written as a number
  }
  EXPECT_EQ(seen, bodies);
}

// A file name holding a terminal escape sequence reaches the terminal only
// through escape::one_line: import's per-file line, the runs table and runs
// show's sources and import records (read back from the database) hold no ESC.
TEST(TerminalText, EscapeSequencesInFileNamesNeverReachTheTerminal) {
  TempDir dir;
  const auto table = dir / "red\x1b[31m\x1b]0;title\x07.csv";
  std::ofstream(table) << "u [m s^-1],X [N]\n0.5,1.5\n";
  const auto has_esc = [](const test::CliResult& result) {
    return result.out.find('\x1b') != std::string::npos || result.err.find('\x1b') != std::string::npos;
  };
  const auto imported = run_cli({"import", table.string(), "--body", "hull", "--sign", "opposing"}, dir.path());
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_NE(imported.out.find("red"), std::string::npos) << imported.out;  // the line is there, made printable
  EXPECT_FALSE(has_esc(imported)) << imported.out;
  const auto again = run_cli({"import", table.string(), "--body", "hull", "--sign", "opposing"}, dir.path());
  EXPECT_FALSE(has_esc(again)) << again.out;  // "already imported (... as PATH ...)"
  const auto listed = run_cli({"runs"}, dir.path());
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  EXPECT_FALSE(has_esc(listed)) << listed.out;
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 1u);
  const auto shown = run_cli({"runs", "show", std::to_string(runs[0].at("id").get<std::int64_t>())}, dir.path());
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_NE(shown.out.find("  import "), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find("red"), std::string::npos) << shown.out;
  EXPECT_FALSE(has_esc(shown)) << shown.out;
}

}  // namespace
}  // namespace hydrocoef
