// The prime, bis and MMG systems (src/derivatives/normalisation.hpp): each
// unit against the sources' formulas written out here by hand, the SI
// dimension of every unit, the identities that keep the equations of motion
// in the same form in every system (force = mass * acceleration, ...),
// derivative units, round trips between the systems to 1e-15, a published bis
// table against the formula its source uses, the normalisation texts, and
// the refusals.
#include "src/derivatives/normalisation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using K = QuantityKind;
using S = NormalisationSystem;

using test::input_error_message;

double relative_error(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

// How many significant digits a printed number shows: "-0.0744" 3, "1.1274" 5, "-1160" 4.
int significant_digits(const std::string& printed) {
  std::string digits;
  for (const char c : printed)
    if (c >= '0' && c <= '9') digits += c;
  const std::size_t first = digits.find_first_not_of('0');
  return first == std::string::npos ? 1 : static_cast<int>(digits.size() - first);
}

// A reference with every value given (or the mass through the displaced
// volume), each drawn log-uniformly over what ships, models and AUVs have.
NormalisationReference random_reference(std::mt19937_64& rng, bool mass_from_volume) {
  const auto log_uniform = [&rng](double low, double high) {
    return std::exp(std::uniform_real_distribution<double>(std::log(low), std::log(high))(rng));
  };
  NormalisationReference reference;
  reference.length = log_uniform(0.3, 400.0);
  reference.speed = log_uniform(0.05, 20.0);
  reference.density = log_uniform(990.0, 1030.0);
  reference.draft = log_uniform(0.05, 25.0);
  reference.gravity = log_uniform(9.78, 9.84);
  if (mass_from_volume) {
    reference.displaced_volume = log_uniform(0.01, 4e5);
  } else {
    reference.mass = log_uniform(10.0, 4e8);
  }
  return reference;
}

// The sources' tables written out by hand (the sources are cited in
// normalisation.hpp): the SI value of one non-dimensional unit and its text.
struct UnitRow {
  S system;
  K quantity;
  std::function<double(double L, double U, double rho, double d, double m, double g)> unit;
  std::string text;
};

std::vector<UnitRow> source_tables() {
  using std::sqrt;
  // clang-format off
  return {
      // Prime, Fossen (2021) appendix D as MSS applies it (clarke83.m, npsauv.m, mariner.m).
      {S::Prime, K::Force,               [](double L, double U, double rho, double, double, double) { return 0.5 * rho * U * U * L * L; }, "1/2 rho U^2 L^2"},
      {S::Prime, K::Moment,              [](double L, double U, double rho, double, double, double) { return 0.5 * rho * U * U * L * L * L; }, "1/2 rho U^2 L^3"},
      {S::Prime, K::LinearVelocity,      [](double, double U, double, double, double, double) { return U; }, "U"},
      {S::Prime, K::AngularVelocity,     [](double L, double U, double, double, double, double) { return U / L; }, "U / L"},
      {S::Prime, K::LinearAcceleration,  [](double L, double U, double, double, double, double) { return U * U / L; }, "U^2 / L"},
      {S::Prime, K::AngularAcceleration, [](double L, double U, double, double, double, double) { return U * U / (L * L); }, "U^2 / L^2"},
      {S::Prime, K::Mass,                [](double L, double, double rho, double, double, double) { return 0.5 * rho * L * L * L; }, "1/2 rho L^3"},
      {S::Prime, K::Inertia,             [](double L, double, double rho, double, double, double) { return 0.5 * rho * std::pow(L, 5); }, "1/2 rho L^5"},
      {S::Prime, K::Length,              [](double L, double, double, double, double, double) { return L; }, "L"},
      {S::Prime, K::Time,                [](double L, double U, double, double, double, double) { return L / U; }, "L / U"},
      {S::Prime, K::Angle,               [](double, double, double, double, double, double) { return 1.0; }, "1"},
      // Bis, Norrbin (1971) via Fossen (2021) appendix D as MSS applies it (supply.m).
      {S::Bis, K::Force,                 [](double, double, double, double, double m, double g) { return m * g; }, "m g"},
      {S::Bis, K::Moment,                [](double L, double, double, double, double m, double g) { return m * g * L; }, "m g L"},
      {S::Bis, K::LinearVelocity,        [](double L, double, double, double, double, double g) { return sqrt(L * g); }, "sqrt(g L)"},
      {S::Bis, K::AngularVelocity,       [](double L, double, double, double, double, double g) { return sqrt(g / L); }, "sqrt(g/L)"},
      {S::Bis, K::LinearAcceleration,    [](double, double, double, double, double, double g) { return g; }, "g"},
      {S::Bis, K::AngularAcceleration,   [](double L, double, double, double, double, double g) { return g / L; }, "g / L"},
      {S::Bis, K::Mass,                  [](double, double, double, double, double m, double) { return m; }, "m"},
      {S::Bis, K::Inertia,               [](double L, double, double, double, double m, double) { return m * L * L; }, "m L^2"},
      {S::Bis, K::Length,                [](double L, double, double, double, double, double) { return L; }, "L"},
      {S::Bis, K::Time,                  [](double L, double, double, double, double, double g) { return sqrt(L / g); }, "sqrt(L/g)"},
      {S::Bis, K::Angle,                 [](double, double, double, double, double, double) { return 1.0; }, "1"},
      // MMG, Yasukawa and Yoshimura (2015): the prime units with L d for the area.
      {S::Mmg, K::Force,                 [](double L, double U, double rho, double d, double, double) { return 0.5 * rho * U * U * L * d; }, "1/2 rho U^2 L d"},
      {S::Mmg, K::Moment,                [](double L, double U, double rho, double d, double, double) { return 0.5 * rho * U * U * L * L * d; }, "1/2 rho U^2 L^2 d"},
      {S::Mmg, K::LinearVelocity,        [](double, double U, double, double, double, double) { return U; }, "U"},
      {S::Mmg, K::AngularVelocity,       [](double L, double U, double, double, double, double) { return U / L; }, "U / L"},
      {S::Mmg, K::LinearAcceleration,    [](double L, double U, double, double, double, double) { return U * U / L; }, "U^2 / L"},
      {S::Mmg, K::AngularAcceleration,   [](double L, double U, double, double, double, double) { return U * U / (L * L); }, "U^2 / L^2"},
      {S::Mmg, K::Mass,                  [](double L, double, double rho, double d, double, double) { return 0.5 * rho * L * L * d; }, "1/2 rho L^2 d"},
      {S::Mmg, K::Inertia,               [](double L, double, double rho, double d, double, double) { return 0.5 * rho * std::pow(L, 4) * d; }, "1/2 rho L^4 d"},
      {S::Mmg, K::Length,                [](double L, double, double, double, double, double) { return L; }, "L"},
      {S::Mmg, K::Time,                  [](double L, double U, double, double, double, double) { return L / U; }, "L / U"},
      {S::Mmg, K::Angle,                 [](double, double, double, double, double, double) { return 1.0; }, "1"},
  };
  // clang-format on
}

TEST(Normalisation, EveryUnitIsTheSourcesFormula) {
  std::mt19937_64 rng(36);
  const std::vector<UnitRow> rows = source_tables();
  ASSERT_EQ(rows.size(), kAllNormalisationSystems.size() * kAllQuantityKinds.size());
  for (int trial = 0; trial < 50; ++trial) {
    const bool from_volume = trial % 2 == 1;
    const NormalisationReference reference = random_reference(rng, from_volume);
    const double m = from_volume ? *reference.density * *reference.displaced_volume : *reference.mass;
    for (const UnitRow& row : rows) {
      SCOPED_TRACE(std::string(to_string(row.system)) + " " + std::string(to_string(row.quantity)));
      const double expected =
          row.unit(*reference.length, *reference.speed, *reference.density, *reference.draft, m, reference.gravity);
      EXPECT_LE(relative_error(to_dimensional(1.0, row.quantity, row.system, reference), expected), 1e-14);
      EXPECT_LE(relative_error(to_nondimensional(expected, row.quantity, row.system, reference), 1.0), 1e-14);
      EXPECT_EQ(scale_text(quantity_scale(row.quantity, row.system)), row.text);
    }
  }
}

// SI dimensions as exponents of kg, m, s (radians are dimensionless here).
using Dimension3 = std::array<int, 3>;

Dimension3 expected_dimension(K quantity) {
  switch (quantity) {
    case K::Force: return {1, 1, -2};
    case K::Moment: return {1, 2, -2};
    case K::LinearVelocity: return {0, 1, -1};
    case K::AngularVelocity: return {0, 0, -1};
    case K::LinearAcceleration: return {0, 1, -2};
    case K::AngularAcceleration: return {0, 0, -2};
    case K::Mass: return {1, 0, 0};
    case K::Inertia: return {1, 2, 0};
    case K::Length: return {0, 1, 0};
    case K::Time: return {0, 0, 1};
    case K::Angle: return {0, 0, 0};
  }
  return {};
}

// Twice the SI dimension of a unit: each reference symbol's dimension times its doubled exponent.
Dimension3 doubled_dimension(const NormalisationScale& scale) {
  // rho, m, U, g, L, d, in the order of ReferenceSymbol.
  constexpr std::array<Dimension3, kReferenceSymbolCount> kSymbolDimensions{
      {{1, -3, 0}, {1, 0, 0}, {0, 1, -1}, {0, 1, -2}, {0, 1, 0}, {0, 1, 0}}};
  Dimension3 sum{};
  for (std::size_t i = 0; i < kReferenceSymbolCount; ++i) {
    for (std::size_t j = 0; j < 3; ++j) sum[j] += scale.doubled_exponents[i] * kSymbolDimensions[i][j];
  }
  return sum;
}

Dimension3 doubled(Dimension3 d) { return {2 * d[0], 2 * d[1], 2 * d[2]}; }

TEST(Normalisation, EveryUnitHasItsQuantitysDimension) {
  for (const S system : kAllNormalisationSystems) {
    for (const K quantity : kAllQuantityKinds) {
      SCOPED_TRACE(std::string(to_string(system)) + " " + std::string(to_string(quantity)));
      EXPECT_EQ(doubled_dimension(quantity_scale(quantity, system)), doubled(expected_dimension(quantity)));
    }
  }
}

TEST(Normalisation, EachSystemUsesOnlyItsReferenceValues) {
  const auto used = [](S system) {
    std::array<bool, kReferenceSymbolCount> any{};
    for (const K quantity : kAllQuantityKinds) {
      const NormalisationScale scale = quantity_scale(quantity, system);
      for (std::size_t i = 0; i < kReferenceSymbolCount; ++i) any[i] = any[i] || scale.doubled_exponents[i] != 0;
    }
    return any;
  };
  // rho, m, U, g, L, d
  EXPECT_EQ(used(S::Prime), (std::array<bool, kReferenceSymbolCount>{true, false, true, false, true, false}));
  EXPECT_EQ(used(S::Bis), (std::array<bool, kReferenceSymbolCount>{false, true, false, true, true, false}));
  EXPECT_EQ(used(S::Mmg), (std::array<bool, kReferenceSymbolCount>{true, false, true, false, true, true}));
  EXPECT_EQ(normalisation_system_needs(S::Prime), "reference length L, reference speed U, water density rho");
  EXPECT_EQ(normalisation_system_needs(S::Mmg), "reference length L, draft d, reference speed U, water density rho");
  EXPECT_NE(normalisation_system_needs(S::Bis).find("the mass m or the displaced volume"), std::string::npos);
}

// A derivative's unit as scales multiplied and divided (the exponents add).
NormalisationScale times(NormalisationScale a, const NormalisationScale& b, int power = 1) {
  a.one_half_power += power * b.one_half_power;
  for (std::size_t i = 0; i < kReferenceSymbolCount; ++i) a.doubled_exponents[i] += power * b.doubled_exponents[i];
  return a;
}

TEST(Normalisation, TheEquationsOfMotionKeepTheirFormInEverySystem) {
  // A system is consistent when the relations between quantities hold for
  // its units, so that m' du'/dt' = X' with no leftover factor.
  for (const S system : kAllNormalisationSystems) {
    SCOPED_TRACE(std::string(to_string(system)));
    const auto unit = [system](K quantity) { return quantity_scale(quantity, system); };
    EXPECT_EQ(unit(K::Force), times(unit(K::Mass), unit(K::LinearAcceleration)));
    EXPECT_EQ(unit(K::Moment), times(unit(K::Inertia), unit(K::AngularAcceleration)));
    EXPECT_EQ(unit(K::Moment), times(unit(K::Force), unit(K::Length)));
    EXPECT_EQ(unit(K::LinearVelocity), times(unit(K::Length), unit(K::Time), -1));
    EXPECT_EQ(unit(K::AngularVelocity), times(unit(K::Angle), unit(K::Time), -1));
    EXPECT_EQ(unit(K::LinearAcceleration), times(unit(K::LinearVelocity), unit(K::Time), -1));
    EXPECT_EQ(unit(K::AngularAcceleration), times(unit(K::AngularVelocity), unit(K::Time), -1));
    EXPECT_EQ(unit(K::Inertia), times(unit(K::Mass), unit(K::Length), 2));
    EXPECT_EQ(unit(K::Angle), NormalisationScale{});
  }
}

// Derivatives of several factor combinations, as the issue names them.
struct NamedKind {
  std::string name;
  DerivativeKind kind;
};

std::vector<NamedKind> derivative_kinds() {
  return {
      {"Y_v", {K::Force, {{K::LinearVelocity, 1}}}},
      {"N_r", {K::Moment, {{K::AngularVelocity, 1}}}},
      {"Y_vr", {K::Force, {{K::LinearVelocity, 1}, {K::AngularVelocity, 1}}}},
      {"N_u|u|", {K::Moment, {{K::LinearVelocity, 2}}}},
      {"Y_vvr", {K::Force, {{K::LinearVelocity, 2}, {K::AngularVelocity, 1}}}},
      {"X_uu delta delta", {K::Force, {{K::LinearVelocity, 2}, {K::Angle, 2}}}},
      {"Y_uv", {K::Force, {{K::LinearVelocity, 1}, {K::LinearVelocity, 1}}}},
      {"K_p|p|", {K::Moment, {{K::AngularVelocity, 2}}}},
      {"Y_vdot", {K::Force, {{K::LinearAcceleration, 1}}}},
      {"Y_rdot", {K::Force, {{K::AngularAcceleration, 1}}}},
      {"N_vdot", {K::Moment, {{K::LinearAcceleration, 1}}}},
      {"N_rdot", {K::Moment, {{K::AngularAcceleration, 1}}}},
      {"Y_0", {K::Force, {}}},
      {"Z_www", {K::Force, {{K::LinearVelocity, 3}}}},
  };
}

TEST(Normalisation, DerivativeUnitsHaveTheirDimension) {
  for (const S system : kAllNormalisationSystems) {
    for (const NamedKind& named : derivative_kinds()) {
      SCOPED_TRACE(std::string(to_string(system)) + " " + named.name);
      Dimension3 expected = expected_dimension(named.kind.output);
      for (const DerivativeFactor& factor : named.kind.factors) {
        const Dimension3 variable = expected_dimension(factor.variable);
        for (std::size_t j = 0; j < 3; ++j) expected[j] -= factor.power * variable[j];
      }
      EXPECT_EQ(doubled_dimension(derivative_scale(named.kind, system)), doubled(expected));
    }
  }
}

TEST(Normalisation, DerivativeUnitsByHand) {
  const auto text = [](const std::string& name, S system) {
    for (const NamedKind& named : derivative_kinds()) {
      if (named.name == name) return scale_text(derivative_scale(named.kind, system));
    }
    ADD_FAILURE() << "no derivative " << name;
    return std::string();
  };
  // Prime, as clarke83.m forms them: damping 1/2 rho L^2 U Tinv^2 (T N' Tinv),
  // added mass 1/2 rho L^3 Tinv^2 (T MA' Tinv), T = diag(1, 1, 1/L).
  EXPECT_EQ(text("Y_v", S::Prime), "1/2 rho U L^2");
  EXPECT_EQ(text("N_r", S::Prime), "1/2 rho U L^4");
  EXPECT_EQ(text("Y_vdot", S::Prime), "1/2 rho L^3");
  EXPECT_EQ(text("Y_rdot", S::Prime), "1/2 rho L^4");
  EXPECT_EQ(text("N_vdot", S::Prime), "1/2 rho L^4");
  EXPECT_EQ(text("N_rdot", S::Prime), "1/2 rho L^5");
  EXPECT_EQ(text("Y_vr", S::Prime), "1/2 rho L^3");
  EXPECT_EQ(text("N_u|u|", S::Prime), "1/2 rho L^3");
  EXPECT_EQ(text("Y_vvr", S::Prime), "1/2 rho L^3 / U");
  EXPECT_EQ(text("X_uu delta delta", S::Prime), "1/2 rho L^2");
  EXPECT_EQ(text("Y_0", S::Prime), "1/2 rho U^2 L^2");
  // Bis, as supply.m forms them: M = m Tinv^2 (T M'' Tinv), D = m sqrt(g/L) Tinv^2 (T D'' Tinv).
  EXPECT_EQ(text("Y_vdot", S::Bis), "m");
  EXPECT_EQ(text("Y_rdot", S::Bis), "m L");
  EXPECT_EQ(text("N_vdot", S::Bis), "m L");
  EXPECT_EQ(text("N_rdot", S::Bis), "m L^2");
  EXPECT_EQ(text("Y_v", S::Bis), "m sqrt(g/L)");
  EXPECT_EQ(text("N_r", S::Bis), "m L sqrt(g L)");        // = m L^2 sqrt(g/L)
  EXPECT_EQ(text("Z_www", S::Bis), "m / (L sqrt(g L))");  // m g / (g L)^(3/2)
  // MMG: X_H = 1/2 rho L d U^2 X_H'(v', r'), so Y_v = 1/2 rho L d U Y_v'.
  EXPECT_EQ(text("Y_v", S::Mmg), "1/2 rho U L d");
  EXPECT_EQ(text("N_r", S::Mmg), "1/2 rho U L^3 d");
  EXPECT_EQ(text("Y_vdot", S::Mmg), "1/2 rho L^2 d");
  EXPECT_EQ(text("N_rdot", S::Mmg), "1/2 rho L^4 d");

  // The added-mass derivatives are masses and inertias in every system.
  for (const S system : kAllNormalisationSystems) {
    EXPECT_EQ(derivative_scale({K::Force, {{K::LinearAcceleration, 1}}}, system), quantity_scale(K::Mass, system));
    EXPECT_EQ(derivative_scale({K::Moment, {{K::AngularAcceleration, 1}}}, system), quantity_scale(K::Inertia, system));
  }

  // Values: Y_vr in prime is 1/2 rho L^3 (U cancels); Y_vvr is 1/2 rho L^3 / U.
  NormalisationReference reference;
  reference.length = 4.5;
  reference.speed = 1.25;
  reference.density = 998.2;
  const double L = 4.5;
  const double U = 1.25;
  const double rho = 998.2;
  EXPECT_LE(relative_error(to_dimensional(0.01, derivative_kinds()[2].kind, S::Prime, reference),
                           0.01 * 0.5 * rho * L * L * L),
            1e-14);
  EXPECT_LE(relative_error(to_dimensional(-0.3, derivative_kinds()[4].kind, S::Prime, reference),
                           -0.3 * 0.5 * rho * L * L * L / U),
            1e-14);
}

// prime -> SI -> bis -> SI -> MMG -> SI -> prime, and the system-to-system calls.
void expect_round_trips(const std::function<double(double, S)>& to_si, const std::function<double(double, S)>& from_si,
                        const std::function<double(double, S, S)>& convert, double value) {
  const double prime_si = to_si(value, S::Prime);
  const double bis = from_si(prime_si, S::Bis);
  const double mmg = from_si(to_si(bis, S::Bis), S::Mmg);
  const double back = from_si(to_si(mmg, S::Mmg), S::Prime);
  EXPECT_LE(relative_error(back, value), 1e-15) << "value " << shortest_number(value);
  for (const S system : kAllNormalisationSystems) {
    EXPECT_LE(relative_error(from_si(to_si(value, system), system), value), 1e-15);
    EXPECT_LE(relative_error(to_si(from_si(prime_si, system), system), prime_si), 1e-15);
  }
  const double chained = convert(convert(convert(value, S::Prime, S::Bis), S::Bis, S::Mmg), S::Mmg, S::Prime);
  EXPECT_LE(relative_error(chained, value), 1e-15);
  EXPECT_LE(relative_error(convert(value, S::Prime, S::Bis), bis), 1e-15);
}

TEST(Normalisation, RoundTripsBetweenTheSystemsTo1e15) {
  std::mt19937_64 rng(3636);
  std::uniform_real_distribution<double> exponent(-8.0, 8.0);
  for (int trial = 0; trial < 200; ++trial) {
    const NormalisationReference reference = random_reference(rng, trial % 2 == 1);
    const double sign = trial % 3 == 0 ? -1.0 : 1.0;
    for (const K quantity : kAllQuantityKinds) {
      SCOPED_TRACE(std::string(to_string(quantity)) + ", trial " + std::to_string(trial));
      expect_round_trips([&](double x, S s) { return to_dimensional(x, quantity, s, reference); },
                         [&](double x, S s) { return to_nondimensional(x, quantity, s, reference); },
                         [&](double x, S a, S b) { return convert_between_systems(x, quantity, a, b, reference); },
                         sign * std::pow(10.0, exponent(rng)));
    }
    for (const NamedKind& named : derivative_kinds()) {
      SCOPED_TRACE(named.name + ", trial " + std::to_string(trial));
      expect_round_trips([&](double x, S s) { return to_dimensional(x, named.kind, s, reference); },
                         [&](double x, S s) { return to_nondimensional(x, named.kind, s, reference); },
                         [&](double x, S a, S b) { return convert_between_systems(x, named.kind, a, b, reference); },
                         sign * std::pow(10.0, exponent(rng)));
    }
  }
}

// The supply vessel's bis matrices (Fossen, Sagatun and Sorensen 1996, "Identification
// of dynamically positioned ships", Control Engineering Practice 4(3):369-376), as
// MSS prints them with the dimensional form it makes of them: github.com/cybergalactic/MSS,
// CRAFT/SHIP/models/supply.m (commit 6bca7942): L = 76.2 m, g = 9.81 m/s^2,
// mass = 6000e3 kg, M = mass Tinv^2 (T Mbis Tinv), D = mass sqrt(g/L) Tinv^2
// (T Dbis Tinv), T = diag(1, 1, 1/L), Tinv = diag(1, 1, L). No second printed form
// of these matrices was found, so the check is against that formula, written here.
TEST(Normalisation, PublishedBisMatricesAgainstTheFormulaTheirSourceUses) {
  constexpr double L = 76.2;
  constexpr double g = 9.81;
  constexpr double mass = 6000e3;
  using Matrix3 = std::array<std::array<double, 3>, 3>;
  using Printed = std::array<std::array<std::string, 3>, 3>;
  const Printed m_printed{{{"1.1274", "0", "0"}, {"0", "1.8902", "-0.0744"}, {"0", "-0.0744", "0.1278"}}};
  const Printed d_printed{{{"0.0358", "0", "0"}, {"0", "0.1183", "-0.0124"}, {"0", "-0.0041", "0.0308"}}};
  const auto parse = [](const Printed& printed) {
    Matrix3 values{};
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) values[i][j] = std::stod(printed[i][j]);
    return values;
  };
  const Matrix3 m_bis = parse(m_printed);
  const Matrix3 d_bis = parse(d_printed);
  const auto product = [](const Matrix3& a, const Matrix3& b) {
    Matrix3 c{};
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
    return c;
  };
  const Matrix3 t{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1 / L}}};
  const Matrix3 t_inv{{{1, 0, 0}, {0, 1, 0}, {0, 0, L}}};
  const Matrix3 t_inv2 = product(t_inv, t_inv);
  const Matrix3 m_source = product(t_inv2, product(t, product(m_bis, t_inv)));
  const Matrix3 d_source = product(t_inv2, product(t, product(d_bis, t_inv)));

  // Surge and sway are forces, yaw a moment; M per acceleration, D per velocity.
  const std::array<K, 3> output{K::Force, K::Force, K::Moment};
  const std::array<K, 3> velocity{K::LinearVelocity, K::LinearVelocity, K::AngularVelocity};
  const std::array<K, 3> acceleration{K::LinearAcceleration, K::LinearAcceleration, K::AngularAcceleration};
  NormalisationReference reference;
  reference.length = L;
  reference.gravity = g;
  reference.mass = mass;
  reference.speed = 2.0;  // for the prime form below; the model is for U < 3 m/s
  reference.density = 1025.0;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      if (m_bis[i][j] == 0.0) continue;
      SCOPED_TRACE("row " + std::to_string(i + 1) + ", column " + std::to_string(j + 1));
      const DerivativeKind added{output[i], {{acceleration[j], 1}}};
      const DerivativeKind damping{output[i], {{velocity[j], 1}}};
      EXPECT_LE(relative_error(to_dimensional(m_bis[i][j], added, S::Bis, reference), mass * m_source[i][j]), 1e-14);
      EXPECT_LE(relative_error(to_dimensional(d_bis[i][j], damping, S::Bis, reference),
                               mass * std::sqrt(g / L) * d_source[i][j]),
                1e-14);
      // bis -> prime -> bis gives the printed digits back.
      const double m_prime = convert_between_systems(m_bis[i][j], added, S::Bis, S::Prime, reference);
      const double d_prime = convert_between_systems(d_bis[i][j], damping, S::Bis, S::Prime, reference);
      EXPECT_EQ(significant(convert_between_systems(m_prime, added, S::Prime, S::Bis, reference),
                            significant_digits(m_printed[i][j])),
                m_printed[i][j]);
      EXPECT_EQ(significant(convert_between_systems(d_prime, damping, S::Prime, S::Bis, reference),
                            significant_digits(d_printed[i][j])),
                d_printed[i][j]);
    }
  }
}

