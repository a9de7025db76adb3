#include "src/derivatives/normalisation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

// A scale from its (1/2) power and the doubled exponents of rho, m, U, g, L, d.
constexpr NormalisationScale make_scale(int one_half_power, int rho, int m, int speed, int g, int length, int draft) {
  return NormalisationScale{one_half_power, {rho, m, speed, g, length, draft}};
}

// The table of the file comment of normalisation.hpp, with every exponent
// doubled; the sources are cited there.
NormalisationScale prime_scale(QuantityKind quantity) {
  switch (quantity) {
    case QuantityKind::Force: return make_scale(1, 2, 0, 4, 0, 4, 0);                 // 1/2 rho U^2 L^2
    case QuantityKind::Moment: return make_scale(1, 2, 0, 4, 0, 6, 0);                // 1/2 rho U^2 L^3
    case QuantityKind::LinearVelocity: return make_scale(0, 0, 0, 2, 0, 0, 0);        // U
    case QuantityKind::AngularVelocity: return make_scale(0, 0, 0, 2, 0, -2, 0);      // U / L
    case QuantityKind::LinearAcceleration: return make_scale(0, 0, 0, 4, 0, -2, 0);   // U^2 / L
    case QuantityKind::AngularAcceleration: return make_scale(0, 0, 0, 4, 0, -4, 0);  // U^2 / L^2
    case QuantityKind::Mass: return make_scale(1, 2, 0, 0, 0, 6, 0);                  // 1/2 rho L^3
    case QuantityKind::Inertia: return make_scale(1, 2, 0, 0, 0, 10, 0);              // 1/2 rho L^5
    case QuantityKind::Length: return make_scale(0, 0, 0, 0, 0, 2, 0);                // L
    case QuantityKind::Time: return make_scale(0, 0, 0, -2, 0, 2, 0);                 // L / U
    case QuantityKind::Angle: return make_scale(0, 0, 0, 0, 0, 0, 0);                 // 1
  }
  return {};
}

NormalisationScale bis_scale(QuantityKind quantity) {
  switch (quantity) {
    case QuantityKind::Force: return make_scale(0, 0, 2, 0, 2, 0, 0);                 // m g
    case QuantityKind::Moment: return make_scale(0, 0, 2, 0, 2, 2, 0);                // m g L
    case QuantityKind::LinearVelocity: return make_scale(0, 0, 0, 0, 1, 1, 0);        // sqrt(L g)
    case QuantityKind::AngularVelocity: return make_scale(0, 0, 0, 0, 1, -1, 0);      // sqrt(g / L)
    case QuantityKind::LinearAcceleration: return make_scale(0, 0, 0, 0, 2, 0, 0);    // g
    case QuantityKind::AngularAcceleration: return make_scale(0, 0, 0, 0, 2, -2, 0);  // g / L
    case QuantityKind::Mass: return make_scale(0, 0, 2, 0, 0, 0, 0);                  // m
    case QuantityKind::Inertia: return make_scale(0, 0, 2, 0, 0, 4, 0);               // m L^2
    case QuantityKind::Length: return make_scale(0, 0, 0, 0, 0, 2, 0);                // L
    case QuantityKind::Time: return make_scale(0, 0, 0, 0, -1, 1, 0);                 // sqrt(L / g)
    case QuantityKind::Angle: return make_scale(0, 0, 0, 0, 0, 0, 0);                 // 1
  }
  return {};
}

NormalisationScale mmg_scale(QuantityKind quantity) {
  switch (quantity) {
    case QuantityKind::Force: return make_scale(1, 2, 0, 4, 0, 2, 2);    // 1/2 rho U^2 L d
    case QuantityKind::Moment: return make_scale(1, 2, 0, 4, 0, 4, 2);   // 1/2 rho U^2 L^2 d
    case QuantityKind::Mass: return make_scale(1, 2, 0, 0, 0, 4, 2);     // 1/2 rho L^2 d
    case QuantityKind::Inertia: return make_scale(1, 2, 0, 0, 0, 8, 2);  // 1/2 rho L^4 d
    default: return prime_scale(quantity);  // velocities, rates, accelerations, length, time, angle
  }
}

