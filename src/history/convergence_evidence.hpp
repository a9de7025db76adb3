// What a run's solver files say about its convergence, beside its force
// history: whether the solver was steady or transient, and whether the case's
// convergence criteria (OpenFOAM's SIMPLE residualControl, CFX's residual
// target) were met at the end. Read by the pipeline from the case
// (src/pipeline/openfoam_convergence.hpp); the history analysis
// (history_analysis.hpp) decides the run's convergence kind from it.
//
// Every statement carries where it was read (file:line), so that `runs show`
// can say why a run was taken as converged.
#pragma once

#include <limits>
#include <optional>
#include <string>

namespace hydrocoef {

enum class SolverKind { Unknown, Steady, Transient };

struct ConvergenceEvidence {
  SolverKind solver = SolverKind::Unknown;
  /// Where the solver's kind was read, e.g. "case/system/fvSchemes:20
  /// (ddtSchemes default steadyState)".
  std::string solver_source;
  /// The case states convergence criteria (e.g. residualControl), read at
  /// criteria_source.
  bool criteria_stated = false;
  std::string criteria_source;
  /// The criteria held at the record's last iteration, which is this
  /// abscissa (iteration number).
  std::optional<double> criteria_met_at;
  /// Where the residuals that met (or missed) the criteria were read
  /// ("case/postProcessing/solverInfo/0/solverInfo.dat:147").
  std::string residuals_source;
  /// When the criteria were stated but not met: the field, its residual and
  /// tolerance, in words.
  std::string criteria_missed;
  /// The slowest decay rate per iteration of the controlled fields' residuals
  /// over the record's tail, reported with the run (the forces creep more
  /// slowly than this: src/history/iterative_error.hpp); NaN when not known.
  double residual_rate = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace hydrocoef
