// I/O errors in every write path of the store, SQLite's own habit (its
// ioerr tests): a VFS registered as the process's default
// (tests/support/failing_vfs.hpp) makes the N-th read, write, sync,
// truncate, size, lock, shared-memory map, open, delete or access fail with
// SQLITE_IOERR_* (or SQLITE_CANTOPEN), once or from then on, for N = 1, 2,
// ... until the operation runs through without meeting the fault
// (tests/support/store_write_paths.hpp). Every failure must be one line of
// InputError, and the database, reopened, must pass its integrity check and
// hold exactly what it held before (or, when the operation said it
// succeeded, exactly what it writes). The database starts in WAL mode (as
// hydrocoef leaves it) or in rollback-journal mode (as an older tool may
// leave it), so faults meet the -wal, -shm and -journal files as well as the
// database.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "tests/support/backend_under_test.hpp"
#include "tests/support/failing_vfs.hpp"
#include "tests/support/store_write_paths.hpp"

namespace hydrocoef::test {
namespace {

struct IoCase {
  WritePath path;
  std::string journal_mode;  ///< "wal" or "delete"
  bool persistent = false;   ///< every I/O call from the N-th on fails, not the N-th alone
};

std::vector<IoCase> io_cases() {
  std::vector<IoCase> out;
  for (const auto& path : store_write_paths())
    for (const char* mode : {"wal", "delete"})
      for (const bool persistent : {false, true}) out.push_back({path, mode, persistent});
  return out;
}

std::string io_case_name(const ::testing::TestParamInfo<IoCase>& info) {
  return info.param.path.name + "_" + info.param.journal_mode + (info.param.persistent ? "_persistent" : "_once");
}

void PrintTo(const IoCase& io, std::ostream* out) { *out << io_case_name({io, 0}); }

class IoErrorInjection : public ::testing::TestWithParam<IoCase> {};

// Every N up to a write path's I/O calls (a few hundred at most).
constexpr long kMostIterations = 3000;

TEST_P(IoErrorInjection, LeavesTheDatabaseAsItWasOrAsWritten) {
  HYDROCOEF_SQLITE_FILE_ONLY("I/O of SQLite's files");
  const IoCase& io = GetParam();
  VfsFaults& faults = install_failing_vfs();
  std::array<long, static_cast<int>(VfsFileKind::Count)> by_kind{};
  const FaultSwitch fault_switch{[&](long n) { faults.arm(n, io.persistent); }, [&] { faults.disarm(); },
                                 [&] { return faults.calls; },
                                 [&] {
                                   for (int k = 0; k < static_cast<int>(VfsFileKind::Count); ++k)
                                     by_kind[static_cast<std::size_t>(k)] += faults.hits_by_kind[k];
                                   return faults.hits;
                                 },
                                 [&] { return faults.first_fault; }};
  const FaultLoopResult result = run_fault_loop(io.path, io.journal_mode, fault_switch, kMostIterations);
  if (HasFailure()) return;

  // The faults fired, the operation failed because of them, and they met the
  // database file and the file of its journal mode.
  EXPECT_GT(result.faults, 0);
  EXPECT_GT(result.failures, 0);
  EXPECT_EQ(result.stride, 1);
  EXPECT_EQ(result.iterations, result.events + 1);
  EXPECT_GT(by_kind[static_cast<std::size_t>(VfsFileKind::MainDatabase)], 0);
  if (io.journal_mode == "wal")
    EXPECT_GT(by_kind[static_cast<std::size_t>(VfsFileKind::Wal)], 0);
  else
    EXPECT_GT(by_kind[static_cast<std::size_t>(VfsFileKind::Journal)], 0);
  // A sync that fails after the commit frame is written leaves the write in
  // the WAL, for the next opening to replay, when no checkpoint after it
  // succeeds: the case the store's "may or may not have been stored" is for.
  if (io.journal_mode == "wal" && io.persistent) EXPECT_GT(result.uncertain_commits_stored, 0);
  std::string messages;
  for (const auto& [message, count] : result.messages) messages += "\n  " + std::to_string(count) + "x " + message;
  std::printf(
      "%s: N = 1..%ld, %ld failed (%ld at a commit that may have stored the write, %ld had), %ld faults; "
      "messages:%s\n",
      io_case_name({io, 0}).c_str(), result.iterations, result.failures, result.uncertain_commits,
      result.uncertain_commits_stored, result.faults, messages.c_str());
}

INSTANTIATE_TEST_SUITE_P(WritePaths, IoErrorInjection, ::testing::ValuesIn(io_cases()), io_case_name);

}  // namespace
}  // namespace hydrocoef::test