// The MMG standard method's example ship, KVLCC2 at full scale (Yasukawa and
// Yoshimura 2015): L = 320 m, d = 20.8 m, displaced volume 312,600 m^3, hull
// derivatives in MMG form as github.com/nikpau/mmgdynamics transcribes them
// (src/mmgdynamics/calibrated_vessels.py, "kvlcc2_full", commit 032fe0cc).
// Between MMG and prime only the area changes (L d for L^2) in every force,
// moment, mass and inertia unit, so each MMG derivative is its prime value
// times L/d; MMG -> prime -> bis -> MMG gives the printed digits back.
TEST(Normalisation, TheMmgStandardShipsDerivativesThroughTheSystems) {
  constexpr double L = 320.0;
  constexpr double d = 20.8;
  NormalisationReference reference;
  reference.length = L;
  reference.draft = d;
  reference.speed = 7.97;  // 15.5 knots
  reference.density = 1025.0;
  reference.displaced_volume = 312600.0;
  const DerivativeFactor v{K::LinearVelocity, 1};
  const DerivativeFactor r{K::AngularVelocity, 1};
  const auto with_powers = [](K output, int v_power, int r_power) {
    DerivativeKind kind{output, {}};
    if (v_power > 0) kind.factors.push_back({K::LinearVelocity, v_power});
    if (r_power > 0) kind.factors.push_back({K::AngularVelocity, r_power});
    return kind;
  };
  struct Row {
    std::string name;
    std::string printed;
    DerivativeKind kind;
  };
  const std::vector<Row> rows{
      {"X'_vv", "-0.040", with_powers(K::Force, 2, 0)},
      {"X'_vr", "0.002", {K::Force, {v, r}}},
      {"X'_rr", "0.011", with_powers(K::Force, 0, 2)},
      {"X'_vvvv", "0.771", with_powers(K::Force, 4, 0)},
      {"Y'_v", "-0.315", with_powers(K::Force, 1, 0)},
      {"Y'_r", "0.083", with_powers(K::Force, 0, 1)},
      {"Y'_vvv", "-1.607", with_powers(K::Force, 3, 0)},
      {"Y'_vvr", "0.379", with_powers(K::Force, 2, 1)},
      {"Y'_vrr", "-0.391", with_powers(K::Force, 1, 2)},
      {"Y'_rrr", "0.008", with_powers(K::Force, 0, 3)},
      {"N'_v", "-0.137", with_powers(K::Moment, 1, 0)},
      {"N'_r", "-0.049", with_powers(K::Moment, 0, 1)},
      {"N'_vvv", "-0.030", with_powers(K::Moment, 3, 0)},
      {"N'_vvr", "-0.294", with_powers(K::Moment, 2, 1)},
      {"N'_vrr", "0.055", with_powers(K::Moment, 1, 2)},
      {"N'_rrr", "-0.013", with_powers(K::Moment, 0, 3)},
      {"m'_x", "0.022", {K::Mass, {}}},
      {"m'_y", "0.223", {K::Mass, {}}},
      {"J'_z", "0.011", {K::Inertia, {}}},
  };
  for (const Row& row : rows) {
    SCOPED_TRACE(row.name);
    const double mmg = std::stod(row.printed);
    const double prime = convert_between_systems(mmg, row.kind, S::Mmg, S::Prime, reference);
    EXPECT_LE(relative_error(prime, mmg * d / L), 1e-14);
    const double bis = convert_between_systems(prime, row.kind, S::Prime, S::Bis, reference);
    const double back = convert_between_systems(bis, row.kind, S::Bis, S::Mmg, reference);
    EXPECT_LE(relative_error(back, mmg), 1e-15);
    // The table prints a fixed three decimals: "-0.040" is -0.04 to three decimals.
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", back);
    EXPECT_EQ(std::string(text), row.printed);
  }
  // The ship's own mass in MMG form: m' = rho V / (1/2 rho L^2 d) = 2 V / (L^2 d).
  const double ship_mass = 1025.0 * 312600.0;
  EXPECT_LE(relative_error(to_nondimensional(ship_mass, K::Mass, S::Mmg, reference), 2.0 * 312600.0 / (L * L * d)),
            1e-14);
  EXPECT_LE(
      relative_error(convert_between_systems(2.0 * 312600.0 / (L * L * d), K::Mass, S::Mmg, S::Bis, reference), 1.0),
      1e-14);
}

