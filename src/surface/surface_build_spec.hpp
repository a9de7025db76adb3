// What a stored surface was built from and how: its build specification,
// stored with the surface (the "build_spec" member of its definition JSON) so
// that `surface rebuild`, the library and the Python module build it again
// from the current runs without any command-line text.
//
// Stored form (JSON, version 1):
//   {"version": 1,
//    "axes": ["u", "current_v"], "outputs": ["X", "N"],
//    "method": "linear",                       (interpolation_name, "rbf" or "gp")
//    "out_of_range": ["error", "clamp"],       (one policy per axis)
//    "where": ["u>=0.1"],                      (clauses of src/core/run_selection.hpp, all must hold)
//    "exclude_runs": [6],
//    "mirror": {"planes": ["v"], "odd": ["current_v"]},
//    "rbf": {"kernel": "cubic", "degree": 1, "smoothing": 0},
//    "resample": null | [[u breakpoints], [current_v breakpoints]],
//    "resample_method": "linear",
//    "far_threshold": 0.25,
//    "gp": {"kernel": "matern52", "degree": 1, "starts": 5, "seed": 1}}   (method "gp" only)
// A stored specification is untrusted input (a database someone else made):
// parse_build_spec checks every member's type, count and value.
#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "src/surface/surface_builder.hpp"

namespace hydrocoef {

struct SurfaceBuildSpec {
  SurfaceSpec surface;                     ///< axes, outputs, method, policies, RBF and resampling
  std::vector<std::string> where;          ///< selection clauses (src/core/run_selection.hpp)
  std::vector<std::int64_t> exclude_runs;  ///< run ids left out
  std::vector<std::string> mirror_planes;  ///< "u", "v", "w" (src/pipeline/fit_runs.hpp MirrorSpec)
  std::vector<std::string> mirror_odd;     ///< disturbances odd in the mirror
};

inline constexpr int kBuildSpecVersion = 1;

/// The stored form (see the file comment).
nlohmann::json build_spec_json(const SurfaceBuildSpec& spec);

/// Reads the stored form back. `context` names the surface for messages
/// ("surface 'surge' in db.sqlite"); InputError for a member that is
/// missing, of the wrong type, or out of range.
SurfaceBuildSpec parse_build_spec(const nlohmann::json& stored, const std::string& context);

/// The stored form from the build options that surfaces built before
/// migration 7 kept (the command line's own strings: "--extrapolate" entries
/// "POLICY" or "AXIS=POLICY", "--resample" entries "AXIS=FROM:TO:COUNT" or
/// "AXIS=X1,X2,..."). Used only by that migration.
nlohmann::json build_spec_from_legacy_options(const nlohmann::json& legacy, const std::string& context);

/// Per-axis out-of-range policies from "POLICY" (every axis) and
/// "AXIS=POLICY" entries; InputError for an axis not among `axes`.
std::vector<std::string> out_of_range_policies(const std::vector<std::string>& axes,
                                               const std::vector<std::string>& entries, const std::string& option);

/// One axis's resampling breakpoints from "AXIS=FROM:TO:COUNT" (COUNT evenly
/// spaced, 2 to 100000) or "AXIS=X1,X2,...".
std::pair<std::string, std::vector<double>> parse_resample_entry(const std::string& text, const std::string& option);

/// The resampling grid of a surface over `axes` from one entry per axis (the
/// form of parse_resample_entry), in the order of `axes`. InputError when an
/// axis has no entry or an entry names an axis the surface does not have.
std::vector<std::vector<double>> resample_grid(const std::vector<std::string>& axes,
                                               const std::vector<std::string>& entries, const std::string& option);

}  // namespace hydrocoef
