// Many writers on one database, on both backends: 8 processes import 50
// files each (every process also re-imports files of the others, mixed in),
// while readers list the runs and build a surface. Every run is there
// exactly once at the end; a listing or a surface build never sees part of
// an import (each file gives 3 runs: a body's run count is always a multiple
// of 3); no process fails, none with a lock error.
//
// Heavy: 400 imports and 400 re-imports; runs in the optimized build.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "tests/support/run_cli.hpp"
#include "tests/support/test_database.hpp"

namespace hydrocoef {
namespace {

using test::shell_quote;
using test::TestDatabase;

constexpr int kWriters = 8;
constexpr int kFilesEach = 50;
constexpr int kRunsPerFile = 3;

std::filesystem::path table(const std::filesystem::path& dir, int writer, int file) {
  // Appended piece by piece: GCC 12 at -O3 warns falsely (stringop-overflow)
  // on "literal" + std::string temporaries.
  std::string name = "w";
  name.append(std::to_string(writer)).append("-").append(std::to_string(file)).append(".csv");
  return dir / name;
}

/// Three surge runs of one file, at speeds no other file has.
void write_table(const std::filesystem::path& path, int writer, int file) {
  std::ofstream out(path);
  out << "u [m s^-1],X [N]\n";
  for (int i = 0; i < kRunsPerFile; ++i) {
    const double u = 0.001 * (writer * kFilesEach * kRunsPerFile + file * kRunsPerFile + i) + 0.01;
    out << u << "," << -(11.0 * u * u) << "\n";
  }
}

std::filesystem::path log_path(const std::filesystem::path& dir, int writer) {
  std::string name = "writer";
  name.append(std::to_string(writer)).append(".log");
  return dir / name;
}

pid_t start(const std::string& script, const std::filesystem::path& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string shell = script + " > " + shell_quote(log.string()) + " 2>&1";
    execl("/bin/sh", "sh", "-c", shell.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

class ImportStorm : public testing::TestWithParam<store::Backend> {};

TEST_P(ImportStorm, EightWritersLoseNothingAndReadersSeeOnlyWholeImports) {
  TestDatabase db(GetParam());
  HYDROCOEF_NEED_DATABASE(db);
  const auto dir = db.dir().path();
  for (int w = 0; w < kWriters; ++w)
    for (int f = 0; f < kFilesEach; ++f) write_table(table(dir, w, f), w, f);
  const std::string cli = shell_quote(HYDROCOEF_CLI) + " --db " + shell_quote(db.location());
  // The database exists before the storm (its creation under contention is
  // tested elsewhere); the readers then always find it.
  ASSERT_EQ(test::run_cli({"--db", db.location(), "import", table(dir, 0, 0).string(), "--body", "b", "--quiet"}, dir)
                .exit_code,
            0);

  std::vector<pid_t> writers;
  for (int w = 0; w < kWriters; ++w) {
    // Each writer imports its files; after each, it re-imports a file of the
    // next writer (imported already or not yet: either is fine).
    std::string script = "export HYDROCOEF_DB_TIMEOUT=600; status=0; ";
    for (int f = 0; f < kFilesEach; ++f) {
      script += cli + " import " + shell_quote(table(dir, w, f).string()) + " --body b --quiet || status=1; ";
      script += cli + " import " + shell_quote(table(dir, (w + 1) % kWriters, f).string()) +
                " --body b --quiet || status=1; ";
    }
    script += "exit $status";
    writers.push_back(start(script, log_path(dir, static_cast<int>(w))));
  }
  // Readers while the writers run: each listing must hold whole imports.
  int listings = 0, builds = 0;
  std::vector<int> exit_codes(writers.size(), -1);
  bool writing = true;
  while (writing) {
    const auto runs = test::run_cli({"--db", db.location(), "runs", "--json"}, dir);
    // EXPECT, not ASSERT: the writers are always waited for.
    EXPECT_EQ(runs.exit_code, 0) << runs.err;
    if (runs.exit_code == 0) {
      const auto listed = nlohmann::json::parse(runs.out);
      EXPECT_EQ(listed.size() % kRunsPerFile, 0u) << "a listing saw part of an import: " << listed.size() << " runs";
    }
    ++listings;
    const auto build =
        test::run_cli({"--db", db.location(), "surface", "build", "s", "--body", "b", "--outputs", "X", "--axes", "u",
                       "--method", "linear", "--extrapolate", "clamp", "--replace", "--json"},
                      dir);
    EXPECT_EQ(build.exit_code, 0) << build.err;
    if (build.exit_code == 0) {
      EXPECT_EQ(nlohmann::json::parse(build.out).at("runs").size() % kRunsPerFile, 0u) << build.out;
    }
    ++builds;
    writing = false;
    for (std::size_t w = 0; w < writers.size(); ++w) {
      if (exit_codes[w] >= 0) continue;
      int status = 0;
      if (waitpid(writers[w], &status, WNOHANG) == writers[w])
        exit_codes[w] = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
      else
        writing = true;
    }
  }
  for (std::size_t w = 0; w < writers.size(); ++w) {
    const std::string log = test::read_text(log_path(dir, static_cast<int>(w)));
    EXPECT_EQ(exit_codes[w], 0) << log;
    EXPECT_EQ(log.find("busy"), std::string::npos) << log;
    EXPECT_EQ(log.find("error"), std::string::npos) << log;
  }
  EXPECT_GT(listings, 0);
  EXPECT_GT(builds, 0);
  const auto runs = test::run_cli({"--db", db.location(), "runs", "--json"}, dir);
  ASSERT_EQ(runs.exit_code, 0) << runs.err;
  const auto listed = nlohmann::json::parse(runs.out);
  EXPECT_EQ(listed.size(), static_cast<std::size_t>(kWriters * kFilesEach * kRunsPerFile));
  std::set<double> speeds;
  for (const auto& run : listed) speeds.insert(run.at("u").get<double>());
  EXPECT_EQ(speeds.size(), listed.size()) << "a run is there twice";
}

INSTANTIATE_TEST_SUITE_P(Backends, ImportStorm, testing::Values(store::Backend::SQLite, store::Backend::PostgreSQL),
                         [](const testing::TestParamInfo<store::Backend>& param) {
                           return std::string(test::backend_name(param.param));
                         });

}  // namespace
}  // namespace hydrocoef
