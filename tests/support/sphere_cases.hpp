// Test support: the four OpenFOAM sphere case folders (data/openfoam-sphere/
// cases: forces averaged over their histories, with standard errors)
// imported through the CLI into the database of `dir` as body "sphere".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/run_cli.hpp"

namespace hydrocoef::test {

inline CliResult import_sphere_cases(const std::filesystem::path& dir) {
  std::vector<std::string> args = {"import"};
  for (const auto& entry : std::filesystem::directory_iterator(HYDROCOEF_SOURCE_DIR "/data/openfoam-sphere/cases"))
    args.push_back(entry.path().string());
  args.insert(args.end(), {"--body", "sphere", "--axes=-x,y,-z", "--quiet"});
  return run_cli(args, dir);
}

}  // namespace hydrocoef::test
