// Assembling M_A from stored forced-oscillation records: runs of one entry
// combined by their weighted mean, symmetric by construction (both halves
// averaged, or one standing for both), missing entries named, same/zero for
// DOFs no run moves, the positive-definite check, and other bodies ignored.
#include "src/pmm/added_mass_assembly.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

PmmRecord record(const std::string& body, std::size_t dof, double omega, double amplitude,
                 const std::vector<std::pair<std::size_t, double>>& added_mass, double se = 0.0) {
  PmmRecord r;
  r.body = body;
  r.dof = dof;
  r.omega = omega;
  r.amplitude = amplitude;
  for (const auto& [component, value] : added_mass) {
    PmmCoefficient c;
    c.component = component;
    c.added_mass = value;
    c.added_mass_se = se;
    c.damping = 0.1 * value;
    r.coefficients.push_back(c);
  }
  return r;
}

TEST(AddedMassAssembly, WeightedMeanSymmetryAndMissingEntries) {
  const std::vector<PmmRecord> records = {
      record("hull", 0, 2.0, 0.01, {{0, 10.0}, {1, 1.0}}, 0.1),
      record("hull", 0, 2.0, 0.02, {{0, 12.0}, {1, 1.0}}, 0.2),  // weight 1/4 of the first
      record("hull", 1, 2.0, 0.01, {{0, 1.6}, {1, 20.0}}, 0.1),
      record("other", 2, 2.0, 0.01, {{2, 99.0}}),
  };
  const AddedMassAssembly a = assemble_added_mass("hull", records);
  EXPECT_EQ(a.records, 3u);
  EXPECT_EQ(a.omega, 2.0);
  EXPECT_NEAR(a.added_mass(0, 0), (10.0 / 0.01 + 12.0 / 0.04) / (1.0 / 0.01 + 1.0 / 0.04), 1e-12);
  // 10 +- 0.1 and 12 +- 0.2 disagree (chi^2 = 80 for one degree of freedom):
  // the standard error of the mean grows by the Birge ratio sqrt(80).
  EXPECT_NEAR(a.added_mass_se(0, 0), std::sqrt(80.0 / (1.0 / 0.01 + 1.0 / 0.04)), 1e-12);
  EXPECT_EQ(a.measured[0][0].runs, 2u);
  EXPECT_EQ(a.measured[0][0].omega_min, 2.0);
  EXPECT_EQ(a.measured[0][0].omega_max, 2.0);
  // Both halves measured: their mean on both sides, and a note when they differ.
  EXPECT_NEAR(a.added_mass(0, 1), 0.5 * (1.0 + 1.6), 1e-12);
  EXPECT_EQ(a.added_mass(0, 1), a.added_mass(1, 0));
  EXPECT_EQ(a.added_mass(2, 2), 0.0);  // other bodies are not mixed in
  bool noted = false;
  for (const auto& n : a.notes) noted = noted || n.find("standard errors") != std::string::npos;
  EXPECT_TRUE(noted);
  EXPECT_TRUE(a.positive_definite);
  // heave..yaw are missing, each named once (upper triangle).
  EXPECT_EQ(a.missing.size(), 6u + 5u + 4u + 3u);
  EXPECT_EQ(a.missing.front().rfind("M_A[surge][heave]", 0), 0u) << a.missing.front();
}

TEST(AddedMassAssembly, SameZeroAndPositiveDefiniteness) {
  const std::vector<PmmRecord> records = {record("ball", 0, 2.0, 0.01, {{0, 7.0}})};
  AddedMassOptions options;
  options.same = {{1, 0}, {2, 0}};
  options.zero = {3, 4, 5};
  const AddedMassAssembly a = assemble_added_mass("ball", records, options);
  EXPECT_TRUE(a.missing.empty());
  EXPECT_EQ(a.added_mass(1, 1), 7.0);
  EXPECT_EQ(a.added_mass(2, 2), 7.0);
  EXPECT_TRUE(a.positive_definite);
  EXPECT_NEAR(a.smallest_eigenvalue, 7.0, 1e-12);
  // An indefinite matrix is reported as such.
  const AddedMassAssembly bad = assemble_added_mass(
      "ball", {record("ball", 0, 2.0, 0.01, {{0, 1.0}, {1, 5.0}}), record("ball", 1, 2.0, 0.01, {{0, 5.0}, {1, 1.0}})});
  EXPECT_FALSE(bad.positive_definite);
  EXPECT_NEAR(bad.smallest_eigenvalue, -4.0, 1e-12);
  test::expect_input_error([&] { assemble_added_mass("nobody", records); }, {"nobody", "no stored"});
  AddedMassOptions wrong;
  wrong.zero = {0};
  test::expect_input_error([&] { assemble_added_mass("ball", records, wrong); }, {"zero surge", "measure"});
}

TEST(AddedMassAssembly, RunsAtDifferentFrequenciesAreNeverCombined) {
  // Surge at omega 2 (two amplitudes) and at omega 3 (2 pi / 3 s): the
  // matrix is one frequency's; each frequency's in-line entries are listed.
  std::vector<PmmRecord> records = {
      record("hull", 0, 2.0, 0.01, {{0, 10.0}}, 0.1),
      record("hull", 0, 2.0, 0.02, {{0, 10.0}}, 0.1),
      record("hull", 0, 3.0, 0.01, {{0, 14.0}}, 0.1),
  };
  records[2].coefficients[0].damping = 5.0;  // the damping of the other frequency
  test::expect_input_error([&] { assemble_added_mass("hull", records); },
                           {"2 periods", "3.14159", "(2 runs)", "2.0943", "(1 run)", "--period"});
  AddedMassOptions at_three;
  at_three.period = 2.0 * std::numbers::pi / 3.0;
  const AddedMassAssembly a = assemble_added_mass("hull", records, at_three);
  EXPECT_EQ(a.omega, 3.0);
  EXPECT_EQ(a.records, 1u);
  EXPECT_EQ(a.other_frequency_records, 2u);
  EXPECT_EQ(a.added_mass(0, 0), 14.0);
  EXPECT_EQ(a.damping(0, 0), 5.0);
  ASSERT_EQ(a.by_frequency.size(), 2u);
  EXPECT_EQ(a.by_frequency[0].omega, 2.0);
  EXPECT_EQ(a.by_frequency[0].runs, 2u);
  EXPECT_EQ(a.by_frequency[0].damping, 1.0);
  EXPECT_EQ(a.by_frequency[0].amplitude_min, 0.01);
  EXPECT_EQ(a.by_frequency[0].amplitude_max, 0.02);
  EXPECT_EQ(a.by_frequency[1].omega, 3.0);
  EXPECT_EQ(a.by_frequency[1].damping, 5.0);
  // Two amplitudes at omega 2 give the quadratic damping there, whatever the period chosen.
  ASSERT_EQ(a.quadratic.size(), 1u);
  EXPECT_EQ(a.quadratic[0].omega, 2.0);
  AddedMassOptions nowhere;
  nowhere.period = 1.0;
  test::expect_input_error([&] { assemble_added_mass("hull", records, nowhere); }, {"period 1 s", "no run"});
  EXPECT_EQ(pmm_frequencies("hull", records), (std::vector<double>{2.0, 3.0}));
}

}  // namespace
}  // namespace hydrocoef
