// Allocation failures in the main write paths of the store, SQLite's own
// habit (its malloc tests): SQLite's allocator, configured before SQLite
// starts (tests/support/failing_malloc.hpp, from a gtest Environment), makes
// the N-th allocation fail, once or from then on, for N = 1, 2, ... up to
// the operation's count (tests/support/store_write_paths.hpp). SQLITE_NOMEM
// must come out as one line of InputError, and the database, reopened, must
// pass its integrity check and hold exactly what it held before (or, when
// the operation said it succeeded, exactly what it writes).
#include <gtest/gtest.h>

#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "tests/support/backend_under_test.hpp"
#include "tests/support/failing_malloc.hpp"
#include "tests/support/store_write_paths.hpp"

namespace hydrocoef::test {
namespace {

// SQLite's allocator can change only before SQLite starts: before the first
// test opens a database.
class FailingMallocEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { install_failing_malloc(); }
};
const bool kFailingMallocRegistered = (::testing::AddGlobalTestEnvironment(new FailingMallocEnvironment), true);

struct AllocCase {
  WritePath path;
  bool persistent = false;  ///< every allocation from the N-th on fails, not the N-th alone
};

std::vector<AllocCase> alloc_cases() {
  std::vector<AllocCase> out;
  for (const auto& path : store_write_paths())
    if (path.name == "import" || path.name == "runs_delete" || path.name == "fit_save" || path.name == "surface_save")
      for (const bool persistent : {false, true}) out.push_back({path, persistent});
  return out;
}

std::string alloc_case_name(const ::testing::TestParamInfo<AllocCase>& info) {
  return info.param.path.name + (info.param.persistent ? "_persistent" : "_once");
}

void PrintTo(const AllocCase& alloc, std::ostream* out) { *out << alloc_case_name({alloc, 0}); }

class AllocFailureInjection : public ::testing::TestWithParam<AllocCase> {};

// Values of N tried per write path: every allocation up to this many, a
// regular sample of them beyond (a write path makes a few thousand).
constexpr long kMostIterations = 600;

TEST_P(AllocFailureInjection, LeavesTheDatabaseAsItWasOrAsWritten) {
  HYDROCOEF_SQLITE_FILE_ONLY("SQLite's allocator");
  const AllocCase& alloc = GetParam();
  AllocFaults& faults = install_failing_malloc();
  const FaultSwitch fault_switch{[&](long n) { faults.arm(n, alloc.persistent); }, [&] { faults.disarm(); },
                                 [&] { return faults.calls; }, [&] { return faults.hits; },
                                 [&] { return "allocation " + std::to_string(faults.fail_at); }};
  const FaultLoopResult result = run_fault_loop(alloc.path, "wal", fault_switch, kMostIterations);
  if (HasFailure()) return;

  // The faults fired and the operation failed because of them, saying so.
  EXPECT_GT(result.faults, 0);
  EXPECT_GT(result.failures, 0);
  bool out_of_memory = false;
  std::string messages;
  for (const auto& [message, count] : result.messages) {
    messages += "\n  " + std::to_string(count) + "x " + message;
    out_of_memory = out_of_memory || message.find("out of memory") != std::string::npos;
  }
  EXPECT_TRUE(out_of_memory) << "no failure said 'out of memory':" << messages;
  std::printf("%s: %ld allocations, N = 1..%ld by %ld, %ld failed, %ld faults; messages:%s\n",
              alloc_case_name({alloc, 0}).c_str(), result.events, result.events + 1, result.stride, result.failures,
              result.faults, messages.c_str());
}

INSTANTIATE_TEST_SUITE_P(WritePaths, AllocFailureInjection, ::testing::ValuesIn(alloc_cases()), alloc_case_name);

}  // namespace
}  // namespace hydrocoef::test
