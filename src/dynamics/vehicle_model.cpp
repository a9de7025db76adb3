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
  return hydrostatic_from_rotation(rotation_body_to_ned(q_nb));
}

inline Vector6 VehicleModel::hydrostatic_from_rotation(const Matrix3& rotation) const {
  // R^T e_z: the NED down direction in body axes (third row of R).
  const Vector3 down_b = rotation.row(2).transpose();
  const Vector3 weight_b = weight_N_ * down_b;
  const Vector3 buoyancy_b = -description_.buoyancy_N * down_b;
  Vector6 tau;
  tau.head<3>() = weight_b + buoyancy_b;
  tau.tail<3>() = description_.r_g_b.cross(weight_b) + description_.r_b_b.cross(buoyancy_b);
  return tau;
}

inline void VehicleModel::add_motion_forces(const Matrix3& rotation, const Vector6& nu, const ModelInputs& inputs,
                                            Vector6& nu_r, Vector6& damping, Vector6& coriolis) const {
  if (inputs.current_n.isZero()) {
    // nu_r = nu: C(nu) is linear in M, so C_RB(nu) nu + C_A(nu) nu = C(M) nu.
    damping += damping_.evaluate(nu, inputs.disturbances);
    coriolis -= coriolis_force(m_, nu);
    return;
  }
  const Vector3 current_b = rotation.transpose() * inputs.current_n;
  nu_r.head<3>() -= current_b;
  damping += damping_.evaluate(nu_r, inputs.disturbances);
  Vector6 current_rate_b = Vector6::Zero();  // nu_c' for a current constant in NED
  current_rate_b.head<3>() = -nu.tail<3>().cross(current_b);
  coriolis += -coriolis_force(m_rb_, nu) - coriolis_force(m_a_, nu_r) + m_a_ * current_rate_b;
}

ForceBreakdown VehicleModel::forces(const StateVector& x, const ModelInputs& inputs) const {
  const Matrix3 rotation = rotation_body_to_ned_any_norm(attitude_nb(x));
  ForceBreakdown f;
  f.nu_r_b = velocity_b(x);
  f.control_b = inputs.tau_b;
  f.hydrostatic_b = hydrostatic_from_rotation(rotation);
  add_motion_forces(rotation, velocity_b(x), inputs, f.nu_r_b, f.damping_b, f.coriolis_b);
  return f;
}

void VehicleModel::derivative(const StateVector& x, const ModelInputs& inputs, StateVector& x_dot) const {
  // The terms of forces() summed as they come: the integrators' hot path
  // keeps no breakdown.
  const Matrix3 rotation = rotation_body_to_ned_any_norm(attitude_nb(x));
  const Vector6 nu = velocity_b(x);
  Vector6 nu_r = nu, total = inputs.tau_b + hydrostatic_from_rotation(rotation);
  add_motion_forces(rotation, nu, inputs, nu_r, total, total);
  x_dot.segment<3>(state_index::kPosition) = rotation * nu.head<3>();
  x_dot.segment<4>(state_index::kAttitude) = quaternion_rate(attitude_nb(x), nu.tail<3>(), kQuaternionNormGain);
  x_dot.segment<6>(state_index::kVelocity) = m_inv_ * total;
}

}  // namespace hydrocoef
