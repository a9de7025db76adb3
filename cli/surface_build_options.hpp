// The options of `hydrocoef surface build`, and the build specification they
// describe (src/surface/surface_build_spec.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/surface/surface_build_spec.hpp"

namespace hydrocoef::cli {

/// What the command line of surface build gives.
struct SurfaceBuildArgs {
  std::string name;
  std::string body;
  std::vector<std::string> outputs;
  std::vector<std::string> axes;
  std::string method = "linear";
  std::vector<std::string> extrapolate;
  std::vector<std::string> where;
  std::vector<std::int64_t> exclude_runs;
  std::vector<std::string> mirror;
  std::vector<std::string> mirror_odd;
  bool replace = false;               ///< a surface of this name may be replaced (rebuild always replaces)
  std::optional<std::string> kernel;  ///< default: cubic (rbf), matern52 (gp)
  int degree = 1;
  int starts = 5;     ///< gp
  unsigned seed = 1;  ///< gp
  double smoothing = 0.0;
  std::vector<std::string> resample;
  std::string resample_method = "linear";
  double far_threshold = 0.25;
  bool json = false;
};

/// Registers the options of surface build (all but --json) on `command`.
void add_surface_build_options(CLI::App& command, SurfaceBuildArgs& args);

/// The build specification the options describe (names and grammar checked
/// before any run is read).
SurfaceBuildSpec surface_build_spec(const SurfaceBuildArgs& args);

}  // namespace hydrocoef::cli
