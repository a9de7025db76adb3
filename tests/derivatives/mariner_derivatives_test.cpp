// A published derivative set through the non-dimensional systems
// (src/derivatives/normalisation.hpp): the Mariner class vessel of Chislett
// and Strom-Tejsen (1965), "Planar motion mechanism tests and full-scale
// steering and manoeuvring predictions for a Mariner class vessel",
// Technical Report Hy-5, Hydro- and Aerodynamics Laboratory, Lyngby.
//
// Where the numbers come from: the MSS toolbox's Mariner model,
// github.com/cybergalactic/MSS, CRAFT/SHIP/models/mariner.m (commit
// 6bca7942a7f8bc6180cbc031b1e602a05e35b5a7; the same table is in the older
// VESSELS/mariner.m, commit 05bddf1b), which cites that report: prime
// derivatives times 1e-5, m' = 798e-5, I_z' = 39.2e-5, x_G' = -0.023,
// L = 160.93 m, U0 = 7.7175 m/s (15 knots). mariner.m normalises with the
// instantaneous speed U = sqrt((U0 + u)^2 + v^2): u' = u/U, v' = v/U,
// r' = r L/U, and turns its prime forces into accelerations with U^2/L
// (linear) and U^2/L^2 (angular).
//
// No second printed form of this set (dimensional or bis) was found (MSS,
// Fossen's model files and the ports of mariner.m searched print it in prime
// form only). So the checks are: prime -> SI -> bis -> prime gives the printed
// digits back; the SI values are those of the formula MSS uses to
// redimensionalise prime derivatives (clarke83.m, Fossen 2021 appendix D); and
// mariner.m's own state derivative, written here from its lines, equals the
// one the SI derivatives give through Newton's law.
// Water density: mariner.m never needs it (it cancels in every acceleration);
// 1025 kg/m^3 is used, as MSS's clarke83.m does.
#include "src/derivatives/normalisation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

using K = QuantityKind;
using S = NormalisationSystem;

constexpr double kLength = 160.93;     // L [m]
constexpr double kSpeed = 7.7175;      // U0 [m/s], 15 knots
constexpr double kDensity = 1025.0;    // rho [kg/m^3], see the file comment
constexpr double kMassPrime = 798e-5;  // m'

// One term of mariner.m: its name, its printed value (times 1e-5), and the
// powers of u, v, r and delta it multiplies in X, Y or N. The added masses
// and the rigid-body values have their own kinds below.
struct Term {
  const char* name;
  const char* printed;        // as mariner.m prints it, times 1e-5
  K output;                   // Force (X, Y) or Moment (N)
  std::array<int, 4> powers;  // u, v, r, delta
};

// clang-format off
const std::vector<Term> kTerms{
    {"Xu", "-184", K::Force, {1, 0, 0, 0}},    {"Xuu", "-110", K::Force, {2, 0, 0, 0}},
    {"Xuuu", "-215", K::Force, {3, 0, 0, 0}},  {"Xvv", "-899", K::Force, {0, 2, 0, 0}},
    {"Xrr", "18", K::Force, {0, 0, 2, 0}},     {"Xrv", "798", K::Force, {0, 1, 1, 0}},
    {"Xdd", "-95", K::Force, {0, 0, 0, 2}},    {"Xudd", "-190", K::Force, {1, 0, 0, 2}},
    {"Xvd", "93", K::Force, {0, 1, 0, 1}},     {"Xuvd", "93", K::Force, {1, 1, 0, 1}},
    {"Yv", "-1160", K::Force, {0, 1, 0, 0}},   {"Yr", "-499", K::Force, {0, 0, 1, 0}},
    {"Yvvv", "-8078", K::Force, {0, 3, 0, 0}}, {"Yvvr", "15356", K::Force, {0, 2, 1, 0}},
    {"Yvu", "-1160", K::Force, {1, 1, 0, 0}},  {"Yru", "-499", K::Force, {1, 0, 1, 0}},
    {"Yd", "278", K::Force, {0, 0, 0, 1}},     {"Yddd", "-90", K::Force, {0, 0, 0, 3}},
    {"Yud", "556", K::Force, {1, 0, 0, 1}},    {"Yuud", "278", K::Force, {2, 0, 0, 1}},
    {"Yvdd", "-4", K::Force, {0, 1, 0, 2}},    {"Yvvd", "1190", K::Force, {0, 2, 0, 1}},
    {"Y0", "-4", K::Force, {0, 0, 0, 0}},      {"Y0u", "-8", K::Force, {1, 0, 0, 0}},
    {"Y0uu", "-4", K::Force, {2, 0, 0, 0}},
    {"Nv", "-264", K::Moment, {0, 1, 0, 0}},   {"Nr", "-166", K::Moment, {0, 0, 1, 0}},
    {"Nvvv", "1636", K::Moment, {0, 3, 0, 0}}, {"Nvvr", "-5483", K::Moment, {0, 2, 1, 0}},
    {"Nvu", "-264", K::Moment, {1, 1, 0, 0}},  {"Nru", "-166", K::Moment, {1, 0, 1, 0}},
    {"Nd", "-139", K::Moment, {0, 0, 0, 1}},   {"Nddd", "45", K::Moment, {0, 0, 0, 3}},
    {"Nud", "-278", K::Moment, {1, 0, 0, 1}},  {"Nuud", "-139", K::Moment, {2, 0, 0, 1}},
    {"Nvdd", "13", K::Moment, {0, 1, 0, 2}},   {"Nvvd", "-489", K::Moment, {0, 2, 0, 1}},
    {"N0", "3", K::Moment, {0, 0, 0, 0}},      {"N0u", "6", K::Moment, {1, 0, 0, 0}},
    {"N0uu", "3", K::Moment, {2, 0, 0, 0}},
};
// clang-format on

