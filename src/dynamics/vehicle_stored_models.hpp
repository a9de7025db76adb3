// A vehicle file's damping "derivatives": {"model": NAME}
// (src/dynamics/vehicle.hpp): the stored derivative model of that name
// (src/store/derivative_store.hpp) filled into the DOF's damping, its terms
// through the same checks as the inline form, its coefficients and
// covariance as stored, its sign on the body (fit_derivative_model stores
// forces on the body).
#pragma once

#include <string>

#include "src/dynamics/vehicle.hpp"

namespace hydrocoef {

class RunDatabase;

/// Fills every DOF whose damping names a stored derivative model. Throws
/// InputError "FILE: key 'damping.Y.derivatives.model': ..." (one line)
/// when there is no model of that name (listing the stored models of the
/// DOF's output), when the model is of another output, or when its terms or
/// covariance are refused as the inline form's would be. `database` names
/// the store in messages.
void resolve_derivative_models(VehicleDescription& vehicle, RunDatabase& store, const std::string& database);

/// Whether any DOF names a stored derivative model.
bool names_derivative_models(const VehicleDescription& vehicle);

}  // namespace hydrocoef
