#include "src/export/derivative_matlab_export.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/run.hpp"
#include "src/core/version.hpp"

namespace hydrocoef {
namespace {

// MATLAB's reserved words (iskeyword).
constexpr std::array<std::string_view, 20> kKeywords{
    "break",  "case", "catch",     "classdef", "continue",   "else",   "elseif", "end",    "for", "function",
    "global", "if",   "otherwise", "parfor",   "persistent", "return", "spmd",   "switch", "try", "while"};

std::string matlab_comment_line(const std::string& text) { return "% " + escape::matlab_comment(text) + "\n"; }

// The MATLAB expression of one factor of a term, its value read by `x`.
std::string factor_expression(const TermFactor& f, const std::string& x) {
  switch (f.power) {
    case 1: return f.odd ? x : "abs(" + x + ")";
    case 2: return f.odd ? x + "*abs(" + x + ")" : x + "^2";
    case 3: return f.odd ? x + "^3" : "abs(" + x + ")^3";
    default: return f.odd ? x + "^3*abs(" + x + ")" : x + "^4";
  }
}

}  // namespace

bool is_matlab_function_name(std::string_view name) {
  if (name.empty() || name.size() > 63) return false;
  const auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
  if (!letter(name.front())) return false;
  for (const char c : name)
    if (!letter(c) && !(c >= '0' && c <= '9') && c != '_') return false;
  return std::find(kKeywords.begin(), kKeywords.end(), name) == kKeywords.end();
}

std::vector<std::string> derivative_matlab_inputs(const std::vector<DerivativeSet>& sets) {
  std::set<std::string> names;
  for (const auto& set : sets)
    for (const auto& name : term_variables(set.terms))
      if (!velocity_index(name)) names.insert(name);
  return {names.begin(), names.end()};
}

std::string derivative_matlab(const std::string& function_name, const std::vector<DerivativeSet>& sets,
                              const Matrix6& mass) {
  if (!is_matlab_function_name(function_name))
    throw InputError("MATLAB function name '" + escape::one_line(function_name) +
                     "': expected a letter then letters, digits or '_' (at most 63, not a keyword)");
  if (sets.empty()) throw InputError("MATLAB export: no derivative sets, expected at least one");
  std::array<bool, 6> seen{};
  for (const auto& set : sets) {
    check_derivative_set(set);
    const auto dof = force_index(set.output);
    if (!dof)
      throw InputError("derivative set '" + escape::one_line(set.name) + "': output '" + escape::one_line(set.output) +
                       "' is not a force or moment; expected X, Y, Z, K, M or N");
    if (seen[*dof])
      throw InputError("derivative set '" + escape::one_line(set.name) + "': a second set of output " + set.output +
                       "; expected one per output");
    seen[*dof] = true;
    for (const auto& term : set.terms)
      for (const auto& f : term.factors())
        if (f.variable == "alpha" || f.variable == "beta" || f.variable == "du")
          throw InputError("derivative set '" + escape::one_line(set.name) + "': term '" + term.text() + "' reads '" +
                           f.variable +
                           "', which is not a state or input of the function; expected u, v, w, p, q, "
                           "r and controls or disturbances");
  }
  for (Eigen::Index i = 0; i < 6; ++i)
    for (Eigen::Index j = 0; j < 6; ++j)
      if (!std::isfinite(mass(i, j)) || std::abs(mass(i, j) - mass(j, i)) > 1e-9 * mass.cwiseAbs().maxCoeff())
        throw InputError("MATLAB export: the mass matrix M = M_RB + M_A is not finite and symmetric at (" +
                         std::to_string(i + 1) + "," + std::to_string(j + 1) + "); expected M = M^T");
  if (Eigen::LLT<Matrix6>(mass).info() != Eigen::Success)
    throw InputError(
        "MATLAB export: the mass matrix M = M_RB + M_A is not positive definite; expected M_RB + M_A "
        "in kg, kg m, kg m^2");

  const std::vector<std::string> inputs = derivative_matlab_inputs(sets);
  const std::string& name = function_name;
  std::string text = "function [xdot, U] = " + name + "(x, ui)\n";
  text += "% [xdot, U] = " + name + "(x, ui) returns the time derivative of the velocity x and the speed U\n";
  text += "% (m/s) of a body whose hydrodynamic forces are the derivative sets listed below.\n";
  text += "%\n";
  text += "% x  = [u v w p q r]'  velocity relative to the water in body axes: x forward,\n";
  text += "%                      y starboard, z down (m/s, rad/s)\n";
  if (inputs.empty()) {
    text += "% ui = []              no inputs: the terms read the velocities alone\n";
  } else {
    text += "% ui = inputs, in this order (SI; names other than u..r are taken as angles, rad):\n";
    for (std::size_t k = 0; k < inputs.size(); ++k)
      text += matlab_comment_line("  ui(" + std::to_string(k + 1) + ") = " + inputs[k]);
  }
  text += "%\n";
  text += "% xdot = M \\ tau, tau the sum of the sets' forces and moments on the body (SNAME: the\n";
  text += "% force of the water on the body, damping negative; N and N m) and M = M_RB + M_A.\n";
  text += "% Only the hydrodynamic terms below are included: add the rigid-body Coriolis and\n";
  text += "% centripetal forces, restoring forces, controls and kinematics for a full model.\n";
  text += "%\n";
  text += matlab_comment_line("Written by hydrocoef " + std::string(kVersion) + ". Derivative sets:");
  for (const auto& set : sets)
    text += matlab_comment_line("  " + set.output + ": '" + set.name + "', terms " + format_terms(set.terms) +
                                ", stated " + std::string(to_string(set.sign)) +
                                (set.sign == SignConvention::OpposingMotion ? " (negated to on-body here)" : ""));
  text += "\n";
  text += "if numel(x) ~= 6, error(" + escape::matlab_string("x must have 6 elements: [u v w p q r]'") + "); end\n";
  text += "if numel(ui) ~= " + std::to_string(inputs.size()) + ", error(" +
          escape::matlab_string("ui must have " + std::to_string(inputs.size()) + " elements") + "); end\n\n";
  text += "% Mass matrix M = M_RB + M_A (kg, kg m, kg m^2)\n";
  text += "M = [";
  for (Eigen::Index i = 0; i < 6; ++i) {
    for (Eigen::Index j = 0; j < 6; ++j) text += (j ? " " : "") + shortest_number(mass(i, j));
    text += i < 5 ? ";\n     " : "];\n\n";
  }
  text += "tau = zeros(6, 1);\n";
  for (const auto& set : sets) {
    const std::size_t dof = *force_index(set.output);
    text += matlab_comment_line(set.output + ": derivative set '" + set.name + "'");
    text += "tau(" + std::to_string(dof + 1) + ") = ...\n";
    for (std::size_t k = 0; k < set.terms.size(); ++k) {
      std::string term;
      for (const auto& f : set.terms[k].factors()) {
        std::string x;
        if (const auto v = velocity_index(f.variable))
          x = "x(" + std::to_string(*v + 1) + ")";
        else
          x = "ui(" + std::to_string(std::lower_bound(inputs.begin(), inputs.end(), f.variable) - inputs.begin() + 1) +
              ")";
        term += (term.empty() ? "" : " * ") + factor_expression(f, x);
      }
      const double c = to_on_body(set.coefficients[k], set.sign);
      text += "    " + std::string(k ? "+ " : "  ") + "(" + shortest_number(c) + ")" +
              (term.empty() ? "" : " * " + term) + (k + 1 < set.terms.size() ? " ..." : ";") + "  " +
              matlab_comment_line(set.terms[k].text());
    }
  }
  text += "\nxdot = M \\ tau;\n";
  text += "U = sqrt(x(1)^2 + x(2)^2 + x(3)^2);\n";
  text += "end\n";
  return text;
}

}  // namespace hydrocoef
