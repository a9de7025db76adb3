// The 6-DOF lookup-table dynamics model (Fossen 2011, eq. 6.1 with current,
// section 10.3), built once from a VehicleDescription and immutable:
//
//   M_RB nu' + C_RB(nu) nu + M_A nu_r' + C_A(nu_r) nu_r + D(nu_r) nu_r + g(eta) = tau
//   p_n' = R(q_nb) nu1,   q_nb' = 1/2 T(q_nb) nu2   (+ norm feedback, kinematics.hpp)
//
// nu_r = nu - nu_c is the velocity relative to the water, nu_c = (R^T v_c_n, 0)
// for a current v_c_n given in NED (irrotational and constant while an input
// holds, so nu_c' = (-nu2 x R^T v_c_n, 0)). D(nu_r) nu_r is the DampingModel's
// force (laws or lookup surfaces); g from weight at the CG and buoyancy at
// the CB. M = M_RB + M_A is inverted once at construction.
//
// State (StateVector, 13 numbers): p_n = (x_n, y_n, z_n) [m] position of CO in
// NED; q_nb (4, scalar first) body-to-NED attitude; nu_b (6) body velocity
// over ground (u, v, w [m/s], p, q, r [rad/s]). Forces in body axes about CO,
// on the body (SNAME signs: damping negative).
//
// derivative() is const, thread-safe and allocates nothing (fixed-size Eigen,
// surfaces evaluated into stack buffers): it is the integrators' hot path.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "src/dynamics/damping.hpp"
#include "src/dynamics/kinematics.hpp"
#include "src/dynamics/motion_terms.hpp"
#include "src/dynamics/rigid_body.hpp"
#include "src/dynamics/vehicle.hpp"

namespace hydrocoef {

class DampingLanes;

using StateVector = Eigen::Matrix<double, 13, 1>;

/// Where each part of the state lives in a StateVector.
namespace state_index {
inline constexpr Eigen::Index kPosition = 0;  ///< p_n, 3
inline constexpr Eigen::Index kAttitude = 3;  ///< q_nb, 4
inline constexpr Eigen::Index kVelocity = 7;  ///< nu_b, 6
}  // namespace state_index

/// A state from its parts; q_nb is normalised.
StateVector make_state(const Vector3& p_n, const Quaternion4& q_nb, const Vector6& nu_b);
inline Vector3 position_n(const StateVector& x) { return x.segment<3>(state_index::kPosition); }
inline Quaternion4 attitude_nb(const StateVector& x) { return x.segment<4>(state_index::kAttitude); }
inline Vector6 velocity_b(const StateVector& x) { return x.segment<6>(state_index::kVelocity); }
/// Projects the attitude back onto the unit sphere (after an integration step).
inline void normalize_attitude(StateVector& x) { motion::normalize(x.data() + state_index::kAttitude); }

/// What acts on the vehicle from outside, held constant over a step.
struct ModelInputs {
  Vector6 tau_b = Vector6::Zero();      ///< control force on the body, commanded + thrusters [N, N m]
  Vector3 current_n = Vector3::Zero();  ///< water velocity in NED [m/s]
  /// Disturbance parameter values [SI], in VehicleModel::disturbance_names() order;
  /// must have at least that many entries.
  std::span<const double> disturbances;
};

/// The terms of the equation of motion at one state, each as a generalized
/// force on the body [N, N m]: M nu' = control + damping + hydrostatic + coriolis.
struct ForceBreakdown {
  Vector6 control_b = Vector6::Zero();
  Vector6 damping_b = Vector6::Zero();      ///< -D(nu_r) nu_r
  Vector6 hydrostatic_b = Vector6::Zero();  ///< -g(eta)
  /// -C_RB(nu) nu - C_A(nu_r) nu_r + M_A nu_c' (the inertial terms moved to the right-hand side)
  Vector6 coriolis_b = Vector6::Zero();
  Vector6 nu_r_b = Vector6::Zero();  ///< velocity relative to the water
  Vector6 total() const { return control_b + damping_b + hydrostatic_b + coriolis_b; }
};

class VehicleModel {
 public:
  /// Gain of the quaternion norm feedback in the kinematics [1/s].
  static constexpr double kQuaternionNormGain = 1.0;

