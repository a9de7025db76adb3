#include "src/core/covariance.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "src/core/dense_decompositions.hpp"

namespace hydrocoef {

std::optional<std::string> covariance_problem(std::span<const double> covariance, std::size_t k) {
  if (covariance.size() != k * k)
    return "found " + std::to_string(covariance.size()) + " numbers, expected " + std::to_string(k * k) + " (" +
           std::to_string(k) + " x " + std::to_string(k) + ")";
  double largest = 0.0;
  for (const double c : covariance) {
    if (!std::isfinite(c)) return "found a number that is not finite, expected a covariance matrix";
    largest = std::max(largest, std::abs(c));
  }
  const double tolerance = 1e-9 * largest;
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (std::abs(covariance[i * k + j] - covariance[j * k + i]) > tolerance)
        return "found entries [" + std::to_string(i) + "][" + std::to_string(j) + "] and [" + std::to_string(j) + "][" +
               std::to_string(i) + "] that differ, expected a symmetric matrix";
  const Eigen::Map<const Eigen::MatrixXd> c(covariance.data(), static_cast<Eigen::Index>(k),
                                            static_cast<Eigen::Index>(k));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen = symmetric_eigen(c, Eigen::EigenvaluesOnly);
  if (k > 0 && eigen.eigenvalues().minCoeff() < -1e-9 * std::max(largest, 1e-300))
    return "found the eigenvalue " + std::to_string(eigen.eigenvalues().minCoeff()) +
           ", expected a positive semi-definite matrix (variances cannot be negative)";
  return std::nullopt;
}

}  // namespace hydrocoef
