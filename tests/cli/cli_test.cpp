// End-to-end tests of the hydrocoef binary: exit codes, --help, --json, the
// ASR-V pipeline, and bad input that must fail with a located message while
// leaving the database exactly as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

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

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::size_t line_count(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

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
  EXPECT_FALSE(test::database_exists(dir / "hydrocoef.db"));
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
  EXPECT_TRUE(test::database_exists(dir / "hydrocoef.db"));  // the default database

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

TEST(Cli, HistoriesWhoseStatisticsWouldNotBeFiniteAreOneLine) {
  // Denormal or huge time steps, denormal forces: "internal error" before (a
  // NaN statistic reached the database); now exit 2, one line naming the
  // file and line, the database unchanged.
  TempDir dir;
  ASSERT_EQ(run_cli({"import", kSurge, "--body", "asr-v"}, dir.path()).exit_code, 0);
  const auto before = dump_database(dir / "hydrocoef.db");
  const std::vector<std::pair<std::string, std::string>> histories = {
      {"denormal-steps", "Time [s],X [N]\n0,1\n5e-324,2\n1e-323,1\n1.5e-323,2\n2e-323,1\n"},
      {"huge-steps", "Time [s],X [N]\n0,1\n1e300,2\n2e300,1\n3e300,2\n4e300,1\n"},
      {"denormal-forces", "Time [s],X [N]\n0,1e-310\n0.1,2e-310\n0.2,1e-310\n0.3,2e-310\n0.4,1e-310\n"}};
  for (const auto& [name, text] : histories) {
    const auto path = dir / (name + ".csv");
    write(path, text);
    const auto result =
        run_cli({"import", path.string(), "--body", "asr-v", "--set", "u=0.1", "--set", "v=0"}, dir.path());
    EXPECT_EQ(result.exit_code, 2) << name << ": " << result.err;
    EXPECT_EQ(line_count(result.err), 1u) << result.err;
    EXPECT_NE(result.err.find(path.string() + ":" + (name == "denormal-forces" ? "2" : "3") + ":"), std::string::npos)
        << result.err;
    EXPECT_NE(result.err.find("expected 0 or a magnitude from 1e-100 to"), std::string::npos) << result.err;
    EXPECT_EQ(result.err.find("internal error"), std::string::npos) << result.err;
    EXPECT_EQ(dump_database(dir / "hydrocoef.db"), before) << name;
  }
}

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
  // Named as given: the default file name, or the server's URL.
  const std::string name = test::on_postgresql() ? test::database_display(dir / "hydrocoef.db") : "hydrocoef.db";
  EXPECT_NE(result.err.find(name), std::string::npos) << result.err;
  EXPECT_FALSE(test::database_exists(dir / "hydrocoef.db"));
}

TEST(Cli, CorruptDatabaseIsReportedNotOverwritten) {
  HYDROCOEF_SQLITE_FILE_ONLY("an SQLite file that is not a database");
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

TEST(Cli, FitByLevelRecoversCoefficientsThatVaryWithTheDisturbance) {
  // X = a(c) u + b(c) u|u| under a current c, with a = 0.1 + 2 c^2 and
  // b = 11 + 5 c: each level's law is exact, and a degree-2 polynomial
  // through the levels' coefficients gives a and b back.
  TempDir dir;
  std::ostringstream table;
  table.precision(17);
  table << "u [m s^-1],current_v [m s^-1],X [N]\n";
  const std::vector<double> levels{0.0, 0.05, 0.1, 0.2};
  for (double c : levels)
    for (double u : {-0.2, 0.05, 0.1, 0.2, 0.3})
      table << u << "," << c << "," << (0.1 + 2 * c * c) * u + (11 + 5 * c) * u * std::abs(u) << "\n";
  write(dir / "sweep.csv", table.str());
  ASSERT_EQ(run_cli({"import", "sweep.csv", "--body", "b", "--disturbance", "current_v"}, dir.path()).exit_code, 0);
  const auto result = run_cli({"fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--by", "current_v", "--curve",
                               "polynomial:2", "--json"},
                              dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto out = nlohmann::json::parse(result.out);
  ASSERT_EQ(out["levels"].size(), levels.size());
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const double c = levels[l];
    EXPECT_NEAR(out["levels"][l]["level"].get<double>(), c, 1e-15);
    EXPECT_NEAR(out["levels"][l]["coefficients"]["u"].get<double>(), 0.1 + 2 * c * c, 1e-9);
    EXPECT_NEAR(out["levels"][l]["coefficients"]["u|u|"].get<double>(), 11 + 5 * c, 1e-9);
  }
  const auto a = out["curves"][0]["polynomial"].get<std::vector<double>>();
  const auto b = out["curves"][1]["polynomial"].get<std::vector<double>>();
  ASSERT_EQ(a.size(), 3u);
  EXPECT_NEAR(a[0], 0.1, 1e-8);
  EXPECT_NEAR(a[1], 0.0, 1e-7);
  EXPECT_NEAR(a[2], 2.0, 1e-6);
  EXPECT_NEAR(b[0], 11.0, 1e-8);
  EXPECT_NEAR(b[1], 5.0, 1e-7);
  EXPECT_NEAR(b[2], 0.0, 1e-6);
  EXPECT_EQ(out["curves"][1]["unit"], "N/(m/s)^2");
  // Each level is stored as a fit of its own.
  const auto fits = nlohmann::json::parse(run_cli({"fits", "--json"}, dir.path()).out);
  EXPECT_EQ(fits.size(), levels.size());
  // Named BASE[current_v=LEVEL], each with its level as its selection.
  bool found = false;
  for (const auto& fit : fits)
    if (fit["name"] == "b:X(u,u|u|)[current_v=0.05]") {
      found = true;
      EXPECT_EQ(fit["where"], "current_v=0.05");
    }
  EXPECT_TRUE(found) << fits.dump();

  const auto text = run_cli(
      {"fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--by", "current_v", "--curve", "pchip", "--no-store"},
      dir.path());
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("PCHIP"), std::string::npos);
  const auto bad = run_cli({"fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--by", "current_w"}, dir.path());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("no disturbance 'current_w'"), std::string::npos) << bad.err;
  const auto bad_curve = run_cli(
      {"fit", "--body", "b", "--dof", "X", "--terms", "u,u|u|", "--by", "current_v", "--curve", "spline"}, dir.path());
  EXPECT_EQ(bad_curve.exit_code, 2);
  EXPECT_NE(bad_curve.err.find("polynomial:D"), std::string::npos) << bad_curve.err;
}

}  // namespace
}  // namespace hydrocoef
