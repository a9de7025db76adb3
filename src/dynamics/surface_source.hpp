// Where a vehicle's damping surfaces come from: a run database, opened
// read-only on first use, so that a vehicle whose damping is all fitted laws
// never opens it (and needs no database file). What `hydrocoef simulate` and
// `equilibrium`, and the C++ and Python simulate, give VehicleModel.
#pragma once

#include <filesystem>

#include "src/dynamics/damping.hpp"

namespace hydrocoef {

/// Surfaces by name from the database at `database` (InputError naming the
/// database for a file that is not one, or listing the stored surfaces for a
/// name that is not there).
SurfaceResolver database_surface_resolver(const std::filesystem::path& database);

}  // namespace hydrocoef
