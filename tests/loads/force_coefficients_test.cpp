// The coefficient arithmetic (src/loads/force_coefficients): each formula
// against numbers worked by hand, no coefficient at U = 0, and a moment
// moved to another point by the cross product written out component by
// component, a zero lever arm needing no force.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "src/loads/force_coefficients.hpp"

namespace hydrocoef {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(ForceCoefficients, FormulasAgainstNumbersWorkedByHand) {
  // The sphere of data/openfoam-sphere: R = 0.15 m, A = pi R^2, L = 2R, water at 0.1 m/s.
  const double rho = 998.2, U = 0.1, A = M_PI * 0.15 * 0.15, L = 0.3, nu = 1.004e-6;
  // q = 1/2 * 998.2 * 0.01 = 4.991 Pa; q A = 0.35279...; a drag of 0.1 N on the body, along -x:
  EXPECT_DOUBLE_EQ(dynamic_pressure(rho, U), 4.991);
  EXPECT_DOUBLE_EQ(force_coefficient(-0.1, rho, U, A), -0.1 / (4.991 * 0.070685834705770348));
  EXPECT_NEAR(force_coefficient(-0.1, rho, U, A), -0.2834523, 1e-7);
  EXPECT_DOUBLE_EQ(moment_coefficient(0.002, rho, U, A, L), 0.002 / (4.991 * 0.070685834705770348 * 0.3));
  EXPECT_DOUBLE_EQ(reynolds_number(U, L, nu), 0.03 / 1.004e-6);  // 29880.478...
  EXPECT_NEAR(reynolds_number(U, L, nu), 29880.478, 1e-3);
  EXPECT_DOUBLE_EQ(froude_number(U, L), 0.1 / std::sqrt(9.80665 * 0.3));  // 0.0583014...
  EXPECT_EQ(kStandardGravity, 9.80665);
  EXPECT_DOUBLE_EQ(speed_through_water({0.3, -0.4, 1.2, 5.0, 6.0, 7.0}), 1.3);  // rates do not count
}

TEST(ForceCoefficients, NoCoefficientAtRest) {
  EXPECT_TRUE(std::isnan(force_coefficient(0.5, 998.2, 0.0, 1.0)));
  EXPECT_TRUE(std::isnan(moment_coefficient(0.5, 998.2, 0.0, 1.0, 1.0)));
  EXPECT_EQ(reynolds_number(0.0, 0.3, 1e-6), 0.0);
  EXPECT_EQ(froude_number(0.0, 0.3), 0.0);
}

TEST(ForceCoefficients, AMomentMovedToAnotherPoint) {
  // M_P = M_O + (O - P) x F, with O - P = d = (1, -2, 0.5), F = (3, 4, -5):
  // d x F = (dy Fz - dz Fy, dz Fx - dx Fz, dx Fy - dy Fx) = (10 - 2, 1.5 + 5, 4 + 6) = (8, 6.5, 10).
  const auto m = moment_about({0.1, 0.2, 0.3}, {3.0, 4.0, -5.0}, {1.5, -1.0, 1.0}, {0.5, 1.0, 0.5});
  EXPECT_DOUBLE_EQ(m[0], 8.1);
  EXPECT_DOUBLE_EQ(m[1], 6.7);
  EXPECT_DOUBLE_EQ(m[2], 10.3);
  // Moved along x only: K keeps its value and needs neither Y nor Z; M and N need Z and Y.
  const auto along_x = moment_about({0.1, 0.2, 0.3}, {kNaN, 4.0, kNaN}, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0});
  EXPECT_EQ(along_x[0], 0.1);
  EXPECT_TRUE(std::isnan(along_x[1]));  // needs Z
  EXPECT_DOUBLE_EQ(along_x[2], 4.3);    // 0.3 + 1 * 4
  // The same point: nothing changes, whatever the forces.
  const auto same = moment_about({0.1, 0.2, 0.3}, {kNaN, kNaN, kNaN}, {1.0, 2.0, 3.0}, {1.0, 2.0, 3.0});
  EXPECT_EQ(same, (std::array<double, 3>{0.1, 0.2, 0.3}));
}

}  // namespace
}  // namespace hydrocoef
