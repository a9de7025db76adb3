// Terms of derivative models of several variables: a force or moment written
// as sum_k c_k t_k(x), each term t_k a product of factors of the body's
// velocities relative to the water, its rates and disturbance or control
// angles, e.g. Y = Y_v v + Y_uv u*v + Y_v|v| v*|v| + Y_uud u^2*delta.
//
// Text form: a term is `1` (the constant) or factors joined by `*`; a factor
// is a name ([A-Za-z_][A-Za-z0-9_]*), a power of a name `x^2`, `x^3`, `x^4`
// (powers 2 to 4: the fourth is MMG's beta^4), or an absolute value `|x|`.
// Blanks around the parts are ignored. Factors of one name combine:
// x^a * |x|^b = |x|^(a+b) sign(x)^a, so `v*|v|` and `|v|*v` are one term and
// `v*v` is `v^2`; the powers of one name add up to at most 4.
//
// Canonical text: factors in a fixed order, translational velocities
// (u, du, v, w), flow angles (alpha, beta), rates (p, q, r), then every other
// name (controls, disturbances) in byte order; each name's factor written as
// x, |x|, x*|x|, x^2, x^3, x^2*|x|, x^3*|x| or x^4. Two spellings of one term
// have one canonical text, so a list that names a term twice is refused.
//
// Units and frames: values are SI in body axes (x forward, y starboard, z
// down; velocities in m/s, rates in rad/s, angles in rad), or the same
// quantities made non-dimensional (prime or bis) when the caller fits in that
// system; a term's value has the unit of the product of its factors (powers()
// gives the exponent of each name, |x| counting as x^1). The names mean
// whatever the caller's runs give under them: a term is not tied to a sign
// convention.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef {

/// One name's part of a term: |x|^power, times sign(x) when odd.
struct TermFactor {
  std::string variable;  ///< the name, e.g. "v" or "delta"
  int power = 1;         ///< 1 to 4: the exponent of the name in the term's unit
  bool odd = true;       ///< true: the factor changes sign with x (x, x*|x|, x^3, x^3*|x|)

  /// The factor at x: |x|^power, negated when odd and x < 0.
  double value(double x) const;
};

/// A product of factors, or the constant 1 (no factors).
class Term {
 public:
  Term() = default;  ///< the constant 1
  /// From factors of distinct names (any order; kept in canonical order).
  /// std::invalid_argument when a name repeats, is not a valid name, or a
  /// power is outside 1..4.
  explicit Term(std::vector<TermFactor> factors);

  const std::vector<TermFactor>& factors() const { return factors_; }
  bool is_constant() const { return factors_.empty(); }
  /// The canonical text, e.g. "u^2*delta", "v*|v|", "1".
  const std::string& text() const { return text_; }
  /// The exponent of each name in the term's unit, |x| counting as x^1:
  /// {"v": 2} for v*|v|; empty for the constant.
  std::map<std::string, int> powers() const;
  /// The names the term needs, in canonical order.
  std::vector<std::string> variables() const;

  /// The term's value at `point` (name -> value). Throws InputError naming
  /// the term and the missing name when the point lacks one.
  double evaluate(const std::map<std::string, double>& point) const;

  friend bool operator==(const Term& a, const Term& b) { return a.text_ == b.text_; }

 private:
  std::vector<TermFactor> factors_;
  std::string text_ = "1";
};

/// Parses one term ("v^2*r", "|v|*v", "1"). Throws InputError naming the
/// term and the column of the problem (1-based within `text`).
Term parse_term(std::string_view text);

/// Parses a comma-separated list ("v, r, v*|v|, u*v"). Throws InputError, one
/// line naming the term text, its place in the list and the column, for an
/// unknown character, an empty term or factor, a power other than 2, 3 or 4,
/// a name raised beyond the fourth power, a constant inside a product, or a
/// term given twice (both spellings named).
std::vector<Term> parse_terms(std::string_view list);

/// The canonical list text, "v, r, v*|v|" (parse_terms reads it back).
std::string format_terms(const std::vector<Term>& terms);

/// Every name the terms need, once, in canonical order.
std::vector<std::string> term_variables(const std::vector<Term>& terms);

/// Whether `name` is a valid variable name: [A-Za-z_][A-Za-z0-9_]*.
bool is_term_variable_name(std::string_view name);

}  // namespace hydrocoef