TEST(Normalisation, EveryOutputNamesItsNormalisation) {
  NormalisationReference mariner;  // Mariner, mariner.m
  mariner.length = 160.93;
  mariner.speed = 7.7175;
  mariner.density = 1025.0;
  EXPECT_EQ(normalisation_text(quantity_scale(K::Force, S::Prime), S::Prime, mariner, "X"),
            "prime (SNAME 1950): X' = X / (1/2 rho U^2 L^2), L = 160.93 m, U = 7.7175 m/s, rho = 1025 kg/m^3");
  EXPECT_EQ(normalisation_text(quantity_scale(K::Length, S::Prime), S::Prime, mariner, "x_G"),
            "prime (SNAME 1950): x_G' = x_G / L, L = 160.93 m");
  EXPECT_EQ(normalisation_text(quantity_scale(K::Angle, S::Prime), S::Prime, mariner, "delta"),
            "prime (SNAME 1950): delta' = delta");
  EXPECT_EQ(normalisation_text(derivative_scale(derivative_kinds()[2].kind, S::Prime), S::Prime, mariner, "Y_vr"),
            "prime (SNAME 1950): Y_vr' = Y_vr / (1/2 rho L^3), L = 160.93 m, rho = 1025 kg/m^3");

  NormalisationReference supply;
  supply.length = 76.2;
  supply.mass = 6000e3;
  supply.gravity = 9.81;
  EXPECT_EQ(normalisation_text(derivative_scale({K::Force, {{K::LinearVelocity, 1}}}, S::Bis), S::Bis, supply, "Y_v"),
            "bis (Norrbin 1971): Y_v'' = Y_v / (m sqrt(g/L)), L = 76.2 m, m = 6e+06 kg, g = 9.81 m/s^2");
  supply.mass.reset();
  supply.displaced_volume = 6000.0;
  supply.density = 1025.0;
  EXPECT_EQ(normalisation_text(quantity_scale(K::Moment, S::Bis), S::Bis, supply, "N"),
            "bis (Norrbin 1971): N'' = N / (m g L), L = 76.2 m, rho = 1025 kg/m^3, m = rho * volume = 6150000 kg "
            "(volume = 6000 m^3), g = 9.81 m/s^2");

  NormalisationReference kvlcc2;  // MMG standard method's example ship, Yasukawa and Yoshimura (2015)
  kvlcc2.length = 320.0;
  kvlcc2.draft = 20.8;
  kvlcc2.speed = 7.97;
  kvlcc2.density = 1025.0;
  EXPECT_EQ(normalisation_text(derivative_scale({K::Force, {{K::LinearVelocity, 1}}}, S::Mmg), S::Mmg, kvlcc2, "Y_v"),
            "MMG (Yasukawa and Yoshimura 2015): Y_v' = Y_v / (1/2 rho U L d), L = 320 m, d = 20.8 m, U = 7.97 m/s, "
            "rho = 1025 kg/m^3");
  EXPECT_EQ(normalisation_text(quantity_scale(K::Inertia, S::Mmg), S::Mmg, kvlcc2, "J_z"),
            "MMG (Yasukawa and Yoshimura 2015): J_z' = J_z / (1/2 rho L^4 d), L = 320 m, d = 20.8 m, "
            "rho = 1025 kg/m^3");

  EXPECT_EQ(describe(derivative_kinds()[4].kind), "force / (linear velocity^2 * angular velocity)");
  EXPECT_EQ(describe(derivative_kinds()[12].kind), "force");
  EXPECT_EQ(normalisation_system_title(S::Bis), "bis (Norrbin 1971)");
}

