#include "src/core/units.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "src/core/error.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

// A unit text is one header cell or option value: \v and \f are not blanks there.
constexpr std::string_view kUnitBlanks = " \t\r\n";

struct Symbol {
  std::string_view name;
  double scale;
  Dimension dimension;
};

constexpr Dimension kMass{{1, 0, 0, 0}};
constexpr Dimension kTime{{0, 0, 1, 0}};
constexpr Dimension kAngle{{0, 0, 0, 1}};
constexpr Dimension kTemperature{{0, 0, 0, 0, 1}};
constexpr Dimension kEnergy{{1, 2, -2, 0}};
constexpr Dimension kPower{{1, 2, -3, 0}};
constexpr Dimension kVolume{{0, 3, 0, 0}};

// Exact symbols are tried before prefix + symbol, so "min" is a minute and
// "Pa" a pascal rather than a milli-inch or a peta-year.
const std::vector<Symbol>& symbols() {
  static const std::vector<Symbol> table = {
      {"m", 1.0, kLength},
      {"g", 1e-3, kMass},
      {"s", 1.0, kTime},
      {"min", 60.0, kTime},
      {"h", 3600.0, kTime},
      {"N", 1.0, kForce},
      {"Pa", 1.0, kPressure},
      {"bar", 1e5, kPressure},
      {"J", 1.0, kEnergy},
      {"W", 1.0, kPower},
      {"L", 1e-3, kVolume},
      {"rad", 1.0, kAngle},
      {"radian", 1.0, kAngle},
      {"deg", std::numbers::pi / 180.0, kAngle},
      {"degree", std::numbers::pi / 180.0, kAngle},
      {"rev", 2.0 * std::numbers::pi, kAngle},
      {"K", 1.0, kTemperature},
  };
  return table;
}

struct Prefix {
  std::string_view name;
  double scale;
};
constexpr std::array<Prefix, 10> kPrefixes = {{{"G", 1e9},
                                               {"M", 1e6},
                                               {"k", 1e3},
                                               {"h", 1e2},
                                               {"c", 1e-2},
                                               {"m", 1e-3},
                                               {"u", 1e-6},
                                               {"\xC2\xB5", 1e-6},  // micro sign
                                               {"n", 1e-9},
                                               {"d", 1e-1}}};

std::optional<Symbol> find_symbol(std::string_view name) {
  for (const auto& symbol : symbols())
    if (symbol.name == name) return symbol;
  for (const auto& prefix : kPrefixes) {
    if (name.size() <= prefix.name.size() || name.substr(0, prefix.name.size()) != prefix.name) continue;
    const auto rest = name.substr(prefix.name.size());
    for (const auto& symbol : symbols())
      if (symbol.name == rest) return Symbol{name, prefix.scale * symbol.scale, symbol.dimension};
  }
  return std::nullopt;
}

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '*' || c == '.'; }

[[noreturn]] void fail(std::string_view unit, const std::string& why) {
  throw InputError("unit '" + std::string(unit) + "': " + why);
}

