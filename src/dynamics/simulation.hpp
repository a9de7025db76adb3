// Runs a scenario on a vehicle model: piecewise-constant inputs, fixed-step
// RK4 or adaptive Dormand–Prince 5(4), samples at the scenario's output rate.
//
// Steps never straddle an input change or an output time: RK4 divides each
// interval between two such times into equal steps no longer than the
// scenario's step; Dormand–Prince ends each advance exactly there (and
// restarts its step-size estimate at input changes). The attitude quaternion
// is renormalised after every RK4 step and every Dormand–Prince interval.
#pragma once

#include <Eigen/StdVector>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "src/dynamics/scenario.hpp"
#include "src/dynamics/trajectory.hpp"
#include "src/dynamics/vehicle_model.hpp"

namespace hydrocoef {

struct SimulationResult {
  std::vector<TrajectorySample> samples;  ///< at t = k / output_rate, and at the end
  StateVector final_state;
  std::size_t steps = 0;           ///< accepted steps
  std::size_t rejected_steps = 0;  ///< Dormand–Prince only
  std::size_t evaluations = 0;     ///< calls of the model's derivative
  /// Largest | |q| - 1 | seen before renormalisation.
  double max_attitude_norm_error = 0.0;
  /// Things a user should know, e.g. a clamped thrust command.
  std::vector<std::string> notes;
};

/// The model inputs of one segment: commanded force plus thrusters (clamped
/// to their limits; a note for each clamped command), current, disturbance
/// values in the model's order (absent = 0). InputError naming the scenario
/// file and the segment's key for a thruster count or name or a disturbance
/// name the vehicle does not have.
struct SegmentInputs {
  Vector6 tau_b = Vector6::Zero();
  Vector3 current_n = Vector3::Zero();
  std::vector<double> disturbances;
};
SegmentInputs segment_inputs(const VehicleModel& model, const Scenario& scenario, std::size_t segment,
                             std::vector<std::string>* notes = nullptr);

/// progress(t, duration) is called after each output interval.
using SimulationProgress = std::function<void(double t_s, double duration_s)>;

/// Simulates the scenario. Throws InputError for inputs the vehicle cannot
/// take (see segment_inputs), a surface queried outside its range under
/// policy "error", or an adaptive step-size underflow.
SimulationResult simulate_model(const VehicleModel& model, const Scenario& scenario,
                                const SimulationProgress& progress = {});

/// The states of motion::kLanes vehicles at a scenario's output times.
struct LaneSimulation {
  std::vector<double> t_s;  ///< 0, then the times of SimulationResult::samples
  /// At t_s; column l: lane l's state.
  std::vector<VehicleModel::LaneState, Eigen::aligned_allocator<VehicleModel::LaneState>> states;
};

/// simulate() for motion::kLanes vehicles that are `model` with the damping
/// models `damping` (the drawn models of an ensemble, reading the model's
/// disturbances), integrated in lock-step: lane l's states are the states of
/// simulate_model(model.with_damping(*damping[l]), scenario)'s samples, bit for bit.
/// RK4 scenarios only (std::invalid_argument otherwise: an adaptive step is
/// each vehicle's own). InputError when any lane fails (a state that leaves
/// the finite numbers, a lookup outside its surface), without saying which:
/// simulate() that lane's vehicle alone for its message.
LaneSimulation simulate_lanes(const VehicleModel& model, const std::array<const DampingModel*, motion::kLanes>& damping,
                              const Scenario& scenario);

}  // namespace hydrocoef
