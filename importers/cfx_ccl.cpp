// CCL parsing, the CCL block of a CFX solver output file, and constant CEL
// evaluation (see cfx_ccl.hpp for the grammar and its sources).
#include "importers/cfx_ccl.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

constexpr std::size_t kMaxObjectDepth = 100;     // CFX-Pre writes about 10 levels
constexpr std::size_t kMaxExpressionDepth = 64;  // expression referring to expression ...
constexpr int kMaxNesting = 200;                 // parentheses and unary operators in one text
constexpr int kMaxDimensionExponent = 1000;

constexpr std::string_view kCclBanner = "CFX Command Language for Run";

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (lower(a[i]) != lower(b[i])) return false;
  return true;
}

bool equal_names(std::string_view a, std::string_view b) {
  return equal_ignoring_case(collapse_blanks(a), collapse_blanks(b));
}

std::string ccl_quoted(std::string_view text, std::size_t max_characters = 80) {
  return "'" + printable_text(text, max_characters) + "'";
}

/// Splits text into lines (without their "\n" or "\r\n"), calling
/// visit(line, number, offset_of_line) for each; number starts at 1.
template <typename Visit>
void for_each_line(std::string_view text, Visit&& visit) {
  std::size_t at = 0;
  std::size_t number = 1;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    const std::size_t next = end == std::string_view::npos ? text.size() : end + 1;
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(at, end - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!visit(line, number, at)) return;
    at = next;
    ++number;
  }
}

/// " +----------+ " (the border of a solver output banner or table).
bool is_border_line(std::string_view line) {
  const auto t = trim(line);
  if (t.size() < 3 || t.front() != '+' || t.back() != '+') return false;
  return t.find_first_not_of("+-") == std::string_view::npos && t.find('-') != std::string_view::npos;
}

/// " |     |" (an empty row of a banner).
bool is_empty_box_line(std::string_view line) {
  const auto t = trim(line);
  return t.size() >= 2 && t.front() == '|' && t.back() == '|' && trim(t.substr(1, t.size() - 2)).empty();
}

bool is_ccl_banner_title(std::string_view line) {
  const auto t = trim(line);
  return t.size() >= 2 && t.front() == '|' && t.back() == '|' && trim(t.substr(1, t.size() - 2)) == kCclBanner;
}

// --- CCL parser -------------------------------------------------------------

class CclParser {
 public:
  CclParser(std::string_view text, std::string file, std::size_t first_line) : text_(text), first_line_(first_line) {
    document_.file = std::move(file);
    stack_.push_back(&document_.root);
    indexes_.push_back(&root_index_);
  }

