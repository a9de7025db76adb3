// Forced-oscillation analysis with known answers: the potential-flow sphere
// (force -rho V/2 x'' exactly), a linear law on every degree of freedom
// after a start-up transient, uneven time steps, the coverage of the stated
// uncertainty under noise, and quadratic damping from three amplitudes.
#include "src/pmm/harmonic_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>
#include <random>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

constexpr double kPi = std::numbers::pi;

struct History {
  std::vector<double> t;
  std::array<std::vector<double>, 6> f;
  std::array<std::span<const double>, 6> spans() const {
    std::array<std::span<const double>, 6> out;
    for (std::size_t c = 0; c < 6; ++c) out[c] = f[c];
    return out;
  }
};

template <typename F>
History sample(double duration, double dt, const F& force_of_time, std::size_t component) {
  History h;
  for (double t = 0.0; t <= duration + 1e-12; t += dt) {
    h.t.push_back(t);
    h.f[component].push_back(force_of_time(t));
  }
  return h;
}

TEST(HarmonicAnalysis, PotentialFlowSphereGivesHalfTheDisplacedMass) {
  const double rho = 998.2, R = 0.15, V = 4.0 / 3.0 * kPi * R * R * R;
  const HarmonicMotion motion{0, 0.03, 2.0 * kPi / 2.0, 0.3};
  const History h = sample(
      20.0, 0.002, [&](double t) { return -0.5 * rho * V * motion.acceleration(t); }, 0);
  const auto result = analyse_forced_oscillation(h.t, h.spans(), motion);
  const auto& x = result.components[0];
  EXPECT_NEAR(x.added_mass, 0.5 * rho * V, 1e-9 * 0.5 * rho * V);  // 7.056 kg
  EXPECT_NEAR(0.5 * rho * V, 7.056, 0.001);
  EXPECT_NEAR(x.damping, 0.0, 1e-9);
  EXPECT_NEAR(x.explained, 1.0, 1e-12);
  EXPECT_NEAR(x.mean, 0.0, 1e-9);
  EXPECT_FALSE(result.components[1].present);
}

TEST(HarmonicAnalysis, EveryDegreeOfFreedomAfterAStartUpTransient) {
  for (std::size_t dof = 0; dof < 6; ++dof) {
    const double A = dof < 3 ? 0.05 : 0.2, omega = 2.0 * kPi / 1.6;
    const HarmonicMotion motion{dof, A, omega, 0.0};
    const double m = 3.0 + static_cast<double>(dof), b = 0.7 + 0.1 * static_cast<double>(dof), mean = -0.4;
    History h;
    for (double t = 0.0; t <= 64.0; t += 0.002) {
      h.t.push_back(t);
      // The transient: a decaying offset and a decaying oscillation at another frequency.
      const double transient = 2.0 * std::exp(-t / 1.5) + std::exp(-t / 2.0) * std::sin(5.3 * t);
      for (std::size_t c = 0; c < 6; ++c) {
        const double scale = c == dof ? 1.0 : 0.1 * static_cast<double>(c + 1);  // couplings too
        h.f[c].push_back(scale * (mean - m * motion.acceleration(t) - b * motion.velocity(t)) + transient);
      }
    }
    const auto result = analyse_forced_oscillation(h.t, h.spans(), motion);
    EXPECT_GT(result.transient_periods, 0u) << dof;
    for (std::size_t c = 0; c < 6; ++c) {
      const double scale = c == dof ? 1.0 : 0.1 * static_cast<double>(c + 1);
      EXPECT_NEAR(result.components[c].added_mass, scale * m, 1e-6 * scale * m) << dof << " " << c;
      EXPECT_NEAR(result.components[c].damping, scale * b, 1e-6 * scale * b) << dof << " " << c;
      EXPECT_NEAR(result.components[c].mean, scale * mean, 1e-6) << dof << " " << c;
    }
  }
}

TEST(HarmonicAnalysis, UnevenTimeStepsAreWeightedByTheTimeTheyStandFor) {
  const HarmonicMotion motion{1, 0.04, 2.0 * kPi / 1.2, 1.0};
  std::mt19937 random(3);
  std::uniform_real_distribution<double> step(0.0005, 0.0025);
  History h;
  for (double t = 0.0; t <= 30.0; t += step(random)) {
    h.t.push_back(t);
    h.f[1].push_back(-5.0 * motion.acceleration(t) - 2.0 * motion.velocity(t));
  }
  const auto result = analyse_forced_oscillation(h.t, h.spans(), motion, {.harmonics = 1, .start_time = 0.0});
  EXPECT_EQ(result.transient_periods, 0u);
  EXPECT_NEAR(result.components[1].added_mass, 5.0, 1e-5 * 5.0);
  EXPECT_NEAR(result.components[1].damping, 2.0, 1e-5 * 2.0);
}

