#include "src/derivatives/model_templates.hpp"

#include <array>
#include <string>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

// Abkowitz, M. A. (1964), Lectures on ship hydrodynamics: steering and
// manoeuvrability, Hydro- og Aerodynamisk Laboratorium, Lyngby: the forces as
// a third-order Taylor expansion about straight running at U0, with the
// terms that the port-starboard symmetry of the hull allows. The truncated
// form here is the one fitted to the Mariner class vessel's planar-motion
// tests (Chislett, M. S. and Strom-Tejsen, J. (1965), Planar motion mechanism
// tests and full-scale steering and maneuvering predictions for a Mariner
// class vessel, Hydro- og Aerodynamisk Laboratorium, Lyngby), term for term
// as Fossen gives it (Handbook of Marine Craft Hydrodynamics and Motion
// Control, Wiley 2011 and 2nd ed. 2021, the Mariner class vessel; his MSS
// toolbox, VESSELS/mariner.m). The constant and the du, du^2 terms of Y and N
// are the propeller's asymmetry at straight running.
constexpr std::string_view kAbkowitzVariables =
    "du = u - U0, the surge velocity's departure from the nominal speed U0 [m/s], v [m/s], r [rad/s] and the "
    "rudder angle delta [rad]; or their prime forms du/U, v/U, r L/U";
constexpr std::string_view kAbkowitzSource =
    "Abkowitz (1964) third-order model as truncated for the Mariner class vessel, Chislett & Strom-Tejsen (1965), "
    "in Fossen, Handbook of Marine Craft Hydrodynamics and Motion Control (2011, 2021), MSS VESSELS/mariner.m";

// Prestero, T. (2001), Verification of a six-degree of freedom simulation
// model for the REMUS autonomous underwater vehicle, MSc thesis, MIT and
// Woods Hole Oceanographic Institution, ch. 3 (the total vehicle forces and
// moments): cross-flow drag Y_v|v| v|v|, Y_r|r| r|r| (and w, q, p alike),
// body lift and Munk moment with fin lift in Y_uv uv, Y_ur ur (Z_uw uw, Z_uq
// uq), the added-mass couplings X_vr vr, X_wq wq, X_rr r^2, X_qq q^2, Y_wp
// wp, Y_pq pq, Z_vp vp, Z_rp rp, and the fins Y_uudr u^2 delta_r, Z_uuds
// u^2 delta_s. Fossen (Handbook, 2nd ed. 2021, the AUV models and the MSS
// remus100.m) builds on the same terms. Propeller thrust and torque and the
// hydrostatic (weight and buoyancy) terms are left out: they are not
// hydrodynamic derivatives. Runs without roll rate cannot fit the p terms;
// drop them from the list (the fit names a term that is zero at every run).
constexpr std::string_view kAuvVariables =
    "u, v, w [m/s], p, q, r [rad/s], rudder angle delta_r and stern-plane angle delta_s [rad], body axes x forward, "
    "y starboard, z down";
constexpr std::string_view kAuvSource =
    "Prestero (2001), REMUS six-degree-of-freedom model, ch. 3; Fossen, Handbook of Marine Craft Hydrodynamics and "
    "Motion Control, 2nd ed. (2021), AUV models";

// Yasukawa, H. and Yoshimura, Y. (2015), Introduction of MMG standard method
// for ship maneuvering predictions, J. Mar. Sci. Technol. 20, 37-52, the
// hull forces: X'_H = -R'_0 + X'_vv v'^2 + X'_vr v' r' + X'_rr r'^2 +
// X'_vvvv v'^4, Y'_H = Y'_v v' + Y'_r r' + Y'_vvv v'^3 + Y'_vvr v'^2 r' +
// Y'_vrr v' r'^2 + Y'_rrr r'^3, N'_H alike, with v' the lateral velocity at
// midship over U and r' = r L_pp / U; forces over (1/2) rho L_pp d U^2, the
// moment over (1/2) rho L_pp^2 d U^2.
constexpr std::string_view kMmgVariables =
    "v = v'_m, the lateral velocity at midship over U, and r = r' = r L_pp / U (non-dimensional); outputs "
    "X'_H, Y'_H over (1/2) rho L_pp d U^2 and N'_H over (1/2) rho L_pp^2 d U^2";
constexpr std::string_view kMmgSource =
    "Yasukawa & Yoshimura (2015), Introduction of MMG standard method for ship maneuvering predictions, J. Mar. Sci. "
    "Technol. 20, 37-52, hull forces";

