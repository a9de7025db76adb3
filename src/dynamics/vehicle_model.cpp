#include "src/dynamics/vehicle_model.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <stdexcept>

#include "src/core/error.hpp"

namespace hydrocoef {

StateVector make_state(const Vector3& p_n, const Quaternion4& q_nb, const Vector6& nu_b) {
  StateVector x;
  x.segment<3>(state_index::kPosition) = p_n;
  x.segment<4>(state_index::kAttitude) = q_nb / q_nb.norm();
  x.segment<6>(state_index::kVelocity) = nu_b;
  return x;
}

VehicleModel::VehicleModel(VehicleDescription description, const SurfaceResolver& resolver)
    : description_(std::move(description)) {
  if (!(description_.mass_kg > 0.0))
    throw InputError(SourceLocation{description_.file}, "key 'mass': expected a positive mass [kg]");
  m_rb_ = rigid_body_mass_matrix(description_.mass_kg, description_.inertia_cg_b, description_.r_g_b);
  m_a_ = description_.added_mass_b;
  m_ = m_rb_ + m_a_;
  if (!symmetric_positive_definite(m_))
    throw InputError(SourceLocation{description_.file},
                     "key 'added_mass': the mass matrix M_RB + M_A is not symmetric positive definite");
  m_inv_ = m_.llt().solve(Matrix6::Identity());
  weight_N_ = description_.mass_kg * description_.gravity_m_s2;

  thrust_allocation_.resize(6, static_cast<Eigen::Index>(description_.thrusters.size()));
  for (std::size_t i = 0; i < description_.thrusters.size(); ++i) {
    const Thruster& t = description_.thrusters[i];
    auto column = thrust_allocation_.col(static_cast<Eigen::Index>(i));
    column.head<3>() = t.direction_b;
    column.tail<3>() = t.position_b.cross(t.direction_b);
  }

  try {
    damping_ = DampingModel(description_.damping, resolver);
  } catch (const InputError& e) {
    throw InputError(SourceLocation{description_.file}, e.what());
  }
}

VehicleModel VehicleModel::with_damping(DampingModel damping) const {
  if (damping.disturbance_names() != damping_.disturbance_names())
    throw std::invalid_argument("VehicleModel::with_damping: a damping model reading other disturbances");
  VehicleModel copy = *this;
  copy.damping_ = std::move(damping);
  return copy;
}

double VehicleModel::clamp_thrust(std::size_t thruster, double thrust_N) const {
  const Thruster& t = description_.thrusters.at(thruster);
  return std::clamp(thrust_N, t.min_thrust_N, t.max_thrust_N);
}

Vector6 VehicleModel::thrust_force(std::span<const double> thrust_N) const {
  if (thrust_N.size() != description_.thrusters.size())
    throw InputError("found " + std::to_string(thrust_N.size()) + " thrust values, expected one per thruster (" +
                     std::to_string(description_.thrusters.size()) + ")");
  Vector6 tau = Vector6::Zero();
  for (std::size_t i = 0; i < thrust_N.size(); ++i)
    tau += thrust_N[i] * thrust_allocation_.col(static_cast<Eigen::Index>(i));
  return tau;
}

Vector6 VehicleModel::hydrostatic_force(const Quaternion4& q_nb) const {
  Vector6 tau = Vector6::Zero();
  add_hydrostatic(rotation_body_to_ned(q_nb), tau.data());
  return tau;
}

// The helpers below add into six plain doubles, element by element: they are
// the integrators' hot path, where Eigen's 3-element halves of 6-vectors made
// the compiler store and reload the sums in pieces (store-forwarding stalls,
// a third of derivative()'s time).

[[gnu::always_inline]] inline void VehicleModel::add_hydrostatic(const Matrix3& rotation, double* tau) const {
  // R^T e_z: the NED down direction in body axes (third row of R). Weight W
  // at the CG and buoyancy B (up) at the CB along it: (W + B, r_g x W + r_b x B).
  const double dx = rotation(2, 0), dy = rotation(2, 1), dz = rotation(2, 2);
  const double wx = weight_N_ * dx, wy = weight_N_ * dy, wz = weight_N_ * dz;
  const double b = -description_.buoyancy_N, bx = b * dx, by = b * dy, bz = b * dz;
  const Vector3& g = description_.r_g_b;
  const Vector3& c = description_.r_b_b;
  tau[0] += wx + bx;
  tau[1] += wy + by;
  tau[2] += wz + bz;
  tau[3] += (g[1] * wz - g[2] * wy) + (c[1] * bz - c[2] * by);
  tau[4] += (g[2] * wx - g[0] * wz) + (c[2] * bx - c[0] * bz);
  tau[5] += (g[0] * wy - g[1] * wx) + (c[0] * by - c[1] * bx);
}

[[gnu::always_inline]] inline void VehicleModel::add_motion_forces(const Matrix3& rotation, const double* nu,
                                                                   const ModelInputs& inputs, double* nu_r,
                                                                   double* damping, double* coriolis) const {
  const Eigen::Map<const Vector6> nu_b(nu);
  if (inputs.current_n.isZero()) {
    // nu_r = nu: C(nu) is linear in M, so C_RB(nu) nu + C_A(nu) nu = C(M) nu.
    const Vector6 d = damping_.evaluate(nu_b, inputs.disturbances);
    for (int i = 0; i < 6; ++i) damping[i] += d[i];
    subtract_coriolis_force(m_, nu, coriolis);
    return;
  }
  const Vector3 current_b = rotation.transpose() * inputs.current_n;
  for (int i = 0; i < 3; ++i) nu_r[i] -= current_b[i];
  const Eigen::Map<const Vector6> nu_r_b(nu_r);
  const Vector6 d = damping_.evaluate(nu_r_b, inputs.disturbances);
  Vector6 current_rate_b = Vector6::Zero();  // nu_c' for a current constant in NED
  current_rate_b.head<3>() = -nu_b.tail<3>().cross(current_b);
  const Vector6 c = -coriolis_force(m_rb_, nu_b) - coriolis_force(m_a_, nu_r_b) + m_a_ * current_rate_b;
  for (int i = 0; i < 6; ++i) damping[i] += d[i];
  for (int i = 0; i < 6; ++i) coriolis[i] += c[i];
}

ForceBreakdown VehicleModel::forces(const StateVector& x, const ModelInputs& inputs) const {
  const Matrix3 rotation = rotation_body_to_ned_any_norm(attitude_nb(x));
  ForceBreakdown f;
  f.nu_r_b = velocity_b(x);
  f.control_b = inputs.tau_b;
  add_hydrostatic(rotation, f.hydrostatic_b.data());
  add_motion_forces(rotation, x.data() + state_index::kVelocity, inputs, f.nu_r_b.data(), f.damping_b.data(),
                    f.coriolis_b.data());
  return f;
}

void VehicleModel::derivative(const StateVector& x, const ModelInputs& inputs, StateVector& x_dot) const {
  // The terms of forces() summed as they come (the integrators' hot path
  // keeps no breakdown), element by element.
  const Matrix3 rotation = rotation_body_to_ned_any_norm(attitude_nb(x));
  const double* nu = x.data() + state_index::kVelocity;
  double nu_r[6], total[6];
  for (int i = 0; i < 6; ++i) {
    nu_r[i] = nu[i];
    total[i] = inputs.tau_b[i];
  }
  add_hydrostatic(rotation, total);
  add_motion_forces(rotation, nu, inputs, nu_r, total, total);
  for (int i = 0; i < 3; ++i)
    x_dot[state_index::kPosition + i] = rotation(i, 0) * nu[0] + rotation(i, 1) * nu[1] + rotation(i, 2) * nu[2];
  quaternion_rate(x.data() + state_index::kAttitude, nu + 3, kQuaternionNormGain,
                  x_dot.data() + state_index::kAttitude);
  for (Eigen::Index i = 0; i < 6; ++i) {
    double sum = 0.0;
    for (Eigen::Index j = 0; j < 6; ++j) sum += m_inv_(i, j) * total[j];
    x_dot[state_index::kVelocity + i] = sum;
  }
}

}  // namespace hydrocoef
