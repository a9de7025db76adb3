// Test support: the ASR-V database as examples/asr-v/run.sh makes it, through
// the CLI: the surge table (opposing) and the yaw table (on body) imported
// with the water's density and viscosity, and the surfaces asr-v-surge
// (X(u)) and asr-v-yaw (N(r)) built with PCHIP, extrapolating linearly.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::test {

/// Makes hydrocoef.db in `dir` as above (fails the test when a command fails).
inline void make_asr_v_example_database(const TempDir& dir) {
  const std::string example = HYDROCOEF_SOURCE_DIR "/examples/asr-v/";
  for (const auto& [file, sign] : std::vector<std::pair<std::string, std::string>>{
           {example + "asr-v-surge-damping.csv", "opposing"}, {example + "asr-v-yaw-damping.csv", "on-body"}}) {
    const auto imported =
        run_cli({"import", file, "--body", "asr-v", "--sign", sign, "--rho", "998.2", "--nu", "1.004e-6"}, dir.path());
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
  }
  for (const auto& [name, output, axis] :
       std::vector<std::array<std::string, 3>>{{"asr-v-surge", "X", "u"}, {"asr-v-yaw", "N", "r"}}) {
    const auto built = run_cli({"surface", "build", name, "--body", "asr-v", "--outputs", output, "--axes", axis,
                                "--method", "pchip", "--extrapolate", "linear"},
                               dir.path());
    ASSERT_EQ(built.exit_code, 0) << built.err;
  }
}

}  // namespace hydrocoef::test
