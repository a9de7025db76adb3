#include "src/core/damping_terms.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "src/core/error.hpp"
#include "src/core/run.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

constexpr std::string_view kAcceptedTerms =
    "accepted terms are 1, x, x|x|, x^2, x^3 and |x| with x one of u, v, w, p, q, r, e.g. '1,u,u|u|'";

// What a term list may hold around and inside its parts.
constexpr std::string_view kTermBlanks = " \t\r\n";

// Built by appending: GCC 12 raises a false -Wrestrict on "'" + std::string(...) in release builds.
std::string in_quotes(std::string_view text) {
  std::string out = "'";
  out += text;
  out += '\'';
  return out;
}

bool looks_like_a_name(std::string_view text) {
  if (text.empty() || !std::isalpha(static_cast<unsigned char>(text.front()))) return false;
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// Splits a term into its shape and the name it is a term of ("" for the
// constant); the caller checks that the name is a velocity component.
std::optional<std::pair<DampingTerm, std::string>> split_term(std::string_view term) {
  if (term == "1") return std::pair{DampingTerm::Constant, std::string()};
  std::pair<DampingTerm, std::string_view> split{DampingTerm::Linear, term};
  if (term.size() >= 3 && term.front() == '|' && term.back() == '|') {
    split = {DampingTerm::AbsLinear, term.substr(1, term.size() - 2)};
  } else if (term.ends_with("^2")) {
    split = {DampingTerm::Quadratic, term.substr(0, term.size() - 2)};
  } else if (term.ends_with("^3")) {
    split = {DampingTerm::Cubic, term.substr(0, term.size() - 2)};
  } else if (term.ends_with('|')) {
    // x|x|: both halves must name the same component.
    const std::string_view outside = term.substr(0, term.find('|'));
    const std::string_view inside = term.substr(outside.size());  // "|x|" when well formed
    if (inside.size() != outside.size() + 2 || inside.front() != '|' || inside.substr(1, outside.size()) != outside)
      return std::nullopt;
    split = {DampingTerm::SignedQuadratic, outside};
  }
  if (!looks_like_a_name(split.second)) return std::nullopt;
  return std::pair{split.first, std::string(split.second)};
}

}  // namespace

DampingLawSpec parse_damping_terms(std::string_view text) {
  const std::string quoted_text = in_quotes(text);
  if (trim(text, kTermBlanks).empty())
    throw InputError("empty damping term list " + quoted_text + "; " + std::string(kAcceptedTerms));

  DampingLawSpec spec;
  std::string first_term_with_variable;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = text.find(',', begin);
    const std::string_view raw =
        trim(text.substr(begin, comma == std::string_view::npos ? text.npos : comma - begin), kTermBlanks);
    if (raw.empty())
      throw InputError("empty damping term in " + quoted_text + " (two commas, or a comma at an end); " +
                       std::string(kAcceptedTerms));
    const std::string term = without_blanks(raw, kTermBlanks);
    const auto parsed = split_term(term);
    if (!parsed)
      throw InputError("unknown damping term '" + std::string(raw) + "' in " + quoted_text + "; " +
                       std::string(kAcceptedTerms));
    const auto& [kind, variable] = *parsed;
    if (kind != DampingTerm::Constant) {
      if (!velocity_index(variable))
        throw InputError("'" + variable + "' in damping term '" + std::string(raw) +
                         "' is not a velocity component; expected one of u, v, w, p, q, r");
      if (spec.variable.empty()) {
        spec.variable = variable;
        first_term_with_variable = raw;
      } else if (variable != spec.variable) {
        throw InputError("damping term '" + std::string(raw) + "' is in " + variable + " but '" +
                         first_term_with_variable + "' is in " + spec.variable + " (in " + quoted_text +
                         "); a damping law has terms of one velocity component only");
      }
    }
    if (std::find(spec.terms.begin(), spec.terms.end(), kind) != spec.terms.end())
      throw InputError("damping term '" + std::string(raw) + "' appears twice in " + quoted_text +
                       "; each term may appear once");
    spec.terms.push_back(kind);
    if (comma == std::string_view::npos) break;
    begin = comma + 1;
  }
  if (spec.variable.empty())
    throw InputError("damping term list " + quoted_text + " has no term in a velocity component; " +
                     std::string(kAcceptedTerms));
  return spec;
}

std::string term_name(DampingTerm term, std::string_view variable) {
  const std::string x(variable);
  switch (term) {
    case DampingTerm::Constant: return "1";
    case DampingTerm::Linear: return x;
    case DampingTerm::SignedQuadratic: return x + "|" + x + "|";
    case DampingTerm::Quadratic: return x + "^2";
    case DampingTerm::Cubic: return x + "^3";
    case DampingTerm::AbsLinear: return "|" + x + "|";
  }
  throw std::invalid_argument("term_name: unknown DampingTerm");
}

std::string format_damping_terms(const DampingLawSpec& spec) {
  std::string out;
  for (DampingTerm term : spec.terms) {
    if (!out.empty()) out += ',';
    out += term_name(term, spec.variable);
  }
  return out;
}

int term_power(DampingTerm term) {
  switch (term) {
    case DampingTerm::Constant: return 0;
    case DampingTerm::Linear:
    case DampingTerm::AbsLinear: return 1;
    case DampingTerm::SignedQuadratic:
    case DampingTerm::Quadratic: return 2;
    case DampingTerm::Cubic: return 3;
  }
  return 0;
}

void throw_unknown_damping_term() { throw std::invalid_argument("basis_value: unknown DampingTerm"); }

void check_damping_law_spec(const DampingLawSpec& spec) {
  if (spec.terms.empty()) throw InputError("damping law has no terms; " + std::string(kAcceptedTerms));
  const bool has_variable_term =
      std::any_of(spec.terms.begin(), spec.terms.end(), [](DampingTerm t) { return t != DampingTerm::Constant; });
  if (!has_variable_term)
    throw InputError("damping law '" + format_damping_terms(spec) + "' has no term in a velocity component; " +
                     std::string(kAcceptedTerms));
  if (!velocity_index(spec.variable))
    throw InputError("damping law variable '" + spec.variable +
                     "' is not a velocity component; expected one of u, v, w, p, q, r");
  for (std::size_t j = 0; j < spec.terms.size(); ++j)
    for (std::size_t i = 0; i < j; ++i)
      if (spec.terms[i] == spec.terms[j])
        throw InputError("damping term '" + term_name(spec.terms[j], spec.variable) +
                         "' appears twice; each term may appear once");
}

}  // namespace hydrocoef
