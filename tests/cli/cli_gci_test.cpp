// hydrocoef gci: runs of one key at three or more mesh levels (disturbance
// parameters mesh and cells) imported through the CLI; the observed order
// and the extrapolated value of f(h) = f0 + C h^p recovered, oscillatory
// convergence reported as such, too few levels refused with the database
// unchanged, the stored result replaced on a re-run, and the numerical
// uncertainty reaching the runs' standard uncertainty and a weighted fit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "tests/support/hostile_names.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using nlohmann::json;
using test::run_cli;
using test::TempDir;

constexpr double kOrderX = 1.7, kOrderY = 2.3;
// cells = N, volume 1, dimension 3: h = N^(-1/3) = 0.005, 0.01, 0.02 (and 0.04).
constexpr double kCells[] = {8e6, 1e6, 125000, 15625};
constexpr double kH[] = {0.005, 0.01, 0.02, 0.04};

double f0_x(double u) { return -(20.0 * u * u + 0.5 * u); }
double f0_y(double u) { return 3.0 * u + 0.25; }
/// X converges monotonically, Y oscillates between the levels.
double x_at(double u, int level) { return f0_x(u) + 40.0 * std::pow(kH[level], kOrderX); }
double y_at(double u, int level) { return f0_y(u) + (level % 2 ? -1.0 : 1.0) * 25.0 * std::pow(kH[level], kOrderY); }

