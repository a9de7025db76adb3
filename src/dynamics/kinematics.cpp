#include "src/dynamics/kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace hydrocoef {

Vector3 euler_from_quaternion(const Quaternion4& q) {
  const double e = q[0], x = q[1], y = q[2], z = q[3];
  const double phi = std::atan2(2.0 * (y * z + x * e), 1.0 - 2.0 * (x * x + y * y));
  const double theta = -std::asin(std::clamp(2.0 * (x * z - y * e), -1.0, 1.0));
  const double psi = std::atan2(2.0 * (x * y + z * e), 1.0 - 2.0 * (y * y + z * z));
  return {phi, theta, psi};
}

Quaternion4 quaternion_from_euler(const Vector3& euler_rad) {
  const double cp = std::cos(0.5 * euler_rad[0]), sp = std::sin(0.5 * euler_rad[0]);
  const double ct = std::cos(0.5 * euler_rad[1]), st = std::sin(0.5 * euler_rad[1]);
  const double cy = std::cos(0.5 * euler_rad[2]), sy = std::sin(0.5 * euler_rad[2]);
  Quaternion4 q;
  q << cp * ct * cy + sp * st * sy,  //
      sp * ct * cy - cp * st * sy,   //
      cp * st * cy + sp * ct * sy,   //
      cp * ct * sy - sp * st * cy;
  if (q[0] < 0.0) q = -q;
  return unit_attitude(q);
}

}  // namespace hydrocoef
