#include "src/core/dense_decompositions.hpp"

namespace hydrocoef {

Eigen::JacobiSVD<Eigen::MatrixXd> jacobi_svd(const Eigen::MatrixXd& a, unsigned int options) {
  return Eigen::JacobiSVD<Eigen::MatrixXd>(a, options);
}

Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> symmetric_eigen(const Eigen::MatrixXd& a, int options) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a, options);
}

Eigen::ColPivHouseholderQR<Eigen::MatrixXd> col_piv_householder_qr(const Eigen::MatrixXd& a) {
  return Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(a);
}

}  // namespace hydrocoef