  CclDocument parse() {
    if (const auto nul = text_.find('\0'); nul != std::string_view::npos) {
      const auto line = static_cast<std::size_t>(std::count(text_.begin(), text_.begin() + nul, '\n'));
      fail(first_line_ + line, "binary data (a NUL byte); expected CCL text");
    }
    std::string pending;
    std::size_t pending_line = 0;
    bool continuing = false;
    for_each_line(text_, [&](std::string_view raw, std::size_t number, std::size_t) {
      const std::size_t line = first_line_ + number - 1;
      std::string_view content = raw;
      if (const auto hash = content.find('#'); hash != std::string_view::npos) content = content.substr(0, hash);
      while (!content.empty() && is_blank(content.back())) content.remove_suffix(1);
      const bool continues = !content.empty() && content.back() == '\\';
      if (continues) content.remove_suffix(1);
      if (continuing) {
        pending += trim_left(content);
      } else {
        pending.assign(content);
        pending_line = line;
      }
      continuing = continues;
      if (!continuing) statement(pending, pending_line);
      return true;
    });
    if (continuing)
      fail(pending_line, "the text ends in a continuation ('\\' at the end of the last line); expected its next line");
    if (stack_.size() > 1) {
      const CclObject& open = *stack_.back();
      fail(open.line, "object " + ccl_quoted(open.title()) + " has no END; expected END before the end of the file");
    }
    return std::move(document_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& message) const {
    throw InputError(document_.location(line), message);
  }

  void statement(std::string_view text, std::size_t line) {
    const auto t = trim(text);
    if (t.empty()) return;
    if (t.front() == '!')
      fail(line, "a Perl (Power Syntax) line " + ccl_quoted(t, 60) + "; expected CCL objects and parameters only");
    if (t.front() == '>')
      fail(line, "a CCL action line " + ccl_quoted(t, 60) + "; expected CCL objects and parameters only");
    if (equal_ignoring_case(t, "END")) {
      if (stack_.size() == 1) fail(line, "END without an object to close; expected 'NAME:' before it");
      stack_.pop_back();
      indexes_.pop_back();
      return;
    }
    const auto equals = t.find('=');
    const auto colon = t.find(':');
    if (equals != std::string_view::npos && (colon == std::string_view::npos || equals < colon)) {
      read_parameter(t, equals, line);
    } else if (colon != std::string_view::npos) {
      read_object(t, colon, line);
    } else {
      fail(line,
           ccl_quoted(t, 60) + " is neither an object ('NAME:' or 'NAME: Label'), a parameter ('Key = Value') nor END");
    }
  }

  void read_parameter(std::string_view t, std::size_t equals, std::size_t line) {
    std::string name = collapse_blanks(t.substr(0, equals));
    if (name.empty()) fail(line, ccl_quoted(t, 60) + " has no name before '='; expected 'Key = Value'");
    if (stack_.size() == 1)
      fail(line, "parameter " + ccl_quoted(name) + " outside every object; expected it between 'NAME:' and END");
    CclObject& current = *stack_.back();
    Index& index = *indexes_.back();
    std::string value(trim(t.substr(equals + 1)));
    // Exact: CEL names (the keys of EXPRESSIONS) are case-sensitive.
    if (const auto found = index.parameters.find(name); found != index.parameters.end()) {
      CclParameter& existing = current.parameters[found->second];
      existing.value = std::move(value);  // the latter definition overrides the first
      existing.line = line;
      return;
    }
    index.parameters.emplace(name, current.parameters.size());
    current.parameters.push_back(CclParameter{std::move(name), std::move(value), line});
  }

  void read_object(std::string_view t, std::size_t colon, std::size_t line) {
    std::string type = collapse_blanks(t.substr(0, colon));
    std::string label = collapse_blanks(t.substr(colon + 1));
    if (type.empty())
      fail(line, ccl_quoted(t, 60) + " has no object type before ':'; expected 'NAME:' or 'NAME: Label'");
    if (stack_.size() > kMaxObjectDepth)
      fail(line, "objects nested more than " + std::to_string(kMaxObjectDepth) + " deep; expected a CFX case");
    CclObject& parent = *stack_.back();
    Index& index = *indexes_.back();
    // The type without regard to case, the label as written (a label holds no line break).
    std::string key;
    key.reserve(type.size() + 1 + label.size());
    for (const char c : type) key += lower(c);
    key += '\n';
    key += label;
    if (const auto found = index.children.find(key); found != index.children.end()) {
      stack_.push_back(&parent.children[found->second]);  // the same object again: merged
      indexes_.push_back(index.child_indexes[found->second].get());
      return;
    }
    index.children.emplace(std::move(key), parent.children.size());
    parent.children.push_back(CclObject{std::move(type), std::move(label), line, {}, {}});
    index.child_indexes.push_back(std::make_unique<Index>());
    stack_.push_back(&parent.children.back());
    indexes_.push_back(index.child_indexes.back().get());
  }

  /// An object's parameters and children by name, so that each parameter or
  /// object costs one hash lookup and a file of n of them parses in O(n)
  /// (a scan of the object's parameters per parameter made it O(n^2): 6.9 MB
  /// of CCL took 166 s). Kept beside the document's tree, whose vectors move
  /// their elements as they grow; child_indexes[i] is children[i]'s.
  struct Index {
    std::unordered_map<std::string, std::size_t> parameters;  ///< exact name -> position
    std::unordered_map<std::string, std::size_t> children;    ///< lower-case type '\n' label -> position
    std::vector<std::unique_ptr<Index>> child_indexes;
  };

  std::string_view text_;
  std::size_t first_line_;
  CclDocument document_;
  std::vector<CclObject*> stack_;
  Index root_index_;
  std::vector<Index*> indexes_;  ///< beside stack_
};

// --- units ------------------------------------------------------------------

struct ExtraUnit {
  std::string_view symbol;
  double pascals;
};
// Pressure units CFX offers that parse_unit does not know (standard
// atmosphere; pound-force per square inch = 4.4482216152605 N / 0.00064516 m^2).
constexpr ExtraUnit kExtraUnits[] = {{"atm", 101325.0}, {"psi", 6894.757293168361}};

/// A unit of CEL text: parse_unit, with atm and psi turned into pascals first.
Unit cel_unit(std::string_view text, const SourceLocation& where, std::string_view whole) {
  std::string rebuilt;
  double extra = 1.0;
  int sign = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == ' ' || c == '\t' || c == '*') {
      ++i;
      continue;
    }
    if (c == '/') {
      rebuilt += " /";
      sign = -1;
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t' && text[j] != '*' && text[j] != '/') ++j;
    const std::string_view factor = text.substr(i, j - i);
    i = j;
    std::string_view symbol = factor;
    std::string_view exponent_text;
    if (const auto caret = factor.find('^'); caret != std::string_view::npos) {
      symbol = factor.substr(0, caret);
      exponent_text = factor.substr(caret + 1);
    } else if (const auto digit = factor.find_first_of("-0123456789"); digit != std::string_view::npos && digit > 0) {
      symbol = factor.substr(0, digit);
      exponent_text = factor.substr(digit);
    }
    const ExtraUnit* extra_unit = nullptr;
    for (const auto& candidate : kExtraUnits)
      if (symbol == candidate.symbol) extra_unit = &candidate;
    if (!extra_unit) {
      rebuilt += ' ';
      rebuilt += factor;
      continue;
    }
    int exponent = 1;
    if (!exponent_text.empty()) {
      const auto [end, ec] =
          std::from_chars(exponent_text.data(), exponent_text.data() + exponent_text.size(), exponent);
      if (ec != std::errc{} || end != exponent_text.data() + exponent_text.size() || exponent < -12 || exponent > 12)
        throw InputError(where, "unit " + ccl_quoted(text) + " in " + ccl_quoted(whole) + ": bad exponent in " +
                                    ccl_quoted(factor) + "; expected an integer from -12 to 12");
    }
    extra *= std::pow(extra_unit->pascals, sign * exponent);
    rebuilt += " Pa^" + std::to_string(exponent);
  }
  Unit unit;
  try {
    unit = parse_unit(rebuilt);
  } catch (const InputError& error) {
    throw InputError(where, std::string(error.what()) + " (in " + ccl_quoted(whole) + ")");
  }
  unit.scale *= extra;
  unit.text = std::string(trim(text));
  return unit;
}

}  // namespace

