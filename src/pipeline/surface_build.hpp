// Building and rebuilding coefficient surfaces from stored runs, as a library
// call shared by the CLI (`surface build`, `surface rebuild`), the public API
// and the Python module:
//
//   select:  the body's runs that the specification's selection keeps
//            (src/core/run_selection.hpp);
//   mirror:  their mirror images beside them (src/pipeline/fit_runs.hpp),
//            never stored as runs;
//   build:   the table or RBF surface with its quality figures
//            (src/surface/surface_builder.hpp);
//   store:   the surface with its build specification
//            (src/surface/surface_build_spec.hpp), so that a rebuild makes it
//            again from the runs of that day without any command-line text.
// Outputs are forces on the body in body axes (N, N m); axes in SI units.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "src/store/database.hpp"
#include "src/surface/stored_surface.hpp"
#include "src/surface/surface_build_spec.hpp"

namespace hydrocoef {

/// A surface built and stored, with what went into it.
struct SurfaceBuildResult {
  StoredSurface stored;            ///< as read back from the database (record id set)
  std::size_t runs_measured = 0;   ///< selected runs of the body
  std::size_t mirror_images = 0;   ///< images added beside them
  std::size_t images_skipped = 0;  ///< images left out at the key of a measured run
  std::size_t runs_skipped = 0;    ///< runs (or images) without every output
  std::string mirror;              ///< the mirror's text ("v", "v,w/current_v"), "" for none
};

/// Builds surface `name` of `body` from the stored runs and stores it.
/// InputError for a bad name or specification (checked before any run is
/// read), when no run is selected, when the runs cannot make the surface
/// (src/surface/surface_builder.hpp), or when a surface of that name exists
/// and `taken` is Refuse (nothing is stored then).
SurfaceBuildResult build_and_store_surface(RunDatabase& database, const std::string& name, const std::string& body,
                                           const SurfaceBuildSpec& spec,
                                           RunDatabase::NameTaken taken = RunDatabase::NameTaken::Refuse);

/// The build specification stored with a surface; InputError when it was not
/// built by a surface build (or its specification is damaged).
SurfaceBuildSpec stored_build_spec(const SurfaceRecord& record);

/// Builds a stored surface again from the current runs with its stored
/// specification, replacing it.
SurfaceBuildResult rebuild_surface(RunDatabase& database, const SurfaceRecord& record);

/// The stored surfaces a rebuild covers: `name` alone when given, else the
/// body's (or every body's) surfaces, only the stale ones when `stale_only`.
std::vector<SurfaceRecord> surfaces_to_rebuild(RunDatabase& database, const std::optional<std::string>& name,
                                               const std::optional<std::string>& body, bool stale_only);

/// What a surface was built from, in the selection language: "all runs",
/// "u>=0.1 exclude-run 6", with ", mirror v" when mirror images stood beside
/// the runs; "(not built by surface build)" or "(build specification not
/// readable)" otherwise.
std::string built_from(const SurfaceRecord& record);

}  // namespace hydrocoef
