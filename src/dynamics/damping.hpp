// Hydrodynamic damping of each degree of freedom, D(nu_r) nu_r of Fossen's
// model, as the dynamics model evaluates it: per generalized-force component
// either a constant damping law (terms of one relative velocity component,
// src/core/damping_terms.hpp), a derivative model of several variables
// (terms such as v, u*v, v*|v|, v^2*r over the relative velocity components
// and disturbance parameters, src/derivatives/terms.hpp) or one output of a
// coefficient surface
// whose axes are relative velocity components or named disturbance
// parameters supplied by the scenario (e.g. "current_v").
//
// The description (DampingSpec) is plain data read from a vehicle file; a
// DampingModel is built from it once, resolving surface names through a
// callback so that this module knows no database, and is then immutable:
// evaluate() is const, thread-safe and allocates nothing. DOFs that read the
// same surface with the same axis bindings share one lookup (GridTable
// interleaves outputs, so six outputs cost under twice one).
//
// Units and signs: nu_r_b = nu_b - nu_c_b, the body velocity relative to the
// water (u, v, w [m/s], p, q, r [rad/s]); the result is the damping force ON
// THE BODY (X, Y, Z [N], K, M, N [N m]; SNAME, damping is negative). A law,
// derivative model or surface given as "opposing" (a damping magnitude,
// positive opposes motion) is negated on evaluation; a derivative model's
// coefficients are SNAME derivatives when given "on-body" (Y_v, Y_uv, ...).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "runtime/src/damping_kernel.h"
#include "src/core/covariance.hpp"
#include "src/core/damping_terms.hpp"
#include "src/core/matrix6.hpp"
#include "src/core/run.hpp"
#include "src/derivatives/terms.hpp"
#include "src/dynamics/rigid_body.hpp"
#include "src/surface/coefficient_surface.hpp"

namespace hydrocoef {

/// Where the damping of one generalized-force component comes from.
struct DofDamping {
  enum class Kind {
    None,         ///< no damping in this DOF
    Law,          ///< F = sum_k c_k term_k(x), x one relative velocity component
    Surface,      ///< one output of a coefficient surface
    Derivatives,  ///< F = sum_k c_k term_k(nu_r, disturbances), terms of several variables
  };
  Kind kind = Kind::None;
  // Law: the terms (their variable is the relative velocity component) and
  // one coefficient per term [force unit / term unit].
  DampingLawSpec law;
  std::vector<double> coefficients;
  // Surface: its name (for the resolver), the output read ("X".."N" or any
  // output name), and for each surface axis where its value comes from: a
  // relative velocity component "u".."r" or a disturbance parameter name.
  // Axes not listed bind by their own name (velocity names to the relative
  // velocity, any other name to the disturbance of that name).
  std::string surface;
  std::string output;
  std::map<std::string, std::string> axis_sources;
  /// How the law's or surface's numbers are signed.
  SignConvention sign = SignConvention::OnBody;
  /// Law: the coefficients' covariance, k x k row by row [unit_i unit_j], in
  /// the law's sign convention; empty when the law states none (it is then
  /// held at its values by Monte Carlo draws, src/dynamics/damping_draws.hpp).
  std::vector<double> covariance;
  /// Law from a stored fit of this name: terms, coefficients, covariance and
  /// sign are filled from the database by resolve_stored_records
  /// (src/dynamics/surface_source.hpp) before the model is built.
  std::string fit;
  /// Surface: use it although its output feeds energy into its own motion
  /// somewhere in its range (src/surface/surface_checks.hpp); refused
  /// otherwise.
  bool allow_unphysical = false;
  /// Derivatives: the terms, one coefficient each in `coefficients` [force
  /// unit / term unit], `covariance` (m x m row by row, optional) and `sign`
  /// as for a law. The names u, v, w, p, q, r read the relative velocity;
  /// any other name reads the disturbance parameter of that name. The flow
  /// angles alpha, beta and the surge perturbation du are refused (the
  /// dynamics model does not derive them): a model fitted in them is given
  /// in u, v, w instead.
  std::vector<Term> terms;
  /// Derivatives from a stored model of this name ("derivatives": {"model":
  /// NAME}): terms, coefficients, covariance and sign filled from the
  /// database as for `fit` (a last member: the tests' positional
  /// initialisers of the members above stay valid).
  std::string derivative_model;
};

/// The damping of X, Y, Z, K, M, N in that order.
using DampingSpec = std::array<DofDamping, 6>;

/// Resolves a surface name to a surface (for example from the run database,
/// see src/surface/stored_surface.hpp); throws InputError when it has none.
using SurfaceResolver = std::function<CoefficientSurface(const std::string& name)>;

class DampingDraws;

class DampingModel {
 public:
  /// The most axes and outputs a surface used for damping may have.
  static constexpr std::size_t kMaxAxes = 8;
  static constexpr std::size_t kMaxOutputs = 32;

  DampingModel() = default;
  /// The most terms of a derivative model.
  static constexpr std::size_t kMaxDerivativeTerms = 64;