// The same polynomials with the drift angle beta in place of v'_m, the
// variable in which earlier MMG papers and many captive-test reports write
// the hull forces (X'_bb, Y'_b, N'_bbr, ...). Yasukawa & Yoshimura take
// beta = atan(-v_m / u), so for small drift angles v'_m ~ -beta: the odd
// powers of beta carry the opposite sign of the v'_m derivatives.
constexpr std::string_view kMmgBetaVariables =
    "beta, the drift angle at midship [rad] (beta = atan(-v_m/u) in Yasukawa & Yoshimura), and r = r' = r L_pp / U";
constexpr std::string_view kMmgBetaSource =
    "MMG hull forces in drift angle and r': the polynomials of Yasukawa & Yoshimura (2015) with beta for v'_m";

constexpr std::string_view kAbkowitzSway =
    "1, du, du^2, v, r, v^3, v^2*r, du*v, du*r, delta, delta^3, du*delta, du^2*delta, v*delta^2, v^2*delta";

constexpr std::array<ModelTemplate, 15> kTemplates = {{
    {"abkowitz", "X", "du, du^2, du^3, v^2, r^2, v*r, delta^2, du*delta^2, v*delta, du*v*delta", kAbkowitzVariables,
     kAbkowitzSource},
    {"abkowitz", "Y", kAbkowitzSway, kAbkowitzVariables, kAbkowitzSource},
    {"abkowitz", "N", kAbkowitzSway, kAbkowitzVariables, kAbkowitzSource},
    {"auv", "X", "u*|u|, v*r, w*q, r^2, q^2", kAuvVariables, kAuvSource},
    {"auv", "Y", "v*|v|, r*|r|, u*v, u*r, w*p, p*q, u^2*delta_r", kAuvVariables, kAuvSource},
    {"auv", "Z", "w*|w|, q*|q|, u*w, u*q, v*p, p*r, u^2*delta_s", kAuvVariables, kAuvSource},
    {"auv", "K", "p*|p|", kAuvVariables, kAuvSource},
    {"auv", "M", "w*|w|, q*|q|, u*w, u*q, v*p, p*r, u^2*delta_s", kAuvVariables, kAuvSource},
    {"auv", "N", "v*|v|, r*|r|, u*v, u*r, w*p, p*q, u^2*delta_r", kAuvVariables, kAuvSource},
    {"mmg", "X", "1, v^2, v*r, r^2, v^4", kMmgVariables, kMmgSource},
    {"mmg", "Y", "v, r, v^3, v^2*r, v*r^2, r^3", kMmgVariables, kMmgSource},
    {"mmg", "N", "v, r, v^3, v^2*r, v*r^2, r^3", kMmgVariables, kMmgSource},
    {"mmg-beta", "X", "1, beta^2, beta*r, r^2, beta^4", kMmgBetaVariables, kMmgBetaSource},
    {"mmg-beta", "Y", "beta, r, beta^3, beta^2*r, beta*r^2, r^3", kMmgBetaVariables, kMmgBetaSource},
    {"mmg-beta", "N", "beta, r, beta^3, beta^2*r, beta*r^2, r^3", kMmgBetaVariables, kMmgBetaSource},
}};

std::string available() {
  std::string out;
  std::string_view current;
  for (const auto& t : kTemplates) {
    if (t.name != current) {
      out += (out.empty() ? "" : "; ") + std::string(t.name) + " (";
      current = t.name;
    } else {
      out += " ";
    }
    out += t.output;
    const bool last_of_name = &t == &kTemplates.back() || (&t + 1)->name != t.name;
    if (last_of_name) out += ")";
  }
  return out;
}

}  // namespace

std::span<const ModelTemplate> model_templates() { return kTemplates; }

const ModelTemplate& find_model_template(std::string_view name, std::string_view output) {
  bool name_known = false;
  for (const auto& t : kTemplates) {
    if (t.name != name) continue;
    name_known = true;
    if (t.output == output) return t;
  }
  const std::string asked = name_known
                                ? "the template " + std::string(name) + " has no output " + printable_text(output, 40)
                                : "no model template named " + printable_text(name, 40);
  throw InputError(asked + "; expected one of " + available());
}

std::vector<Term> model_template_terms(std::string_view name, std::string_view output) {
  return parse_terms(find_model_template(name, output).terms);
}

}  // namespace hydrocoef