// What a reference symbol is, for messages and for normalisation_text.
struct SymbolInfo {
  std::string_view symbol;  // as scale_text writes it
  std::string_view name;    // in messages
  std::string_view unit;
  std::string_view field;  // the reference's field, as a message tells the user to give it
};

constexpr std::array<SymbolInfo, kReferenceSymbolCount> kSymbols{{
    {"rho", "water density rho", "kg/m^3", "density"},
    {"m", "mass m", "kg", "mass"},
    {"U", "reference speed U", "m/s", "speed"},
    {"g", "acceleration of gravity g", "m/s^2", "gravity"},
    {"L", "reference length L", "m", "length"},
    {"d", "draft d", "m", "draft"},
}};

const SymbolInfo& info(ReferenceSymbol symbol) { return kSymbols[static_cast<std::size_t>(symbol)]; }

// "rho U^2" for the given exponents (already integers), in table order.
std::string product_text(const std::array<int, kReferenceSymbolCount>& exponents) {
  std::string text;
  for (std::size_t i = 0; i < kReferenceSymbolCount; ++i) {
    if (exponents[i] == 0) continue;
    if (!text.empty()) text += ' ';
    text += kSymbols[i].symbol;
    if (exponents[i] != 1) text += "^" + std::to_string(exponents[i]);
  }
  return text;
}

std::size_t factor_count(const std::array<int, kReferenceSymbolCount>& exponents) {
  return static_cast<std::size_t>(std::count_if(exponents.begin(), exponents.end(), [](int e) { return e != 0; }));
}

std::string coefficient_text(int one_half_power) {
  if (one_half_power == 0) return {};
  const auto magnitude = static_cast<unsigned>(std::abs(one_half_power));
  if (magnitude > 62) return "2^" + std::to_string(-one_half_power);
  const std::string power = std::to_string(std::uint64_t{1} << magnitude);
  return one_half_power > 0 ? "1/" + power : power;
}

[[noreturn]] void refuse_field(const SymbolInfo& symbol, double value) {
  throw InputError("normalisation reference: the " + std::string(symbol.name) +
                   " must be a finite positive number of " + std::string(symbol.unit) + ", found " +
                   shortest_number(value));
}

void check_field(const std::optional<double>& value, const SymbolInfo& symbol) {
  if (value && !(std::isfinite(*value) && *value > 0.0)) refuse_field(symbol, *value);
}

constexpr SymbolInfo kVolume{"volume", "displaced volume", "m^3", "displaced volume"};

[[noreturn]] void refuse_missing(NormalisationSystem system, const NormalisationScale& scale, std::string_view what,
                                 const std::string& needed, std::string_view how) {
  throw InputError(std::string(normalisation_system_title(system)) + ": the unit of " + std::string(what) + ", " +
                   scale_text(scale) + ", needs the " + needed + ", which is not given; give " + std::string(how) +
                   " with the reference data");
}

// The value of one reference symbol, or a refusal naming what is missing.
double symbol_value(ReferenceSymbol symbol, NormalisationSystem system, const NormalisationScale& scale,
                    const NormalisationReference& reference, std::string_view what) {
  const auto require = [&](const std::optional<double>& value) {
    const SymbolInfo& i = info(symbol);
    if (!value) {
      refuse_missing(system, scale, what, std::string(i.name) + " [" + std::string(i.unit) + "]",
                     "the " + std::string(i.field));
    }
    return *value;
  };
  switch (symbol) {
    case ReferenceSymbol::Density: return require(reference.density);
    case ReferenceSymbol::Speed: return require(reference.speed);
    case ReferenceSymbol::Length: return require(reference.length);
    case ReferenceSymbol::Draft: return require(reference.draft);
    case ReferenceSymbol::Gravity: return reference.gravity;
    case ReferenceSymbol::Mass:
      if (reference.mass) return *reference.mass;
      if (!reference.displaced_volume) {
        refuse_missing(system, scale, what, "mass m [kg] or the displaced volume [m^3] (m = rho * volume)",
                       "the mass or the displaced volume and density");
      }
      if (!reference.density) {
        refuse_missing(system, scale, what, "water density rho [kg/m^3] for the mass m = rho * displaced volume",
                       "the density");
      }
      return *reference.density * *reference.displaced_volume;
  }
  return 1.0;
}

