#include "src/dynamics/vehicle_model.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <stdexcept>

#include "src/core/error.hpp"
#include "src/dynamics/damping_lanes.hpp"

namespace hydrocoef {

StateVector make_state(const Vector3& p_n, const Quaternion4& q_nb, const Vector6& nu_b) {
  StateVector x;
  x.segment<3>(state_index::kPosition) = p_n;
  x.segment<4>(state_index::kAttitude) = unit_attitude(q_nb);
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
  // The exact rotation of a unit q_nb, row-major.
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rotation = rotation_body_to_ned(q_nb);
  Vector6 tau = Vector6::Zero();
  motion::add_hydrostatic(rotation.data(), weight_N_, description_.buoyancy_N, description_.r_g_b.data(),
                          description_.r_b_b.data(), tau.data());
  return tau;
}

// The terms and rates below are written once over T = double (one vehicle) or
// motion::Lanes (kLanes vehicles differing in their damping): see
// motion_terms.hpp. add_damping(nu_r, out) adds each lane's damping force at
// its nu_r to out.

template <class T, class AddDamping>
void VehicleModel::motion_terms(const T* x, const ModelInputs& inputs, AddDamping&& add_damping,
                                motion::Terms<T>& terms) const {
  // The shared kernel's derivative (runtime/src/motion_kernel.h), the
  // damping added between its parts at the velocity relative to the water.
  const int current =
      motion::kernel::hc_motion_begin(x, weight_N_, description_.buoyancy_N, description_.r_g_b.data(),
                                      description_.r_b_b.data(), inputs.current_n.data(), terms.rotation, terms.nu_r,
                                      terms.hydrostatic, terms.damping, terms.coriolis, terms.current_b);
  add_damping(static_cast<const T*>(terms.nu_r), terms.damping);
  motion::kernel::hc_motion_finish(x, current, m_.data(), m_rb_.data(), m_a_.data(), terms.nu_r, terms.current_b,
                                   terms.coriolis);
}

template <class T>
void VehicleModel::rates(const T* x, const Vector6& tau_b, const motion::Terms<T>& terms, T* x_dot) const {
  motion::kernel::hc_motion_rates(x, tau_b.data(), kQuaternionNormGain, m_inv_.data(), terms.rotation,
                                  terms.hydrostatic, terms.damping, terms.coriolis, x_dot);
}

ForceBreakdown VehicleModel::forces(const StateVector& x, const ModelInputs& inputs) const {
  motion::Terms<double> terms;
  motion_terms(
      x.data(), inputs, [&](const double* nu_r, double* out) { add_damping(nu_r, inputs, out); }, terms);
  ForceBreakdown f;
  f.control_b = inputs.tau_b;
  f.nu_r_b = Eigen::Map<const Vector6>(terms.nu_r);
  f.hydrostatic_b = Eigen::Map<const Vector6>(terms.hydrostatic);
  f.damping_b = Eigen::Map<const Vector6>(terms.damping);
  f.coriolis_b = Eigen::Map<const Vector6>(terms.coriolis);
  return f;
}

ForceBreakdown VehicleModel::undamped_forces(const StateVector& x, const ModelInputs& inputs) const {
  motion::Terms<double> terms;
  motion_terms(
      x.data(), inputs, [](const double*, double*) {}, terms);
  ForceBreakdown f;
  f.control_b = inputs.tau_b;
  f.nu_r_b = Eigen::Map<const Vector6>(terms.nu_r);
  f.hydrostatic_b = Eigen::Map<const Vector6>(terms.hydrostatic);
  f.coriolis_b = Eigen::Map<const Vector6>(terms.coriolis);
  return f;
}

void VehicleModel::add_damping(const double* nu_r, const ModelInputs& inputs, double* out) const {
  damping_.add(nu_r, inputs.disturbances, out);
}

void VehicleModel::derivative(const StateVector& x, const ModelInputs& inputs, StateVector& x_dot) const {
  // The terms of forces() summed, without the breakdown.
  motion::Terms<double> terms;
  motion_terms(
      x.data(), inputs, [&](const double* nu_r, double* out) { add_damping(nu_r, inputs, out); }, terms);
  rates(x.data(), inputs.tau_b, terms, x_dot.data());
}

void VehicleModel::derivative_lanes(const DampingLanes& damping, const LaneState& x, const ModelInputs& inputs,
                                    LaneState& x_dot) const {
  using motion::Lanes;
  Lanes state[13], state_dot[13];
  for (int i = 0; i < 13; ++i) state[i] = x.row(i).transpose();
  motion::Terms<Lanes> terms;
  motion_terms(
      state, inputs, [&](const Lanes* nu_r, Lanes* out) { damping.add(nu_r, inputs.disturbances, out); }, terms);
  rates(state, inputs.tau_b, terms, state_dot);
  for (int i = 0; i < 13; ++i) x_dot.row(i) = state_dot[i].transpose();
}

}  // namespace hydrocoef
