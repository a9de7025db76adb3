// Where a vehicle's damping comes from when it names stored records: a run
// database, opened read-only on first use, so that a vehicle whose damping
// is all laws given in its file never opens it (and needs no database file).
// What `hydrocoef simulate`, `equilibrium` and `plot steady`, and the C++
// and Python simulate, give VehicleModel.
#pragma once

#include <filesystem>

#include "src/dynamics/damping.hpp"
#include "src/dynamics/vehicle.hpp"

namespace hydrocoef {

/// Surfaces by name from the database at `database` (InputError naming the
/// database for a file that is not one, or listing the stored surfaces for a
/// name that is not there).
SurfaceResolver database_surface_resolver(const std::filesystem::path& database);

/// Fills what the vehicle takes from the database: every damping law from a
/// stored fit ("fit": NAME: its terms, coefficients, sign convention and
/// covariance, empty when the fit recorded none), and the added mass from
/// the body's forced-oscillation runs ("added_mass": {"from_database":
/// BODY}; InputError naming the missing entries, or when M_RB + M_A is not
/// positive definite). InputError prefixed with the vehicle's file
/// for a fit that is not stored (listing those of the vehicle's DOF), of
/// another force component than the DOF it is given for, or whose stored
/// covariance is not one (src/dynamics/damping.hpp, covariance_problem).
/// Fills each damping that names a stored derivative model likewise
/// (src/dynamics/vehicle_stored_models.hpp). Opens the database only when a
/// fit, a derivative model or the added mass names it.
void resolve_stored_records(VehicleDescription& vehicle, const std::filesystem::path& database);

}  // namespace hydrocoef