// x^(doubled / 2) by products and one square root.
double doubled_power(double x, int doubled) {
  const int whole = doubled / 2;
  const int half = doubled % 2;
  double result = 1.0;
  for (int k = 0; k < std::abs(whole); ++k) result *= x;
  if (whole < 0) result = 1.0 / result;
  if (half == 1) result *= std::sqrt(x);
  if (half == -1) result /= std::sqrt(x);
  return result;
}

// "X'" or "X''" (bis).
std::string nondimensional_symbol(std::string_view symbol, NormalisationSystem system) {
  return std::string(symbol) + (system == NormalisationSystem::Bis ? "''" : "'");
}

}  // namespace

std::string_view to_string(NormalisationSystem system) {
  switch (system) {
    case NormalisationSystem::Prime: return "prime";
    case NormalisationSystem::Bis: return "bis";
    case NormalisationSystem::Mmg: return "mmg";
  }
  return "?";
}

std::string_view normalisation_system_title(NormalisationSystem system) {
  switch (system) {
    case NormalisationSystem::Prime: return "prime (SNAME 1950)";
    case NormalisationSystem::Bis: return "bis (Norrbin 1971)";
    case NormalisationSystem::Mmg: return "MMG (Yasukawa and Yoshimura 2015)";
  }
  return "?";
}

std::string_view normalisation_system_needs(NormalisationSystem system) {
  switch (system) {
    case NormalisationSystem::Prime: return "reference length L, reference speed U, water density rho";
    case NormalisationSystem::Bis:
      return "reference length L, acceleration of gravity g, and the mass m or the displaced volume and water "
             "density rho (m = rho * volume)";
    case NormalisationSystem::Mmg: return "reference length L, draft d, reference speed U, water density rho";
  }
  return "?";
}

NormalisationSystem parse_normalisation_system(std::string_view text) {
  const std::string name = lower(text);
  const auto* found = std::find_if(kAllNormalisationSystems.begin(), kAllNormalisationSystems.end(),
                                   [&name](NormalisationSystem system) { return name == to_string(system); });
  if (found != kAllNormalisationSystems.end()) return *found;
  throw InputError("unknown normalisation system '" + printable_text(text, 40) + "': expected prime, bis or mmg");
}

std::string_view to_string(QuantityKind quantity) {
  switch (quantity) {
    case QuantityKind::Force: return "force";
    case QuantityKind::Moment: return "moment";
    case QuantityKind::LinearVelocity: return "linear velocity";
    case QuantityKind::AngularVelocity: return "angular velocity";
    case QuantityKind::LinearAcceleration: return "linear acceleration";
    case QuantityKind::AngularAcceleration: return "angular acceleration";
    case QuantityKind::Mass: return "mass";
    case QuantityKind::Inertia: return "moment of inertia";
    case QuantityKind::Length: return "length";
    case QuantityKind::Time: return "time";
    case QuantityKind::Angle: return "angle";
  }
  return "?";
}

std::string describe(const DerivativeKind& kind) {
  std::string text(to_string(kind.output));
  if (kind.factors.empty()) return text;
  std::string denominator;
  for (const DerivativeFactor& factor : kind.factors) {
    if (!denominator.empty()) denominator += " * ";
    denominator += to_string(factor.variable);
    if (factor.power != 1) denominator += "^" + std::to_string(factor.power);
  }
  return text + " / " + (kind.factors.size() > 1 ? "(" + denominator + ")" : denominator);
}

NormalisationScale quantity_scale(QuantityKind quantity, NormalisationSystem system) {
  switch (system) {
    case NormalisationSystem::Prime: return prime_scale(quantity);
    case NormalisationSystem::Bis: return bis_scale(quantity);
    case NormalisationSystem::Mmg: return mmg_scale(quantity);
  }
  return {};
}

