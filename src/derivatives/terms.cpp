#include "src/derivatives/terms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

#include "src/core/error.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

// The order of names in a canonical term: translational velocities, flow
// angles, rates; every other name after these, in byte order.
constexpr std::array<std::string_view, 9> kLeadingNames = {"u", "du", "v", "w", "alpha", "beta", "p", "q", "r"};
constexpr int kMaxPower = 4;
// Quoted terms and lists are cut in messages beyond this many characters.
constexpr std::size_t kQuoteLimit = 120;
constexpr std::string_view kBlanks = " \t\r\n";
constexpr std::string_view kAcceptedForms =
    "expected factors x, x^2, x^3, x^4 or |x| joined by '*' (x a name [A-Za-z_][A-Za-z0-9_]*), or 1 alone";

bool is_blank(char c) { return kBlanks.find(c) != std::string_view::npos; }
bool is_name_start(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool is_name_char(char c) { return is_name_start(c) || (c >= '0' && c <= '9'); }

std::size_t name_rank(const std::string& name) {
  const auto it = std::find(kLeadingNames.begin(), kLeadingNames.end(), name);
  return static_cast<std::size_t>(it - kLeadingNames.begin());
}

bool canonical_before(const TermFactor& a, const TermFactor& b) {
  const std::size_t ra = name_rank(a.variable), rb = name_rank(b.variable);
  if (ra != rb) return ra < rb;
  return a.variable < b.variable;
}

std::string factor_text(const TermFactor& f) {
  const std::string& x = f.variable;
  switch (f.power) {
    case 1: return f.odd ? x : "|" + x + "|";
    case 2: return f.odd ? x + "*|" + x + "|" : x + "^2";
    case 3: return f.odd ? x + "^3" : x + "^2*|" + x + "|";
    default: return f.odd ? x + "^3*|" + x + "|" : x + "^4";
  }
}

std::string in_quotes(std::string_view text) { return "\"" + printable_text(text, kQuoteLimit) + "\""; }

// Where a term sits, for messages: its text, its place in a list (0 when
// parsed alone), the list, and the term's offset in the list.
struct TermPlace {
  std::string_view term;
  std::size_t index = 0;
  std::string_view list;
  std::size_t offset = 0;

  [[noreturn]] void fail(std::size_t at, const std::string& what) const {
    std::string where = "term " + in_quotes(trim(term, kBlanks));
    if (index > 0) where += " (term " + std::to_string(index) + " of the list " + in_quotes(list);
    where += (index > 0 ? ", column " : " (column ") + std::to_string(offset + at + 1) + ")";
    throw InputError(where + ": " + what);
  }
};

// One factor's name and powers as written: x^a |x|^b.
struct WrittenFactor {
  std::string name;
  int signed_power = 0;    // a
  int absolute_power = 0;  // b
  std::size_t column = 0;  // of the name, 0-based within the term
};

std::size_t skip_blanks(std::string_view text, std::size_t i) {
  while (i < text.size() && is_blank(text[i])) ++i;
  return i;
}

std::string describe_character(char c) { return "'" + printable_text(std::string_view(&c, 1)) + "'"; }

// Reads a name at i (which must start one); returns the index after it.
std::size_t read_name(std::string_view text, std::size_t i, std::string& name) {
  const std::size_t start = i;
  while (i < text.size() && is_name_char(text[i])) ++i;
  name.assign(text.substr(start, i - start));
  return i;
}

Term parse_placed(const TermPlace& place) {
  const std::string_view text = place.term;
  const std::size_t first = skip_blanks(text, 0);
  if (first == text.size()) place.fail(0, "an empty term; " + std::string(kAcceptedForms));
  std::size_t last = text.size();
  while (last > first && is_blank(text[last - 1])) --last;
  if (text.substr(first, last - first) == "1") return Term();

  std::vector<WrittenFactor> written;
  std::size_t i = first;
  while (true) {
    i = skip_blanks(text, i);
    WrittenFactor factor;
    factor.column = i;
    if (i == text.size() || text[i] == '*') {
      place.fail(i, "an empty factor" + std::string(i == text.size() ? " at the end" : " before '*'") + "; " +
                        std::string(kAcceptedForms));
    } else if (text[i] == '|') {
      i = skip_blanks(text, i + 1);
      if (i == text.size() || !is_name_start(text[i]))
        place.fail(i, (i == text.size() || text[i] == '|' ? std::string("an empty |...|")
                                                          : "character " + describe_character(text[i]) + " in |...|") +
                          "; expected a name between the bars, e.g. |v|");
      factor.column = i;
      i = skip_blanks(text, read_name(text, i, factor.name));
      if (i == text.size() || text[i] != '|')
        place.fail(i, "an unclosed |" + factor.name + "; expected |" + factor.name + "|");
      i = skip_blanks(text, i + 1);
      if (i < text.size() && text[i] == '^')
        place.fail(i, "a power of |" + factor.name + "|; expected powers on the name (" + factor.name + "^2) and |" +
                          factor.name + "| alone");
      factor.absolute_power = 1;
    } else if (is_name_start(text[i])) {
      i = skip_blanks(text, read_name(text, i, factor.name));
      factor.signed_power = 1;
      if (i < text.size() && text[i] == '^') {
        i = skip_blanks(text, i + 1);
        const std::size_t digits = i;
        while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
        if (i == digits) place.fail(digits, "no power after '^'; expected 2, 3 or 4 (x^2, x^3, x^4)");
        const std::string_view power = text.substr(digits, i - digits);
        if (power != "2" && power != "3" && power != "4")
          place.fail(digits, "the power " + std::string(printable_text(power, 20)) + " of " + factor.name +
                                 "; expected 2, 3 or 4 (x^2, x^3, x^4)");
        factor.signed_power = power[0] - '0';
        i = skip_blanks(text, i);
      }
    } else if (text[i] >= '0' && text[i] <= '9') {
      place.fail(i, "a number; expected a name here (the constant term is 1, alone)");
    } else {
      place.fail(i, "the character " + describe_character(text[i]) + "; " + std::string(kAcceptedForms));
    }
    written.push_back(factor);
    if (i == text.size()) break;
    if (text[i] != '*')
      place.fail(i, "the character " + describe_character(text[i]) + " after " + factor.name +
                        "; expected '*' between factors or ',' between terms");
    ++i;
  }

  // Factors of one name combine: x^a |x|^b = |x|^(a+b) sign(x)^a.
  std::vector<TermFactor> factors;
  std::vector<std::size_t> columns;
  for (const auto& w : written) {
    auto it = std::find_if(factors.begin(), factors.end(), [&](const TermFactor& f) { return f.variable == w.name; });
    if (it == factors.end()) {
      factors.push_back({w.name, 0, false});
      columns.push_back(w.column);
      it = factors.end() - 1;
    }
    it->power += w.signed_power + w.absolute_power;
    if (w.signed_power % 2 == 1) it->odd = !it->odd;
    if (it->power > kMaxPower)
      place.fail(columns[static_cast<std::size_t>(it - factors.begin())],
                 "the name " + w.name + " to the power " + std::to_string(it->power) + "; expected at most " +
                     std::to_string(kMaxPower) + " of one name in a term");
  }
  return Term(std::move(factors));
}

}  // namespace

