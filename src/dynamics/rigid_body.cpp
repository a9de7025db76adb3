#include "src/dynamics/rigid_body.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <numbers>
#include <string>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {

Matrix3 skew(const Vector3& a) {
  Matrix3 s;
  s << 0.0, -a.z(), a.y(),  //
      a.z(), 0.0, -a.x(),   //
      -a.y(), a.x(), 0.0;
  return s;
}

Matrix6 rigid_body_mass_matrix(double mass_kg, const Matrix3& inertia_cg_b, const Vector3& r_g_b) {
  const Matrix3 s = skew(r_g_b);
  Matrix6 m = Matrix6::Zero();
  m.topLeftCorner<3, 3>() = mass_kg * Matrix3::Identity();
  m.topRightCorner<3, 3>() = -mass_kg * s;
  m.bottomLeftCorner<3, 3>() = mass_kg * s;
  m.bottomRightCorner<3, 3>() = inertia_cg_b - mass_kg * s * s;
  return m;
}

Matrix6 sphere_added_mass(double rho_kg_m3, double radius_m, const std::optional<Vector3>& rotation_kg_m2) {
  if (!(std::isfinite(radius_m) && radius_m > 0.0))
    throw InputError("sphere radius " + shortest_number(radius_m) + " m; expected a finite radius > 0");
  if (!(std::isfinite(rho_kg_m3) && rho_kg_m3 > 0.0))
    throw InputError("fluid density " + shortest_number(rho_kg_m3) + " kg/m^3; expected a finite density > 0");
  const double half_displaced = 2.0 / 3.0 * std::numbers::pi * rho_kg_m3 * radius_m * radius_m * radius_m;
  Matrix6 m = Matrix6::Zero();
  m.diagonal().head<3>().setConstant(half_displaced);
  if (rotation_kg_m2) m.diagonal().tail<3>() = *rotation_kg_m2;
  return m;
}

Matrix6 coriolis_matrix(const Matrix6& mass, const Vector6& nu_b) {
  const Vector6 momentum = mass * nu_b;
  const Matrix3 sa = skew(momentum.head<3>());
  Matrix6 c = Matrix6::Zero();
  c.topRightCorner<3, 3>() = -sa;
  c.bottomLeftCorner<3, 3>() = -sa;
  c.bottomRightCorner<3, 3>() = -skew(momentum.tail<3>());
  return c;
}

bool symmetric_positive_definite(const Matrix6& matrix, double relative_tolerance) {
  if (!matrix.allFinite()) return false;
  const double scale = matrix.cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) return false;
  if ((matrix - matrix.transpose()).cwiseAbs().maxCoeff() > relative_tolerance * scale) return false;
  const Eigen::LLT<Matrix6> llt(0.5 * (matrix + matrix.transpose()));
  return llt.info() == Eigen::Success && llt.matrixL().toDenseMatrix().diagonal().minCoeff() > 0.0;
}

}  // namespace hydrocoef
