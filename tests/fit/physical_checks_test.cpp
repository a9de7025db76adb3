// Physical checks of damping laws: the exact energy test on each side of
// zero against a brute-force scan, the force at rest, and runs stored with
// the wrong sign convention.
#include "src/fit/physical_checks.hpp"

#include <gtest/gtest.h>

#include <random>

namespace hydrocoef {
namespace {

LawCheckInput law(const std::string& terms, std::vector<double> coefficients, double lo, double hi,
                  SignConvention sign = SignConvention::OnBody) {
  LawCheckInput input;
  input.spec = parse_damping_terms(terms);
  input.coefficients = std::move(coefficients);
  input.sign = sign;
  input.x_min = lo;
  input.x_max = hi;
  return input;
}

bool has(const std::vector<LawCheck>& checks, LawProblem problem) {
  for (const auto& c : checks)
    if (c.problem == problem) return true;
  return false;
}

TEST(PhysicalChecks, DampingLawsPass) {
  // The ASR-V surge law on the body: X = -0.0155 u - 11.0365 u|u|.
  EXPECT_TRUE(check_damping_law(law("u,u|u|", {-0.0155, -11.0365}, -0.4, 0.4)).empty());
  // The same table as damping magnitudes (opposing convention).
  EXPECT_TRUE(check_damping_law(law("u,u|u|", {0.0155, 11.0365}, -0.4, 0.4, SignConvention::OpposingMotion)).empty());
  EXPECT_TRUE(check_damping_law(law("u^3", {-2.0}, -1, 1)).empty());
}

TEST(PhysicalChecks, APositiveLinearTermUnderAQuadraticOneProducesEnergyNearZero) {
  // Y = +3.406 v - 40 v|v|: F·v > 0 for |v| < 0.085.
  const auto checks = check_damping_law(law("v,v|v|", {3.406, -40.0}, -0.1, 0.1));
  ASSERT_TRUE(has(checks, LawProblem::EnergyProducing));
  EXPECT_NE(checks.front().message.find("feeds energy"), std::string::npos) << checks.front().message;
  // The same law fitted only where the quadratic term dominates is physical there.
  EXPECT_FALSE(has(check_damping_law(law("v,v|v|", {3.406, -40.0}, 0.09, 0.2)), LawProblem::EnergyProducing));
}

TEST(PhysicalChecks, EvenTermsProduceEnergyOnOneSide) {
  // X = -u^2 opposes motion for u > 0 but pushes for u < 0.
  EXPECT_FALSE(has(check_damping_law(law("u^2", {-1.0}, 0.0, 1.0)), LawProblem::EnergyProducing));
  EXPECT_TRUE(has(check_damping_law(law("u^2", {-1.0}, -1.0, 1.0)), LawProblem::EnergyProducing));
  // -|u| pushes along the motion for u < 0: (-|u|) u > 0 there.
  EXPECT_TRUE(has(check_damping_law(law("|u|", {-1.0}, -1.0, 0.0)), LawProblem::EnergyProducing));
}

TEST(PhysicalChecks, ExactTestAgreesWithABruteForceScan) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coefficient(-2.0, 2.0), end(-1.0, 1.0);
  const std::vector<DampingTerm> all = {DampingTerm::Linear, DampingTerm::SignedQuadratic, DampingTerm::Quadratic,
                                        DampingTerm::Cubic, DampingTerm::AbsLinear};
  for (int trial = 0; trial < 2000; ++trial) {
    LawCheckInput input;
    input.spec.variable = "u";
    input.spec.terms = all;
    for (std::size_t k = 0; k < all.size(); ++k) input.coefficients.push_back(coefficient(random));
    double a = end(random), b = end(random);
    input.x_min = std::min(a, b), input.x_max = std::max(a, b);
    double worst = -INFINITY;
    for (int i = 0; i <= 20000; ++i) {
      const double x = input.x_min + (input.x_max - input.x_min) * i / 20000.0;
      double force = 0.0;
      for (std::size_t k = 0; k < all.size(); ++k) force += input.coefficients[k] * basis_value(all[k], x);
      worst = std::max(worst, force * x);
    }
    const bool flagged = has(check_damping_law(input), LawProblem::EnergyProducing);
    // Away from the boundary case the two must agree; the scan misses maxima
    // narrower than its step, so only "scan says positive" is binding.
    if (worst > 1e-6) {
      EXPECT_TRUE(flagged) << "trial " << trial << " worst " << worst;
    }
    if (flagged) {
      EXPECT_GT(worst, -1e-9) << "trial " << trial;
    }
  }
}

TEST(PhysicalChecks, ConstantLargerThanItsErrorIsAForceAtRest) {
  auto input = law("1,u,u|u|", {0.02, -0.0155, -11.0}, -0.4, 0.4);
  input.std_errors = {0.005, 0.001, 0.1};
  EXPECT_TRUE(has(check_damping_law(input), LawProblem::ForceAtRest));
  input.std_errors = {0.05, 0.001, 0.1};
  EXPECT_FALSE(has(check_damping_law(input), LawProblem::ForceAtRest));
  input.std_errors = {NAN, NAN, NAN};  // unknown: no claim
  EXPECT_FALSE(has(check_damping_law(input), LawProblem::ForceAtRest));
}

TEST(PhysicalChecks, RunsStoredWithTheOtherSignAreNamed) {
  // Damping magnitudes (positive along the motion) stored as on-body forces.
  const std::vector<double> x = {0.1, 0.2, 0.3}, y = {0.11, 0.44, 0.99};
  auto input = law("u|u|", {11.0}, 0.1, 0.3);
  input.x = x;
  input.y = y;
  EXPECT_TRUE(has(check_damping_law(input), LawProblem::SignContradictsRuns));
  input.sign = SignConvention::OpposingMotion;
  EXPECT_TRUE(check_damping_law(input).empty());
}

}  // namespace
}  // namespace hydrocoef