std::string collapse_blanks(std::string_view text) {
  std::string out;
  bool blank = false;
  for (const char c : trim(text)) {
    if (is_blank(c)) {
      blank = true;
      continue;
    }
    if (blank && !out.empty()) out += ' ';
    blank = false;
    out += c;
  }
  return out;
}

// --- CclObject ----------------------------------------------------------------

const CclParameter* CclObject::parameter(std::string_view name) const {
  const std::string wanted = collapse_blanks(name);
  for (const auto& p : parameters)
    if (p.name == wanted) return &p;
  for (const auto& p : parameters)
    if (equal_ignoring_case(p.name, wanted)) return &p;
  return nullptr;
}

std::vector<const CclObject*> CclObject::children_of_type(std::string_view of_type) const {
  std::vector<const CclObject*> out;
  for (const auto& c : children)
    if (equal_names(c.type, of_type)) out.push_back(&c);
  return out;
}

const CclObject* CclObject::child(std::string_view of_type, std::optional<std::string_view> with_label) const {
  for (const auto& c : children)
    if (equal_names(c.type, of_type) && (!with_label || c.label == collapse_blanks(*with_label))) return &c;
  return nullptr;
}

std::string CclObject::title() const { return label.empty() ? type : type + ": " + label; }

CclDocument parse_ccl(std::string_view text, const std::string& file, std::size_t first_line) {
  return CclParser(text, file, first_line).parse();
}

// --- solver output ------------------------------------------------------------

