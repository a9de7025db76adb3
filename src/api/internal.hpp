// What the public API's implementation (src/api/*.cpp) shares: the library's
// own headers and the Impl structs behind the public classes.
//
// No internal type takes a public type's name (the store's database is
// RunDatabase, an import's conflict rules ImportPolicy, a fit's loss
// LossOptions), so headers may be included in any order.
#pragma once

#include <mutex>
#include <optional>
#include <string>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/run.hpp"
#include "src/core/run_selection.hpp"
#include "src/dynamics/simulation.hpp"
#include "src/dynamics/surface_source.hpp"
#include "src/fit/damping_law.hpp"
#include "src/fit/fit_names.hpp"
#include "src/fit/physical_checks.hpp"
#include "src/pipeline/fit_runs.hpp"
#include "src/pipeline/fit_stored_runs.hpp"
#include "src/pipeline/import_files.hpp"
#include "src/pipeline/run_settings.hpp"
#include "src/pipeline/surface_build.hpp"
#include "src/pipeline/sweep_keys.hpp"
#include "src/store/database.hpp"
#include "src/surface/batch_evaluation.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "src/surface/stored_surface.hpp"

#include "hydrocoef/database.hpp"
#include "hydrocoef/error.hpp"
#include "hydrocoef/plot.hpp"
#include "hydrocoef/simulation.hpp"
#include "hydrocoef/surface.hpp"
#include "hydrocoef/version.hpp"

namespace hydrocoef {
inline namespace api {

struct Surface::Impl {
  CoefficientSurface surface;
  std::string name;
  std::string body;
  std::string method;
  bool stale = false;
};

struct Database::Impl {
  std::string path;
  bool read_only = false;
  std::optional<RunDatabase> store;  ///< empty once closed
  /// Every call holds it: a Database may be shared between threads (the
  /// Python module releases the GIL around long calls).
  std::mutex mutex;

  /// The open store; InputError "PATH: database is closed" after close().
  RunDatabase& open_store();
  /// As open_store, and InputError when the database was opened read-only.
  RunDatabase& writable_store(const char* what);
};

/// How the operations declared outside the Database class (the free functions
/// of include/hydrocoef/analysis.hpp, export.hpp, ...) reach a Database's
/// store. Every use holds the Impl's mutex for the whole call.
struct Database::Access {
  static Impl& impl(const Database& database) { return *database.impl_; }
};

/// The unit of each coefficient of a law ("N", "N/(m/s)", "N m/(rad/s)^2"),
/// in the order of its terms ("1,u,u|u|"), for a force component (X..N) and
/// its velocity component (u..r); empty when the terms do not parse.
std::vector<std::string> coefficient_units(const std::string& terms, const std::string& output,
                                           const std::string& variable);

}  // namespace api
}  // namespace hydrocoef
