// The dense decompositions of dynamic-size matrices that several modules use
// (SVD for the derivative and damping-law fits, the symmetric eigensolver
// for positive-definiteness checks, column-pivoting QR for rank-revealing
// least squares), compiled once in src/core/dense_decompositions.cpp: each
// decomposition's compute() was most of the compile time of every file that
// constructed one. Each function returns Eigen's own object, computed as its
// constructor computes it (the same numbers), so callers use its accessors
// and solve() as before.
#pragma once

#include <Eigen/Dense>

namespace hydrocoef {

/// Eigen::JacobiSVD<MatrixXd>(a, options): options as Eigen's (ComputeThinU, ComputeFullV, ...).
Eigen::JacobiSVD<Eigen::MatrixXd> jacobi_svd(const Eigen::MatrixXd& a, unsigned int options = 0);

/// Eigen::SelfAdjointEigenSolver<MatrixXd>(a, options) of a symmetric a (its lower triangle is read).
Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> symmetric_eigen(const Eigen::MatrixXd& a,
                                                               int options = Eigen::ComputeEigenvectors);

/// Eigen::ColPivHouseholderQR<MatrixXd>(a).
Eigen::ColPivHouseholderQR<Eigen::MatrixXd> col_piv_householder_qr(const Eigen::MatrixXd& a);

}  // namespace hydrocoef
