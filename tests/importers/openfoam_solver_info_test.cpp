// OpenFOAM's solverInfo.dat (importers/openfoam_solver_info): the real
// quarter-sphere runs' residual histories, checked against the final initial
// residuals each run's case.json states (written from the solver's log by
// another program); a vector field's residual is its largest component's;
// malformed files are refused with the file and line.
#include "importers/openfoam_solver_info.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/expect_input_error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
const fs::path kSphere = fs::path(HYDROCOEF_DATA_DIR) / "openfoam-sphere";

TEST(SolverInfo, TheQuarterRunsResidualsAreTheOnesTheirLogsGave) {
  for (const char* name : {"U0.1000", "U0.3000"}) {
    SCOPED_TRACE(name);
    const fs::path case_dir = kSphere / "quarter-cases" / name;
    const fs::path file = find_solver_info(case_dir);
    ASSERT_EQ(file, case_dir / "postProcessing/solverInfo/0/solverInfo.dat");
    const SolverResiduals r = read_solver_info(file);
    std::ifstream json_file(kSphere / "quarter" / name / "case.json");
    const auto json = nlohmann::json::parse(json_file);
    ASSERT_EQ(r.times.size(), json["iterations_run"].get<std::size_t>());
    EXPECT_EQ(r.times.front(), 1.0);
    EXPECT_EQ(r.times.back(), json["iterations_run"].get<double>());
    EXPECT_EQ(r.lines.front(), 3u);
    ASSERT_EQ(r.initial.size(), 4u);  // U, k, p, omega
    const auto& final = json["final_initial_residuals"];
    const double u = std::max({final["Ux"].get<double>(), final["Uy"].get<double>(), final["Uz"].get<double>()});
    EXPECT_EQ(r.initial.at("U").back(), u);
    for (const char* field : {"p", "k", "omega"}) EXPECT_EQ(r.initial.at(field).back(), final[field].get<double>());
  }
}

TEST(SolverInfo, NoSolverInfoFolderIsAnEmptyPath) {
  test::TempDir dir;
  EXPECT_TRUE(find_solver_info(dir.path()).empty());
  fs::create_directories(dir / "postProcessing/solverInfo/0");
  fs::create_directories(dir / "postProcessing/solverInfo/500");
  test::write_bytes(dir / "postProcessing/solverInfo/0/solverInfo.dat", "x");
  test::write_bytes(dir / "postProcessing/solverInfo/500/solverInfo.dat", "x");
  EXPECT_EQ(find_solver_info(dir.path()), dir / "postProcessing/solverInfo/500/solverInfo.dat");  // the restart's
}

TEST(SolverInfo, MalformedFilesAreRefusedWithTheirLine) {
  test::TempDir dir;
  const fs::path file = dir / "solverInfo.dat";
  const std::string header = "# Solver information\n# Time\tp_solver\tp_initial\tp_final\tp_iters\tp_converged\n";
  test::write_bytes(file, "1\tGAMG\t0.5\t0.01\t3\ttrue\n");
  test::expect_input_error([&] { read_solver_info(file); }, {file.string() + ":1", "before the header"});
  test::write_bytes(file, "# Solver information\n");
  test::expect_input_error([&] { read_solver_info(file); }, {file.string(), "no header line"});
  test::write_bytes(file, header + "1\tGAMG\t0.5\t0.01\t3\ttrue\n2\tGAMG\tabc\t0.01\t3\ttrue\n");
  test::expect_input_error([&] { read_solver_info(file); }, {file.string() + ":4", "abc"});
  test::write_bytes(file, header + "1\tGAMG\t0.5\t0.01\t3\ttrue\n2\tGAMG\t-0.5\t0.01\t3\ttrue\n");
  test::expect_input_error([&] { read_solver_info(file); }, {file.string() + ":4", "expected a number >= 0"});
  test::write_bytes(file, header + "2\tGAMG\t0.5\t0.01\t3\ttrue\n2\tGAMG\t0.4\t0.01\t3\ttrue\n");
  test::expect_input_error([&] { read_solver_info(file); }, {file.string() + ":4", "expected increasing times"});
  test::write_bytes(file, header + "1\tGAMG\t0.5\t0.01\n");
  test::expect_input_error([&] { read_solver_info(file); }, {file.string() + ":3"});
  // A run stopped while writing: its last, cut row is dropped.
  test::write_bytes(file, header + "1\tGAMG\t0.5\t0.01\t3\ttrue\n2\tGAMG\t0.4");
  EXPECT_EQ(read_solver_info(file).times.size(), 1u);
}

}  // namespace
}  // namespace hydrocoef