TEST(Normalisation, AMissingReferenceValueIsNamedWithHowToGiveIt) {
  NormalisationReference full;
  full.length = 160.93;
  full.speed = 7.7175;
  full.density = 1025.0;
  full.draft = 7.47;
  full.mass = 1.7e7;

  // Each case: the reference value taken away, the conversion that needs it, and the one line it gives.
  using Conversion = std::function<void(const NormalisationReference&)>;
  const DerivativeKind per_velocity_and_rate{K::Force, {{K::LinearVelocity, 1}, {K::AngularVelocity, 1}}};
  const std::vector<std::tuple<std::optional<double> NormalisationReference::*, Conversion, std::string>> cases = {
      {&NormalisationReference::length, [](const auto& r) { (void)to_dimensional(1.0, K::Force, S::Prime, r); },
       "prime (SNAME 1950): the unit of force, 1/2 rho U^2 L^2, needs the reference length L [m], which is not "
       "given; give the length with the reference data"},
      {&NormalisationReference::speed, [](const auto& r) { (void)to_nondimensional(1.0, K::Moment, S::Mmg, r); },
       "MMG (Yasukawa and Yoshimura 2015): the unit of moment, 1/2 rho U^2 L^2 d, needs the reference speed U "
       "[m/s], which is not given; give the speed with the reference data"},
      {&NormalisationReference::density,
       [&](const auto& r) { (void)to_dimensional(1.0, per_velocity_and_rate, S::Prime, r); },
       "prime (SNAME 1950): the unit of force / (linear velocity * angular velocity), 1/2 rho L^3, needs the "
       "water density rho [kg/m^3], which is not given; give the density with the reference data"},
      {&NormalisationReference::draft, [](const auto& r) { (void)to_dimensional(1.0, K::Mass, S::Mmg, r); },
       "MMG (Yasukawa and Yoshimura 2015): the unit of mass, 1/2 rho L^2 d, needs the draft d [m], which is not "
       "given; give the draft with the reference data"},
      {&NormalisationReference::mass, [](const auto& r) { (void)to_dimensional(1.0, K::Force, S::Bis, r); },
       "bis (Norrbin 1971): the unit of force, m g, needs the mass m [kg] or the displaced volume [m^3] (m = rho "
       "* volume), which is not given; give the mass or the displaced volume and density with the reference "
       "data"}};
  for (const auto& entry : cases) {
    auto without = full;
    (without.*std::get<0>(entry)).reset();
    EXPECT_EQ(input_error_message([&] { std::get<1>(entry)(without); }), std::get<2>(entry));
  }
  auto without_mass = full;
  without_mass.mass.reset();
  auto without_speed = full;
  without_speed.speed.reset();
  auto without_length = full;
  without_length.length.reset();
  auto volume_without_density = without_mass;
  volume_without_density.displaced_volume = 16600.0;
  volume_without_density.density.reset();
  EXPECT_EQ(input_error_message([&] { (void)to_dimensional(1.0, K::Inertia, S::Bis, volume_without_density); }),
            "bis (Norrbin 1971): the unit of moment of inertia, m L^2, needs the water density rho [kg/m^3] for the "
            "mass m = rho * displaced volume, which is not given; give the density with the reference data");
  EXPECT_EQ(input_error_message([&] {
              (void)normalisation_text(quantity_scale(K::Force, S::Prime), S::Prime, without_speed, "X");
            }).rfind("prime (SNAME 1950): the unit of X, 1/2 rho U^2 L^2, needs the reference speed U [m/s]", 0),
            0U);

  // Each system asks only for what the unit uses: prime velocities need no
  // density, bis needs no speed, angles need nothing.
  NormalisationReference speed_only;
  speed_only.speed = 2.0;
  EXPECT_EQ(to_dimensional(0.5, K::LinearVelocity, S::Prime, speed_only), 1.0);
  EXPECT_EQ(to_dimensional(0.25, K::Angle, S::Bis, NormalisationReference{}), 0.25);
  auto bis_without_speed = without_speed;
  EXPECT_EQ(to_dimensional(1.0, K::Force, S::Bis, bis_without_speed), 1.7e7 * 9.80665);
  // Every field each system needs, missing in turn, is refused for the force unit.
  const auto refused = [&full](S system, const std::function<void(NormalisationReference&)>& drop) {
    NormalisationReference reference = full;
    drop(reference);
    return input_error_message([&] { (void)to_dimensional(1.0, K::Force, system, reference); });
  };
  EXPECT_NE(refused(S::Prime, [](auto& r) { r.speed.reset(); }).find("reference speed U"), std::string::npos);
  EXPECT_NE(refused(S::Prime, [](auto& r) { r.density.reset(); }).find("water density rho"), std::string::npos);
  EXPECT_NE(refused(S::Mmg, [](auto& r) { r.length.reset(); }).find("reference length L"), std::string::npos);
  EXPECT_NE(refused(S::Mmg, [](auto& r) { r.density.reset(); }).find("water density rho"), std::string::npos);
  EXPECT_NE(refused(S::Mmg, [](auto& r) { r.draft.reset(); }).find("draft d"), std::string::npos);
  // Bis force m g needs no length, the bis moment does.
  EXPECT_NE(input_error_message([&] {
              (void)to_dimensional(1.0, K::Moment, S::Bis, without_length);
            }).find("reference length L [m]"),
            std::string::npos);
}

