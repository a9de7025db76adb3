// The 6-vectors and 6x6 matrices of marine-vehicle dynamics, one type each
// for the whole library: velocities nu = (u, v, w, p, q, r), generalized
// forces tau = (X, Y, Z, K, M, N), and the mass, added-mass and damping
// matrices between them (rows are force components, columns velocity
// components, both in the order above).
//
// Matrix6 is Eigen's (column-major in memory): index it as m(i, j), never by
// memory offset. Text and file formats that list a matrix row by row go
// through row_major / from_row_major.
#pragma once

#include <Eigen/Core>

#include <array>

namespace hydrocoef {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

/// The 36 entries row by row: (i, j) at [6 * i + j].
inline std::array<double, 36> row_major(const Matrix6& m) {
  std::array<double, 36> out{};
  for (Eigen::Index i = 0; i < 6; ++i)
    for (Eigen::Index j = 0; j < 6; ++j) out[static_cast<std::size_t>(6 * i + j)] = m(i, j);
  return out;
}

/// The matrix of 36 entries given row by row: (i, j) from [6 * i + j].
inline Matrix6 from_row_major(const std::array<double, 36>& entries) {
  Matrix6 m;
  for (Eigen::Index i = 0; i < 6; ++i)
    for (Eigen::Index j = 0; j < 6; ++j) m(i, j) = entries[static_cast<std::size_t>(6 * i + j)];
  return m;
}

}  // namespace hydrocoef