  /// Builds the model; surfaces named by the damping are resolved through
  /// `resolver` once. InputError (prefixed with the vehicle's file) when the
  /// damping cannot be built (see DampingModel) or the mass matrix is not
  /// symmetric positive definite.
  explicit VehicleModel(VehicleDescription description, const SurfaceResolver& resolver = {});

  /// The same vehicle with another damping model (a Monte Carlo draw of this
  /// one's, src/dynamics/damping_draws.hpp): it must read the same
  /// disturbances (std::invalid_argument otherwise).
  VehicleModel with_damping(DampingModel damping) const;

  const VehicleDescription& description() const noexcept { return description_; }
  const Matrix6& rigid_body_mass() const noexcept { return m_rb_; }
  const Matrix6& added_mass() const noexcept { return m_a_; }
  /// M = M_RB + M_A and its inverse.
  const Matrix6& mass_matrix() const noexcept { return m_; }
  const Matrix6& mass_matrix_inverse() const noexcept { return m_inv_; }
  const DampingModel& damping() const noexcept { return damping_; }
  const std::vector<std::string>& disturbance_names() const noexcept { return damping_.disturbance_names(); }
  double weight_N() const noexcept { return weight_N_; }
  double buoyancy_N() const noexcept { return description_.buoyancy_N; }

  /// A thrust command limited to the thruster's range [N].
  double clamp_thrust(std::size_t thruster, double thrust_N) const;
  /// The generalized force of thrusts thrust_N (one per thruster, used as given) [N, N m].
  Vector6 thrust_force(std::span<const double> thrust_N) const;
  /// -g(eta): weight at the CG and buoyancy at the CB in body axes, for a unit q_nb.
  Vector6 hydrostatic_force(const Quaternion4& q_nb) const;
  /// 1/2 nu^T M nu [J]: the kinetic energy of body and entrained water (no current).
  double kinetic_energy(const Vector6& nu_b) const { return 0.5 * nu_b.dot(m_ * nu_b); }

  /// Every term of the equation of motion at state x.
  ForceBreakdown forces(const StateVector& x, const ModelInputs& inputs) const;
  /// The same terms without evaluating the damping (damping_b is zero): the
  /// rigid-body, added-mass and hydrostatic part, which no surface range limits.
  ForceBreakdown undamped_forces(const StateVector& x, const ModelInputs& inputs) const;
  /// x' at state x. Allocates nothing.
  void derivative(const StateVector& x, const ModelInputs& inputs, StateVector& x_dot) const;

  /// motion::kLanes states side by side: row i holds state component i of
  /// every lane (so that a row is one SIMD operand).
  using LaneState = Eigen::Matrix<double, 13, motion::kLanes, Eigen::RowMajor>;
  /// x' of kLanes vehicles, lane l this vehicle with lane l's damping model
  /// (the drawn models of an ensemble, reading this model's disturbances):
  /// lane l's numbers are derivative()'s for with_damping(that model), bit for
  /// bit; the rigid-body arithmetic serves every lane at once. Allocates
  /// nothing.
  void derivative_lanes(const DampingLanes& damping, const LaneState& x, const ModelInputs& inputs,
                        LaneState& x_dot) const;

 private:
  /// Every term but the control force at state x (13 numbers per lane).
  template <class T, class AddDamping>
  void motion_terms(const T* x, const ModelInputs& inputs, AddDamping&& add_damping, motion::Terms<T>& terms) const;
  /// x' (13 numbers per lane) from the terms at x.
  template <class T>
  void rates(const T* x, const Vector6& tau_b, const motion::Terms<T>& terms, T* x_dot) const;
  /// out (6) += this model's damping force at nu_r (6).
  void add_damping(const double* nu_r, const ModelInputs& inputs, double* out) const;

  VehicleDescription description_;
  Matrix6 m_rb_;
  Matrix6 m_a_;
  Matrix6 m_;
  Matrix6 m_inv_;
  double weight_N_ = 0.0;
  Eigen::Matrix<double, 6, Eigen::Dynamic> thrust_allocation_;  // column i: (d_i, r_i x d_i)
  DampingModel damping_;
};

}  // namespace hydrocoef
