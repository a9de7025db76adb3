#include "src/loads/force_coefficients.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

namespace hydrocoef {

double speed_through_water(const std::array<double, 6>& nu_b) { return std::hypot(nu_b[0], nu_b[1], nu_b[2]); }

double dynamic_pressure(double density, double speed) { return 0.5 * density * speed * speed; }

double force_coefficient(double force, double density, double speed, double area) {
  if (speed == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return force / (dynamic_pressure(density, speed) * area);
}

double moment_coefficient(double moment, double density, double speed, double area, double length) {
  if (speed == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return moment / (dynamic_pressure(density, speed) * area * length);
}

double reynolds_number(double speed, double length, double kinematic_viscosity) {
  return speed * length / kinematic_viscosity;
}

double froude_number(double speed, double length, double gravity) { return speed / std::sqrt(gravity * length); }

std::array<double, 3> moment_about(const std::array<double, 3>& moment_o, const std::array<double, 3>& force,
                                   const std::array<double, 3>& o, const std::array<double, 3>& p) {
  const std::array<double, 3> d{o[0] - p[0], o[1] - p[1], o[2] - p[2]};
  // d[i] * force[j], and 0 when the lever arm d[i] is 0 whatever force[j] is.
  const auto term = [&](std::size_t i, std::size_t j) { return d[i] == 0.0 ? 0.0 : d[i] * force[j]; };
  return {moment_o[0] + term(1, 2) - term(2, 1), moment_o[1] + term(2, 0) - term(0, 2),
          moment_o[2] + term(0, 1) - term(1, 0)};
}

}  // namespace hydrocoef