std::optional<CclExcerpt> ccl_from_solver_output(std::string_view out_text) {
  enum class State { Searching, InBanner, InCcl } state = State::Searching;
  std::size_t start_offset = 0;
  std::size_t start_line = 0;
  std::optional<CclExcerpt> found;
  for_each_line(out_text, [&](std::string_view line, std::size_t number, std::size_t offset) {
    switch (state) {
      case State::Searching:
        if (is_ccl_banner_title(line)) state = State::InBanner;
        start_line = number + 1;
        return true;
      case State::InBanner:
        if (is_border_line(line) || is_empty_box_line(line)) {
          start_line = number + 1;
          return true;
        }
        state = State::InCcl;
        start_offset = offset;
        start_line = number;
        [[fallthrough]];
      case State::InCcl:
        if (is_border_line(line)) {
          found = CclExcerpt{out_text.substr(start_offset, offset - start_offset), start_line};
          return false;
        }
        return true;
    }
    return true;
  });
  if (found) return found;
  if (state == State::InCcl) return CclExcerpt{out_text.substr(start_offset), start_line};  // a run still going
  if (state == State::InBanner) return CclExcerpt{std::string_view{}, start_line};          // the banner ends the text
  return std::nullopt;
}

bool looks_like_cfx_solver_output(std::string_view head, std::size_t max_lines) {
  bool found = false;
  for_each_line(head, [&](std::string_view line, std::size_t number, std::size_t) {
    if (is_ccl_banner_title(line)) found = true;
    return !found && number < max_lines;
  });
  return found;
}

// --- CEL ----------------------------------------------------------------------

class CelParser {
 public:
  CelParser(const CelEvaluator& evaluator, std::string_view text, std::size_t line)
      : evaluator_(evaluator), text_(text), line_(line) {}

  CelValue parse() {
    skip_blanks();
    if (at_ >= text_.size()) fail("an empty value; expected a number or a constant expression");
    CelValue value = sum();
    skip_blanks();
    if (at_ < text_.size()) unexpected("after a complete expression");
    return value;
  }