std::string number(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

/// A force table of keys u = speeds at the given mesh levels (0 = finest).
std::filesystem::path write_table(const std::filesystem::path& dir, const std::string& name,
                                  const std::vector<double>& speeds, const std::vector<int>& levels) {
  const auto path = dir / name;
  std::ofstream out(path);
  out << "u [m s^-1],mesh,cells,X [N],Y [N]\n";
  for (const double u : speeds)
    for (const int level : levels)
      out << number(u) << ',' << level + 1 << ',' << number(kCells[level]) << ',' << number(x_at(u, level)) << ','
          << number(y_at(u, level)) << '\n';
  return path;
}

int import_table(const TempDir& dir, const std::filesystem::path& table, const std::string& body = "hull") {
  return run_cli({"import", table.string(), "--body", body, "--sign", "on-body", "--disturbance", "mesh",
                  "--disturbance", "cells", "--quiet"},
                 dir.path())
      .exit_code;
}

const json& key_with_speed(const json& study, double u) {
  for (const auto& key : study["keys"])
    if (std::abs(key["key"]["u"].get<double>() - u) < 1e-12) return key;
  ADD_FAILURE() << "no key u=" << u;
  static const json none;
  return none;
}

TEST(Gci, RecoversTheOrderAndTheExtrapolatedValueOfAPowerLaw) {
  TempDir dir;
  const std::vector<double> speeds = {0.1, 0.2, 0.3};
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "mesh.csv", speeds, {0, 1, 2})), 0);
  const auto result = run_cli({"gci", "--body", "hull", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto study = json::parse(result.out);
  ASSERT_EQ(study["keys"].size(), 3u);
  for (const double u : speeds) {
    const auto& key = key_with_speed(study, u);
    EXPECT_EQ(key["key"]["disturbances"].size(), 0u) << key;  // mesh and cells are not part of the physical key
    EXPECT_EQ(key["levels"], json({1, 2, 3}));
    const auto& x = key["components"]["X"];
    EXPECT_EQ(x["convergence"], "monotonic");
    EXPECT_NEAR(x["r21"].get<double>(), 2.0, 1e-12);
    EXPECT_NEAR(x["apparent_order"].get<double>(), kOrderX, 1e-10);
    EXPECT_NEAR(x["extrapolated"].get<double>(), f0_x(u), 1e-10 * std::abs(f0_x(u)));
    EXPECT_NEAR(x["relative_error"].get<double>(), std::abs((x_at(u, 1) - x_at(u, 0)) / x_at(u, 0)), 1e-12);
    // GCI_fine = 1.25 e_a / (r^p - 1), and u_num = GCI_fine |phi1| / 2.
    const double gci = 1.25 * x["relative_error"].get<double>() / (std::pow(2.0, kOrderX) - 1.0);
    EXPECT_NEAR(x["gci_fine"].get<double>(), gci, 1e-9 * gci);
    EXPECT_NEAR(x["numerical_uncertainty"].get<double>(), gci * std::abs(x_at(u, 0)) / 2.0, 1e-9 * gci);
  }
  EXPECT_EQ(study["stored"], true);
}

TEST(Gci, ReportsOscillatoryConvergence) {
  TempDir dir;
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "mesh.csv", {0.2}, {0, 1, 2})), 0);
  const auto result = run_cli({"gci", "--body", "hull", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto study = json::parse(result.out);
  const auto& y = study["keys"][0]["components"]["Y"];
  EXPECT_EQ(y["convergence"], "oscillatory");
  // Equal ratios: q(p) = 0 and |e32 / e21| = r^p, so p is the law's.
  EXPECT_NEAR(y["apparent_order"].get<double>(), kOrderY, 1e-10);
  const auto text = run_cli({"gci", "--body", "hull", "--no-store"}, dir.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("oscillatory"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("monotonic"), std::string::npos) << text.out;
}

TEST(Gci, UsesTheThreeFinestOfFourLevelsAndSaysSo) {
  TempDir dir;
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "mesh.csv", {0.2}, {0, 1, 2, 3})), 0);
  const auto result = run_cli({"gci", "--body", "hull", "--json", "--no-store"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto study = json::parse(result.out);
  const auto& key = study["keys"][0];
  EXPECT_EQ(key["levels"].size(), 4u);
  ASSERT_EQ(key["notes"].size(), 1u);
  EXPECT_NE(key["notes"][0].get<std::string>().find("mesh=4 left out"), std::string::npos) << key["notes"];
  EXPECT_NEAR(key["components"]["X"]["h"][0].get<double>(), kH[0], 1e-15);
  EXPECT_NEAR(key["components"]["X"]["h"][2].get<double>(), kH[2], 1e-15);
}

TEST(Gci, TooFewLevelsAreRefusedAndTheDatabaseIsUnchanged) {
  TempDir dir;
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "three.csv", {0.1}, {0, 1, 2})), 0);
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "two.csv", {0.3}, {0, 1})), 0);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  const auto result = run_cli({"gci", "--body", "hull"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find("u=0.3"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("2 mesh levels"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("expected 3 or more"), std::string::npos) << result.err;
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
}

TEST(Gci, ARunWithoutACellSizeIsRefusedNamingIt) {
  TempDir dir;
  const auto path = dir / "no-size.csv";
  {
    std::ofstream out(path);
    out << "u [m s^-1],mesh,X [N]\n0.1,1,-1.0\n0.1,2,-1.1\n0.1,3,-1.3\n";
  }
  ASSERT_EQ(
      run_cli({"import", path.string(), "--body", "hull", "--sign", "on-body", "--disturbance", "mesh"}, dir.path())
          .exit_code,
      0);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  const auto result = run_cli({"gci", "--body", "hull"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find("no cell size"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("run "), std::string::npos) << result.err;
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
}

TEST(Gci, EqualCellSizesAreRefused) {
  TempDir dir;
  const auto path = dir / "same.csv";
  {
    std::ofstream out(path);
    out << "u [m s^-1],mesh,cell_size [m],X [N]\n0.1,1,0.01,-1.0\n0.1,2,0.01,-1.1\n0.1,3,0.04,-1.3\n";
  }
  ASSERT_EQ(run_cli({"import", path.string(), "--body", "hull", "--sign", "on-body", "--disturbance", "mesh",
                     "--disturbance", "cell_size"},
                    dir.path())
                .exit_code,
            0);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  const auto result = run_cli({"gci", "--body", "hull"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("same cell size"), std::string::npos) << result.err;
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
}

TEST(Gci, AReRunReplacesTheStoredResult) {
  TempDir dir;
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "mesh.csv", {0.1, 0.2}, {0, 1, 2})), 0);
  ASSERT_EQ(run_cli({"gci", "--body", "hull"}, dir.path()).exit_code, 0);
  const auto rows = [&] {
    const std::string dump = test::dump_database(dir / "hydrocoef.db");
    std::size_t n = 0;
    for (std::size_t at = dump.find("numerical_uncertainty"); at != std::string::npos;
         at = dump.find("numerical_uncertainty", at + 1))
      ++n;
    return n;
  };
  const auto first_runs = run_cli({"runs", "--json"}, dir.path()).out;
  const std::size_t first_rows = rows();
  ASSERT_EQ(run_cli({"gci", "--body", "hull"}, dir.path()).exit_code, 0);
  EXPECT_EQ(rows(), first_rows);
  EXPECT_EQ(run_cli({"runs", "--json"}, dir.path()).out, first_runs);
  const auto stored = json::parse(run_cli({"runs", "--json"}, dir.path()).out);
  std::size_t with = 0;
  for (const auto& run : stored)
    if (!run["forces"]["X"]["numerical_uncertainty"].is_null()) ++with;
  EXPECT_EQ(with, 2u);  // the finest mesh of each key
}

TEST(Gci, TheNumericalUncertaintyReachesTheRunsAndAWeightedFit) {
  TempDir dir;
  const std::vector<double> speeds = {0.1, 0.2, 0.3, 0.4, 0.5};
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "mesh.csv", speeds, {0, 1, 2})), 0);
  const std::vector<std::string> fit = {"fit",    "--body",  "hull",   "--dof",      "X",     "--terms",
                                        "u,u|u|", "--where", "mesh=1", "--no-store", "--json"};
  const auto before = json::parse(run_cli(fit, dir.path()).out);
  EXPECT_EQ(before["weighting"], "none");
  EXPECT_EQ(before["n"], 5);

  const auto study = json::parse(run_cli({"gci", "--body", "hull", "--json"}, dir.path()).out);
  for (const auto& run : json::parse(run_cli({"runs", "--json"}, dir.path()).out)) {
    const auto& x = run["forces"]["X"];
    if (run["disturbances"]["mesh"] != 1) {
      EXPECT_TRUE(x["numerical_uncertainty"].is_null()) << run;
      EXPECT_EQ(x["standard_uncertainty"], 0.0);
      continue;
    }
    const double u = run["u"];
    const double expected = key_with_speed(study, u)["components"]["X"]["numerical_uncertainty"];
    EXPECT_GT(expected, 0.0);
    EXPECT_EQ(x["numerical_uncertainty"].get<double>(), expected);
    EXPECT_EQ(x["standard_uncertainty"].get<double>(), expected);
  }
  const auto after = json::parse(run_cli(fit, dir.path()).out);
  EXPECT_EQ(after["weighting"], "uncertainty");
  EXPECT_TRUE(after["chi2_reduced"].is_number()) << after;
}

