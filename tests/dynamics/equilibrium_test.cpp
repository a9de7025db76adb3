// Steady states: the ASR-V constant-torque yaw test (the paper's calibrated
// 0.0027 and 0.0045 N m) against the closed-form root of the fitted law; a
// negative torque against an independent bisection; surge; drift with a
// current; damping from a lookup surface; no steady state without damping.
#include "src/dynamics/equilibrium.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/dynamics/asr_v_fixture.hpp"

namespace hydrocoef {
namespace {

double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if ((f(lo) < 0.0) == (f(mid) < 0.0))
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(Equilibrium, AsrVYawRateIsTheRootOfTheFittedLaw) {
  const test::YawLaw law = test::fit_asr_v_yaw_law();
  EXPECT_NEAR(law.a, -0.00607516, 1e-8);  // README / paper eq. 6
  EXPECT_NEAR(law.b, -0.0771371, 1e-7);
  const VehicleModel model(test::asr_v_vehicle(law));
  for (const double tau : {0.0027, 0.0045}) {
    EquilibriumInputs in;
    in.tau_b[5] = tau;
    const EquilibriumResult eq = solve_equilibrium(model, in);
    ASSERT_TRUE(eq.converged) << tau;
    const double root = test::positive_yaw_root(law, tau);
    EXPECT_NEAR(eq.nu_b[5], root, 1e-9) << tau;
    EXPECT_NEAR(law(root) + tau, 0.0, 1e-15);
    EXPECT_LT(eq.nu_b.head<5>().cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(eq.forces.damping_b[5], -tau, 1e-12);
  }
  // The roots themselves, for the record: about 0.153 and 0.206 rad/s.
  EXPECT_NEAR(test::positive_yaw_root(law, 0.0027), 0.153, 0.002);
  EXPECT_NEAR(test::positive_yaw_root(law, 0.0045), 0.206, 0.002);
}

TEST(Equilibrium, NegativeTorqueAndSurgeForce) {
  const test::YawLaw law = test::fit_asr_v_yaw_law();
  const VehicleModel model(test::asr_v_vehicle(law));
  EquilibriumInputs yaw_only;
  yaw_only.tau_b[5] = -0.0045;
  const double root = bisect([&](double r) { return law(r) - 0.0045; }, -1.0, 0.0);
  EXPECT_NEAR(solve_equilibrium(model, yaw_only).nu_b[5], root, 1e-9);
  // Surge alone (the yaw law's zero-rate bias would turn the body and couple
  // sway and roll through the Coriolis terms, so it is left out here).
  VehicleDescription no_yaw = test::asr_v_vehicle(law);
  no_yaw.damping[5] = {};
  EquilibriumInputs surge_only;
  surge_only.tau_b[0] = 0.5;
  const double u = bisect([](double x) { return -0.0155 * x - 11.0365 * x * std::abs(x) + 0.5; }, 0.0, 1.0);
  const EquilibriumResult surge = solve_equilibrium(VehicleModel(no_yaw), surge_only);
  ASSERT_TRUE(surge.converged);
  EXPECT_NEAR(surge.nu_b[0], u, 1e-9);
}

TEST(Equilibrium, DriftsWithTheCurrent) {
  VehicleDescription d = test::asr_v_vehicle(test::fit_asr_v_yaw_law());
  d.damping[5] = {};
  const VehicleModel model(d);
  EquilibriumInputs in;
  in.current_n = Vector3(0.08, -0.03, 0.0);
  in.q_nb = quaternion_from_euler(Vector3(0.0, 0.0, 0.7));
  const EquilibriumResult eq = solve_equilibrium(model, in);
  ASSERT_TRUE(eq.converged);
  const Vector3 current_b = rotation_body_to_ned(in.q_nb).transpose() * in.current_n;
  EXPECT_LT((eq.nu_b.head<2>() - current_b.head<2>()).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(eq.forces.nu_r_b.head<2>().norm(), 1e-9);
}

TEST(Equilibrium, FromALookupSurface) {
  // Yaw damping tabulated from the law on the table's own rates, PCHIP.
  const test::YawLaw law = test::fit_asr_v_yaw_law();
  std::vector<double> r, n;
  for (int i = -10; i <= 10; ++i) {
    r.push_back(0.03 * i);
    n.push_back(law(0.03 * i));
  }
  const CoefficientSurface surface(GridTable({{"r", r, Extrapolation::Linear}}, {"N"}, n, Interpolation::Pchip));
  VehicleDescription d = test::asr_v_vehicle(law);
  d.damping[5] = {DofDamping::Kind::Surface, {}, {}, "yaw", "N", {}, SignConvention::OnBody};
  const VehicleModel model(d, [&](const std::string&) { return surface; });
  EquilibriumInputs in;
  in.tau_b[5] = 0.0027;
  const EquilibriumResult eq = solve_equilibrium(model, in);
  ASSERT_TRUE(eq.converged);
  // The surface's own root, found by bisection on the surface.
  const double surface_root = bisect(
      [&](double x) {
        double out = 0.0;
        surface.evaluate(std::span<const double>(&x, 1), std::span<double>(&out, 1));
        return out + 0.0027;
      },
      0.0, 0.3);
  EXPECT_NEAR(eq.nu_b[5], surface_root, 1e-9);
  // and the interpolant is close to the law there.
  EXPECT_NEAR(eq.nu_b[5], test::positive_yaw_root(law, 0.0027), 1e-3);
}

TEST(Equilibrium, NoSteadyStateWithoutDamping) {
  const VehicleModel model(test::asr_v_vehicle(test::fit_asr_v_yaw_law()));
  EquilibriumInputs in;
  in.tau_b[2] = 0.1;  // heave: no damping law in this vehicle
  EXPECT_FALSE(solve_equilibrium(model, in).converged);
  // Surging while turning: with the CG below CO the Coriolis terms ask for a
  // roll moment that only heeling could balance; with the attitude held there
  // is no steady state, and the solver says so.
  EquilibriumInputs turning;
  turning.tau_b[0] = 0.5;
  turning.tau_b[5] = 0.0045;
  EXPECT_FALSE(solve_equilibrium(model, turning).converged);
}

}  // namespace
}  // namespace hydrocoef