double TermFactor::value(double x) const {
  const double magnitude = std::abs(x);
  double out = magnitude;
  for (int k = 1; k < power; ++k) out *= magnitude;
  return odd && x < 0.0 ? -out : out;
}

Term::Term(std::vector<TermFactor> factors) : factors_(std::move(factors)) {
  for (const auto& f : factors_) {
    if (!is_term_variable_name(f.variable))
      throw std::invalid_argument("Term: '" + f.variable + "' is not a variable name");
    if (f.power < 1 || f.power > kMaxPower) throw std::invalid_argument("Term: power outside 1..4");
  }
  std::sort(factors_.begin(), factors_.end(), canonical_before);
  for (std::size_t k = 1; k < factors_.size(); ++k)
    if (factors_[k].variable == factors_[k - 1].variable)
      throw std::invalid_argument("Term: the name '" + factors_[k].variable + "' is given twice");
  if (factors_.empty()) return;
  text_.clear();
  for (const auto& f : factors_) text_ += (text_.empty() ? "" : "*") + factor_text(f);
}

std::map<std::string, int> Term::powers() const {
  std::map<std::string, int> out;
  for (const auto& f : factors_) out[f.variable] = f.power;
  return out;
}

std::vector<std::string> Term::variables() const {
  std::vector<std::string> out;
  std::transform(factors_.begin(), factors_.end(), std::back_inserter(out),
                 [](const TermFactor& f) { return f.variable; });
  return out;
}

double Term::evaluate(const std::map<std::string, double>& point) const {
  double out = 1.0;
  for (const auto& f : factors_) {
    const auto it = point.find(f.variable);
    if (it == point.end())
      throw InputError("term " + in_quotes(text_) + " needs a value of " + f.variable + "; the point has none");
    out *= f.value(it->second);
  }
  return out;
}

Term parse_term(std::string_view text) { return parse_placed({text, 0, {}, 0}); }

std::vector<Term> parse_terms(std::string_view list) {
  std::vector<Term> terms;
  std::vector<std::string_view> spelled;
  std::vector<std::size_t> offsets;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? list.size() : comma;
    const TermPlace place{list.substr(start, end - start), terms.size() + 1, list, start};
    Term term = parse_placed(place);
    for (std::size_t k = 0; k < terms.size(); ++k)
      if (terms[k] == term)
        place.fail(skip_blanks(place.term, 0), "the same term as " + in_quotes(trim(spelled[k], kBlanks)) + " (term " +
                                                   std::to_string(k + 1) + ", column " +
                                                   std::to_string(offsets[k] + skip_blanks(spelled[k], 0) + 1) +
                                                   "), both " + term.text() + "; expected each term once");
    terms.push_back(std::move(term));
    spelled.push_back(place.term);
    offsets.push_back(start);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return terms;
}

std::string format_terms(const std::vector<Term>& terms) {
  std::string out;
  for (const auto& t : terms) out += (out.empty() ? "" : ", ") + t.text();
  return out;
}

std::vector<std::string> term_variables(const std::vector<Term>& terms) {
  std::vector<TermFactor> names;
  for (const auto& t : terms)
    for (const auto& f : t.factors())
      if (std::none_of(names.begin(), names.end(), [&](const TermFactor& n) { return n.variable == f.variable; }))
        names.push_back({f.variable, 1, true});
  std::sort(names.begin(), names.end(), canonical_before);
  std::vector<std::string> out;
  std::transform(names.begin(), names.end(), std::back_inserter(out), [](const TermFactor& n) { return n.variable; });
  return out;
}

bool is_term_variable_name(std::string_view name) {
  return !name.empty() && is_name_start(name.front()) && std::all_of(name.begin(), name.end(), is_name_char);
}

}  // namespace hydrocoef
