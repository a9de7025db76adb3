// Weighted fits whose runs state uncertainties ten times too small
// (src/fit/damping_law: the covariance scaled by the Birge ratio squared):
// over 400 seeded sweeps of 60 runs the stated 95 % intervals of both coefficients cover
// the true ones at the nominal rate (92-98 %), where the unscaled covariance
// covered them about a fifth of the time; with the uncertainties stated right
// the covariance is not scaled down and still covers them at about 95 %.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "src/fit/damping_law.hpp"

namespace hydrocoef {
namespace {

struct Coverage {
  double a = 0.0, b = 0.0;  ///< fraction of sweeps whose interval covers the truth
  double mean_scale = 0.0;  ///< mean covariance scale
};

Coverage coverage(double stated_over_true, int sweeps) {
  const double a_true = 0.0155, b_true = 11.04, noise = 0.01;
  std::mt19937_64 random(20261127);
  std::normal_distribution<double> normal(0.0, 1.0);
  Coverage out;
  int covered_a = 0, covered_b = 0;
  for (int s = 0; s < sweeps; ++s) {
    std::vector<double> x, y, sigma;
    for (int i = 0; i < 60; ++i) {
      const double u = -0.3 + 0.6 * i / 59.0;
      x.push_back(u);
      y.push_back(a_true * u + b_true * u * std::abs(u) + noise * normal(random));
      sigma.push_back(noise * stated_over_true);
    }
    const DampingLawFit fit = fit_damping_law(parse_damping_terms("u,u|u|"), x, y, {}, sigma);
    EXPECT_TRUE(fit.weighted);
    covered_a += std::abs(fit.coefficients[0] - a_true) <= 1.96 * fit.std_errors[0];
    covered_b += std::abs(fit.coefficients[1] - b_true) <= 1.96 * fit.std_errors[1];
    out.mean_scale += fit.covariance_scale / sweeps;
    EXPECT_NEAR(fit.covariance[0], fit.std_errors[0] * fit.std_errors[0], 1e-12 * fit.covariance[0]);
  }
  out.a = static_cast<double>(covered_a) / sweeps;
  out.b = static_cast<double>(covered_b) / sweeps;
  return out;
}

TEST(WeightedFitCoverage, UnderstatedUncertaintiesAreScaledByTheBirgeRatio) {
  const Coverage c = coverage(0.1, 400);
  EXPECT_GE(c.a, 0.92);
  EXPECT_LE(c.a, 0.98);
  EXPECT_GE(c.b, 0.92);
  EXPECT_LE(c.b, 0.98);
  EXPECT_NEAR(c.mean_scale, 100.0, 10.0);  // chi^2/(n-k) about (1/0.1)^2
}

TEST(WeightedFitCoverage, RightUncertaintiesAreNotScaledDown) {
  const Coverage c = coverage(1.0, 400);
  EXPECT_GE(c.a, 0.92);
  EXPECT_GE(c.b, 0.92);
  EXPECT_GE(c.mean_scale, 1.0);
  EXPECT_LT(c.mean_scale, 1.3);
}

}  // namespace
}  // namespace hydrocoef
