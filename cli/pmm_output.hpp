// The added mass export-gazebo takes from the database (--same, --zero):
// what is left of the forced-oscillation output here; `hydrocoef pmm`,
// `pmm-runs` and `added-mass` print what the public API
// (include/hydrocoef/analysis.hpp) returns.
#pragma once

#include <string>
#include <vector>

#include "src/pmm/added_mass_assembly.hpp"

namespace hydrocoef::cli {

/// --same DOF=DOF and --zero DOF of export-gazebo; InputError naming the
/// option for a DOF name that is not one.
AddedMassOptions parse_added_mass_options(const std::vector<std::string>& same, const std::vector<std::string>& zero);

}  // namespace hydrocoef::cli
