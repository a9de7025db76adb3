// What an OpenFOAM case folder says about its run's convergence
// (src/history/convergence_evidence.hpp):
// - steady or transient: system/fvSchemes' `ddtSchemes { default ...; }`
//   (steadyState, or localEuler's local time stepping, is steady; Euler,
//   backward, CrankNicolson are transient), else system/controlDict's
//   `application` (simpleFoam and the other *SimpleFoam solvers are steady);
// - the criteria: the SIMPLE `residualControl` of system/fvSolution, a
//   tolerance per field name or pattern (`p 1e-4; "(k|omega)" 1e-4;`);
// - whether they hold at the end: the initial residuals of the last row of
//   postProcessing/solverInfo/<time>/solverInfo.dat, compared as the solver
//   does (simpleControl: residual < tolerance for every solved field that an
//   entry names; a vector field by its largest component), at the last
//   iteration of the force record;
// - the residuals' decay rate over the record's tail, for the iterative error.
// Patterns are read as OpenFOAM's regular expressions where they are plain
// words, alternations `(a|b)` and `.*`; any other pattern is said not
// understood, and the criteria are then not taken as met.
#pragma once

#include <filesystem>
#include <vector>

#include "src/history/convergence_evidence.hpp"

namespace hydrocoef {

/// `last_iteration`: the abscissa of the force record's last sample.
/// `notes` receives what a user should know (a pattern not understood).
/// InputError (file and line) for a dictionary or solverInfo.dat that cannot
/// be read.
ConvergenceEvidence openfoam_convergence_evidence(const std::filesystem::path& case_dir, double last_iteration,
                                                  std::vector<std::string>& notes);

}  // namespace hydrocoef