TEST(Normalisation, AValueThatIsNotFinitePositiveIsRefusedNamingTheField) {
  NormalisationReference full;
  full.length = 160.93;
  full.speed = 7.7175;
  full.density = 1025.0;
  full.draft = 7.47;
  full.mass = 1.7e7;
  full.displaced_volume = 16600.0;
  struct Field {
    std::function<void(NormalisationReference&, double)> set;
    std::string message_start;
  };
  const std::vector<Field> fields{
      {[](auto& r, double x) { r.length = x; }, "the reference length L must be a finite positive number of m"},
      {[](auto& r, double x) { r.speed = x; }, "the reference speed U must be a finite positive number of m/s"},
      {[](auto& r, double x) { r.density = x; }, "the water density rho must be a finite positive number of kg/m^3"},
      {[](auto& r, double x) { r.draft = x; }, "the draft d must be a finite positive number of m"},
      {[](auto& r, double x) { r.mass = x; }, "the mass m must be a finite positive number of kg"},
      {[](auto& r, double x) { r.displaced_volume = x; },
       "the displaced volume must be a finite positive number of m^3"},
      {[](auto& r, double x) { r.gravity = x; },
       "the acceleration of gravity g must be a finite positive number of m/s^2"},
  };
  const double bad_values[] = {0.0, -1.5, std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::quiet_NaN()};
  for (const Field& field : fields) {
    for (const double bad : bad_values) {
      NormalisationReference reference = full;
      field.set(reference, bad);
      // Refused even by a conversion that does not use the field (an angle).
      for (const S system : kAllNormalisationSystems) {
        EXPECT_EQ(input_error_message([&] { (void)to_nondimensional(1.0, K::Angle, system, reference); }),
                  "normalisation reference: " + field.message_start + ", found " + shortest_number(bad));
      }
    }
  }
  EXPECT_EQ(input_error_message([&] {
              auto reference = full;
              reference.speed = -3.0;
              (void)to_dimensional(1.0, K::Force, S::Prime, reference);
            }),
            "normalisation reference: the reference speed U must be a finite positive number of m/s, found -3");
}

