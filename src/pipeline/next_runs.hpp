// Where to run CFD next: the run keys that most reduce a GP surface's
// largest standard deviation inside bounds (src/surface/gp_design.hpp:
// sequential maximum variance, each point added as a pseudo-run before the
// next), and the sweep manifest that hands them to the CFD set-up and back
// to `hydrocoef import --manifest` (src/pipeline/sweep_keys.hpp).
//
// The keys are ones a person would set up and that no run already covers:
//   - rounded: every coordinate a multiple of its axis's resolution (given,
//     or 1/100 of the bounds' width rounded down to a 1-2-5 step), written
//     as the decimal it is ("0.145", never "0.14482421875");
//   - in the fundamental domain of the surface's mirrors: a surface built
//     with --mirror v is symmetric in v, so a key and its image are the same
//     run; each candidate is replaced by the lexically largest of its images
//     (the plane's own component first: v >= 0), and each run chosen counts
//     with its images;
//   - new: a key at which the body has a run (its axes' values round to the
//     key, or to an image of it) or that is listed as running is never
//     proposed, and keys in flight count as pseudo-runs before the first
//     choice.
// Candidates are the whole lattice of rounded keys in the bounds when it has
// at most `candidates` points, else the corners and the rounded points of a
// Halton sequence until `candidates` distinct keys are found; rounding that
// makes two candidates one leaves one, so the design takes the next best
// instead of the same key twice.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/pipeline/fit_runs.hpp"
#include "src/store/database.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "src/surface/gp_design.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef {

struct NextRunsRequest {
  std::optional<std::string> output;  ///< whose standard deviation is reduced; default the first output
  /// "AXIS=FROM:TO" entries (SI units); an axis without one keeps the
  /// surface's range.
  std::vector<std::string> bounds;
  /// "AXIS=STEP" entries (SI units, STEP > 0): the keys' resolution; an axis
  /// without one gets 1/100 of its bounds' width rounded down to 1, 2 or 5
  /// times a power of ten.
  std::vector<std::string> round;
  std::size_t count = 5;
  std::size_t candidates = 4096;
  /// The surface's mirror planes (its build specification's); empty: none.
  MirrorSpec mirror;
  /// Keys on the surface's axes (one value per axis, axis order): runs the
  /// database holds, and runs asked for that are not imported yet.
  std::vector<std::vector<double>> imported, running;
};

struct NextRuns {
  std::string output, unit;            ///< the output whose uncertainty is reduced
  std::vector<std::string> axes;       ///< the surface's axes (velocity components, disturbances)
  std::vector<double> lower, upper;    ///< the bounds searched, per axis
  std::vector<double> resolution;      ///< per axis: every key is a multiple of it
  std::vector<bool> resolution_given;  ///< per axis: by --round (else the default)
  std::string mirror;                  ///< the mirror's text ("v", "" for none)
  std::string domain;                  ///< the fundamental domain in words ("v >= 0"; "" without a mirror)
  std::size_t candidates = 0;          ///< distinct new keys searched
  std::size_t imported_skipped = 0;    ///< candidate keys left out: a run is there
  std::size_t running_skipped = 0;     ///< candidate keys left out: listed as running
  std::vector<SuggestedRun> runs;      ///< in the order chosen
  double largest_sd_after = 0.0;       ///< over the candidates once all are added
};

/// The next runs of a GP surface. InputError for a surface that is not a GP,
/// an unknown output or axis, a malformed bound or resolution, bounds that
/// are not finite or not wider than their resolution, a count outside 1 to
/// 1000 or above the number of new keys at that resolution, or keys whose
/// size is not the surface's axis count.
NextRuns suggest_next_runs(const CoefficientSurface& surface, const NextRunsRequest& request);

/// The keys on a surface's axes of the body's runs in the database (runs
/// without one of its disturbances are left out).
std::vector<std::vector<double>> imported_keys(RunDatabase& database, const std::string& body,
                                               const CoefficientSurface& surface);

/// The keys on a surface's axes of a sweep manifest's rows of `body` (rows
/// that name another body are left out): the runs in flight. InputError
/// naming FILE:LINE for a row without a value of one of the axes.
std::vector<std::vector<double>> running_keys(const std::filesystem::path& manifest, const std::string& body,
                                              const CoefficientSurface& surface);

/// The mirror a stored surface was built with; none for a surface without a
/// build specification.
MirrorSpec surface_mirror(const SurfaceRecord& record);

/// Writes the suggestions as a sweep manifest: a header "path,body,AXES...",
/// then one row per run: a case name "next-01", ..., the body and the axis
/// values (SI). Written whole or not at all (src/core/atomic_file.hpp).
void write_next_runs_manifest(const NextRuns& next, const std::string& body, const std::filesystem::path& file);

}  // namespace hydrocoef
