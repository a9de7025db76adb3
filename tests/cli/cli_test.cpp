// End-to-end tests of the hydrocoef binary: exit codes, --help, --json, the
// ASR-V pipeline, and bad input that must fail with a located message while
// leaving the database exactly as it was.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"

namespace hydrocoef {
namespace {

using test::CliResult;
using test::dump_database;
using test::run_cli;
using test::TempDir;

const std::string kExamples = HYDROCOEF_SOURCE_DIR "/examples/asr-v/";
const std::string kSurge = kExamples + "asr-v-surge-damping.csv";
const std::string kYaw = kExamples + "asr-v-yaw-damping.csv";

void write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::size_t line_count(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

TEST(Cli, VersionAndHelpExitZero) {
  TempDir dir;
  const auto version = run_cli({"--version"}, dir.path());
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find("hydrocoef "), std::string::npos);
  for (const std::string command : {"import", "runs", "fit", "fits"}) {
    const auto help = run_cli({command, "--help"}, dir.path());
    EXPECT_EQ(help.exit_code, 0) << command;
    EXPECT_NE(help.out.find("--json"), std::string::npos) << command;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "hydrocoef.db"));
}

TEST(Cli, UsageErrorsExitTwoWithOneLine) {
  TempDir dir;
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{}, {"frobnicate"}, {"import"}, {"fit", "--body", "b"}, {"runs", "--bogus"}}) {
    const auto result = run_cli(args, dir.path());
    EXPECT_EQ(result.exit_code, 2) << (args.empty() ? "" : args[0]);
    EXPECT_EQ(line_count(result.err), 1u) << result.err;
  }
}

TEST(Cli, AsrVPipelineReproducesThePapersLaws) {
  TempDir dir;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli({"import", kYaw, "--body", "asr-v"}, dir.path()).exit_code, 0);
  EXPECT_TRUE(std::filesystem::exists(dir / "hydrocoef.db"));  // the default database

  const auto runs = run_cli({"runs", "--body", "asr-v", "--json"}, dir.path());
  ASSERT_EQ(runs.exit_code, 0) << runs.err;
  const auto run_list = nlohmann::json::parse(runs.out);
  EXPECT_EQ(run_list.size(), 39u);  // 20 + 20 rows, one shared run at rest

  const auto surge = run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "1,u,u|u|", "--json"}, dir.path());
  ASSERT_EQ(surge.exit_code, 0) << surge.err;
  const auto s = nlohmann::json::parse(surge.out);
  EXPECT_NEAR(s["coefficients"]["u"].get<double>(), 0.01551, 5e-6);
  EXPECT_NEAR(s["coefficients"]["u|u|"].get<double>(), 11.0364, 5e-5);
  EXPECT_EQ(s["n"].get<int>(), 20);
  EXPECT_GT(s["r2"].get<double>(), 0.9999);
  EXPECT_GT(s["rmse"].get<double>(), 0.0);
  EXPECT_EQ(s["sign_convention"], "opposing");
  for (const auto* term : {"1", "u", "u|u|"}) EXPECT_GT(s["std_errors"][term].get<double>(), 0.0) << term;

  const auto no_constant = run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--json"}, dir.path());
  const auto n = nlohmann::json::parse(no_constant.out);
  EXPECT_NEAR(n["coefficients"]["u"].get<double>(), 0.02184, 5e-6);
  EXPECT_NEAR(n["coefficients"]["u|u|"].get<double>(), 11.0229, 5e-5);
  EXPECT_FALSE(n["coefficients"].contains("1"));

  const auto yaw = run_cli({"fit", "--body", "asr-v", "--dof", "N", "--terms", "1,r,r|r|", "--json"}, dir.path());
  const auto y = nlohmann::json::parse(yaw.out);
  EXPECT_NEAR(y["coefficients"]["r"].get<double>(), -0.006075, 5e-7);
  EXPECT_NEAR(y["coefficients"]["r|r|"].get<double>(), -0.07714, 5e-6);
  EXPECT_EQ(y["sign_convention"], "on-body");

  const auto fits = nlohmann::json::parse(run_cli({"fits", "--json"}, dir.path()).out);
  ASSERT_EQ(fits.size(), 3u);
  for (const auto& fit : fits) EXPECT_EQ(fit["runs"].size(), 20u);

  // The readable output names the law, its units and the sign convention.
  const auto text = run_cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "1,u,u|u|", "--no-store"}, dir.path());
  EXPECT_NE(text.out.find("u|u|"), std::string::npos);
  EXPECT_NE(text.out.find("N/(m/s)^2"), std::string::npos);
  EXPECT_NE(text.out.find("opposes motion"), std::string::npos);
}