TEST(Gci, AFitOfRunsWhoseUncertaintyChangesBecomesStaleOnce) {
  TempDir dir;
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "mesh.csv", {0.1, 0.2, 0.3}, {0, 1, 2})), 0);
  ASSERT_EQ(
      run_cli({"fit", "--body", "hull", "--dof", "X", "--terms", "u,u|u|", "--where", "mesh=1", "--name", "surge-x"},
              dir.path())
          .exit_code,
      0);
  ASSERT_EQ(run_cli({"fit", "--body", "hull", "--dof", "Y", "--terms", "1,u", "--where", "mesh=1", "--name", "sway-y",
                     "--unweighted"},
                    dir.path())
                .exit_code,
            0);
  const auto stale = [&] {
    std::map<std::string, bool> out;
    for (const auto& fit : json::parse(run_cli({"fits", "--json"}, dir.path()).out)) out[fit["name"]] = fit["stale"];
    return out;
  };
  EXPECT_EQ(stale(), (std::map<std::string, bool>{{"surge-x", false}, {"sway-y", false}}));
  const auto first = json::parse(run_cli({"gci", "--body", "hull", "--json"}, dir.path()).out);
  EXPECT_EQ(first["fits_made_stale"], 2);
  EXPECT_EQ(stale(), (std::map<std::string, bool>{{"surge-x", true}, {"sway-y", true}}));
  ASSERT_EQ(run_cli({"fit", "--refit"}, dir.path()).exit_code, 0);
  EXPECT_EQ(stale(), (std::map<std::string, bool>{{"surge-x", false}, {"sway-y", false}}));
  // The same study again changes no uncertainty: nothing becomes stale.
  const auto again = json::parse(run_cli({"gci", "--body", "hull", "--json"}, dir.path()).out);
  EXPECT_EQ(again["fits_made_stale"], 0);
  EXPECT_EQ(stale(), (std::map<std::string, bool>{{"surge-x", false}, {"sway-y", false}}));
}

