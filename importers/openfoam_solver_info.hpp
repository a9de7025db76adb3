// OpenFOAM's solverInfo function object output
// (postProcessing/solverInfo/<start time>/solverInfo.dat): per iteration or
// time step, each solved field's linear solver, its initial and final
// residuals (per component for vectors: Ux_initial, Uy_initial, ...), the
// iterations and whether the linear solve converged. What hydrocoef needs of
// it is the initial residual of each field, which is what the SIMPLE and
// PIMPLE residualControl of the case compares with its tolerances (for a
// vector field its largest component).
//
// Layout (OpenFOAM v1912 to 12): a first comment line, then a header line
// "# Time<TAB>U_solver<TAB>Ux_initial<TAB>..." whose columns the rows follow,
// tab-separated; solver names and true/false are words, the rest numbers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hydrocoef {

struct SolverResiduals {
  std::filesystem::path file;
  std::vector<double> times;         ///< the first column: iteration or time
  std::vector<std::uint32_t> lines;  ///< 1-based line of each row
  /// Per field (p, U, k, omega...): the initial residual of each row, for a
  /// vector or tensor field the largest of its components'.
  std::map<std::string, std::vector<double>> initial;
};

/// Reads a solverInfo.dat. InputError naming the file and line for a file
/// without its header, a row that does not match it, a residual that is not
/// a finite number >= 0, times that do not increase, or a file over 1 GiB.
SolverResiduals read_solver_info(const std::filesystem::path& file);

/// The solverInfo.dat of a case folder: the one in the latest start-time
/// folder of postProcessing/solverInfo, or an empty path when there is none
/// (the older `residuals` function object writes no initial residuals by
/// field and is not read).
std::filesystem::path find_solver_info(const std::filesystem::path& case_dir);

}  // namespace hydrocoef
