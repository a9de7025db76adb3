// Test fixture shared by the dynamics tests: the ASR-V yaw damping law fitted
// here from the paper's table (examples/asr-v/asr-v-yaw-damping.csv, moment
// on the body) with fit_damping_law, a vehicle built around it, and the root
// of the law found independently in closed form.
#pragma once

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/dynamics/rigid_body.hpp"
#include "src/dynamics/vehicle.hpp"
#include "src/fit/damping_law.hpp"

namespace hydrocoef::test {

/// c, a, b of N(r) = c + a r + b r|r| fitted to the paper's yaw table.
struct YawLaw {
  double c = 0.0, a = 0.0, b = 0.0;
  double operator()(double r) const { return c + a * r + b * r * std::abs(r); }
};

inline YawLaw fit_asr_v_yaw_law() {
  std::ifstream in(HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-yaw-damping.csv");
  if (!in) throw std::runtime_error("cannot open the ASR-V yaw table");
  std::vector<double> r, n;
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    std::istringstream fields(line);
    std::string x, y;
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    r.push_back(std::stod(x));
    n.push_back(std::stod(y));
  }
  const DampingLawFit fit = fit_damping_law(parse_damping_terms("1,r,r|r|"), r, n);
  return {fit.coefficients[0], fit.coefficients[1], fit.coefficients[2]};
}

/// The positive root of c + a r + b r|r| + tau = 0 (a, b < 0, tau + c > 0):
/// b r^2 + a r + (c + tau) = 0.
inline double positive_yaw_root(const YawLaw& law, double tau) {
  const double disc = law.a * law.a - 4.0 * law.b * (law.c + tau);
  return (-law.a - std::sqrt(disc)) / (2.0 * law.b);
}

/// ASR-V: 6.7 kg, R = 0.15 m, solid-sphere inertia, CG 2 cm below the centre,
/// neutral, sphere added mass, the fitted yaw law, eq. (5) in surge and sway.
inline VehicleDescription asr_v_vehicle(const YawLaw& law) {
  VehicleDescription v;
  v.name = "asr-v (test)";
  v.mass_kg = 6.7;
  v.inertia_cg_b = Matrix3::Identity() * (0.4 * 6.7 * 0.15 * 0.15);
  v.r_g_b = Vector3(0.0, 0.0, 0.02);
  v.buoyancy_N = v.mass_kg * v.gravity_m_s2;
  v.added_mass_b = sphere_added_mass(v.rho_kg_m3, 0.15);
  v.damping[5].kind = DofDamping::Kind::Law;
  v.damping[5].law = parse_damping_terms("1,r,r|r|");
  v.damping[5].coefficients = {law.c, law.a, law.b};
  for (const std::size_t dof : {0, 1}) {
    v.damping[dof].kind = DofDamping::Kind::Law;
    v.damping[dof].law = parse_damping_terms(dof == 0 ? "u,u|u|" : "v,v|v|");
    v.damping[dof].coefficients = {-0.0155, -11.0365};
  }
  return v;
}

}  // namespace hydrocoef::test