  /// Resolves every surface of `spec` once. Throws InputError naming the DOF
  /// ("damping of N") when a law has no terms or a coefficient count differs,
  /// a derivative model has no terms or more than kMaxDerivativeTerms, a
  /// coefficient that is not finite, a covariance that is not one, or a name
  /// the dynamics model cannot supply (alpha, beta, du),
  /// a surface is needed but `resolver` is empty or fails, an output or an
  /// axis binding names nothing the surface has, or a surface is too large.
  DampingModel(const DampingSpec& spec, const SurfaceResolver& resolver);

  /// Disturbance parameters the surfaces read, sorted by name. evaluate()
  /// takes their values in this order.
  const std::vector<std::string>& disturbance_names() const noexcept { return disturbance_names_; }
  /// True when the DOF (0..5 = X..N) has a law or a surface.
  bool damped(std::size_t dof) const noexcept { return damped_[dof]; }

  /// The damping force on the body at relative velocity nu_r_b with the given
  /// disturbance values (SI, disturbance_names() order). Throws as the
  /// surfaces do (InputError outside a surface's range under policy "error").
  Vector6 evaluate(const Vector6& nu_r_b, std::span<const double> disturbances) const;
  /// tau (6) += evaluate(nu_r_b (6), disturbances), term by term in
  /// evaluate's order (so tau = 0 gives evaluate's numbers bit for bit).
  /// Throws as evaluate; allocates nothing.
  void add(const double* nu_r_b, std::span<const double> disturbances, double* tau) const;
  /// As evaluate, and jacobian(i, j) = d tau_i / d nu_r_j: the laws' and
  /// derivative models' exact derivatives (d|x|/dx taken as 0 at x = 0) and
  /// the surfaces' own gradients along the axes bound to
  /// velocity components (the disturbances are held) [N or N m per m/s or
  /// rad/s]. For equilibrium solving, not the hot path.
  Vector6 evaluate_with_jacobian(const Vector6& nu_r_b, std::span<const double> disturbances, Matrix6& jacobian) const;

 private:
  struct Law {
    std::size_t dof = 0;
    std::size_t variable = 0;
    std::size_t count = 0;
    std::array<DampingTerm, 6> terms{};
    std::array<double, 6> coefficients{};  // sign folded in: force on the body
    std::array<int, 6> codes{};            // the terms as the shared kernel's codes (HC_DAMPING_*)
  };
  /// One name's factor of a derivative term: |x|^power, negated when odd
  /// and x < 0 (TermFactor with its name resolved): source 0..5 a nu_r
  /// component, 6 + k disturbance k (runtime/src/damping_kernel.h).
  using Factor = hc_damping_factor;
  struct Derivatives {
    std::size_t dof = 0;
    std::string text;                  // the terms' canonical list, for messages
    std::vector<double> coefficients;  // sign folded in: force on the body
    std::vector<std::size_t> begin;    // term k's factors: factors[begin[k] .. begin[k + 1])
    std::vector<Factor> factors;
    /// sum_k coefficients[k] * term_k at nu_r_b (6) and the disturbances.
    double value(const double* nu_r_b, std::span<const double> disturbances) const;
  };
  struct Lookup {
    CoefficientSurface surface;
    std::string key;   // surface name + bindings: DOFs with equal keys share the lookup
    std::string name;  // the surface's name
    std::size_t axis_count = 0;
    std::array<std::size_t, kMaxAxes> source{};  // 0..5: nu_r component; 6 + k: disturbance k
    std::size_t used = 0;                        // outputs read
    std::array<std::size_t, 6> output{};
    std::array<std::size_t, 6> dof{};
    std::array<double, 6> sign{};
  };

 public:
  /// What the model evaluates, as plain data (for the runtime file,
  /// src/export/runtime_export.hpp): per DOF its kind and numbers, with the
  /// signs folded in as evaluate() uses them.
  struct DofLayout {
    DofDamping::Kind kind = DofDamping::Kind::None;
    std::size_t variable = 0;                // Law: the nu_r component
    std::vector<int> codes;                  // Law: term codes (HC_DAMPING_*)
    std::vector<double> coefficients;        // Law, Derivatives: on the body
    std::vector<std::size_t> begin;          // Derivatives: term k's factors [begin[k], begin[k + 1])
    std::vector<hc_damping_factor> factors;  // Derivatives
    std::string surface;                     // Surface: its name
    std::size_t output = 0;                  // Surface: the output read
    double sign = 1.0;                       // Surface: +1 or -1 (to forces on the body)
    std::vector<std::size_t> sources;        // Surface: per axis, 0..5 nu_r, 6 + k disturbance k
  };
  std::array<DofLayout, 6> layout() const;

 private:
  /// Surface l's outputs at nu_r_b (6) and the disturbances into out.
  static void look_up(const Lookup& l, const double* nu_r_b, std::span<const double> disturbances, double* out);

  friend class DampingDraws;  // makes copies with drawn coefficients and surfaces
  friend class DampingLanes;  // evaluates several models of one shape at once

  std::array<bool, 6> damped_{};
  std::vector<Law> laws_;
  std::vector<Derivatives> derivatives_;
  std::vector<Lookup> lookups_;
  std::vector<std::string> disturbance_names_;
};

}  // namespace hydrocoef