void apply_factor(std::string_view whole, std::string_view factor, int sign, Unit& unit) {
  // A factor is SYMBOL, SYMBOL^EXP or SYMBOLEXP (m2, s-1).
  std::string_view symbol = factor;
  int exponent = 1;
  if (const auto caret = factor.find('^'); caret != std::string_view::npos) {
    symbol = factor.substr(0, caret);
    const auto digits = factor.substr(caret + 1);
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
    if (ec != std::errc{} || end != digits.data() + digits.size())
      fail(whole, "bad exponent in '" + std::string(factor) + "'; expected an integer such as s^-1");
  } else {
    const auto digit = factor.find_first_of("-0123456789");
    if (digit != std::string_view::npos && digit > 0) {
      symbol = factor.substr(0, digit);
      const auto digits = factor.substr(digit);
      auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
      if (ec != std::errc{} || end != digits.data() + digits.size())
        fail(whole, "bad exponent in '" + std::string(factor) + "'");
    }
  }
  if (symbol == "1" && exponent == 1) return;
  // Physical units never need large powers; a bound keeps the dimension
  // arithmetic far from integer overflow and the scale finite.
  constexpr int kMaxExponent = 12;
  if (exponent < -kMaxExponent || exponent > kMaxExponent)
    fail(whole, "exponent " + std::to_string(exponent) + " in '" + std::string(factor) + "'; expected -" +
                    std::to_string(kMaxExponent) + " to " + std::to_string(kMaxExponent));
  const auto found = find_symbol(symbol);
  if (!found)
    fail(whole, "unknown unit symbol '" + std::string(symbol) +
                    "'; known: m g s min h N Pa bar J W L rad deg rev K with prefixes G M k h c d m u n");
  exponent *= sign;
  unit.scale *= std::pow(found->scale, exponent);
  for (std::size_t i = 0; i < unit.dimension.exponents.size(); ++i)
    unit.dimension.exponents[i] += found->dimension.exponents[i] * exponent;
}

}  // namespace

std::string si_unit_name(const Dimension& dimension) {
  // Printed in the order engineers write them: kg m rad s (rad s^-1, N = kg m s^-2).
  static constexpr std::array<std::string_view, 5> names = {"kg", "m", "s", "rad", "K"};
  static constexpr std::array<std::size_t, 5> order = {0, 1, 3, 4, 2};
  std::string out;
  for (const std::size_t i : order) {
    const int e = dimension.exponents[i];
    if (e == 0) continue;
    if (!out.empty()) out += ' ';
    out += names[i];
    if (e != 1) out += '^' + std::to_string(e);
  }
  return out.empty() ? "1" : out;
}

Unit parse_unit(std::string_view text) {
  std::string_view body = trim(text, kUnitBlanks);
  if (!body.empty() && body.front() == '[' && body.back() == ']')
    body = trim(body.substr(1, body.size() - 2), kUnitBlanks);
  Unit unit;
  unit.text = std::string(body);
  int sign = 1;
  std::size_t i = 0;
  bool divided = false;
  while (i < body.size()) {
    if (is_separator(body[i])) {
      ++i;
      continue;
    }
    if (body[i] == '/') {
      if (divided) fail(body, "more than one '/'; write it as 'kg m^-3'");
      divided = true;
      sign = -1;
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < body.size() && !is_separator(body[j]) && body[j] != '/') ++j;
    apply_factor(body, body.substr(i, j - i), sign, unit);
    i = j;
  }
  for (const int e : unit.dimension.exponents)
    if (e < -24 || e > 24)
      fail(body, "a base unit is raised to the power " + std::to_string(e) + "; expected a physical unit");
  if (!std::isfinite(unit.scale) || unit.scale == 0.0 || std::abs(std::log10(unit.scale)) > 60)
    fail(body, "its factor to SI is out of range; expected a physical unit");
  return unit;
}

bool dimension_matches(const Dimension& found, const Dimension& expected) {
  if (found == expected) return true;
  // Allow the angle to be implicit (rad is dimensionless in SI) only where an
  // angle is expected, and never for more than one power of it.
  if (expected.exponents[3] == 1 && found.exponents[3] == 0) {
    Dimension without_angle = expected;
    without_angle.exponents[3] = 0;
    return found == without_angle;
  }
  return false;
}

NameAndUnit split_name_and_unit(std::string_view header) {
  const auto text = trim(header, kUnitBlanks);
  NameAndUnit out;
  const auto open = text.rfind('[');
  if (open != std::string_view::npos && !text.empty() && text.back() == ']') {
    out.name = std::string(trim(text.substr(0, open), kUnitBlanks));
    out.unit = std::string(trim(text.substr(open + 1, text.size() - open - 2), kUnitBlanks));
    out.has_unit = true;
  } else {
    out.name = std::string(text);
  }
  return out;
}

}  // namespace hydrocoef
