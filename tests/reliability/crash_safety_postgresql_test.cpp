// Crash safety on PostgreSQL, as tests/reliability/crash_safety_test.cpp
// checks it on an SQLite file: a child process imports force tables, one
// `hydrocoef import` call (= one transaction) after another, into a database
// on the test server and is killed with SIGKILL at random moments: half after
// an import reported itself committed, half while it holds the write lock
// (inside its transaction); kills wait for these events, not for the clock.
// After every kill, every source file is all there (all its runs, each with X
// and N from that file) or not at all, every import reported done is there,
// and the next writer is not kept waiting by the killed one (the server ends
// the dead session's transaction and its lock).
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <thread>

#include "src/store/database.hpp"
#include "tests/support/process_group.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/test_database.hpp"

namespace hydrocoef::test {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kFiles = 30;
constexpr int kRowsPerFile = 400;
constexpr int kKills = 16;

std::string file_name(int file) { return "run-" + std::to_string(100 + file) + ".csv"; }

/// The files whose runs are all there; a file partly there is a problem.
std::set<std::string> whole_files(const std::string& location, std::string& problems) {
  RunDatabase database(location, RunDatabase::OpenMode::MustExist);
  std::map<std::string, int> runs_per_file;
  for (const auto& run : database.runs()) {
    const auto& x = run.tau_b[0];
    const auto& n = run.tau_b[5];
    if (!x || !n || x->source_path != n->source_path) {
      problems += "run " + describe(run.key) + " without X and N of one file; ";
      continue;
    }
    ++runs_per_file[std::filesystem::path(x->source_path).filename().string()];
  }
  std::set<std::string> out;
  for (const auto& [file, count] : runs_per_file) {
    if (count == kRowsPerFile)
      out.insert(file);
    else
      problems += file + " has " + std::to_string(count) + " runs; ";
  }
  return out;
}

/// True while some session holds the database's write lock (a
/// transaction-scoped advisory lock on the key pair src/store/postgresql_backend.cpp takes).
bool write_lock_held(store::Connection& connection) {
  auto held = connection.prepare(
      "SELECT count(*) FROM pg_locks WHERE locktype = 'advisory' AND granted AND classid = 1752786034 AND "
      "objid = (hashtext(current_schema()) & 2147483647)::oid AND database = (SELECT oid FROM pg_database WHERE "
      "datname = current_database())");
  held.step();
  return held.get_int(0) > 0;
}

TEST(CrashSafetyPostgreSQL, KilledImportsLeaveWholeFilesOrNone) {
  TestDatabase db(store::Backend::PostgreSQL);
  HYDROCOEF_NEED_DATABASE(db);
  const auto dir = db.dir().path();
  for (int f = 0; f < kFiles; ++f) {
    std::ofstream out(dir / file_name(f));
    out.precision(17);
    out << "u [m s^-1],X [N],N [N m]\n";
    for (int r = 0; r < kRowsPerFile; ++r) {
      const double u = 0.001 * (f * kRowsPerFile + r + 1);
      out << u << ',' << -3.0 * u * u << ',' << 0.25 * u << '\n';
    }
  }
  const auto call_started = Clock::now();
  ASSERT_EQ(run_cli({"--db", db.location(), "import", file_name(0)}, dir).exit_code, 0);
  const auto call_ms = std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - call_started).count();

  auto watcher = db.connect();
  std::mt19937 random(20261126);
  std::set<std::string> committed{file_name(0)};
  int kills = 0, kills_holding_lock = 0, rounds_with_progress = 0;
  for (int round = 0; round < kKills; ++round) {
    std::string problems;
    const auto before = whole_files(db.location(), problems);
    ASSERT_EQ(problems, "") << "before round " << round;
    std::string script = "for f in";
    for (int f = 0; f < kFiles; ++f)
      if (!before.count(file_name(f))) script += " " + file_name(f);
    if (script == "for f in") break;
    script += "; do " + shell_quote(HYDROCOEF_CLI) + " --db " + shell_quote(db.location()) +
              " import \"$f\" >/dev/null 2>>import-errors.log && echo \"$f\" >>done.log; done";
    std::filesystem::remove(dir / "done.log");
    const pid_t child = start_group(script, dir);
    // Kills follow events (an import committed, the write lock taken), never
    // the clock alone: a loaded machine moves where a kill lands, not what
    // the test sees.
    const auto holding_lock = [&] { return write_lock_held(watcher); };
    if (round % 2 == 0) {
      EXPECT_TRUE(wait_for_event(child, [&] { return !lines_of(dir / "done.log").empty(); }))
          << "round " << round << ": the child ended without committing an import";
      const double calls = std::uniform_real_distribution<double>(0.0, 1.2)(random);
      std::this_thread::sleep_for(std::chrono::milliseconds(static_cast<long>(calls * static_cast<double>(call_ms))));
    } else {
      wait_for_event(child, holding_lock);
      std::this_thread::sleep_for(std::chrono::microseconds(std::uniform_int_distribution<int>(0, 20000)(random)));
      wait_for_event(child, holding_lock);
    }
    const bool holding = holding_lock();
    kill_group(child);
    ++kills;
    if (holding) ++kills_holding_lock;
    const auto done = lines_of(dir / "done.log");
    committed.insert(done.begin(), done.end());
    const auto after = whole_files(db.location(), problems);
    EXPECT_EQ(problems, "") << "after kill " << kills;
    for (const auto& file : committed) EXPECT_TRUE(after.count(file)) << file << " was committed, then lost";
    if (after.size() > before.size()) ++rounds_with_progress;
  }
  EXPECT_EQ(lines_of(dir / "import-errors.log"), std::set<std::string>{});
  // The next writer finds no lock of a dead session, and every file arrives whole.
  std::vector<std::string> args = {"--db", db.location(), "import"};
  for (int f = 0; f < kFiles; ++f) args.push_back(file_name(f));
  const auto rest = run_cli(args, dir, "/dev/null", "HYDROCOEF_DB_TIMEOUT=20 ");
  EXPECT_EQ(rest.exit_code, 0) << rest.err;
  std::string problems;
  EXPECT_EQ(whole_files(db.location(), problems).size(), static_cast<std::size_t>(kFiles));
  EXPECT_EQ(problems, "");
  EXPECT_GE(kills_holding_lock, kKills / 4);
  EXPECT_GE(rounds_with_progress, kKills / 2);  // every even round waits for a committed import
  std::cout << "crash safety (PostgreSQL): one import call took " << call_ms << " ms; " << kills << " SIGKILLs ("
            << kills_holding_lock << " holding the write lock), " << committed.size()
            << " imports committed before a kill, 0 runs lost or partial\n";
}

}  // namespace
}  // namespace hydrocoef::test
