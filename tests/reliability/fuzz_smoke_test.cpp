// Smoke run of the libFuzzer targets (tests/fuzz), which the sanitizer build
// makes against its own library (HYDROCOEF_FUZZ_SMOKE; they need Clang, and
// a GCC build finds those of scripts/fuzz.sh in build/fuzz instead): each
// target replays its regression files in
// tests/data/bad/fuzz-regressions/TARGET/ (every crash a fuzzer ever found)
// and then fuzzes from the malformed-input corpus for a fixed number of
// inputs (kFuzzRuns, seed 1: the same inputs every run, however loaded the
// machine; about a second each under ASan). Without the fuzz build the test
// is skipped, saying so.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSource(HYDROCOEF_SOURCE_DIR);

// $HYDROCOEF_FUZZ_DIR; else the targets this build made (the sanitizer build
// with HYDROCOEF_FUZZ_SMOKE, as scripts/build.sh test configures it); else
// those of a fuzzing session's build/fuzz.
fs::path fuzz_dir() {
  if (const char* dir = std::getenv("HYDROCOEF_FUZZ_DIR")) return dir;
#ifdef HYDROCOEF_FUZZ_SMOKE_DIR
  return HYDROCOEF_FUZZ_SMOKE_DIR;
#else
  return kSource / "build" / "fuzz" / "tests" / "fuzz";
#endif
}

struct Run {
  int exit_code = -1;
  std::string log;
};

Run run(const std::string& command, const fs::path& log) {
  const int status = std::system((command + " >" + shell_quote(log.string()) + " 2>&1").c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(log)};
}

class FuzzSmoke : public ::testing::TestWithParam<std::string> {};

// Inputs each target runs after its corpus: a count, not a time (a loaded
// machine runs the same inputs, only slower).
constexpr long kFuzzRuns = 8000;

TEST_P(FuzzSmoke, ReplaysRegressionsAndFuzzesBriefly) {
  const fs::path exe = fuzz_dir() / GetParam();
  if (!fs::exists(exe))
    GTEST_SKIP() << exe
                 << " is not built (it needs Clang): the sanitizer build of scripts/build.sh test makes it, "
                    "or scripts/fuzz.sh --build-only";
  TempDir dir;
  const fs::path regressions = kSource / "tests" / "data" / "bad" / "fuzz-regressions" / GetParam();
  if (fs::is_directory(regressions) && !fs::is_empty(regressions)) {
    const auto replay =
        run(shell_quote(exe.string()) + " -runs=0 " + shell_quote(regressions.string()), dir / "replay.log");
    EXPECT_EQ(replay.exit_code, 0) << replay.log;
  }
  fs::create_directory(dir / "corpus");
  for (const char* folder : {"bad", "vtp-encodings", "fuzz-seeds"})
    for (const auto& entry : fs::directory_iterator(kSource / "tests" / "data" / folder))
      if (const auto extension = entry.path().extension();
          entry.is_regular_file() && (extension == ".csv" || extension == ".vtp" || extension == ".bin" ||
                                      extension == ".ccl" || extension == ".foam"))
        fs::copy_file(entry.path(), dir / "corpus" / entry.path().filename(), fs::copy_options::skip_existing);
  const auto fuzz =
      run(shell_quote(exe.string()) + " -seed=1 -runs=" + std::to_string(kFuzzRuns) + " -max_len=4096 -timeout=10 " +
              "-print_final_stats=1 -artifact_prefix=" + shell_quote((dir / "").string()) + " " +
              shell_quote((dir / "corpus").string()),
          dir / "fuzz.log");
  EXPECT_EQ(fuzz.exit_code, 0) << fuzz.log;
  const std::string key = "stat::number_of_executed_units:";
  const auto at = fuzz.log.find(key);
  ASSERT_NE(at, std::string::npos) << fuzz.log;
  const long executed = std::strtol(fuzz.log.c_str() + at + key.size(), nullptr, 10);
  // -runs counts the mutated inputs; the corpus's own files are run first,
  // and libFuzzer counts some of them too.
  EXPECT_GE(executed, kFuzzRuns) << fuzz.log;
}

const std::vector<std::string> kTargets = {"cfdpost_export_fuzz",
                                           "cfx_monitor_fuzz",
                                           "force_table_fuzz",
                                           "units_fuzz",
                                           "vehicle_fuzz",
                                           "scenario_fuzz",
                                           "vtp_fuzz",
                                           "stored_record_fuzz",
                                           "case_motion_fuzz",
                                           "cfx_ccl_fuzz",
                                           "openfoam_dictionary_fuzz",
                                           "captive_table_fuzz",
                                           "runtime_file_fuzz"};

INSTANTIATE_TEST_SUITE_P(Targets, FuzzSmoke, ::testing::ValuesIn(kTargets));

// A target built but not listed above would never run in the smoke test.
TEST(FuzzSmokeTargets, EveryBuiltTargetIsListed) {
  if (!fs::is_directory(fuzz_dir())) GTEST_SKIP() << fuzz_dir() << " does not exist: run scripts/fuzz.sh --build-only";
  for (const auto& entry : fs::directory_iterator(fuzz_dir())) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.size() > 5 && name.ends_with("_fuzz")) {
      EXPECT_NE(std::find(kTargets.begin(), kTargets.end(), name), kTargets.end())
          << name << " is built but not in the smoke test's list";
    }
  }
}

}  // namespace
}  // namespace hydrocoef::test
