// The grid-convergence index: exact recovery of f(h) = f0 + C h^p, the
// worked example of Celik et al. (2008), Table 1, to its printed digits
// (monotonic, low-order and oscillatory columns), and the cases with no
// answer.
#include "src/uncertainty/gci.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

TEST(Gci, RecoversOrderAndLimitOfAPowerLaw) {
  for (const double p : {1.0, 1.7, 2.0, 3.0}) {
    for (const double C : {0.3, -2.0}) {
      // r21 = 1.5, r32 = 1.6; cells large enough that phi2 - phi1 keeps its
      // digits (the differences are what the procedure works on).
      const std::array<double, 3> h{0.1, 0.15, 0.24};
      std::array<double, 3> phi{};
      for (std::size_t i = 0; i < 3; ++i) phi[i] = 4.2 + C * std::pow(h[i], p);
      const GciResult r = grid_convergence_index(h, phi);
      EXPECT_EQ(r.convergence, GridConvergence::Monotonic);
      EXPECT_NEAR(r.apparent_order, p, 1e-10) << p << " " << C;
      EXPECT_NEAR(r.extrapolated, 4.2, 1e-10) << p << " " << C;
      EXPECT_NEAR(r.extrapolated32, 4.2, 1e-10);
      // GCI32 / (r21^p GCI21) is phi1/phi2 exactly on a power law (each
      // GCI is relative to its own finer value).
      EXPECT_NEAR(r.asymptotic_ratio, std::abs(phi[0] / phi[1]), 1e-9);
    }
  }
}

/// Rounds to the digits Celik et al. print: `decimals` after the point.
double printed(double value, int decimals) {
  return std::round(value * std::pow(10.0, decimals)) / std::pow(10.0, decimals);
}

TEST(Gci, CelikTable1MonotonicColumn) {
  // Celik et al. (2008), Table 1, first column: N = 18000, 8000, 4500 cells
  // in 2-D, phi = 6.063, 5.972, 5.863. Published: p = 1.53, phi_ext = 6.1685,
  // e_a = 1.5 %, e_ext = 1.7 %, GCI_fine = 2.2 %.
  const std::array<double, 3> h{representative_cell_size(18000, 1, 2), representative_cell_size(8000, 1, 2),
                                representative_cell_size(4500, 1, 2)};
  const GciResult r = grid_convergence_index(h, {6.063, 5.972, 5.863});
  EXPECT_EQ(r.convergence, GridConvergence::Monotonic);
  EXPECT_EQ(printed(r.r21, 1), 1.5);
  EXPECT_EQ(printed(r.r32, 3), 1.333);
  EXPECT_EQ(printed(r.apparent_order, 2), 1.53);
  EXPECT_EQ(printed(r.extrapolated, 4), 6.1685);
  EXPECT_EQ(printed(100 * r.relative_error, 1), 1.5);
  EXPECT_EQ(printed(100 * r.extrapolated_relative_error, 1), 1.7);
  EXPECT_EQ(printed(100 * r.gci_fine, 1), 2.2);
  EXPECT_TRUE(r.note.empty()) << r.note;
}

TEST(Gci, CelikTable1LowOrderColumn) {
  // Second column: N = 18000, 4500, 980; phi = 10.7880, 10.7250, 10.6050.
  // Published: r21 = 2.0, r32 = 2.143, p = 0.75, phi_ext = 10.8801,
  // e_a = 0.6 %, e_ext = 0.85 %, GCI_fine = 1.1 %.
  const std::array<double, 3> h{representative_cell_size(18000, 1, 2), representative_cell_size(4500, 1, 2),
                                representative_cell_size(980, 1, 2)};
  const GciResult r = grid_convergence_index(h, {10.7880, 10.7250, 10.6050});
  EXPECT_EQ(r.convergence, GridConvergence::Monotonic);
  EXPECT_EQ(printed(r.r21, 1), 2.0);
  EXPECT_EQ(printed(r.r32, 3), 2.143);
  EXPECT_EQ(printed(r.apparent_order, 2), 0.75);
  EXPECT_EQ(printed(r.extrapolated, 4), 10.8801);
  EXPECT_EQ(printed(100 * r.relative_error, 1), 0.6);
  EXPECT_EQ(printed(100 * r.extrapolated_relative_error, 2), 0.85);
  EXPECT_EQ(printed(100 * r.gci_fine, 1), 1.1);
}

TEST(Gci, CelikTable1OscillatoryColumn) {
  // Third column: the same meshes, phi = 6.0042, 5.9624, 6.0909 (the value
  // goes down, then up: oscillatory convergence). Published: p = 1.5,
  // phi_ext = 6.0269, e_a = 0.7 %, e_ext = 0.38 %, GCI_fine = 0.47 %.
  const std::array<double, 3> h{representative_cell_size(18000, 1, 2), representative_cell_size(4500, 1, 2),
                                representative_cell_size(980, 1, 2)};
  const GciResult r = grid_convergence_index(h, {6.0042, 5.9624, 6.0909});
  EXPECT_EQ(r.convergence, GridConvergence::Oscillatory);
  EXPECT_EQ(printed(r.apparent_order, 1), 1.5);
  EXPECT_EQ(printed(r.extrapolated, 4), 6.0269);
  EXPECT_EQ(printed(100 * r.relative_error, 1), 0.7);
  EXPECT_EQ(printed(100 * r.extrapolated_relative_error, 2), 0.38);
  EXPECT_EQ(printed(100 * r.gci_fine, 2), 0.47);
}

TEST(Gci, CasesWithoutAnAnswerSaySo) {
  const std::array<double, 3> h{1.0, 2.0, 4.0};
  EXPECT_EQ(grid_convergence_index(h, {1.0, 1.0, 1.3}).convergence, GridConvergence::Converged);
  EXPECT_EQ(grid_convergence_index(h, {1.0, 1.2, 1.2}).convergence, GridConvergence::NotFound);
  const GciResult close = grid_convergence_index({1.0, 1.1, 1.2}, {1.0, 1.1, 1.3});
  EXPECT_NE(close.note.find("1.3"), std::string::npos) << close.note;
  EXPECT_THROW(grid_convergence_index({2.0, 1.0, 4.0}, {1, 2, 3}), InputError);
  EXPECT_THROW(grid_convergence_index({1.0, 2.0, 4.0}, {1, NAN, 3}), InputError);
  EXPECT_THROW(representative_cell_size(0, 1, 3), InputError);
  EXPECT_DOUBLE_EQ(representative_cell_size(1000, 8.0, 3), 0.2);
}

}  // namespace
}  // namespace hydrocoef
