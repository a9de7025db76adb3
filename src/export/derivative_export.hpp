// Exports of a derivative set, a fitted model of one output in several
// variables (src/derivatives/derivative_fit.hpp): CSV and JSON, each in
// dimensional form (SI) or non-dimensional form in the set's normalisation
// system (prime, bis or MMG, src/derivatives/normalisation.hpp), the system,
// its symbol definition and reference values named in the file.
//
// Units and signs. Dimensional coefficients are SI, in the output's unit
// (N for X, Y, Z; N m for K, M, N) over the term's unit (m/s for u, v, w;
// rad/s for p, q, r; rad for every other name, which is taken to be a
// control or disturbance angle such as delta or beta, unscaled by every
// system). Body axes x forward, y starboard, z down; the coefficients are
// written in the set's sign convention, which the file names ("on-body":
// SNAME derivatives, the force of the water on the body, damping negative).
// A non-dimensional coefficient is the dimensional one divided by its scale
// (derivative_scale: the output's scale over the product of its variables'
// scales), its standard error likewise and the covariance by the product of
// the two scales.
//
// The dimensional JSON's "terms", "coefficients" and "covariance" are the
// object a vehicle file's "derivatives" takes (src/dynamics/vehicle.hpp).
// Exports never touch the database; a refused export writes nothing.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "src/core/sign_convention.hpp"
#include "src/derivatives/normalisation.hpp"
#include "src/derivatives/terms.hpp"

namespace hydrocoef {

/// What is exported: one fitted output.
struct DerivativeSet {
  std::string name;                  ///< e.g. the fit's name (data: any text)
  std::string output;                ///< "X".."N" for non-dimensional forms; any name otherwise
  std::vector<Term> terms;           ///< in the order of the coefficients
  std::vector<double> coefficients;  ///< SI [output unit / term unit], in `sign`
  /// m x m row by row [unit_i unit_j], or empty (standard errors then come
  /// from std_errors alone, or are not written).
  std::vector<double> covariance;
  /// One per term, or empty: the square roots of the covariance's diagonal
  /// are used when it is given.
  std::vector<double> std_errors;
  SignConvention sign = SignConvention::OnBody;
  NormalisationSystem system = NormalisationSystem::Prime;
  NormalisationReference reference;  ///< what the non-dimensional form needs
};

enum class DerivativeForm { Dimensional, NonDimensional };

/// Throws InputError, one line naming the set and the term, for: no terms,
/// a coefficient, standard error or covariance count other than the terms',
/// a value that is not finite, a negative standard error, a covariance that
/// is not one (src/core/covariance.hpp), or standard errors that disagree
/// with the covariance's diagonal (beyond 1e-12 relative).
void check_derivative_set(const DerivativeSet& set);

/// The standard errors the export writes: std_errors, or the square roots of
/// the covariance's diagonal; empty when the set has neither.
std::vector<double> derivative_std_errors(const DerivativeSet& set);

/// What a term's coefficient of `output` is, for the normalisation: the
/// output a force (X, Y, Z) or moment (K, M, N), u, v, w, du linear
/// velocities, p, q, r angular velocities, every other name an angle.
/// InputError naming the output when it is not one of X..N.
DerivativeKind derivative_kind(std::string_view output, const Term& term);

/// The SI unit of a term's coefficient of `output` ("N/(m/s)^2",
/// "N m/((m/s) (rad/s))", "N" for the constant); the output's unit is "1"
/// (dimensionless) for an output not in X..N.
std::string derivative_unit(std::string_view output, const Term& term);

/// The set's coefficients (and standard errors, covariance) in `form`, and
/// the scale of each coefficient (1 in dimensional form). Throws as
/// check_derivative_set, and as scale_value when the reference lacks a value
/// the non-dimensional form needs.
struct DerivativeNumbers {
  std::vector<double> coefficients, std_errors, covariance, scales;
  std::vector<std::string> scale_texts;  ///< e.g. "1/2 rho U L^2"; empty in dimensional form
  std::string normalisation;             ///< normalisation_text of the output; empty in dimensional form
};
DerivativeNumbers derivative_numbers(const DerivativeSet& set, DerivativeForm form);

/// CSV: '#' comment lines (the set, output, sign convention, form and
/// normalisation), a header "output,term,coefficient,std_error,unit" (or
/// "scale" for the non-dimensional form), then one row per term, with one
/// more column per term "cov:TERM" when the set has a covariance. Numbers
/// are written shortest round-trip (src/core/numbers.hpp), texts through
/// escape::csv_text.
std::string derivative_csv(const DerivativeSet& set, DerivativeForm form);

/// JSON (indented): {"format": "hydrocoef-derivative-set", "version": 1,
/// "name", "output", "sign", "form": "dimensional" | the system's name,
/// "normalisation" (non-dimensional: "system", "text", "reference"),
/// "terms": "v, r, ...", "coefficients": [...], "std_errors": [...] (when
/// known), "covariance": [[...], ...] (when given), "units" (dimensional) or
/// "scales" (non-dimensional): one text per term}.
std::string derivative_json(const DerivativeSet& set, DerivativeForm form);

/// Writes text atomically (whole or not at all).
void write_derivative_export(const std::filesystem::path& path, const std::string& text);

}  // namespace hydrocoef