TEST(Normalisation, BadDerivativesAndSystemNamesAreRefused) {
  NormalisationReference reference;
  reference.length = 10.0;
  reference.speed = 1.0;
  reference.density = 1000.0;
  EXPECT_EQ(input_error_message([&] {
              (void)to_dimensional(1.0, DerivativeKind{K::Force, {{K::LinearVelocity, 0}}}, S::Prime, reference);
            }),
            "derivative force / linear velocity^0: the power of linear velocity must be 1 to 16 (|x| counts as x), "
            "found 0");
  EXPECT_EQ(input_error_message([&] {
              (void)derivative_scale(DerivativeKind{K::Moment, {{K::AngularVelocity, 17}}}, S::Bis);
            }),
            "derivative moment / angular velocity^17: the power of angular velocity must be 1 to 16 (|x| counts as "
            "x), found 17");
  EXPECT_EQ(parse_normalisation_system("prime"), S::Prime);
  EXPECT_EQ(parse_normalisation_system("Bis"), S::Bis);
  EXPECT_EQ(parse_normalisation_system("MMG"), S::Mmg);
  for (const S system : kAllNormalisationSystems) EXPECT_EQ(parse_normalisation_system(to_string(system)), system);
  EXPECT_EQ(input_error_message([] { (void)parse_normalisation_system("sname"); }),
            "unknown normalisation system 'sname': expected prime, bis or mmg");
}

}  // namespace
}  // namespace hydrocoef
