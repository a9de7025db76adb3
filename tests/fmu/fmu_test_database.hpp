// The database the FMU tests export from: the ASR-V surge runs (one axis, u)
// with a pchip surface extrapolating linearly and one refusing values outside
// its axis, and a two-axis grid (u, v; outputs X, Y) built with pchip and,
// from part of its runs, with linear; each states a standard deviation. Built through the CLI, as a user would.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::test {

/// The grid's runs; `offset` added to X (another file's content).
inline void write_fmu_grid_csv(const std::filesystem::path& path, double offset = 0.0) {
  std::ofstream out(path);
  out << "u [m s^-1],v [m s^-1],X [N],Y [N]\n";
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j) {
      const double u = 0.1 * i, v = 0.1 * (j - 2);
      out << u << "," << v << "," << offset - 3.0 * u * std::abs(u) - 0.4 * v * v + 0.01 * i * j << ","
          << -2.0 * v * std::abs(v) + 0.3 * u * v - 0.02 * (i + j) << "\n";
    }
}

/// Makes hydrocoef.db in `dir`: surfaces "surge" (pchip, linear outside),
/// "surge-strict" (linear, error outside) of body asr-v, "grid" (pchip,
/// u and v clamped) and "grid-high" (linear, linear outside, on u >= 0.2 and
/// v >= 0.1 only: ranges without 0) of body grid.
inline void make_fmu_database(const TempDir& dir) {
  const std::string surge = HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-surge-damping.csv";
  auto imported = run_cli({"import", surge, "--body", "asr-v", "--sign", "opposing", "--rho", "998.2"}, dir.path());
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  write_fmu_grid_csv(dir / "grid.csv");
  imported = run_cli({"import", (dir / "grid.csv").string(), "--body", "grid"}, dir.path());
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"surface", "build", "surge", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method", "pchip",
            "--extrapolate", "linear"},
           {"surface", "build", "surge-strict", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method",
            "linear", "--extrapolate", "error"},
           {"surface", "build", "grid", "--body", "grid", "--outputs", "X,Y", "--axes", "u,v", "--method", "pchip",
            "--extrapolate", "clamp"},
           {"surface", "build", "grid-high", "--body", "grid", "--outputs", "X,Y", "--axes", "u,v", "--method",
            "linear", "--extrapolate", "linear", "--where", "u>=0.2", "--where", "v>=0.05"}}) {
    const auto built = run_cli(args, dir.path());
    ASSERT_EQ(built.exit_code, 0) << built.err;
  }
}

/// `hydrocoef export-fmu BODY --surface NAME -o FILE`, asserting success.
inline void export_fmu_file(const TempDir& dir, const std::string& body, const std::string& surface,
                            const std::string& file) {
  const auto exported = run_cli({"export-fmu", body, "--surface", surface, "-o", file}, dir.path());
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
}

}  // namespace hydrocoef::test
