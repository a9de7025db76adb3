// The equation of motion: energy and momentum of a tumbling body with
// off-diagonal inertia, CG offset and full added mass (no damping, gravity or
// control) conserved over 100 s; hydrostatic restoring against Fossen eq. 4.6
// and the small-angle roll period; thruster allocation of an H layout; the
// derivative allocates nothing.
#include "src/dynamics/vehicle_model.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numbers>
#include <random>

#include "src/dynamics/damping_lanes.hpp"
#include "src/dynamics/integrators.hpp"
#include "tests/support/count_allocations.hpp"

namespace hydrocoef {
namespace {

VehicleDescription tumbling_body() {
  VehicleDescription v;
  v.mass_kg = 4.0;
  v.inertia_cg_b << 0.30, 0.02, -0.03,  //
      0.02, 0.50, 0.04,                 //
      -0.03, 0.04, 0.70;
  v.r_g_b = Vector3(0.02, -0.01, 0.03);
  v.gravity_m_s2 = 0.0;  // g = 0: no restoring
  v.buoyancy_N = 0.0;
  // A full symmetric added-mass matrix with couplings (positive definite).
  Matrix6 a;
  a << 2.0, 0.1, 0.0, 0.0, 0.05, 0.0,  //
      0.1, 3.0, 0.2, 0.0, 0.0, 0.03,   //
      0.0, 0.2, 4.0, 0.02, 0.0, 0.0,   //
      0.0, 0.0, 0.02, 0.1, 0.0, 0.0,   //
      0.05, 0.0, 0.0, 0.0, 0.2, 0.01,  //
      0.0, 0.03, 0.0, 0.0, 0.01, 0.15;
  v.added_mass_b = a;
  return v;
}

// Impulse of body + fluid in NED (Kirchhoff): P = R (M11 v + M12 w), H = R (M21 v + M22 w) + p x P.
std::pair<Vector3, Vector3> impulse_n(const VehicleModel& model, const StateVector& x) {
  const Vector6 h_b = model.mass_matrix() * velocity_b(x);
  const Matrix3 r = rotation_body_to_ned(attitude_nb(x).normalized());
  const Vector3 p = r * h_b.head<3>();
  return {p, r * h_b.tail<3>() + position_n(x).cross(p)};
}

TEST(VehicleModel, TumblingBodyConservesEnergyAndImpulseFor100Seconds) {
  const VehicleModel model(tumbling_body());
  Vector6 nu0;
  nu0 << 0.3, -0.2, 0.1, 1.5, -0.8, 0.6;  // tumbling: rates about all three axes
  StateVector x = make_state(Vector3(0.1, 0.2, 0.3), quaternion_from_euler(Vector3(0.2, -0.1, 0.5)), nu0);
  const double energy0 = model.kinetic_energy(nu0);
  const auto [p0, h0] = impulse_n(model, x);
  ModelInputs inputs;
  auto f = [&](double, const StateVector& s, StateVector& ds) { model.derivative(s, inputs, ds); };
  Rk4Workspace<StateVector> w;
  const double h = 2e-3;
  double worst = 0.0;
  for (int i = 0; i < 50000; ++i) {
    rk4_step(f, i * h, h, x, w);
    normalize_attitude(x);
    if (i % 500 == 499) worst = std::max(worst, std::abs(model.kinetic_energy(velocity_b(x)) / energy0 - 1.0));
  }
  EXPECT_LT(worst, 1e-9);
  std::cout << "largest relative energy change over 100 s: " << worst << '\n';
  // The body did tumble: its velocity in body axes changed a lot.
  EXPECT_GT((velocity_b(x) - nu0).norm(), 0.1);
  const auto [p1, h1] = impulse_n(model, x);
  // Impulses drift only by RK4's truncation error (h^4); a wrong C would move them at O(1).
  EXPECT_LT((p1 - p0).norm(), 1e-8 * p0.norm());
  EXPECT_LT((h1 - h0).norm(), 1e-8 * h0.norm());
}

TEST(VehicleModel, CoriolisTermDoesNoWork) {
  const VehicleModel model(tumbling_body());
  Vector6 nu;
  nu << 0.5, 0.1, -0.3, 0.9, 1.1, -0.4;
  const StateVector x = make_state(Vector3::Zero(), quaternion_from_euler(Vector3(0.3, 0.2, 0.1)), nu);
  const ForceBreakdown f = model.forces(x, ModelInputs{});
  EXPECT_NEAR(nu.dot(f.coriolis_b), 0.0, 1e-13);
  EXPECT_GT(f.coriolis_b.norm(), 0.1);
}

VehicleDescription bottom_heavy(double z_g, double inertia) {
  VehicleDescription v;
  v.mass_kg = 6.7;
  v.inertia_cg_b = Matrix3::Identity() * inertia;
  v.r_g_b = Vector3(0.0, 0.0, z_g);
  v.buoyancy_N = v.mass_kg * v.gravity_m_s2;
  return v;
}

TEST(VehicleModel, HydrostaticsMatchFossenEq46) {
  VehicleDescription d = bottom_heavy(0.02, 0.06);
  d.r_b_b = Vector3(0.01, -0.005, -0.01);
  d.r_g_b = Vector3(-0.004, 0.003, 0.02);
  d.buoyancy_N = 70.0;  // not neutral
  const VehicleModel model(d);
  const double W = d.mass_kg * d.gravity_m_s2, B = d.buoyancy_N;
  const double phi = 0.3, theta = -0.2, psi = 1.0;
  const Vector6 tau = model.hydrostatic_force(quaternion_from_euler(Vector3(phi, theta, psi)));
  const double sp = std::sin(phi), cp = std::cos(phi), st = std::sin(theta), ct = std::cos(theta);
  const Vector3 rg = d.r_g_b, rb = d.r_b_b;
  Vector6 g;  // Fossen eq. 4.6, g(eta); the force on the body is -g
  g << (W - B) * st, -(W - B) * ct * sp, -(W - B) * ct * cp,
      -(rg.y() * W - rb.y() * B) * ct * cp + (rg.z() * W - rb.z() * B) * ct * sp,
      (rg.z() * W - rb.z() * B) * st + (rg.x() * W - rb.x() * B) * ct * cp,
      -(rg.x() * W - rb.x() * B) * ct * sp - (rg.y() * W - rb.y() * B) * st;
  EXPECT_LT((tau + g).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(VehicleModel, RollPeriodOfABottomHeavyBodyIsThePendulumPeriod) {
  // W = B and CG below CB: a pure restoring couple W z_g sin(phi) about the
  // CG, which stays put; small-angle period T = 2 pi sqrt(I_gx / (W z_g)).
  const double z_g = 0.02, inertia = 0.0603;
  const VehicleModel model(bottom_heavy(z_g, inertia));
  const double W = model.weight_N();
  const double period = 2.0 * std::numbers::pi * std::sqrt(inertia / (W * z_g));
  const double phi0 = 0.01;
  // Start at rest with the CO moved so that the CG sits at the origin.
  const Quaternion4 q0 = quaternion_from_euler(Vector3(phi0, 0.0, 0.0));
  StateVector x = make_state(-rotation_body_to_ned(q0) * Vector3(0, 0, z_g), q0, Vector6::Zero());
  ModelInputs inputs;
  auto f = [&](double, const StateVector& s, StateVector& ds) { model.derivative(s, inputs, ds); };
  Rk4Workspace<StateVector> w;
  const double h = 5e-4;
  std::vector<double> upward_crossings;
  double phi_prev = phi0;
  double t = 0.0;
  while (upward_crossings.size() < 4) {
    rk4_step(f, t, h, x, w);
    normalize_attitude(x);
    t += h;
    const double phi = euler_from_quaternion(attitude_nb(x))[0];
    if (phi_prev < 0.0 && phi >= 0.0) upward_crossings.push_back(t - h * phi / (phi - phi_prev));
    phi_prev = phi;
    ASSERT_LT(t, 20.0 * period);
  }
  const double measured = (upward_crossings[3] - upward_crossings[0]) / 3.0;
  // Finite amplitude lengthens the period by phi0^2/16 = 6e-6.
  EXPECT_NEAR(measured / period, 1.0, 2e-5);
  // The CG did not move (no net force).
  const Vector3 cg_n = position_n(x) + rotation_body_to_ned(attitude_nb(x)) * Vector3(0, 0, z_g);
  EXPECT_LT(cg_n.norm(), 1e-9);
}

TEST(VehicleModel, DampedRollReturnsUpright) {
  VehicleDescription d = bottom_heavy(0.02, 0.0603);
  d.damping[3].kind = DofDamping::Kind::Law;
  d.damping[3].law = parse_damping_terms("p,p|p|");
  d.damping[3].coefficients = {-0.05, -0.08};
  d.added_mass_b = sphere_added_mass(998.2, 0.15);
  const VehicleModel model(d);
  StateVector x = make_state(Vector3::Zero(), quaternion_from_euler(Vector3(0.5, 0.0, 0.0)), Vector6::Zero());
  ModelInputs inputs;
  auto f = [&](double, const StateVector& s, StateVector& ds) { model.derivative(s, inputs, ds); };
  Rk4Workspace<StateVector> w;
  for (int i = 0; i < 15000; ++i) {
    rk4_step(f, i * 2e-3, 2e-3, x, w);
    normalize_attitude(x);
  }
  EXPECT_LT(std::abs(euler_from_quaternion(attitude_nb(x))[0]), 1e-3);
}

TEST(VehicleModel, HThrustersMakeAPureYawMoment) {
  VehicleDescription d = bottom_heavy(0.02, 0.06);
  for (const auto& [name, x, y] :
       {std::tuple{"pf", 0.06, -0.12}, {"pa", -0.06, -0.12}, {"sf", 0.06, 0.12}, {"sa", -0.06, 0.12}})
    d.thrusters.push_back({name, Vector3(x, y, 0.05), Vector3::UnitX(), -1.0, 1.0});
  const VehicleModel model(d);
  // Port forward, starboard backward: N = -sum y_i f_i = 2 * 0.12 * 0.5 * 2.
  const std::vector<double> thrust{0.5, 0.5, -0.5, -0.5};
  const Vector6 tau = model.thrust_force(thrust);
  Vector6 expected = Vector6::Zero();
  expected[5] = 0.24;
  EXPECT_LT((tau - expected).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(model.clamp_thrust(0, 3.0), 1.0);
  EXPECT_EQ(model.clamp_thrust(0, -3.0), -1.0);
}

// derivative() sums the terms as it goes; forces() keeps them apart. Both
// are one equation of motion: nu' = M^-1 (control + damping + hydrostatic +
// coriolis), p' = R nu1, q' the quaternion rate, with and without a current
// (which changes the damping's velocity and the Coriolis terms).
TEST(VehicleModel, DerivativeIsTheBreakdownsTotal) {
  VehicleDescription d = tumbling_body();
  d.gravity_m_s2 = 9.81;
  d.buoyancy_N = 0.9 * d.mass_kg * 9.81;
  for (std::size_t k = 0; k < 6; ++k) {
    const std::string v(1, "uvwpqr"[k]);
    d.damping[k].kind = DofDamping::Kind::Law;
    d.damping[k].law = parse_damping_terms(v + "," + v + "|" + v + "|");
    d.damping[k].coefficients = {-0.1 * static_cast<double>(k + 1), -1.0};
  }
  const VehicleModel model(d);
  Vector6 nu;
  nu << 0.3, -0.2, 0.1, 0.5, -0.4, 0.6;
  const StateVector x = make_state(Vector3(1.0, 2.0, 3.0), quaternion_from_euler(Vector3(0.3, -0.2, 1.1)), nu);
  for (const Vector3& current : {Vector3::Zero().eval(), Vector3(0.2, -0.1, 0.05)}) {
    ModelInputs inputs;
    inputs.current_n = current;
    inputs.tau_b << 1.0, -2.0, 0.5, 0.1, -0.2, 0.3;
    StateVector dx;
    model.derivative(x, inputs, dx);
    const ForceBreakdown f = model.forces(x, inputs);
    const Vector6 nu_dot = model.mass_matrix_inverse() * f.total();
    EXPECT_LT((dx.segment<6>(state_index::kVelocity) - nu_dot).cwiseAbs().maxCoeff(), 1e-12 * nu_dot.norm());
    const Matrix3 r = rotation_body_to_ned(attitude_nb(x));
    EXPECT_LT((dx.segment<3>(state_index::kPosition) - r * nu.head<3>()).norm(), 1e-14);
    EXPECT_LT((dx.segment<4>(state_index::kAttitude) - quaternion_rate(attitude_nb(x), nu.tail<3>(), 1.0)).norm(),
              1e-15);
    // The relative velocity: nu minus the current in body axes.
    EXPECT_LT((f.nu_r_b.head<3>() - (nu.head<3>() - r.transpose() * current)).norm(), 1e-15);
    EXPECT_GT(f.damping_b.cwiseAbs().minCoeff(), 0.0);
  }
}

// kLanes vehicles with their own damping at their own states, at once: each
// lane's x' is derivative()'s for that vehicle, bit for bit, with and without
// a current.
TEST(VehicleModel, LaneDerivativesAreEachVehiclesOwn) {
  VehicleDescription d = tumbling_body();
  d.gravity_m_s2 = 9.81;
  d.buoyancy_N = 0.9 * d.mass_kg * 9.81;
  d.r_b_b = Vector3(0.0, 0.01, -0.02);
  std::vector<DampingModel> damping;
  for (std::size_t l = 0; l < motion::kLanes; ++l) {
    for (std::size_t k = 0; k < 6; ++k) {
      const std::string v(1, "uvwpqr"[k]);
      d.damping[k].kind = DofDamping::Kind::Law;
      d.damping[k].law = parse_damping_terms(v + "," + v + "|" + v + "|");
      d.damping[k].coefficients = {-0.1 * static_cast<double>(k + 1), -1.0 - 0.1 * static_cast<double>(l)};
    }
    damping.push_back(VehicleModel(d).damping());
  }
  const VehicleModel model(d);
  std::array<const DampingModel*, motion::kLanes> models;
  for (std::size_t l = 0; l < models.size(); ++l) models[l] = &damping[l];
  const DampingLanes lanes(models);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (const Vector3& current : {Vector3::Zero().eval(), Vector3(0.2, -0.1, 0.05)}) {
    ModelInputs inputs;
    inputs.current_n = current;
    inputs.tau_b << 1.0, -2.0, 0.5, 0.1, -0.2, 0.3;
    VehicleModel::LaneState x, x_dot;
    for (Eigen::Index l = 0; l < motion::kLanes; ++l) {
      Vector6 nu;
      for (Eigen::Index i = 0; i < 6; ++i) nu[i] = 0.5 * uniform(rng);
      // An attitude off the unit sphere, as within an RK4 step.
      x.col(l) = make_state(Vector3(uniform(rng), uniform(rng), uniform(rng)),
                            quaternion_from_euler(Vector3(uniform(rng), 0.5 * uniform(rng), 3.0 * uniform(rng))), nu);
      x.col(l).segment<4>(state_index::kAttitude) *= 1.0 + 1e-3 * uniform(rng);
    }
    model.derivative_lanes(lanes, x, inputs, x_dot);
    for (Eigen::Index l = 0; l < motion::kLanes; ++l) {
      StateVector own;
      model.with_damping(damping[static_cast<std::size_t>(l)]).derivative(x.col(l), inputs, own);
      for (Eigen::Index i = 0; i < 13; ++i)
        EXPECT_EQ(std::bit_cast<std::uint64_t>(x_dot(i, l)), std::bit_cast<std::uint64_t>(own[i]))
            << "lane " << l << ", component " << i;
    }
  }
}

TEST(VehicleModel, DerivativeAllocatesNothing) {
  VehicleDescription d = tumbling_body();
  for (std::size_t k = 0; k < 6; ++k) {
    d.damping[k].kind = DofDamping::Kind::Law;
    d.damping[k].law = parse_damping_terms(std::string(1, "uvwpqr"[k]) + "," + std::string(1, "uvwpqr"[k]) + "|" +
                                           std::string(1, "uvwpqr"[k]) + "|");
    d.damping[k].coefficients = {-0.1, -1.0};
  }
  const VehicleModel model(d);
  ModelInputs inputs;
  inputs.current_n = Vector3(0.1, 0.05, 0.0);
  StateVector x = make_state(Vector3::Zero(), quaternion_from_euler(Vector3(0.1, 0.2, 0.3)), Vector6::Constant(0.2));
  StateVector dx;
  const std::size_t before = test::allocation_count();
  for (int i = 0; i < 100; ++i) model.derivative(x, inputs, dx);
  EXPECT_EQ(test::allocation_count(), before);
  EXPECT_TRUE(dx.allFinite());
}

}  // namespace
}  // namespace hydrocoef
