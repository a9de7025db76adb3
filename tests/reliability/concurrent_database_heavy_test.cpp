// Several processes on one database that does not exist yet: in each of 20
// rounds, six hydrocoef processes start together on a fresh path, four
// importing different files (two bodies), one fitting and one listing runs.
// No process fails with an internal error or a signal; every import either
// committed (its runs are there at the end) or was refused with one clear
// line; a fit or listing that came before any run (or the file) says so. Then a read-only
// copy of the result in a read-only folder answers runs, query, export and
// report.
//
// Heavy: 120 processes; runs in the optimized build.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/backend_under_test.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::shell_quote;
using test::TempDir;

// A force table of surge runs at speeds offset by `shift` (distinct bytes, distinct runs).
void write_table(const std::filesystem::path& path, double shift) {
  std::ofstream out(path);
  out << "u [m s^-1],X [N]\n";
  for (int i = 0; i < 12; ++i) {
    const double u = 0.05 * i + shift;
    out << u << "," << -(0.02 * u + 11.0 * u * u) << "\n";
  }
}

struct Outcome {
  int exit_code = -1;
  std::string err;
};

TEST(ConcurrentDatabase, SixProcessesOnANewDatabaseLoseNothing) {
  TempDir dir;
  const auto table = [&](int k) { return dir / std::string("t").append(std::to_string(k)).append(".csv"); };
  for (int k = 0; k < 4; ++k) write_table(table(k), 0.001 * (k + 1));
  const std::string cli = shell_quote(HYDROCOEF_CLI);
  for (int round = 0; round < 20; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const auto work = dir / ("round" + std::to_string(round));
    std::filesystem::create_directories(work);
    const std::string db = shell_quote(test::database_location(work / "hydrocoef.db"));
    std::vector<std::string> commands;
    for (int k = 0; k < 4; ++k)
      commands.push_back(cli + " --db " + db + " import " + shell_quote(table(k).string()) + " --body " +
                         (k < 2 ? "a" : "b") + " --sign on-body --quiet");
    commands.push_back(cli + " --db " + db + " fit --body a --dof X --terms " + shell_quote("u,u|u|") + " --no-store");
    commands.push_back(cli + " --db " + db + " runs");
    // Start all six, then wait for each.
    std::vector<pid_t> pids;
    for (std::size_t i = 0; i < commands.size(); ++i) {
      const std::string err = (work / ("err" + std::to_string(i))).string();
      const pid_t pid = fork();
      ASSERT_GE(pid, 0);
      if (pid == 0) {
        const std::string shell = commands[i] + " > /dev/null 2> " + shell_quote(err);
        execl("/bin/sh", "sh", "-c", shell.c_str(), static_cast<char*>(nullptr));
        _exit(127);
      }
      pids.push_back(pid);
    }
    std::vector<Outcome> outcomes(pids.size());
    for (std::size_t i = 0; i < pids.size(); ++i) {
      int status = 0;
      ASSERT_EQ(waitpid(pids[i], &status, 0), pids[i]);
      ASSERT_TRUE(WIFEXITED(status)) << commands[i] << " ended by a signal";
      outcomes[i].exit_code = WEXITSTATUS(status);
      outcomes[i].err = test::read_text(work / ("err" + std::to_string(i)));
    }
    int committed_a = 0, committed_b = 0;
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      const auto& o = outcomes[i];
      EXPECT_TRUE(o.exit_code == 0 || o.exit_code == 2) << commands[i] << ": exit " << o.exit_code << ": " << o.err;
      EXPECT_EQ(o.err.find("internal error"), std::string::npos) << commands[i] << ": " << o.err;
      if (o.exit_code == 2) {
        EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
      }
      if (i < 4) {
        // Imports must all succeed: nothing else holds the database for long.
        EXPECT_EQ(o.exit_code, 0) << commands[i] << ": " << o.err;
        if (o.exit_code == 0) (i < 2 ? committed_a : committed_b) += 12;
      }
      // A fit that starts before any import finished: no database yet (an
      // empty schema on PostgreSQL), or no runs yet.
      if (i == 4 && o.exit_code == 2) {
        EXPECT_TRUE(o.err.find("no runs") != std::string::npos || o.err.find("no database here") != std::string::npos ||
                    o.err.find("an empty database") != std::string::npos)
            << o.err;
      }
    }
    // Every committed import's runs are there.
    const auto runs = test::run_cli({"runs", "--json"}, work);
    ASSERT_EQ(runs.exit_code, 0) << runs.err;
    const auto listed = nlohmann::json::parse(runs.out);
    int found_a = 0, found_b = 0;
    for (const auto& run : listed) (run.at("body") == "a" ? found_a : found_b) += 1;
    EXPECT_EQ(found_a, committed_a);
    EXPECT_EQ(found_b, committed_b);
  }

  // A read-only copy in a read-only folder.
  if (test::on_postgresql()) return;  // an SQLite file's copy
  const auto shelf = dir / "shelf";
  std::filesystem::create_directories(shelf / "share");
  ASSERT_EQ(test::run_cli({"surface", "build", "s", "--body", "a", "--outputs", "X", "--axes", "u", "--method",
                           "linear", "--extrapolate", "clamp"},
                          dir / "round0")
                .exit_code,
            0);
  std::filesystem::copy_file(dir / "round0" / "hydrocoef.db", shelf / "share" / "hydrocoef.db");
  chmod((shelf / "share" / "hydrocoef.db").c_str(), 0444);
  chmod((shelf / "share").c_str(), 0555);
  const std::string db = (shelf / "share" / "hydrocoef.db").string();
  for (const auto& args :
       std::vector<std::vector<std::string>>{{"--db", db, "runs"},
                                             {"--db", db, "query", "s", "u=0.2"},
                                             {"--db", db, "export", "s", "--format", "csv", "-o", "s.csv"},
                                             {"--db", db, "report", "-o", "report"}}) {
    const auto result = test::run_cli(args, shelf);
    EXPECT_EQ(result.exit_code, 0) << args[2] << ": " << result.err;
  }
  chmod((shelf / "share").c_str(), 0755);
}

}  // namespace
}  // namespace hydrocoef
