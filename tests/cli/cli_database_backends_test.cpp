// The CLI on both store backends: the ASR-V chain (import, runs, fit,
// surface build, query, export) through --db and $HYDROCOEF_DB on an SQLite
// file and on the PostgreSQL test server; merge of shards and copy between
// backends; a refused import that leaves the database as it was; a password
// in the URL refused before anything is opened.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.hpp"
#include "tests/support/test_database.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TestDatabase;

const std::string kExamples = HYDROCOEF_SOURCE_DIR "/examples/asr-v/";
const std::string kSurge = kExamples + "asr-v-surge-damping.csv";
const std::string kYaw = kExamples + "asr-v-yaw-damping.csv";

/// Runs a shell command line in `cwd`, capturing its output.
test::CliResult run_shell(const std::string& command, const std::filesystem::path& cwd) {
  const std::string full = "cd " + test::shell_quote(cwd.string()) + " && " + command + " >.sh-out 2>.sh-err";
  const int status = std::system(full.c_str());
  test::CliResult out;
  out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  out.out = test::read_text(cwd / ".sh-out");
  out.err = test::read_text(cwd / ".sh-err");
  return out;
}

class CliBackends : public testing::TestWithParam<store::Backend> {
 protected:
  test::CliResult cli(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", db_.location()});
    return run_cli(args, db_.dir().path());
  }
  TestDatabase db_{GetParam()};
};

