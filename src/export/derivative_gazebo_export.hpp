// gz-sim Hydrodynamics parameters from derivative sets of several
// variables (src/export/derivative_export.hpp), with every cross term gz-sim
// can hold. gz-sim's system (src/systems/hydrodynamics/Hydrodynamics.cc,
// the version reading 36 linear and 2 x 216 quadratic parameters) applies,
// in the link's axes with s = (u, v, w, p, q, r) relative to the water,
//
//   F_i = sum_j L_ij s_j + sum_jk A_ijk s_j |s_k| + sum_jk Q_ijk s_j s_k
//
// reading L_ij as <{f}{J}>, A_ijk as <{f}{J}abs{K}> and Q_ijk as <{f}{J}{K}>
// with f one of x y z k m n (the force) and J, K one of U V W P Q R, e.g.
// <yV>, <yUabsV> (u |v| in Y), <nUR> (u r in N); added mass <{f}Dot{J}>
// = -Ma. A derivative term maps onto one parameter when it is, in u..r:
//   a         -> {f}{A}          a*|a| -> {f}{A}abs{A}     a^2 -> {f}{A}{A}
//   a*b       -> {f}{A}{B}       a*|b| -> {f}{A}abs{B}     (a before b in u..r order)
// Anything else (a constant, |a|, |a|*|b|, a cubic such as v^2*r, three
// names, a control or disturbance such as delta) cannot be written: it is
// refused, naming the set and the term, unless drop_unrepresentable, when it
// is left out and listed in `dropped` and in the file's comments.
//
// Signs and axes as src/export/gazebo_export.hpp documents for the laws:
// the parameters are SNAME derivatives on the body (sets stated "opposing"
// are negated); in an FLU link (x forward, y left, z up) each parameter is
// multiplied by t_i t_j (t_i t_j t_k for Q) with t = (1,-1,-1,1,-1,-1).
// gz-sim warns that the Q parameters (s_j s_k, e.g. <xUU>) "may cause
// instabilities"; a note says so when one is written.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "src/core/matrix6.hpp"
#include "src/export/derivative_export.hpp"
#include "src/export/gazebo_export.hpp"

namespace hydrocoef {

struct DerivativeGazeboOptions {
  std::string link_name = "base_link";
  GazeboLinkAxes link_axes = GazeboLinkAxes::Flu;
  /// Leave out terms gz-sim cannot hold (listed) instead of refusing.
  bool drop_unrepresentable = false;
  /// Ma, positive, body axes (kg, kg m, kg m^2); checked by check_added_mass.
  /// Without it the added-mass parameters are written as 0, with a note.
  std::optional<Matrix6> added_mass;
};

struct DerivativeGazeboExport {
  std::vector<GazeboElement> elements;  ///< in file order; values in the link's axes
  std::vector<std::string> dropped;     ///< "Y: v^2*r (...why)", with drop_unrepresentable
  std::vector<std::string> notes;
  std::string text;  ///< the whole file
};

/// The gz-sim SDF parameter of a term of force `dof` (0..5 = X..N), and the
/// factor (+-1) that takes an FRD value into FLU; nullopt with `why` set
/// when gz-sim cannot hold it.
struct GzParameter {
  std::string name;
  double flu_factor = 1.0;
};
std::optional<GzParameter> gz_parameter(std::size_t dof, const Term& term, std::string& why);

/// Builds the parameters of the sets (at most one per output; outputs X..N).
/// Throws InputError, one line naming the set and the term or output, for a
/// set check_derivative_set refuses, an output not in X..N, two sets of one
/// output, a term gz-sim cannot hold (without drop_unrepresentable), an
/// empty link name, or an added mass check_added_mass refuses.
DerivativeGazeboExport derivative_gazebo(const std::vector<DerivativeSet>& sets,
                                         const DerivativeGazeboOptions& options);

}  // namespace hydrocoef
