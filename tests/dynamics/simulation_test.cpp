// Scenario runs: the ASR-V constant-torque yaw test (0.0027 and 0.0045 N m,
// RK4 and Dormand–Prince) settles at the root of the fitted damping law;
// output timing; piecewise inputs; drift with a current; thruster commands
// (clamped, named) and inputs the vehicle cannot take.
#include "src/dynamics/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/dynamics/asr_v_fixture.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

Scenario yaw_scenario(double tau, IntegratorSettings::Method method) {
  Scenario s = load_scenario(std::string(HYDROCOEF_SOURCE_DIR "/examples/asr-v/scenario-yaw-") +
                             (tau == 0.0027 ? "0.0027" : "0.0045") + ".json");
  s.integrator.method = method;
  // The example's 1 ms RK4 step, coarsened for the sanitizer build's speed: the
  // steady state is a fixed point of RK4 whatever the step.
  s.integrator.step_s = 0.005;
  return s;
}

class AsrVYaw : public ::testing::TestWithParam<std::tuple<double, IntegratorSettings::Method>> {};

TEST_P(AsrVYaw, SettlesAtTheRootOfTheDampingLaw) {
  const auto [tau, method] = GetParam();
  const test::YawLaw law = test::fit_asr_v_yaw_law();
  const VehicleModel model(test::asr_v_vehicle(law));
  const Scenario scenario = yaw_scenario(tau, method);
  ASSERT_EQ(scenario.segments[0].tau_b[5], tau);
  const SimulationResult result = simulate_model(model, scenario);
  ASSERT_EQ(result.samples.size(), 601u);  // 60 s at 10 Hz, and t = 0
  const double root = test::positive_yaw_root(law, tau);
  EXPECT_NEAR(velocity_b(result.final_state)[5], root, 1e-6);
  EXPECT_NEAR(result.samples.back().nu_b[5], root, 1e-6);
  // From rest, yaw acceleration (tau + c) / I_z (a sphere adds no yaw inertia),
  // then rising with decreasing acceleration, never overshooting.
  const double i_z = 0.4 * 6.7 * 0.15 * 0.15;
  const auto& first = result.samples.front();
  EXPECT_NEAR((model.mass_matrix_inverse() * first.forces.total())[5], (tau + law.c) / i_z, 1e-12);
  for (std::size_t k = 1; k < result.samples.size(); ++k) {
    EXPECT_GE(result.samples[k].nu_b[5], result.samples[k - 1].nu_b[5] - 1e-12);
    EXPECT_LE(result.samples[k].nu_b[5], root + 1e-9);
  }
  // A pure yaw: nothing else moves.
  EXPECT_LT(result.samples.back().nu_b.head<5>().cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT(result.max_attitude_norm_error, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(PaperTorques, AsrVYaw,
                         ::testing::Combine(::testing::Values(0.0027, 0.0045),
                                            ::testing::Values(IntegratorSettings::Method::Rk4,
                                                              IntegratorSettings::Method::DormandPrince45)));

TEST(Simulation, OutputTimesAndPiecewiseInputs) {
  const VehicleModel model(test::asr_v_vehicle(test::fit_asr_v_yaw_law()));
  Scenario s;
  s.file = "inline.json";
  s.duration_s = 2.05;
  s.output_rate_Hz = 4.0;
  s.integrator.step_s = 0.01;
  s.segments.resize(2);
  s.segments[0].tau_b[5] = 0.004;
  s.segments[1].start_s = 1.3;  // between two output times
  const SimulationResult result = simulate_model(model, s);
  // 0, 0.25, ..., 2.0 and the end 2.05.
  ASSERT_EQ(result.samples.size(), 10u);
  for (std::size_t k = 0; k < 9; ++k) EXPECT_EQ(result.samples[k].t_s, 0.25 * static_cast<double>(k));
  EXPECT_EQ(result.samples.back().t_s, 2.05);
  EXPECT_EQ(result.samples[5].forces.control_b[5], 0.004);  // t = 1.25
  EXPECT_EQ(result.samples[6].forces.control_b[5], 0.0);    // t = 1.5
  // The steps fit the intervals: 0..1.25 (125 steps), 1.25..1.3 (5), 1.3..1.5 (20), ... 2.05 (5).
  EXPECT_EQ(result.steps, 205u);
  // After the torque is removed the rate falls.
  EXPECT_LT(result.samples.back().nu_b[5], result.samples[5].nu_b[5]);
}

TEST(Simulation, DriftsWithTheCurrent) {
  VehicleDescription d = test::asr_v_vehicle(test::fit_asr_v_yaw_law());
  // Strong linear terms so that it settles in seconds, and damped roll, pitch
  // and yaw (an undamped bottom-heavy body would keep rocking after the
  // initial push and move CO to and fro).
  for (std::size_t k = 0; k < 6; ++k) {
    d.damping[k].kind = DofDamping::Kind::Law;
    const std::string x(1, "uvwpqr"[k]);
    d.damping[k].law = parse_damping_terms(x + "," + x + "|" + x + "|");
    d.damping[k].coefficients = {k < 3 ? -5.0 : -0.5, -1.0};
  }
  const VehicleModel model(d);
  Scenario s;
  s.duration_s = 60.0;
  s.output_rate_Hz = 1.0;
  s.integrator.method = IntegratorSettings::Method::DormandPrince45;
  s.initial_euler_rad = Vector3(0.0, 0.0, 0.5);
  s.segments.resize(1);
  s.segments[0].current_n = Vector3(0.1, 0.05, 0.0);
  const SimulationResult result = simulate_model(model, s);
  const auto& last = result.samples.back();
  const Vector3 current_b = rotation_body_to_ned(last.q_nb).transpose() * Vector3(0.1, 0.05, 0.0);
  EXPECT_LT((last.nu_b.head<2>() - current_b.head<2>()).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_LT(last.forces.nu_r_b.head<3>().norm(), 1e-7);
  // Carried along: the position grows at the current's speed.
  const auto& before = result.samples[result.samples.size() - 11];
  EXPECT_NEAR((last.p_n - before.p_n).x() / 10.0, 0.1, 1e-6);
  EXPECT_NEAR((last.p_n - before.p_n).y() / 10.0, 0.05, 1e-6);
}

// kLanes vehicles with their own damping in lock-step: each lane's states at
// the output times are simulate()'s for that vehicle, bit for bit, through a
// change of torque and a current switched on; an adaptive scenario is
// refused, and a lane that leaves the finite numbers fails the run.
TEST(Simulation, LanesAreEachVehiclesOwnRun) {
  VehicleDescription d = test::asr_v_vehicle(test::fit_asr_v_yaw_law());
  std::vector<DampingModel> damping;
  for (std::size_t l = 0; l < motion::kLanes; ++l) {
    for (std::size_t k = 0; k < 6; ++k) {
      d.damping[k].kind = DofDamping::Kind::Law;
      const std::string x(1, "uvwpqr"[k]);
      d.damping[k].law = parse_damping_terms(x + "," + x + "|" + x + "|");
      d.damping[k].coefficients = {(k < 3 ? -5.0 : -0.5) * (1.0 + 0.1 * static_cast<double>(l)), -1.0};
    }
    damping.push_back(VehicleModel(d).damping());
  }
  const VehicleModel model(d);
  std::array<const DampingModel*, motion::kLanes> models;
  for (std::size_t l = 0; l < models.size(); ++l) models[l] = &damping[l];
  Scenario s;
  s.duration_s = 4.0;
  s.output_rate_Hz = 5.0;
  s.integrator.method = IntegratorSettings::Method::Rk4;
  s.integrator.step_s = 0.01;
  s.initial_euler_rad = Vector3(0.2, -0.1, 0.5);
  s.initial_nu_b << 0.1, 0.0, -0.05, 0.0, 0.2, 0.1;
  s.segments.resize(2);
  s.segments[0].tau_b << 0.5, 0.0, 0.0, 0.0, 0.0, 0.01;
  s.segments[1].start_s = 1.55;  // between two outputs
  s.segments[1].current_n = Vector3(0.1, 0.05, 0.0);
  const LaneSimulation lanes = simulate_lanes(model, models, s);
  for (std::size_t l = 0; l < models.size(); ++l) {
    const SimulationResult own = simulate_model(model.with_damping(damping[l]), s);
    ASSERT_EQ(lanes.states.size(), own.samples.size());
    for (std::size_t k = 0; k < own.samples.size(); ++k) {
      EXPECT_EQ(lanes.t_s[k], own.samples[k].t_s);
      const StateVector x = lanes.states[k].col(static_cast<Eigen::Index>(l));
      for (Eigen::Index i = 0; i < 3; ++i) EXPECT_EQ(x[i], own.samples[k].p_n[i]) << "lane " << l << " at " << k;
      for (Eigen::Index i = 0; i < 4; ++i)
        EXPECT_EQ(unit_attitude(attitude_nb(x))[i], own.samples[k].q_nb[i]) << "lane " << l << " at " << k;
      for (Eigen::Index i = 0; i < 6; ++i) EXPECT_EQ(x[7 + i], own.samples[k].nu_b[i]) << "lane " << l << " at " << k;
    }
  }
  // The lanes moved apart: their damping differs.
  EXPECT_NE(lanes.states.back()(7, 0), lanes.states.back()(7, 1));

  Scenario adaptive = s;
  adaptive.integrator.method = IntegratorSettings::Method::DormandPrince45;
  EXPECT_THROW(simulate_lanes(model, models, adaptive), std::invalid_argument);
  // A segment at the very end that sets a disturbance beyond a surface's axis
  // (policy "error"): simulate() fails at its last output, and so do the lanes.
  {
    VehicleDescription e = d;
    e.damping[1].kind = DofDamping::Kind::Surface;
    e.damping[1].surface = "sway";
    e.damping[1].output = "Y";
    e.damping[1].law = {};
    e.damping[1].coefficients.clear();
    const auto resolver = [](const std::string&) {
      std::vector<GridAxis> axes{{"current_y", {0.0, 0.5, 1.0}, Extrapolation::Error}};
      return CoefficientSurface(GridTable(axes, {"Y"}, {0.0, -0.1, -0.3}, Interpolation::Linear));
    };
    const VehicleModel swaying(e, resolver);
    std::array<const DampingModel*, motion::kLanes> same;
    same.fill(&swaying.damping());
    Scenario late = s;
    late.segments[0].disturbances = {{"current_y", 0.5}};
    late.segments[1].start_s = late.duration_s;
    late.segments[1].disturbances = {{"current_y", 2.0}};
    expect_input_error([&] { simulate_model(swaying, late); }, {"current_y", "outside"});
    expect_input_error([&] { simulate_lanes(swaying, same, late); }, {"current_y", "outside"});
    late.segments[1].disturbances = {{"current_y", 1.0}};
    EXPECT_EQ(simulate_lanes(swaying, same, late).states.size(), simulate_model(swaying, late).samples.size());
  }
  // Surge damping that pushes instead of holding back: that lane runs away.
  d.damping[0].coefficients = {-5.0, 1e6};
  damping[3] = VehicleModel(d).damping();
  expect_input_error([&] { simulate_lanes(model, models, s); }, {"finite"});
}

TEST(Simulation, ThrusterCommands) {
  VehicleDescription d = test::asr_v_vehicle(test::fit_asr_v_yaw_law());
  d.thrusters.push_back({"port", Vector3(0.0, -0.12, 0.0), Vector3::UnitX(), -1.0, 1.0});
  d.thrusters.push_back({"starboard", Vector3(0.0, 0.12, 0.0), Vector3::UnitX(), -1.0, 1.0});
  const VehicleModel model(d);
  Scenario s;
  s.file = "thrust.json";
  s.duration_s = 1.0;
  s.segments.resize(2);
  s.segments[0].thrust_N = {0.01, -2.0};  // the second is clamped to -1 N
  s.segments[1].start_s = 0.5;
  s.segments[1].thrust_by_name_N = {{"port", 0.02}};
  std::vector<std::string> notes;
  const SegmentInputs first = segment_inputs(model, s, 0, &notes);
  EXPECT_NEAR(first.tau_b[0], 0.01 - 1.0, 1e-15);
  EXPECT_NEAR(first.tau_b[5], 0.12 * 0.01 + 0.12 * 1.0, 1e-15);  // N = -y f
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("starboard"), std::string::npos);
  const SegmentInputs second = segment_inputs(model, s, 1, nullptr);
  EXPECT_NEAR(second.tau_b[0], 0.02, 1e-15);

  s.segments[1].thrust_by_name_N = {{"bow", 0.02}};
  expect_input_error([&] { simulate_model(model, s); },
                     {"thrust.json", "segments[1].thrusters.bow", "port, starboard"});
  s.segments[1].thrust_by_name_N = {};
  s.segments[1].thrust_N = {0.1};
  expect_input_error([&] { simulate_model(model, s); }, {"thrust.json", "segments[1].thrusters", "found 1", "(2"});
  s.segments[1].thrust_N = {};
  s.segments[1].disturbances = {{"current_v", 0.1}};
  expect_input_error([&] { simulate_model(model, s); }, {"thrust.json", "segments[1].disturbances.current_v", "none"});
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

// What cannot be done is refused before the first step, with the limit; a
// state that leaves the finite numbers stops the run where it happened.
TEST(SimulationLimits, StepsSamplesAndTolerancesThatCannotBeHonouredAreRefused) {
  const VehicleModel model(test::asr_v_vehicle(test::fit_asr_v_yaw_law()));
  Scenario s;
  s.file = "limits.json";
  s.duration_s = 60.0;
  s.output_rate_Hz = 10.0;
  s.segments.resize(1);
  const auto refused = [&](const Scenario& scenario, const std::vector<std::string>& pieces) {
    try {
      (void)simulate_model(model, scenario);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
      for (const auto& piece : pieces)
        EXPECT_NE(std::string(error.what()).find(piece), std::string::npos) << error.what();
    }
  };
  for (const double step : {1e-300, 1e-30, 1e-19}) {
    Scenario tiny = s;
    tiny.integrator.step_s = step;
    refused(tiny, {"limits.json", "integrator.step", "expected at most 1e10"});
  }
  Scenario long_run = s;
  long_run.duration_s = 1e12;
  refused(long_run, {"output_rate", "expected at most 1e7"});
  Scenario fast_output = s;
  fast_output.output_rate_Hz = 1e12;
  refused(fast_output, {"output_rate", "output samples"});
  Scenario strict = s;
  strict.integrator.method = IntegratorSettings::Method::DormandPrince45;
  strict.integrator.relative_tolerance = 1e-300;
  strict.integrator.absolute_tolerance = 1e-300;
  refused(strict, {"integrator.rtol", "2.2e-14"});

  Scenario huge = s;
  huge.duration_s = 1.0;
  huge.integrator.step_s = 0.01;
  huge.segments[0].tau_b[5] = 1e308;
  refused(huge, {"limits.json", "left the finite numbers", "between t = 0"});
}

}  // namespace
}  // namespace hydrocoef