TEST(HarmonicAnalysis, StatedUncertaintyCoversTheTruthUnderNoise) {
  const HarmonicMotion motion{0, 0.05, 2.0 * kPi / 2.0, 0.0};
  const double m = 7.0, b = 1.5;
  int covered_m = 0, covered_b = 0;
  const int cases = 200;
  for (int seed = 0; seed < cases; ++seed) {
    std::mt19937 random(static_cast<unsigned>(1000 + seed));
    std::normal_distribution<double> noise(0.0, 0.05);
    History h;
    for (double t = 0.0; t <= 60.0; t += 0.01) {
      h.t.push_back(t);
      h.f[0].push_back(-m * motion.acceleration(t) - b * motion.velocity(t) + 0.5 * std::exp(-t) + noise(random));
    }
    const auto result = analyse_forced_oscillation(h.t, h.spans(), motion);
    const auto& x = result.components[0];
    if (std::abs(x.added_mass - m) <= 1.96 * x.added_mass_se) ++covered_m;
    if (std::abs(x.damping - b) <= 1.96 * x.damping_se) ++covered_b;
  }
  std::cout << "coverage of the 95 % intervals: added mass " << covered_m << "/200, damping " << covered_b << "/200\n";
  EXPECT_GE(covered_m, 180) << covered_m;
  EXPECT_LE(covered_m, 196) << covered_m;
  EXPECT_GE(covered_b, 180) << covered_b;
  EXPECT_LE(covered_b, 196) << covered_b;
}

TEST(HarmonicAnalysis, QuadraticDampingFromThreeAmplitudes) {
  const double m = 4.0, b = 0.8, c = 12.0, omega = 2.0 * kPi / 1.5;
  std::vector<double> amplitudes{0.02, 0.05, 0.1}, equivalent;
  for (const double A : amplitudes) {
    const HarmonicMotion motion{0, A, omega, 0.0};
    const History h = sample(
        30.0, 0.0005,
        [&](double t) {
          const double v = motion.velocity(t);
          return -m * motion.acceleration(t) - b * v - c * v * std::abs(v);
        },
        0);
    const auto result = analyse_forced_oscillation(h.t, h.spans(), motion, {.harmonics = 3, .start_time = 0.0});
    EXPECT_NEAR(result.components[0].added_mass, m, 1e-6 * m);
    // The third harmonic of x'|x'| is there and fitted.
    EXPECT_GT(std::abs(result.components[0].quadrature[2]), 1e-3);
    EXPECT_NEAR(result.components[0].explained, 1.0, 1e-3);
    equivalent.push_back(result.components[0].damping);
  }
  const auto fit = fit_quadratic_damping(amplitudes, omega, equivalent);
  EXPECT_NEAR(fit.linear, b, 1e-6);
  EXPECT_NEAR(fit.quadratic, c, 1e-6 * c);
}

TEST(HarmonicAnalysis, RefusesWhatCannotBeAnalysed) {
  const HarmonicMotion motion{0, 0.05, 2.0 * kPi, 0.0};
  const History short_history = sample(
      2.5, 0.01, [](double) { return 1.0; }, 0);
  try {
    analyse_forced_oscillation(short_history.t, short_history.spans(), motion);
    FAIL() << "accepted 2 periods";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected at least 3"), std::string::npos) << e.what();
  }
  History h = sample(
      10.0, 0.01, [](double) { return 1.0; }, 0);
  h.t[5] = h.t[4];
  EXPECT_THROW(analyse_forced_oscillation(h.t, h.spans(), motion), InputError);
  EXPECT_THROW(analyse_forced_oscillation(h.t, h.spans(), HarmonicMotion{0, 0.0, 1.0, 0.0}), InputError);
  EXPECT_THROW(fit_quadratic_damping(std::vector<double>{0.1}, 1.0, std::vector<double>{1.0}), InputError);
  EXPECT_NEAR(keulegan_carpenter(0.03, 0.3), 2.0 * kPi * 0.1, 1e-15);
  EXPECT_NEAR(stokes_number(0.3, 2.0, 1e-6), 45000.0, 1e-6);
}

TEST(HarmonicAnalysis, PeriodsShorterThanAFewStepsAreRefusedBeforeTheyAreCounted) {
  // 10 s at 0.01 s: omega 1e20 (or a period of 1e-20 s) gave 10^20 periods,
  // converted to a count before any check (SIGSEGV); 1e-18 s and 1e-9 s
  // asked for vectors of 10^18 and 10^10 periods.
  const History h = sample(
      10.0, 0.01, [](double t) { return std::sin(3.0 * t); }, 0);
  EXPECT_EQ(kMinStepsPerPeriod, 4.0);
  for (const double omega : {1e20, 2.0 * kPi / 1e-20, 2.0 * kPi / 1e-18, 2.0 * kPi / 1e-9, 2.0 * kPi / 0.039}) {
    try {
      (void)analyse_forced_oscillation(h.t, h.spans(), HarmonicMotion{0, 0.05, omega, 0.0});
      ADD_FAILURE() << "accepted omega " << omega;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is shorter than 4 sampling steps"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("expected a period of at least 0.04 s"), std::string::npos) << e.what();
    }
  }
  // Four steps are enough to be counted (and many periods are still read).
  const auto result = analyse_forced_oscillation(h.t, h.spans(), HarmonicMotion{0, 0.05, 2.0 * kPi / 0.04, 0.0});
  EXPECT_GE(result.periods + result.transient_periods, 240u);
}

