// Test helper of tests/runtime: a scenario stepped through
// libhydrocoef_runtime's hc_runtime_vehicle_step_rk4 as simulate_model steps
// it, compared with simulate_model's trajectory bit for bit.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "hydrocoef/runtime.h"
#include "src/dynamics/scenario.hpp"
#include "src/dynamics/simulation.hpp"
#include "src/dynamics/vehicle_model.hpp"
#include "tests/support/same_bits.hpp"

namespace hydrocoef {
namespace test {}  // namespace test

// Steps a scenario through the C API as simulate_model steps it (one segment:
// its inputs held; the output events at k / rate, each span in equal RK4
// steps of at most the scenario's step) and compares every output state and
// the final state with simulate_model's, bit for bit.
inline void expect_simulate_bit_for_bit(const VehicleModel& model, const hc_runtime_model* runtime,
                                        const Scenario& scenario) {
  ASSERT_EQ(scenario.segments.size(), 1u);
  const SimulationResult result = simulate_model(model, scenario);
  const SegmentInputs inputs = segment_inputs(model, scenario, 0);
  StateVector x =
      make_state(scenario.initial_position_n, quaternion_from_euler(scenario.initial_euler_rad), scenario.initial_nu_b);
  const auto outputs =
      static_cast<std::size_t>(std::floor(scenario.duration_s * scenario.output_rate_Hz * (1.0 + 1e-12)));
  ASSERT_EQ(result.samples.size(), outputs + 1);  // the duration is a multiple of the output interval
  double t = 0.0;
  std::size_t mismatches = 0, steps = 0;
  for (std::size_t k = 1; k <= outputs; ++k) {
    const double event = static_cast<double>(k) / scenario.output_rate_Hz;
    const auto count =
        std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil((event - t) / scenario.integrator.step_s - 1e-9)));
    const double h = (event - t) / static_cast<double>(count);
    for (std::size_t s = 0; s < count; ++s) {
      char err[256] = "";
      ASSERT_EQ(hc_runtime_vehicle_step_rk4(runtime, x.data(), inputs.tau_b.data(), inputs.current_n.data(),
                                            inputs.disturbances.data(), h, err, sizeof err),
                HC_RUNTIME_OK)
          << err;
    }
    steps += count;
    t = event;
    const TrajectorySample& sample = result.samples[k];
    for (int i = 0; i < 3; ++i) mismatches += !test::same_bits(x[i], sample.p_n[i]);
    // A sample states the attitude normalised once more (make_sample, unit_attitude); the state is compared at the end.
    const Quaternion4 q = unit_attitude(attitude_nb(x));
    for (int i = 0; i < 4; ++i) mismatches += !test::same_bits(q[i], sample.q_nb[i]);
    for (int i = 0; i < 6; ++i) mismatches += !test::same_bits(x[7 + i], sample.nu_b[i]);
  }
  EXPECT_EQ(steps, result.steps);
  for (int i = 0; i < 13; ++i) mismatches += !test::same_bits(x[i], result.final_state[i]);
  EXPECT_EQ(mismatches, 0u);
  // The run went somewhere: the comparison is not of a vehicle at rest.
  EXPECT_GT(result.final_state.segment<6>(state_index::kVelocity).norm(), 1e-3);
}

}  // namespace hydrocoef