// What a term's derivative is the coefficient of: X, Y or N per u^a v^b r^c delta^d.
DerivativeKind kind_of(const Term& term) {
  constexpr std::array<K, 4> kVariables{K::LinearVelocity, K::LinearVelocity, K::AngularVelocity, K::Angle};
  DerivativeKind kind{term.output, {}};
  for (std::size_t i = 0; i < 4; ++i) {
    if (term.powers[i] > 0) kind.factors.push_back({kVariables[i], term.powers[i]});
  }
  return kind;
}

// The added masses of mariner.m: force or moment per linear or angular acceleration.
struct AddedMass {
  const char* name;
  const char* printed;  // times 1e-5
  DerivativeKind kind;
};
const std::vector<AddedMass> kAddedMasses{
    {"Xudot", "-42", {K::Force, {{K::LinearAcceleration, 1}}}},
    {"Yvdot", "-748", {K::Force, {{K::LinearAcceleration, 1}}}},
    {"Yrdot", "-9.354", {K::Force, {{K::AngularAcceleration, 1}}}},
    {"Nvdot", "4.646", {K::Moment, {{K::LinearAcceleration, 1}}}},
    {"Nrdot", "-43.8", {K::Moment, {{K::AngularAcceleration, 1}}}},
};

double value_of(const char* printed) { return std::stod(std::string(printed) + "e-5"); }

// How many significant digits a printed number shows: "-9.354" 4, "-1160" 4, "-0.023" 2.
int significant_digits(const std::string& printed) {
  std::string digits;
  for (const char c : printed)
    if (c >= '0' && c <= '9') digits += c;
  const std::size_t first = digits.find_first_not_of('0');
  return first == std::string::npos ? 1 : static_cast<int>(digits.size() - first);
}

NormalisationReference mariner_reference(double speed) {
  NormalisationReference reference;
  reference.length = kLength;
  reference.speed = speed;
  reference.density = kDensity;
  // The bis mass unit is the ship's own mass, m' redimensionalised.
  reference.mass = kMassPrime * 0.5 * kDensity * kLength * kLength * kLength;
  return reference;
}