 private:
  SourceLocation where() const { return evaluator_.document_.location(line_); }

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(where(), message + " (in " + ccl_quoted(text_) + ")");
  }
  [[noreturn]] void not_constant(const std::string& message) const {
    throw CelNotConstant(where(), message + " (in " + ccl_quoted(text_) + ")");
  }
  [[noreturn]] void unexpected(const std::string& context) const {
    fail(ccl_quoted(text_.substr(at_, 1)) + " " + context +
         "; expected numbers, units in brackets, + - * / ^, parentheses and names of LIBRARY: CEL: EXPRESSIONS:");
  }

  void skip_blanks() {
    while (at_ < text_.size() && is_blank(text_[at_])) ++at_;
  }
  bool take(char c) {
    skip_blanks();
    if (at_ < text_.size() && text_[at_] == c) {
      ++at_;
      return true;
    }
    return false;
  }

  void check_finite(const CelValue& v, std::string_view operation) const {
    if (!std::isfinite(v.value))
      fail("the " + std::string(operation) + " gives " + (std::isnan(v.value) ? "NaN" : "an infinite value") +
           "; expected a finite constant");
  }

  CelValue sum() {
    CelValue left = product();
    for (;;) {
      skip_blanks();
      if (at_ >= text_.size() || (text_[at_] != '+' && text_[at_] != '-')) return left;
      const char op = text_[at_++];
      const CelValue right = product();
      if (!(left.dimension == right.dimension))
        fail(std::string(op == '+' ? "a sum" : "a difference") + " of " + si_unit_name(left.dimension) + " and " +
             si_unit_name(right.dimension) + "; expected terms of one dimension");
      left = CelValue{op == '+' ? left.value + right.value : left.value - right.value, left.dimension};
      check_finite(left, op == '+' ? "sum" : "difference");
    }
  }

  CelValue product() {
    CelValue left = unary();
    for (;;) {
      skip_blanks();
      if (at_ >= text_.size() || (text_[at_] != '*' && text_[at_] != '/')) return left;
      const char op = text_[at_++];
      const CelValue right = unary();
      if (op == '/' && right.value == 0.0) fail("a division by zero; expected a non-zero divisor");
      CelValue result{op == '*' ? left.value * right.value : left.value / right.value, left.dimension};
      for (std::size_t i = 0; i < result.dimension.exponents.size(); ++i) {
        const long long e = static_cast<long long>(left.dimension.exponents[i]) +
                            (op == '*' ? 1 : -1) * static_cast<long long>(right.dimension.exponents[i]);
        if (e > kMaxDimensionExponent || e < -kMaxDimensionExponent)
          fail("a dimension raised beyond the power " + std::to_string(kMaxDimensionExponent) +
               "; expected a physical quantity");
        result.dimension.exponents[i] = static_cast<int>(e);
      }
      check_finite(result, op == '*' ? "product" : "quotient");
      left = result;
    }
  }

  struct NestingGuard {
    explicit NestingGuard(CelParser& parser) : parser_(parser) {
      if (++parser_.nesting_ > kMaxNesting)
        parser_.fail("parentheses or signs nested more than " + std::to_string(kMaxNesting) + " deep");
    }
    ~NestingGuard() { --parser_.nesting_; }
    CelParser& parser_;
  };

  CelValue unary() {
    NestingGuard guard(*this);
    if (take('-')) {
      CelValue v = unary();
      v.value = -v.value;
      return v;
    }
    if (take('+')) return unary();
    return power();
  }

  CelValue power() {
    const CelValue base = primary();
    if (!take('^')) return base;
    const std::size_t exponent_at = at_;
    const CelValue exponent = unary();
    if (!(exponent.dimension == kDimensionless))
      fail("an exponent with the unit " + si_unit_name(exponent.dimension) + "; expected a dimensionless exponent");
    CelValue result{std::pow(base.value, exponent.value), base.dimension};
    if (!(base.dimension == kDimensionless)) {
      const double rounded = std::round(exponent.value);
      if (std::abs(exponent.value - rounded) > 1e-12 || std::abs(rounded) > 12)
        fail("the power " + printable_text(trim(text_.substr(exponent_at, at_ - exponent_at)), 40) +
             " of a quantity with the unit " + si_unit_name(base.dimension) +
             "; expected a whole power from -12 to 12 (fractional powers only of dimensionless values)");
      const long long n = static_cast<long long>(rounded);
      for (std::size_t i = 0; i < result.dimension.exponents.size(); ++i) {
        const long long e = static_cast<long long>(base.dimension.exponents[i]) * n;
        if (e > kMaxDimensionExponent || e < -kMaxDimensionExponent)
          fail("a dimension raised beyond the power " + std::to_string(kMaxDimensionExponent) +
               "; expected a physical quantity");
        result.dimension.exponents[i] = static_cast<int>(e);
      }
    }
    check_finite(result, "power");
    return result;
  }

  CelValue primary() {
    skip_blanks();
    if (at_ >= text_.size()) fail("the text ends where a value is expected; expected a number, a name or '('");
    const char c = text_[at_];
    if (c == '(') {
      NestingGuard guard(*this);
      ++at_;
      const CelValue inside = sum();
      if (!take(')')) {
        if (at_ >= text_.size()) fail("'(' without its ')'; expected ')'");
        unexpected("where ')' is expected");
      }
      return inside;
    }
    if ((c >= '0' && c <= '9') || c == '.') return number();
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_') return name();
    if (c == '@') not_constant("a locator '@'; expected a constant expression");
    if (c == '[') unexpected("(a unit must follow a number)");
    unexpected("where a value is expected");
  }

  CelValue number() {
    const std::size_t start = at_;
    while (at_ < text_.size() && ((text_[at_] >= '0' && text_[at_] <= '9') || text_[at_] == '.')) ++at_;
    if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
      std::size_t j = at_ + 1;
      if (j < text_.size() && (text_[j] == '+' || text_[j] == '-')) ++j;
      if (j < text_.size() && text_[j] >= '0' && text_[j] <= '9') {
        at_ = j;
        while (at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9') ++at_;
      }
    }
    const std::string_view digits = text_.substr(start, at_ - start);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc{} || end != digits.data() + digits.size() || !std::isfinite(value))
      fail("the number " + ccl_quoted(digits) + " cannot be read; expected a finite number such as 8.899E-4");
    CelValue result{value, kDimensionless};
    skip_blanks();
    if (at_ < text_.size() && text_[at_] == '[') {
      const auto close = text_.find(']', at_);
      if (close == std::string_view::npos) fail("a unit '[' without its ']'; expected a unit such as [m s^-1]");
      const Unit unit = cel_unit(text_.substr(at_ + 1, close - at_ - 1), where(), text_);
      at_ = close + 1;
      result.value *= unit.scale;
      result.dimension = unit.dimension;
      check_finite(result, "unit conversion");
    }
    return result;
  }

  CelValue name() {
    const std::size_t start = at_;
    while (at_ < text_.size()) {
      const char c = text_[at_];
      const bool name_char = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
                             c == '.' || c == ' ' || c == '\t';
      if (!name_char) break;
      ++at_;
    }
    const std::string name = collapse_blanks(text_.substr(start, at_ - start));
    skip_blanks();
    if (at_ < text_.size() && text_[at_] == '(')
      not_constant("a function call " + ccl_quoted(name + "(") + "; expected a constant expression (no functions)");
    if (at_ < text_.size() && text_[at_] == '@')
      not_constant("a locator " + ccl_quoted(name + "@") + "; expected a constant expression");
    if (!evaluator_.has_expression(name))
      not_constant("the name " + ccl_quoted(name) +
                   " is no expression of LIBRARY: CEL: EXPRESSIONS: (a variable such as x, t or Temperature, or a "
                   "constant); expected a constant expression");
    return evaluator_.expression(name, line_);
  }

  const CelEvaluator& evaluator_;
  std::string_view text_;
  std::size_t line_;
  std::size_t at_ = 0;
  int nesting_ = 0;
};

