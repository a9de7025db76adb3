// Named term lists of the common derivative models, so that a fit can ask
// for "abkowitz" Y instead of spelling fifteen terms. Each template is only a
// list of terms (src/derivatives/terms.hpp): what its names mean (which
// velocities, angles, dimensional or prime) is stated with it, and the
// caller's runs must give values under those names.
//
//   abkowitz  X, Y, N  Abkowitz's third-order Taylor expansion about straight
//                      running at U0, truncated as in the Mariner class model
//                      (Chislett & Strom-Tejsen 1965, as given by Fossen),
//                      over du = u - U0, v, r and the rudder angle delta.
//   auv       X..N     the AUV model of Prestero (2001) that Fossen's texts
//                      build on: cross-flow drag x*|x|, body and fin lift
//                      u*v, u*r (u*w, u*q), added-mass couplings, fin terms
//                      u^2*delta_r and u^2*delta_s.
//   mmg       X, Y, N  MMG hull forces (Yasukawa & Yoshimura 2015) in the
//                      non-dimensional lateral velocity at midship v (v'_m)
//                      and yaw rate r (r' = r L / U).
//   mmg-beta  X, Y, N  the same polynomials in the drift angle beta and r'.
//
// Powers up to 4 (MMG's v'^4 and beta^4) are accepted by the term parser.
// Signs: body axes x forward, y starboard, z down; each source's own sign
// conventions for delta and beta are noted with its templates.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "src/derivatives/terms.hpp"

namespace hydrocoef {

struct ModelTemplate {
  std::string_view name;       ///< "abkowitz", "auv", "mmg", "mmg-beta"
  std::string_view output;     ///< "X", "Y", "Z", "K", "M" or "N"
  std::string_view terms;      ///< the term list, as parse_terms reads it
  std::string_view variables;  ///< what the template's names mean, one line
  std::string_view source;     ///< where the term list comes from
};

/// Every template, by name and then output.
std::span<const ModelTemplate> model_templates();

/// The template `name` for `output`. Throws InputError naming what was asked
/// and listing the templates (with their outputs) when there is none.
const ModelTemplate& find_model_template(std::string_view name, std::string_view output);

/// parse_terms of find_model_template(name, output).terms.
std::vector<Term> model_template_terms(std::string_view name, std::string_view output);

}  // namespace hydrocoef
