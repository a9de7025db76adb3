// `hydrocoef import` on inputs as users keep them, on the repository's real
// OpenFOAM sphere data: folders with READMEs, notes and logs beside the data
// (skipped, listed in one note), --key-from-name on files named on the
// command line, --prefer-surfaces inside a case folder, and a forced-
// oscillation case, which is `hydrocoef pmm`'s (refused, database untouched).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::TempDir;

const fs::path kSphere = HYDROCOEF_SOURCE_DIR "/data/openfoam-sphere";

nlohmann::json runs_of(const fs::path& dir) { return nlohmann::json::parse(run_cli({"runs", "--json"}, dir).out); }

TEST(CliImportInputs, FilesThatAreNotCfdDataAreSkippedWithOneNote) {
  TempDir dir;
  fs::copy(kSphere / "cases" / "u0.10_v0.00" / "postProcessing", dir / "run", fs::copy_options::recursive);
  std::ofstream(dir / "run" / "README.txt") << "Sphere, u = 0.1 m/s.\n";
  std::ofstream(dir / "run" / "SOURCE.txt") << "data/openfoam-sphere/cases/u0.10_v0.00\n";
  std::ofstream(dir / "run" / "notes.md") << "# notes\n";
  std::ofstream(dir / "run" / "log.simpleFoam") << "Time = 1\n";
  const auto result = run_cli(
      {"import", "run", "--body", "sphere", "--axes=-x,y,-z", "--flow", "0.1,0,0", "--rho", "998.2"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err << result.out;
  // One run, from forces/0/force.dat; one note lists the seven other files.
  ASSERT_EQ(runs_of(dir.path()).size(), 1u);
  std::size_t notes = 0, at = 0;
  while ((at = result.out.find("skipped as not CFD data", at)) != std::string::npos) ++notes, ++at;
  EXPECT_EQ(notes, 1u) << result.out;
  EXPECT_NE(result.out.find("note: 7 files skipped as not CFD data"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("README.txt, SOURCE.txt"), std::string::npos) << result.out;
}

TEST(CliImportInputs, KeyFromNameAppliesToFilesNamedOnTheCommandLine) {
  TempDir dir;
  for (const char* run : {"u0.10_v0.00", "u0.30_v0.00"}) {
    fs::create_directories(dir / run);
    for (const char* f : {"force.dat", "moment.dat"}) fs::copy_file(kSphere / "full" / run / f, dir / run / f);
  }
  const auto result = run_cli({"import", "u0.10_v0.00/force.dat", "u0.30_v0.00/force.dat", "--body", "sphere",
                               "--axes=-x,y,-z", "--rho", "998.2", "--key-from-name", "u{u}_v{v}"},
                              dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto runs = runs_of(dir.path());
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_DOUBLE_EQ(runs[0].at("u").get<double>(), 0.1);
  EXPECT_DOUBLE_EQ(runs[1].at("u").get<double>(), 0.3);
  // The same file twice under two names of one key: refused with both sources, nothing stored.
  fs::create_directories(dir / "again" / "u0.10_v0.00");
  for (const char* f : {"force.dat", "moment.dat"})
    fs::copy_file(kSphere / "full" / "u0.30_v0.00" / f, dir / "again" / "u0.10_v0.00" / f);
  const auto twice = run_cli({"--db", "twice.db", "import", "u0.10_v0.00/force.dat", "again/u0.10_v0.00/force.dat",
                              "--body", "sphere", "--axes=-x,y,-z", "--rho", "998.2", "--key-from-name", "u{u}_v{v}"},
                             dir.path());
  EXPECT_EQ(twice.exit_code, 2) << twice.out;
  EXPECT_NE(twice.err.find("from two files of this import: u0.10_v0.00/force.dat (u from the name pattern"),
            std::string::npos)
      << twice.err;
  EXPECT_FALSE(fs::exists(dir / "twice.db"));
}

TEST(CliImportInputs, PreferSurfacesReadsACaseFoldersVtkExport) {
  TempDir dir;
  const fs::path run = kSphere / "cases" / "u0.30_v0.00";
  const auto history =
      run_cli({"--db", "history.db", "import", run.string(), "--body", "sphere", "--axes=-x,y,-z"}, dir.path());
  ASSERT_EQ(history.exit_code, 0) << history.err;
  const auto surfaces = run_cli({"--db", "surfaces.db", "import", run.string(), "--body", "sphere", "--axes=-x,y,-z",
                                 "--prefer-surfaces", "--json"},
                                dir.path());
  ASSERT_EQ(surfaces.exit_code, 0) << surfaces.err;
  const auto json = nlohmann::json::parse(surfaces.out);
  ASSERT_EQ(json.at("files").size(), 1u);
  EXPECT_EQ(json.at("files")[0].at("format"), "vtk");
  EXPECT_TRUE(json.at("files")[0].contains("surface"));
  const auto a = nlohmann::json::parse(run_cli({"--db", "history.db", "runs", "--json"}, dir.path()).out);
  const auto b = nlohmann::json::parse(run_cli({"--db", "surfaces.db", "runs", "--json"}, dir.path()).out);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  // One run read two ways: the same key from the case's 0/U, the drag of the
  // integrated surface close to the forces function object's.
  EXPECT_DOUBLE_EQ(b[0].at("u").get<double>(), a[0].at("u").get<double>());
  const double x_history = a[0].at("forces").at("X").at("total").get<double>();
  const double x_surface = b[0].at("forces").at("X").at("total").get<double>();
  EXPECT_LT(x_surface, 0.0);
  EXPECT_NEAR(x_surface, x_history, 0.1 * std::abs(x_history));
  EXPECT_FALSE(b[0].at("forces").at("X").contains("statistics"));  // one surface, not a mean over a history
}

TEST(CliImportInputs, AForcedOscillationCaseNamesPmm) {
  TempDir dir;
  const fs::path pmm_case = HYDROCOEF_SOURCE_DIR "/examples/openfoam-sphere/pmm/surge-A0.015-T2";
  const auto result = run_cli({"import", pmm_case.string(), "--body", "sphere", "--axes=-x,y,-z"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("a forced-oscillation case"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("hydrocoef pmm " + pmm_case.string()), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_FALSE(fs::exists(dir / "hydrocoef.db"));
}

}  // namespace
}  // namespace hydrocoef