TEST(HarmonicAnalysis, WholePeriodsAreCountedFromTheWindowStartWhateverThePhase) {
  // 3.2 periods of a motion of phase pi (a reversed axis): counted from the
  // motion's phase crossing 2 pi k they were 2 and refused; from the first
  // sample they are 3, and the fit is the one of phase 0 with the force
  // reversed (the same window, the basis negated).
  const double m = 7.0, b = 0.6, omega = 2.0 * kPi / 2.0;
  const HarmonicMotion reversed{0, 0.03, omega, kPi}, forward{0, 0.03, omega, 0.0};
  const auto force = [&](const HarmonicMotion& motion) {
    return sample(
        6.4, 0.01, [&](double t) { return -m * motion.acceleration(t) - b * motion.velocity(t) + 0.2; }, 0);
  };
  const History h_reversed = force(reversed), h_forward = force(forward);
  const auto r = analyse_forced_oscillation(h_reversed.t, h_reversed.spans(), reversed, {.start_time = 0.0});
  const auto f = analyse_forced_oscillation(h_forward.t, h_forward.spans(), forward, {.start_time = 0.0});
  EXPECT_EQ(r.periods, 3u);
  EXPECT_EQ(r.window_start, 0.0);
  EXPECT_EQ(r.window_start, f.window_start);
  EXPECT_EQ(r.window_end, f.window_end);
  EXPECT_NEAR(r.components[0].added_mass, m, 1e-9 * m);
  EXPECT_NEAR(r.components[0].added_mass, f.components[0].added_mass, 1e-12 * m);
  EXPECT_NEAR(r.components[0].damping, f.components[0].damping, 1e-12 * b);
  // A history too short says where the periods were counted from, and --start.
  const History short_history = sample(
      5.0, 0.01, [](double t) { return std::sin(t); }, 0);
  for (const std::optional<double> start : {std::optional<double>{}, std::optional<double>{0.5}}) {
    try {
      (void)analyse_forced_oscillation(short_history.t, short_history.spans(), reversed, {.start_time = start});
      ADD_FAILURE() << "accepted 2 periods";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("2 whole period(s) of 2 s counted from"), std::string::npos) << what;
      EXPECT_NE(what.find(start ? "--start 0.5 s" : "first sample at 0 s"), std::string::npos) << what;
      EXPECT_NE(what.find("--start"), std::string::npos) << what;
    }
  }
}

TEST(HarmonicAnalysis, AmplitudesAndPeriodsThatGiveNoMeaningfulNumbersAreRefused) {
  const History h = sample(
      20.0, 0.01, [](double t) { return std::sin(kPi * t); }, 0);
  // 5e-324 m: A w and A w^2 round to 0 (M_A was infinite); 1e308 m: A w^2 is
  // infinite (M_A was 0, "100 % explained").
  for (const double amplitude : {5e-324, 1e-320, 1e308}) {
    try {
      (void)analyse_forced_oscillation(h.t, h.spans(), HarmonicMotion{0, amplitude, kPi, 0.0});
      ADD_FAILURE() << "accepted amplitude " << amplitude;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("expected both finite and well above zero"), std::string::npos) << e.what();
    }
  }
  // A period of one or two sampling steps puts every sample at one phase:
  // the sampled sine is zero and M_A meaningless (it was -2.6e8 kg).
  for (const double period : {0.01, 0.02}) {
    try {
      const auto result = analyse_forced_oscillation(h.t, h.spans(), HarmonicMotion{0, 0.05, 2.0 * kPi / period, 0.0});
      ADD_FAILURE() << "accepted period " << period << ": M_A " << result.components[0].added_mass;
    } catch (const InputError&) {}
  }
  // Ten harmonics of a period of 8 steps are not resolved; one is.
  const HarmonicMotion coarse{0, 0.05, 2.0 * kPi / 0.08, 0.0};
  try {
    (void)analyse_forced_oscillation(h.t, h.spans(), coarse, {.harmonics = 10});
    ADD_FAILURE() << "accepted 10 harmonics of 8 samples";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("do not resolve 10 harmonics"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("fewer --harmonics"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW((void)analyse_forced_oscillation(h.t, h.spans(), coarse));
}

}  // namespace
}  // namespace hydrocoef
