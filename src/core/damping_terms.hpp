// Damping laws as data: one generalized-force component written as a linear
// combination of basis terms of one velocity component, F(x) = sum_k c_k
// b_k(x), for example the surge law X(u) = c0 + c1 u + c2 u|u|. The terms,
// their canonical text and the law's value live here, apart from the fit
// (src/fit/damping_law.hpp, with Ceres), so that what only evaluates laws
// (the dynamics model, plots, exports) neither includes nor links the fitter.
//
// Units: x is in the velocity component's SI unit (m/s for u, v, w; rad/s for
// p, q, r) and the force in N (X, Y, Z) or N m (K, M, N). A coefficient's unit
// is the force's unit divided by its basis term's unit (for u|u|: N s^2 m^-2).
// A law is in whatever sign convention its coefficients were given in
// (src/core/sign_convention.hpp converts).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace hydrocoef {

/// A basis term of a damping law in the velocity component x.
enum class DampingTerm {
  Constant,         ///< 1: an offset, e.g. a CFD zero-speed bias
  Linear,           ///< x
  SignedQuadratic,  ///< x|x|: quadratic drag that keeps opposing motion when x changes sign
  Quadratic,        ///< x^2: even in x
  Cubic,            ///< x^3
  AbsLinear         ///< |x|: even in x
};

/// Which terms a law has and which velocity component they are terms of.
struct DampingLawSpec {
  std::string variable;            ///< "u", "v", "w", "p", "q" or "r"
  std::vector<DampingTerm> terms;  ///< in the order coefficients are reported; no repeats
};

/// Parses a comma-separated term list such as "1,u,u|u|" or "r, r|r|, r^3".
/// Accepted terms are 1, x, x|x|, x^2, x^3 and |x| with x one of u, v, w, p,
/// q, r; whitespace around and inside terms is ignored. Throws InputError,
/// naming the offending term and listing the accepted forms, when the list is
/// empty or has an empty entry, a term is unknown or repeated, the terms mix
/// two velocity components ("u,r|r|"), or no term names a component (just "1").
DampingLawSpec parse_damping_terms(std::string_view text);

/// Checks a spec built in code as parse_damping_terms checks text: some
/// terms, one in a velocity component, the variable one of u..r, no term
/// twice. Throws InputError naming what is wrong.
void check_damping_law_spec(const DampingLawSpec& spec);

/// The term as parse_damping_terms accepts it: "1", "u", "u|u|", "u^2", "u^3", "|u|".
/// variable: the velocity component's name, e.g. "u".
std::string term_name(DampingTerm term, std::string_view variable);

/// The canonical text of a spec, "1,u,u|u|"; parse_damping_terms reads it back.
std::string format_damping_terms(const DampingLawSpec& spec);

/// The power of the velocity in a term: 0 for the constant, 1 for x and |x|,
/// 2 for x|x| and x^2, 3 for x^3 (a coefficient's unit is force / velocity^power).
int term_power(DampingTerm term);

/// std::invalid_argument for a DampingTerm outside the enumeration.
[[noreturn]] void throw_unknown_damping_term();

/// Every basis term's value at x, indexed by DampingTerm (x in m/s or rad/s;
/// each in x's unit to the term's power, 1 for Constant).
/// T: double, or an Eigen array of lanes (the same operations in every lane).
static_assert(static_cast<int>(DampingTerm::AbsLinear) == 5, "basis_values lists every DampingTerm in order");
template <class T = double>
inline std::array<T, 6> basis_values(const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    const double magnitude = std::abs(x);
    return {1.0, x, x * magnitude, x * x, x * x * x, magnitude};
  } else {
    const T magnitude = x.abs();
    return {T::Ones(), x, x * magnitude, x * x, x * x * x, magnitude};
  }
}

/// The basis term's value at x; std::invalid_argument for a DampingTerm
/// outside the enumeration.
inline double basis_value(DampingTerm term, double x) {
  const auto index = static_cast<std::size_t>(term);
  if (index >= 6) throw_unknown_damping_term();
  return basis_values(x)[index];
}

/// The law's value sum_k coefficients[k] basis_value(terms[k], x), summed in
/// term order [force unit]; terms without a coefficient (or coefficients
/// without a term) are left out. The basis values are computed once, not per
/// term. Allocates nothing (the dynamics' hot path).
inline double damping_law_value(std::span<const DampingTerm> terms, std::span<const double> coefficients, double x) {
  const std::array<double, 6> basis = basis_values(x);
  double value = 0.0;
  for (std::size_t k = 0; k < terms.size() && k < coefficients.size(); ++k) {
    const auto index = static_cast<std::size_t>(terms[k]);
    if (index >= 6) throw_unknown_damping_term();
    value += coefficients[k] * basis[index];
  }
  return value;
}

}  // namespace hydrocoef