TEST(Cli, ReimportAddsNothingAndSaysSo) {
  TempDir dir;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v"}, dir.path()).exit_code, 0);
  const auto before = dump_database(dir / "hydrocoef.db");
  const auto again = run_cli({"import", kSurge, "--body", "asr-v", "--json"}, dir.path());
  EXPECT_EQ(again.exit_code, 0);
  const auto result = nlohmann::json::parse(again.out);
  EXPECT_EQ(result["files"][0]["status"], "already_imported");
  EXPECT_EQ(result["files"][0]["runs_created"], 0);
  EXPECT_EQ(dump_database(dir / "hydrocoef.db"), before);
  const auto text = run_cli({"import", kSurge, "--body", "asr-v"}, dir.path());
  EXPECT_NE(text.out.find("already imported"), std::string::npos) << text.out;
}

struct BadTable {
  const char* name;
  const char* text;
  const char* location;  // "file:line:column" suffix expected in the message
  const char* expected;  // part of the message
};

class CliBadTable : public ::testing::TestWithParam<BadTable> {};

TEST_P(CliBadTable, FailsWithLocationExitTwoAndDatabaseUnchanged) {
  const BadTable& bad = GetParam();
  TempDir dir;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v"}, dir.path()).exit_code, 0);
  const auto before = dump_database(dir / "hydrocoef.db");
  const auto path = dir / (std::string(bad.name) + ".csv");
  write(path, bad.text);
  // A good new file in the same call must not land either.
  const auto result = run_cli({"import", kYaw, path.string(), "--body", "asr-v"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1u) << result.err;
  EXPECT_NE(result.err.find(path.string() + ":" + bad.location), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(bad.expected), std::string::npos) << result.err;
  EXPECT_EQ(dump_database(dir / "hydrocoef.db"), before);
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, CliBadTable,
    ::testing::Values(BadTable{"bad_unit", "u [m s^-1],X [furlong]\n0.1,1\n", "1:12", "furlong"},
                      BadTable{"wrong_unit", "u [m s^-1],X [N m]\n0.1,1\n", "1:12", "expected kg m s^-2"},
                      BadTable{"missing_column", "# only speeds\nu [m s^-1]\n0.1\n", "2", "no force or moment column"},
                      BadTable{"text_in_number", "u [m s^-1],X [N]\n0.1,1\n0.2,abc\n", "3:5", "found 'abc'"},
                      BadTable{"nan", "u [m s^-1],X [N]\n0.1,NaN\n", "2:5", "expected a finite number"},
                      BadTable{"short_row", "u [m s^-1],X [N]\n0.1,1\n0.2\n", "3", "found 1 fields, expected 2"},
                      BadTable{"unknown_column", "u [m s^-1],X [N],Foo [N]\n0.1,1,2\n", "1:18", "--column"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(Cli, ConflictingRunNeedsReplace) {
  TempDir dir;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v"}, dir.path()).exit_code, 0);
  const auto before = dump_database(dir / "hydrocoef.db");
  write(dir / "other.csv", "u [m s^-1],X [N]\n0.1,0.2\n");
  const auto refused = run_cli({"import", "other.csv", "--body", "asr-v"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("already has X"), std::string::npos) << refused.err;
  EXPECT_EQ(dump_database(dir / "hydrocoef.db"), before);
  EXPECT_EQ(run_cli({"import", "other.csv", "--body", "asr-v", "--replace"}, dir.path()).exit_code, 0);
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--where", "u=0.1", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0]["forces"]["X"]["total"].get<double>(), 0.2);
}

TEST(Cli, ReadingCommandsDoNotCreateADatabase) {
  TempDir dir;
  const auto result = run_cli({"runs"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("hydrocoef.db"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "hydrocoef.db"));
}

TEST(Cli, CorruptDatabaseIsReportedNotOverwritten) {
  TempDir dir;
  write(dir / "hydrocoef.db", std::string(8192, 'x'));
  const auto result = run_cli({"import", kSurge}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("hydrocoef.db"), std::string::npos) << result.err;
  EXPECT_EQ(test::read_text(dir / "hydrocoef.db"), std::string(8192, 'x'));
}

TEST(Cli, UnitsInHeadersAreConvertedToSi) {
  TempDir dir;
  write(dir / "mm.csv", "# speeds in mm/s, force in kN\nu [ mm s^-1 ];X [ kN ]\n100;0.002\n");
  ASSERT_EQ(run_cli({"import", "mm.csv", "--body", "b"}, dir.path()).exit_code, 0);
  const auto runs = nlohmann::json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_DOUBLE_EQ(runs[0]["u"].get<double>(), 0.1);
  EXPECT_DOUBLE_EQ(runs[0]["forces"]["X"]["total"].get<double>(), 2.0);
}

}  // namespace
}  // namespace hydrocoef