NormalisationScale derivative_scale(const DerivativeKind& kind, NormalisationSystem system) {
  NormalisationScale scale = quantity_scale(kind.output, system);
  for (const DerivativeFactor& factor : kind.factors) {
    if (factor.power < 1 || factor.power > kMaxDerivativePower) {
      throw InputError("derivative " + describe(kind) + ": the power of " + std::string(to_string(factor.variable)) +
                       " must be 1 to " + std::to_string(kMaxDerivativePower) + " (|x| counts as x), found " +
                       std::to_string(factor.power));
    }
    const NormalisationScale variable = quantity_scale(factor.variable, system);
    scale.one_half_power -= factor.power * variable.one_half_power;
    for (std::size_t i = 0; i < kReferenceSymbolCount; ++i) {
      scale.doubled_exponents[i] -= factor.power * variable.doubled_exponents[i];
    }
  }
  return scale;
}

std::string scale_text(const NormalisationScale& scale) {
  // Each exponent n/2 splits into a whole part and, when n is odd, a square
  // root: L^(3/2) = L sqrt(L), g^(-1/2) = sqrt(1/g).
  std::array<int, kReferenceSymbolCount> above{};
  std::array<int, kReferenceSymbolCount> below{};
  std::array<int, kReferenceSymbolCount> root_above{};
  std::array<int, kReferenceSymbolCount> root_below{};
  for (std::size_t i = 0; i < kReferenceSymbolCount; ++i) {
    const int n = scale.doubled_exponents[i];
    if (n / 2 > 0) above[i] = n / 2;
    if (n / 2 < 0) below[i] = -(n / 2);
    if (n % 2 == 1) root_above[i] = 1;
    if (n % 2 == -1) root_below[i] = 1;
  }
  // A square root goes above the line unless it only has symbols below it:
  // sqrt(g/L), sqrt(g L), and m / (L sqrt(g L)).
  const std::size_t roots_above = factor_count(root_above);
  const std::size_t roots_below = factor_count(root_below);
  std::string root;
  if (roots_above > 0 && roots_below > 0) {
    const std::string under = product_text(root_below);
    root = "sqrt(" + product_text(root_above) + "/" + (roots_below > 1 ? "(" + under + ")" : under) + ")";
  } else if (roots_above + roots_below > 0) {
    root = "sqrt(" + product_text(roots_above > 0 ? root_above : root_below) + ")";
  }
  const bool root_is_below = roots_above == 0 && roots_below > 0;

  const auto joined = [](std::string text, const std::string& part) {
    if (part.empty()) return text;
    return text.empty() ? part : text + " " + part;
  };
  std::string numerator = joined(coefficient_text(scale.one_half_power), product_text(above));
  if (!root_is_below) numerator = joined(numerator, root);
  if (numerator.empty()) numerator = "1";
  std::string denominator = product_text(below);
  if (root_is_below) denominator = joined(denominator, root);
  if (denominator.empty()) return numerator;
  const bool one_factor = factor_count(below) + (root_is_below ? 1 : 0) == 1;
  return numerator + " / " + (one_factor ? denominator : "(" + denominator + ")");
}

void check_normalisation_reference(const NormalisationReference& reference) {
  check_field(reference.length, info(ReferenceSymbol::Length));
  check_field(reference.speed, info(ReferenceSymbol::Speed));
  check_field(reference.density, info(ReferenceSymbol::Density));
  check_field(reference.draft, info(ReferenceSymbol::Draft));
  check_field(reference.mass, info(ReferenceSymbol::Mass));
  check_field(reference.displaced_volume, kVolume);
  check_field(reference.gravity, info(ReferenceSymbol::Gravity));
}