CelEvaluator::CelEvaluator(const CclDocument& document) : document_(document) {
  for (const CclObject* library : document.root.children_of_type("LIBRARY"))
    for (const CclObject* cel : library->children_of_type("CEL"))
      for (const CclObject* expressions : cel->children_of_type("EXPRESSIONS"))
        for (const auto& p : expressions->parameters) expressions_[p.name] = p;  // the last definition wins
}

CelValue CelEvaluator::evaluate(std::string_view text, std::size_t line) const {
  return CelParser(*this, text, line).parse();
}

CelValue CelEvaluator::expression(const std::string& name, std::size_t used_on_line) const {
  if (const auto cached = cache_.find(name); cached != cache_.end()) return cached->second;
  const auto it = expressions_.find(name);
  if (it == expressions_.end())
    throw CelNotConstant(document_.location(used_on_line),
                         "the name " + ccl_quoted(name) + " is no expression of LIBRARY: CEL: EXPRESSIONS:");
  if (std::find(evaluating_.begin(), evaluating_.end(), name) != evaluating_.end()) {
    std::string chain;
    for (auto i = std::find(evaluating_.begin(), evaluating_.end(), name); i != evaluating_.end(); ++i)
      chain += printable_text(*i, 40) + " -> ";
    throw InputError(document_.location(used_on_line), "the expressions refer to each other in a cycle (" + chain +
                                                           printable_text(name, 40) +
                                                           "); expected each to end in numbers");
  }
  if (evaluating_.size() >= kMaxExpressionDepth)
    throw InputError(document_.location(used_on_line), "expressions refer to expressions more than " +
                                                           std::to_string(kMaxExpressionDepth) +
                                                           " deep; expected a shorter chain");
  evaluating_.push_back(name);
  struct Pop {
    std::vector<std::string>& names;
    ~Pop() { names.pop_back(); }
  } pop{evaluating_};
  const CelValue value = evaluate(it->second);
  cache_[name] = value;
  return value;
}

double CelEvaluator::evaluate_as(const CclParameter& parameter, const Dimension& expected,
                                 std::string_view what) const {
  const CelValue v = evaluate(parameter);
  if (v.dimension == expected || (v.value == 0.0 && v.dimension == kDimensionless)) return v.value;
  throw InputError(document_.location(parameter.line),
                   ccl_quoted(parameter.name + " = " + parameter.value) + " has the unit " + si_unit_name(v.dimension) +
                       "; expected " + std::string(what) + " (" + si_unit_name(expected) + ")");
}

}  // namespace hydrocoef