double relative_error(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

// prime -> SI -> bis -> SI -> prime, compared with the printed digits.
void expect_printed_digits_back(double prime, const std::string& printed, double printed_scale,
                                const std::function<double(double, S)>& to_si,
                                const std::function<double(double, S)>& from_si) {
  const double bis = from_si(to_si(prime, S::Prime), S::Bis);
  const double back = from_si(to_si(bis, S::Bis), S::Prime);
  EXPECT_LE(relative_error(back, prime), 1e-15);
  EXPECT_EQ(significant(back / printed_scale, significant_digits(printed)), printed);
}

TEST(MarinerDerivatives, PrimeToBisAndBackGivesThePrintedDigits) {
  const NormalisationReference reference = mariner_reference(kSpeed);
  for (const Term& term : kTerms) {
    SCOPED_TRACE(term.name);
    const DerivativeKind kind = kind_of(term);
    expect_printed_digits_back(
        value_of(term.printed), term.printed, 1e-5,
        [&](double x, S s) { return to_dimensional(x, kind, s, reference); },
        [&](double x, S s) { return to_nondimensional(x, kind, s, reference); });
  }
  for (const AddedMass& added : kAddedMasses) {
    SCOPED_TRACE(added.name);
    expect_printed_digits_back(
        value_of(added.printed), added.printed, 1e-5,
        [&](double x, S s) { return to_dimensional(x, added.kind, s, reference); },
        [&](double x, S s) { return to_nondimensional(x, added.kind, s, reference); });
  }
  const auto quantity = [&reference](K kind) {
    return std::pair{[&reference, kind](double x, S s) { return to_dimensional(x, kind, s, reference); },
                     [&reference, kind](double x, S s) { return to_nondimensional(x, kind, s, reference); }};
  };
  const auto [mass_to_si, mass_from_si] = quantity(K::Mass);
  expect_printed_digits_back(798e-5, "798", 1e-5, mass_to_si, mass_from_si);
  const auto [inertia_to_si, inertia_from_si] = quantity(K::Inertia);
  expect_printed_digits_back(39.2e-5, "39.2", 1e-5, inertia_to_si, inertia_from_si);
  const auto [length_to_si, length_from_si] = quantity(K::Length);
  expect_printed_digits_back(-0.023, "-0.023", 1.0, length_to_si, length_from_si);

  // In bis the ship's mass is 1, I_z'' = I_z / (m L^2) = 39.2/798 (the radius
  // of gyration squared over L^2) and x_G'' = x_G' (both are over L).
  EXPECT_LE(relative_error(convert_between_systems(798e-5, K::Mass, S::Prime, S::Bis, reference), 1.0), 1e-14);
  EXPECT_LE(relative_error(convert_between_systems(39.2e-5, K::Inertia, S::Prime, S::Bis, reference), 39.2 / 798.0),
            1e-14);
  EXPECT_LE(relative_error(convert_between_systems(-0.023, K::Length, S::Prime, S::Bis, reference), -0.023), 1e-15);
  // Y_v'' = Y_v' (1/2 rho U L^2) / (m sqrt(g/L)) = Y_v' U / (m' sqrt(g L)), by hand.
  const double yv_bis = value_of("-1160") * kSpeed / (kMassPrime * std::sqrt(9.80665 * kLength));
  EXPECT_LE(relative_error(convert_between_systems(value_of("-1160"), kind_of(kTerms[10]), S::Prime, S::Bis, reference),
                           yv_bis),
            1e-14);
}

TEST(MarinerDerivatives, SiValuesAreThoseOfTheFormulaMssRedimensionalisesWith) {
  // clarke83.m: MA = (1/2 rho L^3) Tinv^2 (T MA' Tinv), N = (1/2 rho L^2 U) Tinv^2 (T N' Tinv),
  // T = diag(1, 1, 1/L), Tinv = diag(1, 1, L), on the sway-yaw block [Y; N] per [v; r] or [vdot; rdot].
  const NormalisationReference reference = mariner_reference(kSpeed);
  const double L = kLength;
  const double added_unit = 0.5 * kDensity * L * L * L;
  const double damping_unit = 0.5 * kDensity * L * L * kSpeed;
  // (row, column) of the 2x2 sway-yaw block: entry scale Tinv^2 T .. Tinv = t_i t_j with t = (1, L).
  const auto t = [L](int index) { return index == 0 ? 1.0 : L; };
  struct Entry {
    const char* printed;
    DerivativeKind kind;
    int row;
    int column;
    double unit;
  };
  const std::vector<Entry> entries{
      {"-748", {K::Force, {{K::LinearAcceleration, 1}}}, 0, 0, added_unit},
      {"-9.354", {K::Force, {{K::AngularAcceleration, 1}}}, 0, 1, added_unit},
      {"4.646", {K::Moment, {{K::LinearAcceleration, 1}}}, 1, 0, added_unit},
      {"-43.8", {K::Moment, {{K::AngularAcceleration, 1}}}, 1, 1, added_unit},
      {"-1160", {K::Force, {{K::LinearVelocity, 1}}}, 0, 0, damping_unit},
      {"-499", {K::Force, {{K::AngularVelocity, 1}}}, 0, 1, damping_unit},
      {"-264", {K::Moment, {{K::LinearVelocity, 1}}}, 1, 0, damping_unit},
      {"-166", {K::Moment, {{K::AngularVelocity, 1}}}, 1, 1, damping_unit},
  };
  for (const Entry& entry : entries) {
    SCOPED_TRACE(std::string(entry.printed) + "e-5");
    const double prime = value_of(entry.printed);
    const double expected = entry.unit * t(entry.row) * t(entry.row) * (1.0 / t(entry.row)) * prime * t(entry.column);
    EXPECT_LE(relative_error(to_dimensional(prime, entry.kind, S::Prime, reference), expected), 1e-14);
  }
}

TEST(MarinerDerivatives, SiDerivativesGiveMarinerMsOwnAccelerations) {
  // A state of mariner.m: perturbed surge, sway and yaw rate, and 4 deg rudder.
  constexpr double u = 0.6;                             // m/s, about U0
  constexpr double v = -0.4;                            // m/s
  constexpr double r = 0.003;                           // rad/s
  const double delta = 4.0 * std::numbers::pi / 180.0;  // rad
  const double U = std::sqrt((kSpeed + u) * (kSpeed + u) + v * v);
  const double L = kLength;

  // mariner.m's lines, in prime: states over U, forces as sums of terms, the
  // mass matrix, and the accelerations it returns.
  const std::array<double, 4> prime_state{u / U, v / U, r * L / U, delta};
  const auto prime_sum = [&prime_state](K output, char force) {
    double sum = 0.0;
    for (const Term& term : kTerms) {
      if (term.output != output || term.name[0] != force) continue;
      double monomial = value_of(term.printed);
      for (std::size_t i = 0; i < 4; ++i) monomial *= std::pow(prime_state[i], term.powers[i]);
      sum += monomial;
    }
    return sum;
  };
  const double Xp = prime_sum(K::Force, 'X');
  const double Yp = prime_sum(K::Force, 'Y');
  const double Np = prime_sum(K::Moment, 'N');
  const double m = 798e-5;
  const double Iz = 39.2e-5;
  const double xG = -0.023;
  const double m11 = m - value_of("-42");
  const double m22 = m - value_of("-748");
  const double m23 = m * xG - value_of("-9.354");
  const double m32 = m * xG - value_of("4.646");
  const double m33 = Iz - value_of("-43.8");
  const double det = m22 * m33 - m23 * m32;
  const double udot_source = Xp * (U * U / L) / m11;
  const double vdot_source = -(-m33 * Yp + m23 * Np) * (U * U / L) / det;
  const double rdot_source = (-m32 * Yp + m22 * Np) * (U * U / (L * L)) / det;

  // The same in SI: each derivative made dimensional (with the instantaneous
  // U, as mariner.m normalises with it), forces from the SI state, masses
  // from m', I_z', x_G' and the added masses, and Newton's law.
  const NormalisationReference reference = mariner_reference(U);
  const std::array<double, 4> state{u, v, r, delta};
  const auto si_sum = [&](K output, char force) {
    double sum = 0.0;
    for (const Term& term : kTerms) {
      if (term.output != output || term.name[0] != force) continue;
      double monomial = to_dimensional(value_of(term.printed), kind_of(term), S::Prime, reference);
      for (std::size_t i = 0; i < 4; ++i) monomial *= std::pow(state[i], term.powers[i]);
      sum += monomial;
    }
    return sum;
  };
  const auto added = [&](const char* name) {
    for (const AddedMass& a : kAddedMasses) {
      if (std::string(a.name) == name) return to_dimensional(value_of(a.printed), a.kind, S::Prime, reference);
    }
    ADD_FAILURE() << "no added mass " << name;
    return 0.0;
  };
  const double mass = to_dimensional(m, K::Mass, S::Prime, reference);
  const double inertia = to_dimensional(Iz, K::Inertia, S::Prime, reference);
  const double x_g = to_dimensional(xG, K::Length, S::Prime, reference);
  const double M11 = mass - added("Xudot");
  const double M22 = mass - added("Yvdot");
  const double M23 = mass * x_g - added("Yrdot");
  const double M32 = mass * x_g - added("Nvdot");
  const double M33 = inertia - added("Nrdot");
  const double X = si_sum(K::Force, 'X');
  const double Y = si_sum(K::Force, 'Y');
  const double N = si_sum(K::Moment, 'N');
  const double determinant = M22 * M33 - M23 * M32;
  EXPECT_LE(relative_error(X / M11, udot_source), 1e-13);
  EXPECT_LE(relative_error((M33 * Y - M23 * N) / determinant, vdot_source), 1e-13);
  EXPECT_LE(relative_error((M22 * N - M32 * Y) / determinant, rdot_source), 1e-13);
  // The accelerations are not trivially small (the check would be empty otherwise).
  EXPECT_GT(std::abs(udot_source), 1e-3);
  EXPECT_GT(std::abs(vdot_source), 1e-3);
  EXPECT_GT(std::abs(rdot_source), 1e-6);

  // And one force to the digits mariner.m's formula gives: Y = Y' (1/2 rho U^2 L^2).
  EXPECT_LE(relative_error(Y, Yp * 0.5 * kDensity * U * U * L * L), 1e-13);
  EXPECT_LE(relative_error(N, Np * 0.5 * kDensity * U * U * L * L * L), 1e-13);
}

TEST(MarinerDerivatives, TheNormalisationIsNamed) {
  const NormalisationReference reference = mariner_reference(kSpeed);
  EXPECT_EQ(normalisation_text(derivative_scale(kind_of(kTerms[13]), S::Prime), S::Prime, reference, "Y_vvr"),
            "prime (SNAME 1950): Y_vvr' = Y_vvr / (1/2 rho L^3 / U), L = 160.93 m, U = 7.7175 m/s, rho = 1025 kg/m^3");
}

}  // namespace
}  // namespace hydrocoef
