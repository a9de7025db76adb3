// A MATLAB function from derivative sets of several variables
// (src/export/derivative_export.hpp), in the form of the vessel models of
// Fossen's Marine Systems Simulator (MSS): a file NAME.m holding
//
//   function [xdot, U] = NAME(x, ui)
//
// with x = [u v w p q r]' the body's velocity relative to the water (body
// axes x forward, y starboard, z down; m/s, rad/s) and ui the inputs the
// terms read besides u..r (controls and disturbances such as a rudder angle
// delta, in the order the header lists; SI, angles in rad). It returns
// xdot = M \ tau, tau the sum of the sets' forces and moments on the body
// (SNAME signs; sets stated "opposing" are negated) and M = M_RB + M_A the
// mass matrix given to the export, and U = sqrt(u^2 + v^2 + w^2). Like MSS's
// models the function checks the sizes of its arguments; unlike them it
// holds the hydrodynamic damping alone: rigid-body Coriolis, restoring
// forces and kinematics are the caller's (MSS's m-files have them).
//
// Names are data: the function name must be a MATLAB identifier (refused
// otherwise); set and input names appear only in comments and strings,
// written through escape::matlab_comment and escape::matlab_string; the
// terms read x(k) and ui(k), never a variable named after an input.
#pragma once

#include <string>
#include <vector>

#include "src/core/matrix6.hpp"
#include "src/export/derivative_export.hpp"

namespace hydrocoef {

/// Whether `name` can name a MATLAB function: a letter then letters, digits
/// or '_', at most 63 characters, not a keyword.
bool is_matlab_function_name(std::string_view name);

/// The inputs ui the sets read, in the order of ui: every name other than
/// u, v, w, p, q, r, sorted.
std::vector<std::string> derivative_matlab_inputs(const std::vector<DerivativeSet>& sets);

/// The whole m-file. Throws InputError, one line naming what is wrong, for a
/// function name that is not a MATLAB identifier, a set check_derivative_set
/// refuses, an output not in X..N or given twice, a term in alpha, beta or
/// du (not states of the function), or a mass matrix that is not finite,
/// symmetric and positive definite.
std::string derivative_matlab(const std::string& function_name, const std::vector<DerivativeSet>& sets,
                              const Matrix6& mass);

}  // namespace hydrocoef
