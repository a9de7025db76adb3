// Physical checks of a damping law before it drives a simulation: a damping
// force must take energy out of the motion. A law fitted to noisy CFD forces
// can do the opposite over part of its range (a positive linear sway term
// under a small quadratic one), can hold a force at rest (a constant term
// the data support), or can have the opposite sign of what its runs say.
// `fit` prints these as warnings; `export-gazebo` refuses them unless the
// user allows them.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "src/core/damping_terms.hpp"
#include "src/core/run.hpp"

namespace hydrocoef {

enum class LawProblem {
  EnergyProducing,     ///< the power F·x of the velocity-dependent part is > 0 somewhere in the range
  ForceAtRest,         ///< the constant term is larger than its standard error
  SignContradictsRuns  ///< the runs' own forces push along the motion for the convention they are stored in
};

struct LawCheck {
  LawProblem problem;
  std::string message;  ///< one line: what, where (x and F·x) and what it means
};

struct LawCheckInput {
  DampingLawSpec spec;
  std::vector<double> coefficients;  ///< same order as spec.terms
  std::vector<double> std_errors;    ///< same order; NaN or empty where unknown
  SignConvention sign = SignConvention::OnBody;
  double x_min = 0.0;  ///< the fitted range of the velocity component [m/s or rad/s]
  double x_max = 0.0;
  std::span<const double> x;  ///< the runs' velocities (optional: the sign check needs them)
  std::span<const double> y;  ///< the runs' forces, in `sign`'s convention
};

/// Checks a law. The energy check is exact: on each side of x = 0 the power
/// of the velocity-dependent terms is x^2 (a + b x + c x^2), whose largest
/// value on an interval is at an end or where its derivative vanishes. The constant term is
/// left out of it (a force at rest is its own check). Returns nothing when
/// the law is physical on its range.
std::vector<LawCheck> check_damping_law(const LawCheckInput& input);

/// "energy-producing", "force-at-rest", "sign-contradicts-runs".
std::string_view law_problem_name(LawProblem problem);

}  // namespace hydrocoef