TEST_P(CliBackends, TheAsrVChainGivesTheSameNumbersOnEitherBackend) {
  HYDROCOEF_NEED_DATABASE(db_);
  ASSERT_EQ(cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing"}).exit_code, 0);
  ASSERT_EQ(cli({"import", kYaw, "--body", "asr-v"}).exit_code, 0);
  const auto again = cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--json"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(nlohmann::json::parse(again.out)["files"][0]["status"], "already_imported") << again.out;

  const auto runs = nlohmann::json::parse(cli({"runs", "--body", "asr-v", "--json"}).out);
  const auto fit = cli({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--json"});
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const auto build = cli({"surface", "build", "yaw", "--body", "asr-v", "--outputs", "N", "--axes", "r", "--method",
                          "pchip", "--extrapolate", "clamp"});
  ASSERT_EQ(build.exit_code, 0) << build.err;
  const auto query = cli({"query", "yaw", "r=0.3", "--json"});
  ASSERT_EQ(query.exit_code, 0) << query.err;
  const auto exported = cli({"export", "yaw", "--format", "csv", "-o", "yaw.csv"});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;

  // The same commands on a plain SQLite file give the same numbers.
  test::TempDir reference;
  const auto ref = [&](std::vector<std::string> args) { return run_cli(args, reference.path()); };
  ref({"import", kSurge, "--body", "asr-v", "--sign", "opposing"});
  ref({"import", kYaw, "--body", "asr-v"});
  ref({"surface", "build", "yaw", "--body", "asr-v", "--outputs", "N", "--axes", "r", "--method", "pchip",
       "--extrapolate", "clamp"});
  EXPECT_EQ(runs, nlohmann::json::parse(ref({"runs", "--body", "asr-v", "--json"}).out));
  const auto ref_fit =
      nlohmann::json::parse(ref({"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|", "--json"}).out);
  EXPECT_EQ(nlohmann::json::parse(fit.out).at("coefficients"), ref_fit.at("coefficients"));
  EXPECT_EQ(nlohmann::json::parse(query.out), nlohmann::json::parse(ref({"query", "yaw", "r=0.3", "--json"}).out));
}

TEST_P(CliBackends, HydrocoefDbSetsTheDefaultDatabase) {
  HYDROCOEF_NEED_DATABASE(db_);
  const auto import = run_cli({"import", kSurge, "--body", "asr-v"}, db_.dir().path(), "/dev/null",
                              "HYDROCOEF_DB=" + test::shell_quote(db_.location()) + " ");
  ASSERT_EQ(import.exit_code, 0) << import.err;
  EXPECT_FALSE(std::filesystem::exists(db_.dir() / "hydrocoef.db") && GetParam() == store::Backend::PostgreSQL);
  EXPECT_FALSE(nlohmann::json::parse(cli({"runs", "--json"}).out).empty());
}

TEST_P(CliBackends, ARefusedImportLeavesTheDatabaseAsItWas) {
  HYDROCOEF_NEED_DATABASE(db_);
  ASSERT_EQ(cli({"import", kSurge, "--body", "asr-v"}).exit_code, 0);
  const std::string before = db_.dump();
  // The same runs from another file: refused without --replace.
  std::filesystem::copy_file(kSurge, db_.dir() / "copy.csv");
  { std::ofstream(db_.dir() / "copy.csv", std::ios::app) << "\n"; }
  const auto refused = cli({"import", (db_.dir() / "copy.csv").string(), "--body", "asr-v"});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_EQ(db_.dump(), before);
}

TEST_P(CliBackends, ShardsMergeAndADatabaseCopiesAcrossBackends) {
  HYDROCOEF_NEED_DATABASE(db_);
  const auto dir = db_.dir().path();
  ASSERT_EQ(run_cli({"--db", "a.db", "import", kSurge, "--body", "asr-v", "--sign", "opposing"}, dir).exit_code, 0);
  ASSERT_EQ(run_cli({"--db", "b.db", "import", kYaw, "--body", "asr-v"}, dir).exit_code, 0);
  // A body's reference data in one shard, a derivative model in the other: each merged and counted.
  ASSERT_EQ(run_cli({"--db", "a.db", "body", "set", "asr-v", "--length", "0.3"}, dir).exit_code, 0);
  const auto fitted = run_cli({"--db", "b.db", "derivatives", "fit", "--body", "asr-v", "--output", "N", "--terms",
                               "r, r*|r|", "--name", "yaw-damping"},
                              dir);
  ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
  const auto merged = cli({"merge", "a.db", "b.db", "--json"});
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  const auto report = nlohmann::json::parse(merged.out);
  ASSERT_EQ(report.at("shards").size(), 2u);
  EXPECT_EQ(report.at("shards").at(0).at("imports_added"), 1);
  EXPECT_EQ(report.at("shards").at(0).at("body_references_added"), 1);
  EXPECT_EQ(report.at("shards").at(0).at("derivative_models_added"), 0);
  EXPECT_EQ(report.at("shards").at(1).at("body_references_added"), 0);
  EXPECT_EQ(report.at("shards").at(1).at("derivative_models_added"), 1);
  const auto text = cli({"merge", "a.db", "b.db"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("0 imports added (1 here already)"), std::string::npos) << text.out;
  const auto remerged = nlohmann::json::parse(cli({"merge", "a.db", "b.db", "--json"}).out);
  EXPECT_EQ(remerged.at("shards").at(0).at("body_references_already"), 1);
  EXPECT_EQ(remerged.at("shards").at(1).at("derivative_models_already"), 1);
  const auto models = nlohmann::json::parse(cli({"derivatives", "list", "--json"}).out);
  EXPECT_NE(models.dump().find("yaw-damping"), std::string::npos) << models.dump();

  const auto copied = run_cli({"copy", "--from", db_.location(), "--to", "back.db", "--json"}, dir);
  ASSERT_EQ(copied.exit_code, 0) << copied.err;
  EXPECT_EQ(TestDatabase(store::Backend::SQLite, (dir / "back.db").string()).dump(), db_.dump());
  const auto again = run_cli({"copy", "--from", db_.location(), "--to", "back.db"}, dir);
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("expected an empty database"), std::string::npos) << again.err;
  for (const std::string command : {"merge", "copy"}) EXPECT_EQ(run_cli({command, "--help"}, dir).exit_code, 0);
}

TEST_P(CliBackends, TheSlurmExamplesImportEachCaseIntoTheTeamDatabaseOrIntoShardsToMerge) {
  HYDROCOEF_NEED_DATABASE(db_);
  const auto dir = db_.dir().path();
  const std::string cases = HYDROCOEF_SOURCE_DIR "/data/openfoam-sphere/cases";
  {
    std::ofstream list(dir / "cases.txt");
    for (const char* name : {"u0.10_v0.00", "u0.10_v0.05", "u0.20_v0.10", "u0.30_v0.00"})
      list << cases << "/" << name << "\n";
  }
  const std::string path =
      "PATH=" + test::shell_quote(std::filesystem::path(HYDROCOEF_CLI).parent_path().string()) + ":\"$PATH\" ";
  const std::string examples = HYDROCOEF_SOURCE_DIR "/examples/cluster/";
  // Slurm runs each array task with its SLURM_ARRAY_TASK_ID; so does this loop.
  for (int task = 1; task <= 4; ++task) {
    const std::string id = "SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " ";
    const auto team = run_shell(path + id + "HYDROCOEF_DB=" + test::shell_quote(db_.location()) + " bash " +
                                    test::shell_quote(examples + "import-array.sbatch") + " cases.txt",
                                dir);
    ASSERT_EQ(team.exit_code, 0) << team.err;
    const auto shard = run_shell(
        path + id + "bash " + test::shell_quote(examples + "import-array-shards.sbatch") + " cases.txt shards", dir);
    ASSERT_EQ(shard.exit_code, 0) << shard.err;
  }
  // A requeued task adds nothing.
  const auto requeued = run_shell(path + "SLURM_ARRAY_TASK_ID=2 HYDROCOEF_DB=" + test::shell_quote(db_.location()) +
                                      " bash " + test::shell_quote(examples + "import-array.sbatch") + " cases.txt",
                                  dir);
  ASSERT_EQ(requeued.exit_code, 0) << requeued.err;
  EXPECT_EQ(nlohmann::json::parse(requeued.out)["files"][0]["status"], "already_imported") << requeued.out;
  std::vector<std::string> merge = {"--db", "merged.db", "merge"};
  for (int task = 1; task <= 4; ++task) merge.push_back("shards/task-" + std::to_string(task) + ".db");
  ASSERT_EQ(run_cli(merge, dir).exit_code, 0);
  const auto team_runs = nlohmann::json::parse(cli({"runs", "--json"}).out);
  EXPECT_EQ(team_runs.size(), 4u);
  EXPECT_EQ(team_runs, nlohmann::json::parse(run_cli({"--db", "merged.db", "runs", "--json"}, dir).out));
}

INSTANTIATE_TEST_SUITE_P(Backends, CliBackends, testing::Values(store::Backend::SQLite, store::Backend::PostgreSQL),
                         [](const testing::TestParamInfo<store::Backend>& param) {
                           return std::string(test::backend_name(param.param));
                         });

TEST(CliDatabaseUrl, APasswordInTheUrlIsRefusedBeforeAnythingIsOpened) {
  test::TempDir dir;
  const auto result = run_cli({"--db", "postgresql://cfd:secret@localhost/team", "runs"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find(".pgpass"), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  const auto unknown = run_cli({"--db", "mysql://db/team", "runs"}, dir.path());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("unknown scheme"), std::string::npos) << unknown.err;
}

TEST(CliDatabaseUrl, AnUnreachableServerIsOneLineAndExitTwo) {
  test::TempDir dir;
  const auto result =
      run_cli({"--db", "postgresql:///none?host=" + dir.path().string() + "&connect_timeout=2", "runs"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("cannot connect to the PostgreSQL server"), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

}  // namespace
}  // namespace hydrocoef
