// How `hydrocoef pmm` and `hydrocoef added-mass` report: readable tables or
// JSON. Units follow the entry: M_A[i][j] in kg (two translations), kg m (one
// rotation), kg m^2 (two rotations); D[i][j] in N s/m, N s or N m s.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "src/pipeline/pmm_runs.hpp"
#include "src/pmm/added_mass_assembly.hpp"

namespace hydrocoef::cli {

/// The runs analysed, and what storing them did (empty when not stored).
void print_pmm_runs(const std::vector<PmmRun>& runs, const std::vector<PmmSaved>& saved, const std::string& database,
                    bool json);

/// The stored analyses, one line each (pmm-runs).
void print_pmm_records(const std::vector<PmmRecord>& records, bool json);
/// What pmm-runs delete removed.
void print_pmm_deleted(const std::vector<PmmDeleted>& deleted, const std::string& database, bool json);

/// The assembled matrices.
void print_added_mass(const AddedMassAssembly& assembly, bool json);

/// --same DOF=DOF and --zero DOF of added-mass and export-gazebo; InputError
/// naming the option for a DOF name that is not one.
AddedMassOptions parse_added_mass_options(const std::vector<std::string>& same, const std::vector<std::string>& zero);

/// "kg", "kg m", "kg m^2" for M_A[i][j]; "N s/m", "N s", "N m s" for D[i][j].
std::string added_mass_unit(std::size_t i, std::size_t j);
std::string pmm_damping_unit(std::size_t i, std::size_t j);

}  // namespace hydrocoef::cli
