// Every command that reads a database, run on every tampered copy of a good
// one (tests/data/tampered/make-tampered.sh: foreign triggers and views,
// dropped columns, impossible schema versions, values of the wrong type,
// hostile names, oversized, truncated and overflowing blobs, broken files):
// each exits 0 or 2, never with a signal or "internal error", says what is
// wrong on one line, stays under an address-space limit, runs no command
// smuggled in a name, and leaves the database's bytes as they were.
//
// Heavy: about a thousand runs of the command line; runs in the optimized
// build (an address-space limit cannot be combined with AddressSanitizer).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "src/core/source_file.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::shell_quote;
using test::TempDir;

const std::string kExamples = HYDROCOEF_SOURCE_DIR "/examples/asr-v/";

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

std::string file_hash(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return sha256_hex(bytes);
}

// A good database: the ASR-V runs, fits of X and N, a grid and an RBF surface.
void make_good_database(const std::filesystem::path& dir) {
  const std::vector<std::vector<std::string>> steps = {
      {"import", kExamples + "asr-v-surge-damping.csv", "--body", "asr-v", "--sign", "opposing", "--rho", "998.2"},
      {"import", kExamples + "asr-v-yaw-damping.csv", "--body", "asr-v"},
      {"fit", "--body", "asr-v", "--dof", "X", "--terms", "u,u|u|"},
      {"fit", "--body", "asr-v", "--dof", "N", "--terms", "1,r,r|r|"},
      {"surface", "build", "surge", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method", "pchip",
       "--extrapolate", "linear"},
      {"surface", "build", "rbf", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method", "rbf"},
      {"surface", "build", "asr-v-yaw", "--body", "asr-v", "--outputs", "N", "--axes", "r", "--method", "pchip",
       "--extrapolate", "linear"},
      {"surface", "build", "asr-v-surge", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method", "pchip",
       "--extrapolate", "linear"},
  };
  for (const auto& step : steps) {
    const auto result = run_cli(step, dir);
    ASSERT_EQ(result.exit_code, 0) << step[0] << ": " << result.err;
  }
}

// The commands that read a database; "DB" stands for the database.
std::vector<std::vector<std::string>> reading_commands() {
  std::vector<std::vector<std::string>> commands = {
      {"runs"},
      {"runs", "--json"},
      {"fits"},
      {"surface", "list"},
      {"surface", "show", "surge"},
      {"surface", "show", "rbf", "--json"},
      {"query", "surge", "u=0.3"},
      {"query", "rbf", "u=0.3", "--json"},
      {"export-gazebo", "asr-v", "-o", "out/g.sdf", "--allow-missing", "--drop-constant"},
      {"plot", "fit", "asr-v:N(1,r,r|r|)", "-o", "out/f.svg"},
      {"plot", "surface", "surge", "-o", "out/s.svg"},
      {"report", "-o", "out/report"},
      {"simulate", "--vehicle", kExamples + "vehicle-surfaces.json", "--scenario",
       kExamples + "scenario-yaw-0.0027.json", "--out", "out/traj.csv"},
      {"equilibrium", "--vehicle", kExamples + "vehicle-surfaces.json", "--tau", "X=0.1"},
  };
  for (const char* format : {"csv", "json", "c", "mat", "jsbsim", "vtk"})
    commands.push_back({"export", "surge", "--format", format, "-o", std::string("out/e.") + format});
  return commands;
}

TEST(TamperedDatabases, EveryCommandRefusesCleanlyAndChangesNothing) {
  if (std::system("command -v sqlite3 > /dev/null") != 0) GTEST_SKIP() << "the sqlite3 program is not installed";
  TempDir dir;
  std::filesystem::create_directories(dir / "good");
  make_good_database(dir / "good");
  const auto good = dir / "good" / "hydrocoef.db";
  // Fold the WAL into the file, as make-tampered.sh expects.
  ASSERT_EQ(
      std::system(("sqlite3 " + shell_quote(good.string()) + " 'PRAGMA journal_mode = DELETE' > /dev/null").c_str()),
      0);

  const auto tampered = dir / "tampered";
  const std::string make = "bash " +
                           shell_quote(std::string(HYDROCOEF_SOURCE_DIR) + "/tests/data/tampered/make-tampered.sh") +
                           " " + shell_quote(good.string()) + " " + shell_quote(tampered.string()) + " > " +
                           shell_quote((dir / "count.txt").string());
  ASSERT_EQ(std::system(make.c_str()), 0);
  std::vector<std::filesystem::path> databases;
  for (const auto& entry : std::filesystem::directory_iterator(tampered)) databases.push_back(entry.path());
  std::sort(databases.begin(), databases.end());
  ASSERT_GE(databases.size(), 30u);

  const auto commands = reading_commands();
  std::size_t refused = 0;
  for (const auto& database : databases) {
    const std::string name = database.stem().string();
    const auto work = dir / ("run-" + name);
    std::filesystem::create_directories(work / "out");
    const auto copy = work / "hydrocoef.db";
    std::filesystem::copy_file(database, copy);
    const std::string before = file_hash(copy);
    bool any_refused = false;
    // The address-space limit: 3 GB, far above what these commands need and
    // far below what an unchecked size from the file would take.
    const std::string limit = kSanitized ? "" : "ulimit -v 3000000 && ";
    for (const auto& command : commands) {
      const auto result = run_cli(command, work, "/dev/null", limit);
      const std::string what = name + ": hydrocoef " + command[0] + " " + (command.size() > 1 ? command[1] : "");
      EXPECT_TRUE(result.exit_code == 0 || result.exit_code == 2)
          << what << " exit " << result.exit_code << ": " << result.err;
      EXPECT_EQ(result.err.find("internal error"), std::string::npos) << what << ": " << result.err;
      if (result.exit_code == 2) {
        any_refused = true;
        // One line, naming the database (or, for a plot, what failed).
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << what << ": " << result.err;
        EXPECT_LE(result.err.size(), 2100u) << what;
      }
      EXPECT_EQ(file_hash(copy), before) << what << " changed the database";
      EXPECT_FALSE(std::filesystem::exists(work / "PWNED")) << what;
      EXPECT_FALSE(std::filesystem::exists(work / "out" / "PWNED")) << what;
    }
    // A writer: refused with the database unchanged, or (for a defect that
    // only a reader of that table meets) an import that works.
    const auto imported =
        run_cli({"import", kExamples + "asr-v-surge-damping.csv", "--body", "other", "--sign", "opposing"}, work,
                "/dev/null", limit);
    EXPECT_TRUE(imported.exit_code == 0 || imported.exit_code == 2) << name << ": import: " << imported.err;
    EXPECT_EQ(imported.err.find("internal error"), std::string::npos) << name << ": " << imported.err;
    if (imported.exit_code != 0) {
      EXPECT_EQ(file_hash(copy), before) << name << ": a refused import changed the database";
      any_refused = true;
    }
    if (any_refused) ++refused;
    EXPECT_TRUE(any_refused) << name << ": no command noticed anything wrong";
  }
  EXPECT_EQ(refused, databases.size());
}

}  // namespace
}  // namespace hydrocoef