TEST(Gci, AFitOverEveryMeshIsToldThatTheMeshVaries) {
  TempDir dir;
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "mesh.csv", {0.1, 0.2, 0.3}, {0, 1, 2})), 0);
  const auto text = run_cli({"fit", "--body", "hull", "--dof", "X", "--terms", "u,u|u|", "--no-store"}, dir.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("the runs differ in cells, mesh"), std::string::npos) << text.out;
  const auto result = json::parse(
      run_cli({"fit", "--body", "hull", "--dof", "X", "--terms", "u,u|u|", "--no-store", "--json"}, dir.path()).out);
  EXPECT_EQ(result["varying_conditions"], json({"cells", "mesh"}));
  EXPECT_EQ(result["n"], 9);
}

TEST(Gci, ASurfaceRefusesRunsOfSeveralMeshesAtOnePoint) {
  TempDir dir;
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "mesh.csv", {0.1, 0.2, 0.3}, {0, 1, 2})), 0);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  // 9 runs at 3 points of u: refused naming two runs at one point.
  const auto mixed =
      run_cli({"surface", "build", "surge", "--body", "hull", "--outputs", "X", "--axes", "u"}, dir.path());
  EXPECT_EQ(mixed.exit_code, 2);
  EXPECT_NE(mixed.err.find("have the same coordinates on the surface's axes"), std::string::npos) << mixed.err;
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
  const auto fine =
      run_cli({"surface", "build", "surge", "--body", "hull", "--outputs", "X", "--axes", "u", "--where", "mesh=1"},
              dir.path());
  EXPECT_EQ(fine.exit_code, 0) << fine.err;
}

TEST(Gci, NoStoreLeavesTheDatabaseUnchanged) {
  TempDir dir;
  ASSERT_EQ(import_table(dir, write_table(dir.path(), "mesh.csv", {0.1}, {0, 1, 2})), 0);
  const std::string before = test::dump_database(dir / "hydrocoef.db");
  const auto result = run_cli({"gci", "--body", "hull", "--no-store", "--json"}, dir.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(json::parse(result.out)["stored"], false);
  EXPECT_EQ(test::dump_database(dir / "hydrocoef.db"), before);
}

TEST(Gci, HostileBodyNamesAreDataInTheTableAndTheJson) {
  TempDir dir;
  std::size_t tried = 0;
  for (const std::string& name : test::hostile_names()) {
    try {
      check_name(NameKind::Body, name, {}, "test");
    } catch (const InputError&) {
      continue;  // a name no body can have
    }
    // The names a terminal or a JSON reader could take for something else.
    if (std::none_of(name.begin(), name.end(), [](char c) {
          const auto b = static_cast<unsigned char>(c);
          return b < 0x20 || b >= 0x7f || c == '"' || c == '\\';
        }))
      continue;
    ++tried;
    // Other bytes for each body: the same file again would be another reading of it.
    const auto table = write_table(dir.path(), "mesh.csv", {0.1 * static_cast<double>(tried)}, {0, 1, 2});
    ASSERT_EQ(import_table(dir, table, name), 0) << name;
    const auto result = run_cli({"gci", "--body", name, "--json", "--no-store"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << name << ": " << result.err;
    const auto study = json::parse(result.out);
    EXPECT_EQ(study["body"], name);
    EXPECT_EQ(study["keys"][0]["key"]["body"], name);
    const auto text = run_cli({"gci", "--body", name, "--no-store"}, dir.path());
    ASSERT_EQ(text.exit_code, 0) << name;
    EXPECT_TRUE(test::terminal_safe(text.out)) << name << ": a control character in " << text.out;
  }
  EXPECT_GT(tried, 5u);
}

}  // namespace
}  // namespace hydrocoef
