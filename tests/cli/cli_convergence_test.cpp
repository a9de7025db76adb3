// A run stores what the CFD says, through the CLI: a converged steady case
// (the quarter sphere runs met their residualControl) is stored as its final
// iterate, unflagged, and `runs show` says why, naming the files; a case
// whose free stream is nowhere is refused with one line, exit 2 and the
// database unchanged, and imported at rest only with --at-rest; a force file
// given with --key-from-name takes its key from its name; gci refuses window
// means of steady runs unless --allow-unconverged.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/file_bytes.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
const fs::path kSphere = fs::path(HYDROCOEF_SOURCE_DIR) / "data" / "openfoam-sphere";

std::size_t lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(CliConvergence, AConvergedCaseIsItsFinalIterateAndRunsShowSaysWhy) {
  test::TempDir dir;
  const auto imported =
      run_cli({"import", (kSphere / "quarter-cases/U0.1000").string(), "--body", "sphere", "--axes=-x,y,-z", "--json"},
              dir.path());
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  const auto json = nlohmann::json::parse(imported.out);
  const auto& statistics = json["files"][0]["statistics"];
  EXPECT_EQ(statistics["convergence"], "converged");
  EXPECT_TRUE(statistics["flags"].empty());
  EXPECT_EQ(statistics["components"]["X"]["window"], "final iterate");
  const auto runs = run_cli({"runs"}, dir.path());
  EXPECT_NE(runs.out.find("converged"), std::string::npos) << runs.out;
  const auto show = run_cli({"runs", "show", "1"}, dir.path());
  ASSERT_EQ(show.exit_code, 0) << show.err;
  EXPECT_NE(show.out.find("convergence: converged: the convergence criteria ("), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("system/fvSolution:44: SIMPLE residualControl"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("solverInfo.dat:147"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("final iterate, iteration 145: iterative error"), std::string::npos) << show.out;
  const auto show_json = nlohmann::json::parse(run_cli({"runs", "show", "1", "--json"}, dir.path()).out);
  EXPECT_EQ(show_json["convergence"], "converged");
  EXPECT_EQ(show_json["forces"]["X"]["statistics"]["convergence"], "converged");
}

TEST(CliConvergence, ACaseWithoutAFreeStreamIsRefusedUnlessAtRest) {
  test::TempDir dir;
  fs::copy(kSphere / "quarter-cases/U0.1000", dir / "XMin-case", fs::copy_options::recursive);
  test::write_bytes(dir / "XMin-case/0/U",
                    "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
                    "internalField uniform (0 0 0);\nboundaryField\n{\n"
                    "    XMin { type zeroGradient; }\n    sphere { type noSlip; }\n}\n");
  ASSERT_EQ(run_cli({"import", (kSphere / "quarter-cases/U0.3000").string(), "--body", "sphere"}, dir.path()).exit_code,
            0);
  const auto before = test::dump_database(dir / "hydrocoef.db");
  const auto refused = run_cli({"import", (dir / "XMin-case").string(), "--body", "sphere"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(lines(refused.err), 1u) << refused.err;
  EXPECT_NE(refused.err.find("no body velocity found"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find((dir / "XMin-case/0/U").string() + ": no patch with a free stream"), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("--at-rest"), std::string::npos) << refused.err;
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
  const auto at_rest =
      run_cli({"import", (dir / "XMin-case").string(), "--body", "sphere", "--at-rest", "--json"}, dir.path());
  ASSERT_EQ(at_rest.exit_code, 0) << at_rest.err;
  EXPECT_EQ(nlohmann::json::parse(at_rest.out)["files"][0]["key"]["u"], 0.0);
}

TEST(CliConvergence, GciRefusesWindowMeansOfSteadyRunsUnlessAllowed) {
  // Three full-domain runs that never met their residualControl, stored as
  // three mesh levels of one key: a study of window means is refused.
  test::TempDir dir;
  int level = 1;
  for (const char* name : {"u0.10_v0.00", "u0.10_v0.05", "u0.30_v0.00"}) {
    const auto r =
        run_cli({"import", (kSphere / "cases" / name).string(), "--body", "sphere", "--flow", "0.1,0,0", "--set",
                 "mesh=" + std::to_string(level), "--set", "cells=" + std::to_string(100000 * level * level * level)},
                dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ++level;
  }
  const auto before = test::dump_database(dir / "hydrocoef.db");
  const auto refused = run_cli({"gci", "--body", "sphere"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(lines(refused.err), 1u) << refused.err;
  EXPECT_NE(refused.err.find("steady-window"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--allow-unconverged"), std::string::npos) << refused.err;
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
  const auto allowed = run_cli({"gci", "--body", "sphere", "--allow-unconverged", "--no-store"}, dir.path());
  ASSERT_EQ(allowed.exit_code, 0) << allowed.err;
  EXPECT_NE(allowed.out.find("fine to coarse: steady-window, steady-window, steady-window"), std::string::npos)
      << allowed.out;
  EXPECT_NE(allowed.out.find("did not converge"), std::string::npos) << allowed.out;
}

}  // namespace
}  // namespace hydrocoef
