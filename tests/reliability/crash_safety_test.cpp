// Crash safety of the run database: a child process imports force tables one
// `hydrocoef import` call (= one transaction) after another and is killed
// with SIGKILL at random moments: half of them after an import reported
// itself committed, half while a call has the database open (so inside its
// transaction); the kills wait for these events, not for the clock. After
// every kill the file must pass PRAGMA integrity_check, every file that an
// import reported as done must be there, and every source file must be all
// there (all its runs, each with its X and N and their provenance) or not at
// all. A reader thread queries the database through the library the whole
// time and must never see a partial import (WAL: readers see the last commit).
#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "src/core/error.hpp"
#include "src/store/database.hpp"
#include "tests/support/process_group.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kFiles = 40;
constexpr int kRowsPerFile = 400;
constexpr int kKills = 22;

double surge(int file, int row) { return 0.001 * (file * kRowsPerFile + row + 1); }
double force_x(double u) { return -3.0 * u * std::abs(u) - 0.5 * u; }
double moment_n(double u) { return 0.25 * u; }

std::string file_name(int file) { return "run-" + std::to_string(100 + file) + ".csv"; }

void write_tables(const fs::path& dir) {
  for (int f = 0; f < kFiles; ++f) {
    std::ofstream out(dir / file_name(f));
    out.precision(17);
    out << "u [m s^-1],X [N],N [N m]\n";
    for (int r = 0; r < kRowsPerFile; ++r) {
      const double u = surge(f, r);
      out << u << ',' << force_x(u) << ',' << moment_n(u) << '\n';
    }
  }
}

/// Checks the database file with the SQLite C API: integrity, no orphans, and
/// per source file all or nothing. Returns the problems found ("" when none)
/// and the names of the files fully present.
struct Census {
  std::string problems;
  std::set<std::string> present;
};

Census census(const fs::path& db_path) {
  Census out;
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK) {
    out.problems = "cannot open: " + std::string(sqlite3_errmsg(db));
    sqlite3_close(db);
    return out;
  }
  sqlite3_busy_timeout(db, 5000);
  auto rows = [&](const std::string& sql) {
    std::vector<std::vector<std::string>> result;
    sqlite3_stmt* statement = nullptr;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &statement, nullptr) != SQLITE_OK) {
      out.problems += "SQL error in '" + sql + "': " + sqlite3_errmsg(db) + "; ";
      return result;
    }
    while (sqlite3_step(statement) == SQLITE_ROW) {
      std::vector<std::string> row;
      for (int c = 0; c < sqlite3_column_count(statement); ++c) {
        const auto* text = sqlite3_column_text(statement, c);
        row.emplace_back(text ? reinterpret_cast<const char*>(text) : "NULL");
      }
      result.push_back(std::move(row));
    }
    sqlite3_finalize(statement);
    return result;
  };
  const auto integrity = rows("PRAGMA integrity_check");
  if (integrity.size() != 1 || integrity[0][0] != "ok") out.problems += "integrity_check is not ok; ";
  const auto mode = rows("PRAGMA journal_mode");
  if (mode.empty() || mode[0][0] != "wal") out.problems += "journal_mode is not wal; ";
  if (!rows("PRAGMA foreign_key_check").empty()) out.problems += "foreign_key_check reports orphans; ";
  if (rows("SELECT id FROM run WHERE id NOT IN (SELECT run_id FROM run_force)").size() != 0)
    out.problems += "a run without forces; ";
  // Per source: runs, X and N components, and that each value is the file's.
  for (const auto& source : rows("SELECT id, path FROM source_file")) {
    const std::string name = fs::path(source[1]).filename().string();
    if (name == "seed.csv") continue;
    const auto forces = rows(
        "SELECT r.u, f.component, f.total FROM run_force "
        "f JOIN run r ON r.id = f.run_id "
        "WHERE f.source_id = " +
        source[0]);
    std::map<std::string, int> per_component;
    bool values_ok = true;
    for (const auto& f : forces) {
      ++per_component[f[1]];
      const double u = std::stod(f[0]), total = std::stod(f[2]);
      const double expected = f[1] == "X" ? force_x(u) : moment_n(u);
      if (std::abs(total - expected) > 1e-12 * std::max(1.0, std::abs(expected))) values_ok = false;
    }
    if (per_component["X"] != kRowsPerFile || per_component["N"] != kRowsPerFile || forces.size() != 2u * kRowsPerFile)
      out.problems += name + " is partly there (" + std::to_string(forces.size()) + " force rows); ";
    else if (!values_ok)
      out.problems += name + " has wrong values; ";
    else
      out.present.insert(name);
  }
  const auto run_count = rows("SELECT count(*) FROM run");
  const std::size_t expected_runs = 1 + out.present.size() * kRowsPerFile;  // + the seed run
  if (run_count.empty() || std::stoul(run_count[0][0]) != expected_runs)
    out.problems += "run count " + (run_count.empty() ? "?" : run_count[0][0]) + ", expected " +
                    std::to_string(expected_runs) + " (runs outside complete files); ";
  sqlite3_close(db);
  return out;
}