double scale_value(const NormalisationScale& scale, NormalisationSystem system, const NormalisationReference& reference,
                   std::string_view what) {
  check_normalisation_reference(reference);
  double value = std::ldexp(1.0, -scale.one_half_power);
  for (std::size_t i = 0; i < kReferenceSymbolCount; ++i) {
    const int doubled = scale.doubled_exponents[i];
    if (doubled == 0) continue;
    value *= doubled_power(symbol_value(static_cast<ReferenceSymbol>(i), system, scale, reference, what), doubled);
  }
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(std::string(normalisation_system_title(system)) + ": the unit of " + std::string(what) + ", " +
                     scale_text(scale) + ", is " + shortest_number(value) +
                     " for this reference data, which no number can be converted with");
  }
  return value;
}

double to_dimensional(double value, QuantityKind quantity, NormalisationSystem system,
                      const NormalisationReference& reference) {
  return value * scale_value(quantity_scale(quantity, system), system, reference, to_string(quantity));
}

double to_nondimensional(double value, QuantityKind quantity, NormalisationSystem system,
                         const NormalisationReference& reference) {
  return value / scale_value(quantity_scale(quantity, system), system, reference, to_string(quantity));
}

double to_dimensional(double value, const DerivativeKind& kind, NormalisationSystem system,
                      const NormalisationReference& reference) {
  return value * scale_value(derivative_scale(kind, system), system, reference, describe(kind));
}

double to_nondimensional(double value, const DerivativeKind& kind, NormalisationSystem system,
                         const NormalisationReference& reference) {
  return value / scale_value(derivative_scale(kind, system), system, reference, describe(kind));
}

double convert_between_systems(double value, QuantityKind quantity, NormalisationSystem from, NormalisationSystem to,
                               const NormalisationReference& reference) {
  return to_nondimensional(to_dimensional(value, quantity, from, reference), quantity, to, reference);
}

double convert_between_systems(double value, const DerivativeKind& kind, NormalisationSystem from,
                               NormalisationSystem to, const NormalisationReference& reference) {
  return to_nondimensional(to_dimensional(value, kind, from, reference), kind, to, reference);
}

std::string normalisation_text(const NormalisationScale& scale, NormalisationSystem system,
                               const NormalisationReference& reference, std::string_view symbol) {
  (void)scale_value(scale, system, reference, symbol);  // refuses missing or bad reference values
  std::string text = std::string(normalisation_system_title(system)) + ": " + nondimensional_symbol(symbol, system) +
                     " = " + std::string(symbol);
  const std::string formula = scale_text(scale);
  if (formula == "1") return text;
  const bool compound = formula.find_first_of(" /") != std::string::npos;
  text += " / " + (compound ? "(" + formula + ")" : formula);
  // The values the scale uses, in the order L, d, U, rho, m, g.
  const auto uses = [&scale](ReferenceSymbol s) { return scale.doubled_exponents[static_cast<std::size_t>(s)] != 0; };
  const auto append = [&text](const SymbolInfo& s, double value) {
    text += ", " + std::string(s.symbol) + " = " + shortest_number(value) + " " + std::string(s.unit);
  };
  if (uses(ReferenceSymbol::Length)) append(info(ReferenceSymbol::Length), *reference.length);
  if (uses(ReferenceSymbol::Draft)) append(info(ReferenceSymbol::Draft), *reference.draft);
  if (uses(ReferenceSymbol::Speed)) append(info(ReferenceSymbol::Speed), *reference.speed);
  const bool mass_from_volume = uses(ReferenceSymbol::Mass) && !reference.mass;
  if (uses(ReferenceSymbol::Density) || mass_from_volume) append(info(ReferenceSymbol::Density), *reference.density);
  if (mass_from_volume) {
    text += ", m = rho * volume = " + shortest_number(*reference.density * *reference.displaced_volume) +
            " kg (volume = " + shortest_number(*reference.displaced_volume) + " m^3)";
  } else if (uses(ReferenceSymbol::Mass)) {
    append(info(ReferenceSymbol::Mass), *reference.mass);
  }
  if (uses(ReferenceSymbol::Gravity)) append(info(ReferenceSymbol::Gravity), reference.gravity);
  return text;
}

}  // namespace hydrocoef
