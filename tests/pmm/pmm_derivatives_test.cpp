// Sway and yaw derivatives from pure sway and pure yaw runs
// (src/pmm/pmm_derivatives.hpp), with known answers: force histories made
// from a published derivative set go through the harmonic analysis and come
// back; a motion phase wrong by pi/2 turns them as the first harmonic says;
// runs of several amplitudes and frequencies are grouped and combined; runs
// that are not sway or yaw are refused, naming them.
//
// The set: the Mariner class vessel (Chislett and Strom-Tejsen 1965,
// Technical Report Hy-5, Hydro- and Aerodynamics Laboratory, Lyngby), prime
// values times 1e-5 as printed in the MSS toolbox's
// CRAFT/SHIP/models/mariner.m (github.com/cybergalactic/MSS, commit
// 6bca7942; tests/derivatives/mariner_derivatives_test.cpp checks them
// through the systems): Y_v -1160, Y_vdot -748, N_v -264, N_vdot 4.646,
// Y_r -499, Y_rdot -9.354, N_r -166, N_rdot -43.8; L = 160.93 m,
// U = 7.7175 m/s, rho = 1025 kg/m^3.
#include "src/pmm/pmm_derivatives.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/derivatives/normalisation.hpp"
#include "src/pmm/added_mass_assembly.hpp"
#include "src/pmm/harmonic_analysis.hpp"

