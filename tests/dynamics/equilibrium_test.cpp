// Steady states: the ASR-V constant-torque yaw test (the paper's calibrated
// 0.0027 and 0.0045 N m) against the closed-form root of the fitted law; a
// negative torque against an independent bisection; surge; drift with a
// current; damping from a lookup surface; surge damping from two-axis GP,
// grid and RBF surfaces X(u, v) against the steady state of a simulation;
// no steady state without damping.
#include "src/dynamics/equilibrium.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "src/dynamics/damping_draws.hpp"
#include "src/dynamics/ensemble.hpp"
#include "src/dynamics/simulation.hpp"
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

// Surge drag of a body moving at (u, v): X = -c u sqrt(u^2 + v^2) - d u [N],
// the ASR-V surge law when v = 0. A thrust of 0.13 N gives about 0.107 m/s.
double surge_drag(double u, double v) { return -11.0365 * u * std::hypot(u, v) - 0.0155 * u; }

// Synthetic CFD runs of the drag on a 6 x 5 lattice over u in [0.05, 0.3],
// v in [-0.1, 0.1], none at rest: the samples every surface kind below is
// built from. Below u = 0.05 each surface is clamped (flat in u), so from rest
// the slope Newton's method sees along u is zero: only following the motion
// (the thrust accelerates the body into the runs' range) finds the root.
struct DragRuns {
  std::vector<double> u, v, points, x;
};
DragRuns drag_runs() {
  DragRuns runs;
  for (int i = 1; i <= 6; ++i) runs.u.push_back(0.05 * i);
  for (int j = -2; j <= 2; ++j) runs.v.push_back(0.05 * j);
  for (const double v : runs.v)
    for (const double u : runs.u) {  // u fastest, the grid table's layout
      runs.points.insert(runs.points.end(), {u, v});
      runs.x.push_back(surge_drag(u, v));
    }
  return runs;
}

CoefficientSurface drag_surface(CoefficientSurface::Kind kind) {
  const DragRuns runs = drag_runs();
  switch (kind) {
    case CoefficientSurface::Kind::Gp: {
      GpOptions options;
      options.starts = 2;
      return CoefficientSurface(GpSurfaces(2, runs.points, 1, runs.x, {}, options, {"u", "v"},
                                           {RbfOutOfRange::Clamp, RbfOutOfRange::Extrapolate}),
                                {"u", "v"}, {"X"});
    }
    case CoefficientSurface::Kind::Grid:
      return CoefficientSurface(GridTable({{"u", runs.u, Extrapolation::Clamp}, {"v", runs.v, Extrapolation::Linear}},
                                          {"X"}, runs.x, Interpolation::Pchip));
    case CoefficientSurface::Kind::Rbf: {
      RbfOptions options;
      options.out_of_range = {RbfOutOfRange::Clamp, RbfOutOfRange::Extrapolate};
      return CoefficientSurface(RbfSurface(2, runs.points, 1, runs.x, options), {"u", "v"}, {"X"});
    }
  }
  return drag_surface(CoefficientSurface::Kind::Gp);
}

/// ASR-V with its surge damping read from `surface` at (u, v), and damping
/// in every other DOF (a simulation settles only when every DOF is damped;
/// the yaw law without the fitted zero-rate bias, which would turn the body).
VehicleModel surface_drag_vehicle(const CoefficientSurface& surface) {
  VehicleDescription d = test::asr_v_vehicle(test::fit_asr_v_yaw_law());
  d.damping[0] = {DofDamping::Kind::Surface, {}, {}, "drag", "X", {}, SignConvention::OnBody};
  for (const std::size_t dof : {1, 2, 3, 4, 5}) {
    d.damping[dof].kind = DofDamping::Kind::Law;
    const std::string x(1, "uvwpqr"[dof]);
    d.damping[dof].law = parse_damping_terms(x + "," + x + "|" + x + "|");
    d.damping[dof].coefficients = dof < 3 ? std::vector<double>{-1.0, -11.0365} : std::vector<double>{-0.06, -0.08};
  }
  return VehicleModel(d, [&](const std::string&) { return surface; });
}

/// The velocity a simulation from rest under a constant force settles at.
Vector6 simulated_steady_state(const VehicleModel& model, const Vector6& tau_b) {
  Scenario scenario;
  scenario.duration_s = 400.0;
  scenario.output_rate_Hz = 0.1;
  scenario.integrator.method = IntegratorSettings::Method::DormandPrince45;
  scenario.integrator.max_step_s = 1.0;
  ScenarioSegment segment;
  segment.tau_b = tau_b;
  scenario.segments = {segment};
  const SimulationResult result = simulate_model(model, scenario);
  const std::size_t n = result.samples.size();
  // Settled: the last two samples (10 s apart) agree.
  EXPECT_LT((velocity_b(result.final_state) - result.samples[n - 2].nu_b).cwiseAbs().maxCoeff(), 1e-9);
  return velocity_b(result.final_state);
}

// The 2-D surfaces of CFD runs: the equilibrium is the state a simulation
// settles at, for a GP, a PCHIP grid and a cubic RBF alike.
TEST(Equilibrium, TwoAxisSurfacesSettleWhereTheSimulationDoes) {
  for (const auto kind :
       {CoefficientSurface::Kind::Gp, CoefficientSurface::Kind::Grid, CoefficientSurface::Kind::Rbf}) {
    const CoefficientSurface surface = drag_surface(kind);
    SCOPED_TRACE(surface.method_name());
    const VehicleModel model = surface_drag_vehicle(surface);
    EquilibriumInputs in;
    in.tau_b[0] = 0.13;
    const EquilibriumResult eq = solve_equilibrium(model, in);
    ASSERT_TRUE(eq.converged) << eq.residual_b.transpose();
    EXPECT_GT(eq.continuation_s, 0.0);  // Newton alone stays at rest
    const Vector6 settled = simulated_steady_state(model, in.tau_b);
    EXPECT_NEAR(settled[0], 0.107, 0.002);  // the drag law's root, about
    EXPECT_LT((eq.nu_b - settled).cwiseAbs().maxCoeff(), 1e-6) << eq.nu_b.transpose() << " / " << settled.transpose();
    EXPECT_NEAR(eq.forces.damping_b[0], -0.13, 1e-9);
  }
}

// The band of the 2-D GP surface: every draw reaches a steady state, and the
// nominal one lies inside the 95 % interval.
TEST(Equilibrium, SamplesOfATwoAxisGpSurfaceGiveABand) {
  const VehicleModel model = surface_drag_vehicle(drag_surface(CoefficientSurface::Kind::Gp));
  const DampingDraws draws(model.damping(), model.description().damping);
  EquilibriumInputs in;
  in.tau_b[0] = 0.13;
  const EquilibriumResult nominal = solve_equilibrium(model, in);
  ASSERT_TRUE(nominal.converged);
  EnsembleOptions options;
  options.samples = 16;
  options.percentiles = {2.5, 50.0, 97.5};
  options.threads = 1;
  const EquilibriumSamples band = solve_equilibrium_samples(model, draws, in, options);
  EXPECT_EQ(band.samples, 16u);
  EXPECT_GT(band.standard_deviation[0], 0.0);
  EXPECT_LE(band.percentile_values[0][0], nominal.nu_b[0]);
  EXPECT_GE(band.percentile_values[2][0], nominal.nu_b[0]);
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