/// True when a process of the group has the database file open (the
/// hydrocoef the shell runs is between opening and closing its RunDatabase).
bool database_open_in_group(pid_t group) {
  for (const auto& proc : live_processes(group)) {
    std::error_code ec;
    for (const auto& fd : fs::directory_iterator(proc / "fd", ec)) {
      const auto target = fs::read_symlink(fd.path(), ec).string();
      if (!ec && target.size() >= 8 && target.compare(target.size() - 8, 8, "/runs.db") == 0) return true;
    }
  }
  return false;
}

/// Reader: opens the database through the library and lists the runs, again
/// and again; every listing must hold whole files only.
class Reader {
 public:
  explicit Reader(fs::path db) : db_(std::move(db)), thread_([this] { loop(); }) {}
  ~Reader() { stop(); }
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  std::size_t queries() const { return queries_; }
  std::vector<std::string> problems() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return problems_;
  }

 private:
  void loop() {
    while (!stop_) {
      try {
        RunDatabase database(db_, RunDatabase::OpenMode::MustExist);
        std::map<std::string, int> runs_per_file;
        std::string problem;
        for (const auto& run : database.runs()) {
          const auto& x = run.tau_b[0];
          const auto& n = run.tau_b[5];
          if (!x || !n) {
            problem = "run " + describe(run.key) + " without X or N";
            break;
          }
          if (x->source_path != n->source_path || x->source_line == 0) problem = "run with mixed provenance";
          ++runs_per_file[fs::path(x->source_path).filename().string()];
        }
        for (const auto& [file, count] : runs_per_file)
          if (file != "seed.csv" && count != kRowsPerFile)
            problem =
                "saw " + std::to_string(count) + " runs of " + file + ", expected " + std::to_string(kRowsPerFile);
        if (!problem.empty()) {
          const std::lock_guard<std::mutex> lock(mutex_);
          problems_.push_back(problem);
        }
        ++queries_;
      } catch (const std::exception& error) {
        const std::lock_guard<std::mutex> lock(mutex_);
        problems_.push_back(std::string("reader failed: ") + error.what());
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }

  fs::path db_;
  std::atomic<bool> stop_{false};
  std::atomic<std::size_t> queries_{0};
  std::mutex mutex_;
  std::vector<std::string> problems_;
  std::thread thread_;
};

TEST(CrashSafety, KilledImportsLeaveWholeRunsOrNone) {
  TempDir dir;
  write_tables(dir.path());
  {
    std::ofstream seed(dir / "seed.csv");
    seed << "u [m s^-1],X [N],N [N m]\n-1,1,0\n";
  }
  const fs::path db = dir / "runs.db";
  ASSERT_EQ(run_cli({"--db", "runs.db", "import", "seed.csv"}, dir.path()).exit_code, 0);

  // One uninterrupted call, timed: the random moments after an event scale
  // with it (where a kill lands, not whether work gets through).
  const auto call_started = Clock::now();
  ASSERT_EQ(run_cli({"--db", "runs.db", "import", file_name(0)}, dir.path()).exit_code, 0);
  const auto call_ms = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - call_started).count();

  Reader reader(db);
  std::mt19937 random(20240607);    // fixed seed: the same kill schedule every run
  std::set<std::string> committed;  // files whose import call returned 0 before a kill
  int kills = 0, kills_with_database_open = 0, rounds_with_progress = 0;
  for (int round = 0; round < kKills; ++round) {
    const Census before = census(db);
    ASSERT_EQ(before.problems, "") << "before round " << round;
    std::string script = "for f in";
    for (int f = 0; f < kFiles; ++f)
      if (!before.present.count(file_name(f))) script += " " + file_name(f);
    if (script == "for f in") break;  // everything is in: nothing left to interrupt
    script += "; do " + shell_quote(HYDROCOEF_CLI) +
              " --db runs.db import \"$f\" >/dev/null 2>>import-errors.log && "
              "echo \"$f\" >>done.log; done";
    fs::remove(dir / "done.log");

    const pid_t child = start_group(script, dir.path());
    // Kills follow what the child has done, never the clock alone, so that a
    // loaded machine changes where a kill lands but not what the test sees.
    const auto open = [&] { return database_open_in_group(child); };
    if (round % 2 == 0) {
      // Let work through: once the child reports an import committed, a
      // random moment of what follows (starting up, parsing, writing,
      // between calls).
      EXPECT_TRUE(wait_for_event(child, [&] { return !lines_of(dir / "done.log").empty(); }))
          << "round " << round << ": the child ended without committing an import";
      const double calls = std::uniform_real_distribution<double>(0.0, 1.2)(random);
      std::this_thread::sleep_for(std::chrono::milliseconds(static_cast<long>(calls * static_cast<double>(call_ms))));
    } else {
      // Inside an import: a random time after a call opened the database,
      // and while a call has it open (the next call's, if this one ended).
      wait_for_event(child, open);
      std::this_thread::sleep_for(std::chrono::microseconds(std::uniform_int_distribution<int>(0, 40000)(random)));
      wait_for_event(child, open);
    }
    const bool database_open = open();
    kill_group(child);
    ++kills;
    if (database_open) ++kills_with_database_open;
    const auto done = lines_of(dir / "done.log");
    committed.insert(done.begin(), done.end());

    const Census after = census(db);
    EXPECT_EQ(after.problems, "") << "after kill " << kills;
    for (const auto& file : committed) EXPECT_TRUE(after.present.count(file)) << file << " was committed, then lost";
    for (const auto& file : before.present) EXPECT_TRUE(after.present.count(file)) << file << " was lost";
    if (after.present.size() > before.present.size()) ++rounds_with_progress;
  }
  EXPECT_EQ(lines_of(dir / "import-errors.log"), std::set<std::string>{});

  // Finish without interruption: every file arrives whole.
  std::vector<std::string> args = {"--db", "runs.db", "import"};
  for (int f = 0; f < kFiles; ++f) args.push_back(file_name(f));
  const auto rest = run_cli(args, dir.path());
  EXPECT_EQ(rest.exit_code, 0) << rest.err;
  reader.stop();
  const Census final_census = census(db);
  EXPECT_EQ(final_census.problems, "");
  EXPECT_EQ(final_census.present.size(), static_cast<std::size_t>(kFiles));

  const auto reader_problems = reader.problems();
  EXPECT_TRUE(reader_problems.empty()) << reader_problems.size() << " bad reads, first: " << reader_problems.front();
  EXPECT_GE(reader.queries(), 20u);
  EXPECT_GE(kills, 20);
  // The schedule must really have hit open transactions and let work through
  // (every even round waits for a committed import).
  EXPECT_GE(kills_with_database_open, kKills / 4);
  EXPECT_GE(rounds_with_progress, kKills / 2);
  std::cout << "crash safety: one import call took " << call_ms << " ms; " << kills << " SIGKILLs ("
            << kills_with_database_open << " with the database open), " << committed.size()
            << " imports reported committed before a kill, " << rounds_with_progress << " rounds with progress, "
            << reader.queries() << " reader queries, 0 runs lost or partial\n";
  RecordProperty("kills", kills);
  RecordProperty("kills_with_database_open", kills_with_database_open);
}

}  // namespace
}  // namespace hydrocoef::test