namespace hydrocoef {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kLength = 160.93, kSpeed = 7.7175, kDensity = 1025.0;

// Prime values times 1e5, in the order Y velocity, Y acceleration, N velocity, N acceleration.
constexpr std::array<double, 4> kSwayPrime{-1160.0, -748.0, -264.0, 4.646};
constexpr std::array<double, 4> kYawPrime{-499.0, -9.354, -166.0, -43.8};

NormalisationReference mariner() {
  NormalisationReference reference;
  reference.length = kLength;
  reference.speed = kSpeed;
  reference.density = kDensity;
  return reference;
}

/// The Mariner's derivatives of a test in SI.
std::array<double, 4> dimensional(std::size_t dof) {
  const auto& prime = dof == kPmmSway ? kSwayPrime : kYawPrime;
  std::array<double, 4> out{};
  for (std::size_t k = 0; k < 4; ++k)
    out[k] = to_dimensional(prime[k] * 1e-5, pmm_derivative_kind(dof, k), NormalisationSystem::Prime, mariner());
  return out;
}

double relative_error(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

/// A run's record as src/pipeline/pmm_runs stores it: the analysis of the
/// Y and N histories made from `d` (SI, in the order above) under the motion
/// `truth`, analysed as `stated` (the motion the record says).
PmmRecord run(std::int64_t id, const HarmonicMotion& truth, const HarmonicMotion& stated,
              const std::array<double, 4>& d, double u = kSpeed) {
  std::vector<double> t;
  std::array<std::vector<double>, 6> f;
  const double period = 2.0 * kPi / truth.omega, dt = period / 200.0;
  for (int n = 0; n <= 200 * 12; ++n) {
    const double time = dt * n;
    t.push_back(time);
    const double x1 = truth.velocity(time), x2 = truth.acceleration(time);  // v, vdot (or r, rdot)
    f[1].push_back(25.0 + d[0] * x1 + d[1] * x2);
    f[5].push_back(-40.0 + d[2] * x1 + d[3] * x2);
  }
  std::array<std::span<const double>, 6> spans;
  spans[1] = f[1];
  spans[5] = f[5];
  const HarmonicAnalysis analysis = analyse_forced_oscillation(t, spans, stated);
  PmmRecord record;
  record.id = id;
  record.body = "mariner";
  record.nu_b = {u, 0.0, 0.0, 0.0, 0.0, 0.0};
  record.dof = stated.dof;
  record.amplitude = stated.amplitude;
  record.omega = stated.omega;
  record.phase = stated.phase;
  record.source_path = "run" + std::to_string(id) + ".csv";
  for (const std::size_t c : {std::size_t{1}, std::size_t{5}}) {
    const HarmonicComponent& fit = analysis.components[c];
    PmmCoefficient coefficient;
    coefficient.component = c;
    coefficient.mean = fit.mean;
    coefficient.added_mass = fit.added_mass;
    coefficient.added_mass_se = fit.added_mass_se;
    coefficient.damping = fit.damping;
    coefficient.damping_se = fit.damping_se;
    record.coefficients.push_back(coefficient);
  }
  return record;
}

HarmonicMotion motion(std::size_t dof, double amplitude, double omega_prime, double phase = 0.0) {
  return HarmonicMotion{dof, amplitude, omega_prime * kSpeed / kLength, phase};
}

TEST(PmmDerivatives, NamesUnitsAndSources) {
  EXPECT_EQ(pmm_derivative_name(kPmmSway, 0), "Y_v");
  EXPECT_EQ(pmm_derivative_name(kPmmSway, 1), "Y_vdot");
  EXPECT_EQ(pmm_derivative_name(kPmmSway, 3), "N_vdot");
  EXPECT_EQ(pmm_derivative_name(kPmmYaw, 2), "N_r");
  EXPECT_EQ(pmm_derivative_name(kPmmYaw, 3), "N_rdot");
  EXPECT_EQ(pmm_derivative_unit(kPmmSway, 0), "N s/m");
  EXPECT_EQ(pmm_derivative_unit(kPmmSway, 1), "kg");
  EXPECT_EQ(pmm_derivative_unit(kPmmSway, 3), "kg m");
  EXPECT_EQ(pmm_derivative_unit(kPmmYaw, 1), "kg m");
  EXPECT_EQ(pmm_derivative_unit(kPmmYaw, 2), "N m s");
  EXPECT_EQ(pmm_derivative_unit(kPmmYaw, 3), "kg m^2");
  EXPECT_EQ(pmm_derivative_source(kPmmSway, 1), "-M_A[sway][sway]");
  EXPECT_EQ(pmm_derivative_source(kPmmSway, 2), "-D[yaw][sway]");
  EXPECT_EQ(pmm_derivative_source(kPmmYaw, 1), "-M_A[sway][yaw]");
  // The prime scales are the classical ones: Y_vdot / (1/2 rho L^3), N_rdot / (1/2 rho L^5), Y_v / (1/2 rho U L^2).
  EXPECT_EQ(scale_text(derivative_scale(pmm_derivative_kind(kPmmSway, 1), NormalisationSystem::Prime)), "1/2 rho L^3");
  EXPECT_EQ(scale_text(derivative_scale(pmm_derivative_kind(kPmmYaw, 3), NormalisationSystem::Prime)), "1/2 rho L^5");
  EXPECT_EQ(scale_text(derivative_scale(pmm_derivative_kind(kPmmSway, 0), NormalisationSystem::Prime)),
            "1/2 rho U L^2");
}

TEST(PmmDerivatives, MarinerSwayAndYawComeBackThroughTheHarmonicAnalysis) {
  for (const std::size_t dof : {kPmmSway, kPmmYaw}) {
    const std::array<double, 4> truth = dimensional(dof);
    // 0.05 L of sway, 0.1 rad of yaw, omega' = 1.5, a phase that is not zero.
    const HarmonicMotion m = motion(dof, dof == kPmmSway ? 0.05 * kLength : 0.1, 1.5, 0.4);
    const PmmRunDerivatives d = pmm_run_derivatives(run(7, m, m, truth));
    EXPECT_EQ(d.id, 7);
    EXPECT_EQ(d.dof, dof);
    EXPECT_DOUBLE_EQ(d.speed, kSpeed);
    for (std::size_t k = 0; k < 4; ++k) {
      EXPECT_LE(relative_error(d.derivatives[k].value, truth[k]), 1e-9) << pmm_derivative_name(dof, k);
      // Noise-free periodic histories: the period-to-period spread is round-off.
      EXPECT_LE(d.derivatives[k].std_error, 1e-9 * std::abs(truth[k])) << pmm_derivative_name(dof, k);
      // And back to the printed prime value.
      const double prime =
          to_nondimensional(d.derivatives[k].value, pmm_derivative_kind(dof, k), NormalisationSystem::Prime, mariner());
      const auto& printed = dof == kPmmSway ? kSwayPrime : kYawPrime;
      EXPECT_LE(relative_error(prime, printed[k] * 1e-5), 1e-9) << pmm_derivative_name(dof, k);
    }
  }
}

TEST(PmmDerivatives, AMotionPhaseWrongByAQuarterPeriodTurnsThemAsTheFirstHarmonicSays) {
  // The run moved as y_a sin(omega t + pi/2) but is analysed as y_a sin(omega t):
  // F = -Y_v y_a omega sin - Y_vdot y_a omega^2 cos, read as Y_v' v' + Y_vdot' vdot'
  // with v' = y_a omega cos, vdot' = -y_a omega^2 sin: Y_v' = -omega Y_vdot, Y_vdot' = Y_v / omega.
  for (const std::size_t dof : {kPmmSway, kPmmYaw}) {
    const std::array<double, 4> truth = dimensional(dof);
    const HarmonicMotion stated = motion(dof, dof == kPmmSway ? 3.0 : 0.1, 2.0, 0.0);
    HarmonicMotion moved = stated;
    moved.phase = kPi / 2.0;
    const PmmRunDerivatives d = pmm_run_derivatives(run(1, moved, stated, truth));
    const double w = stated.omega;
    for (const std::size_t k : {std::size_t{0}, std::size_t{2}}) {
      EXPECT_LE(relative_error(d.derivatives[k].value, -w * truth[k + 1]), 1e-9) << pmm_derivative_name(dof, k);
      EXPECT_LE(relative_error(d.derivatives[k + 1].value, truth[k] / w), 1e-9) << pmm_derivative_name(dof, k + 1);
    }
    // And a phase wrong by pi changes every sign.
    moved.phase = kPi;
    const PmmRunDerivatives flipped = pmm_run_derivatives(run(2, moved, stated, truth));
    for (std::size_t k = 0; k < 4; ++k)
      EXPECT_LE(relative_error(flipped.derivatives[k].value, -truth[k]), 1e-9) << pmm_derivative_name(dof, k);
  }
}

TEST(PmmDerivatives, RunsAreGroupedByMotionSpeedAndFrequencyAndCombined) {
  const std::array<double, 4> sway = dimensional(kPmmSway), yaw = dimensional(kPmmYaw);
  // Frequency dependence: the second frequency's runs carry other derivatives.
  std::array<double, 4> sway_fast = sway;
  for (double& x : sway_fast) x *= 1.1;
  std::vector<PmmRecord> records = {
      run(1, motion(kPmmYaw, 0.1, 1.0), motion(kPmmYaw, 0.1, 1.0), yaw),
      run(2, motion(kPmmSway, 4.0, 2.0), motion(kPmmSway, 4.0, 2.0), sway_fast),
      run(3, motion(kPmmSway, 4.0, 1.0), motion(kPmmSway, 4.0, 1.0), sway),
      run(4, motion(kPmmSway, 8.0, 1.0), motion(kPmmSway, 8.0, 1.0), sway),
      run(5, motion(kPmmSway, 8.0, 1.0), motion(kPmmSway, 8.0, 1.0), sway, 2.0 * kSpeed),
  };
  PmmRecord surge = records[0];
  surge.id = 6;
  surge.dof = 0;
  records.push_back(surge);
  PmmRecord other_body = records[2];
  other_body.id = 8;
  other_body.body = "another";
  records.push_back(other_body);

  const PmmDerivativeSet set = pmm_derivative_set("mariner", records);
  EXPECT_EQ(set.runs.size(), 5u);
  EXPECT_EQ(set.other_runs, 1u);  // the surge run
  ASSERT_EQ(set.groups.size(), 4u);
  // Sway first, by speed then frequency: (U, omega'=1) runs 3 and 4; (U, 2) run 2; (2U, 1) run 5; yaw run 1.
  EXPECT_EQ(set.groups[0].record_ids, (std::vector<std::int64_t>{3, 4}));
  EXPECT_DOUBLE_EQ(set.groups[0].amplitude_min, 4.0);
  EXPECT_DOUBLE_EQ(set.groups[0].amplitude_max, 8.0);
  EXPECT_EQ(set.groups[1].record_ids, (std::vector<std::int64_t>{2}));
  EXPECT_EQ(set.groups[2].record_ids, (std::vector<std::int64_t>{5}));
  EXPECT_DOUBLE_EQ(set.groups[2].speed, 2.0 * kSpeed);
  EXPECT_EQ(set.groups[3].dof, kPmmYaw);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_LE(relative_error(set.groups[0].derivatives[k].value, sway[k]), 1e-9);
    EXPECT_LE(relative_error(set.groups[1].derivatives[k].value, sway_fast[k]), 1e-9);
    EXPECT_LE(relative_error(set.groups[3].derivatives[k].value, yaw[k]), 1e-9);
    // The group is the weighted mean the added-mass matrix takes, negated.
    const auto [mean, se] =
        combine_pmm_estimates({set.runs[2].derivatives[k].value, set.runs[3].derivatives[k].value},
                              {set.runs[2].derivatives[k].std_error, set.runs[3].derivatives[k].std_error});
    EXPECT_EQ(set.groups[0].derivatives[k].value, mean);
    EXPECT_EQ(set.groups[0].derivatives[k].std_error, se);
  }
  // A speed given for every run puts runs 3, 4 and 5 in one group.
  const PmmDerivativeSet at_speed = pmm_derivative_set("mariner", records, {}, 3.0);
  ASSERT_EQ(at_speed.groups.size(), 3u);
  EXPECT_EQ(at_speed.groups[0].record_ids, (std::vector<std::int64_t>{3, 4, 5}));
  EXPECT_DOUBLE_EQ(at_speed.groups[0].speed, 3.0);
  // Chosen runs only.
  const PmmDerivativeSet chosen = pmm_derivative_set("mariner", records, {4, 1});
  EXPECT_EQ(chosen.runs.size(), 2u);
  EXPECT_EQ(chosen.groups.size(), 2u);
}

std::string message_of(const auto& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(PmmDerivatives, RunsThatAreNotSwayOrYawAreRefusedNamingThem) {
  const std::array<double, 4> sway = dimensional(kPmmSway);
  PmmRecord surge = run(3, motion(kPmmSway, 4.0, 1.0), motion(kPmmSway, 4.0, 1.0), sway);
  surge.dof = 0;
  surge.source_path = "surge-A4.csv";
  std::string m = message_of([&] { (void)pmm_run_derivatives(surge); });
  EXPECT_NE(m.find("pmm run 3 (surge-A4.csv)"), std::string::npos) << m;
  EXPECT_NE(m.find("moves surge; expected a sway"), std::string::npos) << m;
  // A body with only surge runs: named with what they move.
  m = message_of([&] { (void)pmm_derivative_set("mariner", {surge}); });
  EXPECT_NE(m.find("body 'mariner' has no sway or yaw forced-oscillation runs (it has 1 surge)"), std::string::npos)
      << m;
  // Chosen by id: refused naming the run.
  const PmmRecord ok = run(4, motion(kPmmSway, 4.0, 1.0), motion(kPmmSway, 4.0, 1.0), sway);
  m = message_of([&] { (void)pmm_derivative_set("mariner", {ok, surge}, {3}); });
  EXPECT_NE(m.find("pmm run 3 (surge-A4.csv) of body 'mariner' moves surge"), std::string::npos) << m;
  m = message_of([&] { (void)pmm_derivative_set("mariner", {ok}, {9}); });
  EXPECT_NE(m.find("pmm run 9: not a stored forced-oscillation run of body 'mariner'"), std::string::npos) << m;
  m = message_of([&] { (void)pmm_derivative_set("nobody", {ok}); });
  EXPECT_NE(m.find("body 'nobody' has no stored forced-oscillation runs"), std::string::npos) << m;
  // A sway run without N.
  PmmRecord no_n = ok;
  no_n.coefficients.pop_back();
  m = message_of([&] { (void)pmm_run_derivatives(no_n); });
  EXPECT_NE(m.find("pmm run 4 (run4.csv): its history has no N"), std::string::npos) << m;
  m = message_of([&] { (void)pmm_derivative_set("mariner", {ok}, {}, std::nan("")); });
  EXPECT_NE(m.find("expected a finite forward speed"), std::string::npos) << m;
}

}  // namespace
}  // namespace hydrocoef
