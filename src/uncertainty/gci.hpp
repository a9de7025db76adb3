// Numerical uncertainty of a CFD result from runs at three mesh levels: the
// grid-convergence index by the procedure of Celik, Ghia, Roache, Freitas,
// Coleman and Raad, "Procedure for estimation and reporting of uncertainty
// due to discretization in CFD applications", ASME J. Fluids Eng. 130 (2008)
// 078001 (called "Celik et al." below, its steps numbered as there):
//
//   1. representative cell size h = (V / N)^(1/D) of each mesh;
//   2. refinement ratios r21 = h2/h1, r32 = h3/h2 (1 = finest), each > 1.3
//      recommended;
//   3. apparent order p from |ln|e32/e21| + q(p)| / ln r21 with
//      q(p) = ln((r21^p - s)/(r32^p - s)), s = sign(e32/e21), e21 = phi2 - phi1,
//      e32 = phi3 - phi2, solved by fixed-point iteration;
//   4. extrapolated value phi_ext21 = (r21^p phi1 - phi2)/(r21^p - 1);
//   5. approximate relative error e_a21 = |(phi1 - phi2)/phi1|, extrapolated
//      relative error e_ext21 = |(phi_ext21 - phi1)/phi_ext21|, and the fine-grid
//      convergence index GCI_fine21 = 1.25 e_a21 / (r21^p - 1).
//
// Oscillatory convergence (s < 0) is handled as Celik et al. do: the same
// formulas with s = -1, and the result says so. Divergence (p not found,
// or no change between levels) is reported instead of a number.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

namespace hydrocoef {

enum class GridConvergence {
  Monotonic,    ///< e32/e21 > 0
  Oscillatory,  ///< e32/e21 < 0: the result alternates between levels
  Converged,    ///< e21 = 0 (to round-off): the two finest levels agree; GCI 0
  NotFound      ///< the apparent order did not converge, or e32 = 0 with e21 != 0
};

std::string_view grid_convergence_name(GridConvergence kind);

struct GciResult {
  GridConvergence convergence = GridConvergence::NotFound;
  double r21 = 0.0, r32 = 0.0;
  double apparent_order = 0.0;               ///< p
  double extrapolated = 0.0;                 ///< phi_ext21
  double extrapolated32 = 0.0;               ///< phi_ext32
  double relative_error = 0.0;               ///< e_a21 (a fraction, not %)
  double extrapolated_relative_error = 0.0;  ///< e_ext21
  double gci_fine = 0.0;                     ///< GCI_fine21 (a fraction)
  double gci_medium = 0.0;                   ///< GCI_fine32 = 1.25 e_a32 / (r32^p - 1)
  /// GCI_fine32 / (r21^p GCI_fine21): close to 1 in the asymptotic range.
  double asymptotic_ratio = 0.0;
  int iterations = 0;
  std::string note;  ///< why a result is missing, or a warning (r < 1.3)

  /// The uncertainty of phi1 in its own unit: GCI_fine21 |phi1|.
  double uncertainty(double phi1) const;
};

/// The representative cell size (V / N)^(1/D) of a mesh of N cells filling
/// V m^D (D = 1, 2 or 3). InputError for N = 0, V <= 0 or another D.
double representative_cell_size(double cells, double volume, int dimension);

/// Celik et al.'s procedure on three levels, h and phi given fine (index 0)
/// to coarse (index 2), with the safety factor 1.25 of a three-grid study.
/// InputError unless h1 < h2 < h3, all finite and positive, and phi finite.
GciResult grid_convergence_index(const std::array<double, 3>& h, const std::array<double, 3>& phi,
                                 double safety_factor = 1.25);

}  // namespace hydrocoef
