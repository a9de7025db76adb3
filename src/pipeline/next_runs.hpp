// Where to run CFD next: the run keys that most reduce a GP surface's
// largest standard deviation inside bounds (src/surface/gp_design.hpp:
// sequential maximum variance, each point added as a pseudo-run before the
// next), and the sweep manifest that hands them to the CFD set-up and back
// to `hydrocoef import --manifest` (src/pipeline/sweep_keys.hpp).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/surface/coefficient_surface.hpp"
#include "src/surface/gp_design.hpp"

namespace hydrocoef {

struct NextRunsRequest {
  std::optional<std::string> output;  ///< whose standard deviation is reduced; default the first output
  /// "AXIS=FROM:TO" entries (SI units); an axis without one keeps the
  /// surface's range.
  std::vector<std::string> bounds;
  std::size_t count = 5;
  std::size_t candidates = 4096;
};

struct NextRuns {
  std::string output, unit;          ///< the output whose uncertainty is reduced
  std::vector<std::string> axes;     ///< the surface's axes (velocity components, disturbances)
  std::vector<double> lower, upper;  ///< the bounds searched, per axis
  std::vector<SuggestedRun> runs;    ///< in the order chosen
  double largest_sd_after = 0.0;     ///< over the candidates once all are added
};

/// The next runs of a GP surface. InputError for a surface that is not a GP,
/// an unknown output or axis, a malformed or empty bound, or a count outside
/// 1 to 1000.
NextRuns suggest_next_runs(const CoefficientSurface& surface, const NextRunsRequest& request);

/// Writes the suggestions as a sweep manifest: a header "path,body,AXES...",
/// then one row per run: a case name "next-01", ..., the body and the axis
/// values (SI). Written whole or not at all (src/core/atomic_file.hpp).
void write_next_runs_manifest(const NextRuns& next, const std::string& body, const std::filesystem::path& file);

}  // namespace hydrocoef
