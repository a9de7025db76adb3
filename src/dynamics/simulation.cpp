#include "src/dynamics/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "src/core/error.hpp"
#include "src/dynamics/damping_lanes.hpp"
#include "src/dynamics/integrators.hpp"

namespace hydrocoef {
namespace {

[[noreturn]] void fail(const Scenario& scenario, const std::string& key, const std::string& message) {
  throw InputError(SourceLocation{scenario.file}, "key '" + key + "': " + message);
}

std::string list_or_none(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "none" : out;
}

struct Event {
  double t = 0.0;
  bool output = false;
  std::size_t segment = 0;  // segment that starts here, 0 = none (segment 0 starts at t = 0)
};

std::vector<Event> event_times(const Scenario& scenario) {
  std::vector<Event> events;
  const double duration = scenario.duration_s;
  const double rate = scenario.output_rate_Hz;
  const auto outputs = static_cast<std::size_t>(std::floor(duration * rate * (1.0 + 1e-12)));
  for (std::size_t k = 1; k <= outputs; ++k) events.push_back({static_cast<double>(k) / rate, true, 0});
  if (events.empty() || events.back().t < duration * (1.0 - 1e-12))
    events.push_back({duration, true, 0});
  else
    events.back().t = std::min(events.back().t, duration);
  for (std::size_t i = 1; i < scenario.segments.size(); ++i) {
    const double start = scenario.segments[i].start_s;
    auto it = std::lower_bound(events.begin(), events.end(), start, [](const Event& e, double t) { return e.t < t; });
    const double tolerance = 1e-12 * std::max(1.0, duration);
    if (it != events.end() && std::abs(it->t - start) <= tolerance) {
      it->segment = i;
    } else if (it != events.begin() && std::abs(std::prev(it)->t - start) <= tolerance) {
      std::prev(it)->segment = i;
    } else {
      events.insert(it, {start, false, i});
    }
  }
  return events;
}

}  // namespace

SegmentInputs segment_inputs(const VehicleModel& model, const Scenario& scenario, std::size_t segment,
                             std::vector<std::string>* notes) {
  const ScenarioSegment& s = scenario.segments.at(segment);
  const std::string path = "segments[" + std::to_string(segment) + "]";
  const auto& thrusters = model.description().thrusters;
  std::vector<std::string> names;
  for (const auto& t : thrusters) names.push_back(t.name);

  SegmentInputs in;
  in.tau_b = s.tau_b;
  in.current_n = s.current_n;
  std::vector<double> thrust(thrusters.size(), 0.0);
  if (!s.thrust_N.empty()) {
    if (s.thrust_N.size() != thrusters.size())
      fail(scenario, path + ".thrusters",
           "found " + std::to_string(s.thrust_N.size()) + " thrust values, expected one per thruster of the vehicle (" +
               std::to_string(thrusters.size()) + ": " + list_or_none(names) + ")");
    thrust = s.thrust_N;
  }
  for (const auto& [name, value] : s.thrust_by_name_N) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      fail(scenario, path + ".thrusters." + name, "unknown thruster, the vehicle has: " + list_or_none(names));
    thrust[static_cast<std::size_t>(it - names.begin())] = value;
  }
  for (std::size_t i = 0; i < thrust.size(); ++i) {
    const double clamped = model.clamp_thrust(i, thrust[i]);
    if (clamped != thrust[i] && notes)
      notes->push_back(path + ": thruster '" + names[i] + "' command " + std::to_string(thrust[i]) + " N clamped to " +
                       std::to_string(clamped) + " N");
    thrust[i] = clamped;
  }
  if (!thrust.empty()) in.tau_b += model.thrust_force(thrust);

  const auto& disturbance_names = model.disturbance_names();
  in.disturbances.assign(disturbance_names.size(), 0.0);
  for (const auto& [name, value] : s.disturbances) {
    const auto it = std::find(disturbance_names.begin(), disturbance_names.end(), name);
    if (it == disturbance_names.end())
      fail(scenario, path + ".disturbances." + name,
           "unknown disturbance, the vehicle's surfaces read: " + list_or_none(disturbance_names));
    in.disturbances[static_cast<std::size_t>(it - disturbance_names.begin())] = value;
  }
  return in;
}

namespace {

// What a simulation can do, checked before the first step so that nothing is
// reported that was not done: the output samples are held in memory, RK4's
// step count must fit (and be run in reasonable time: 1e10 steps are about
// 2.5 hours here), and an adaptive tolerance below about 100 machine epsilons
// cannot be met in double precision.
constexpr double kMaxOutputSamples = 1e7;
constexpr double kMaxRk4Steps = 1e10;
constexpr double kMinRelativeTolerance = 100.0 * 2.220446049250313e-16;

void check_limits(const Scenario& scenario) {
  const double samples = scenario.duration_s * scenario.output_rate_Hz;
  if (!(samples <= kMaxOutputSamples))
    fail(scenario, "output_rate",
         "duration " + std::to_string(scenario.duration_s) + " s at " + std::to_string(scenario.output_rate_Hz) +
             " Hz is " + std::to_string(samples) +
             " output samples; expected at most 1e7 (a lower output_rate or "
             "a shorter duration)");
  const IntegratorSettings& settings = scenario.integrator;
  if (settings.method == IntegratorSettings::Method::Rk4) {
    const double steps = scenario.duration_s / settings.step_s;
    if (!(steps <= kMaxRk4Steps))
      fail(scenario, "integrator.step",
           "a step of " + std::to_string(settings.step_s) + " s over " + std::to_string(scenario.duration_s) +
               " s is " + std::to_string(steps) + " steps; expected at most 1e10 (a step of at least " +
               std::to_string(scenario.duration_s / kMaxRk4Steps) + " s)");
  } else if (!(settings.relative_tolerance >= kMinRelativeTolerance)) {
    fail(scenario, "integrator.rtol",
         "found " + std::to_string(settings.relative_tolerance) +
             ", expected at least 2.2e-14 (100 machine epsilons: a smaller relative error cannot be met in double "
             "precision)");
  }
}

/// The first non-finite entry of the state, or nullopt.
std::optional<std::size_t> non_finite(const StateVector& x) {
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i])) return static_cast<std::size_t>(i);
  return std::nullopt;
}

}  // namespace

namespace {

/// What a run needs before its first step, checked: every segment's inputs,
/// the output and segment times, the initial state.
struct Plan {
  std::vector<SegmentInputs> segments;
  std::vector<Event> events;
  StateVector initial;
};

Plan plan_run(const VehicleModel& model, const Scenario& scenario, std::vector<std::string>* notes) {
  if (scenario.segments.empty() || !(scenario.duration_s > 0.0) || !(scenario.output_rate_Hz > 0.0))
    throw InputError(SourceLocation{scenario.file},
                     "a scenario needs a positive duration and output rate and a segment");
  check_limits(scenario);
  Plan plan;
  for (std::size_t i = 0; i < scenario.segments.size(); ++i)
    plan.segments.push_back(segment_inputs(model, scenario, i, notes));
  plan.events = event_times(scenario);
  plan.initial =
      make_state(scenario.initial_position_n, quaternion_from_euler(scenario.initial_euler_rad), scenario.initial_nu_b);
  return plan;
}

/// The model inputs of a segment (pointing into it).
ModelInputs inputs_of(const SegmentInputs& segment) {
  ModelInputs inputs;
  inputs.tau_b = segment.tau_b;
  inputs.current_n = segment.current_n;
  inputs.disturbances = segment.disturbances;
  return inputs;
}

/// RK4 steps from one event to the next: as many of equal size as keep each
/// at most `step` (one at least).
std::pair<std::size_t, double> rk4_steps(double span, double step) {
  const auto steps = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(span / step - 1e-9)));
  return {steps, span / static_cast<double>(steps)};
}

}  // namespace

SimulationResult simulate_model(const VehicleModel& model, const Scenario& scenario,
                                const SimulationProgress& progress) {
  SimulationResult result;
  const Plan plan = plan_run(model, scenario, &result.notes);
  StateVector x = plan.initial;
  ModelInputs inputs = inputs_of(plan.segments[0]);
  auto f = [&](double, const StateVector& state, StateVector& state_dot) {
    model.derivative(state, inputs, state_dot);
  };
  auto track_norm = [&](const StateVector& state) {
    result.max_attitude_norm_error =
        std::max(result.max_attitude_norm_error, std::abs(attitude_nb(state).norm() - 1.0));
  };

  const std::vector<Event>& events = plan.events;
  result.samples.reserve(events.size() + 1);
  result.samples.push_back(make_sample(model, 0.0, x, inputs));

  const IntegratorSettings& settings = scenario.integrator;
  Rk4Workspace<StateVector> rk4;
  AdaptiveOptions adaptive;
  adaptive.relative_tolerance = settings.relative_tolerance;
  adaptive.absolute_tolerance = settings.absolute_tolerance;
  adaptive.max_step = settings.max_step_s;
  DormandPrince45<StateVector> dopri(adaptive);

  double t = 0.0;
  for (const Event& event : events) {
    if (settings.method == IntegratorSettings::Method::Rk4) {
      const auto [steps, h] = rk4_steps(event.t - t, settings.step_s);
      for (std::size_t k = 0; k < steps; ++k) {
        rk4_step(f, t + static_cast<double>(k) * h, h, x, rk4);
        track_norm(x);
        normalize_attitude(x);
      }
      result.steps += steps;
      result.evaluations += 4 * steps;
    } else {
      double t_local = t;
      dopri.advance(f, t_local, event.t, x);
      track_norm(x);
      normalize_attitude(x);
    }
    // A state that left the finite numbers (a force or velocity near 1e308)
    // stops the run where it happened, never a trajectory of NaN.
    if (const auto bad = non_finite(x))
      throw InputError(SourceLocation{scenario.file},
                       "the state left the finite numbers (entry " + std::to_string(*bad) +
                           " of position, attitude "
                           "and velocity) between t = " +
                           std::to_string(t) + " s and " + std::to_string(event.t) +
                           " s; expected forces, velocities and currents the vehicle model can integrate");
    t = event.t;
    if (event.segment != 0) {
      inputs = inputs_of(plan.segments[event.segment]);
      dopri.reset_step();
    }
    if (event.output) result.samples.push_back(make_sample(model, t, x, inputs));
    if (progress) progress(t, scenario.duration_s);
  }
  if (settings.method == IntegratorSettings::Method::DormandPrince45) {
    result.steps = dopri.stats().accepted;
    result.rejected_steps = dopri.stats().rejected;
    result.evaluations = dopri.stats().evaluations;
  }
  result.final_state = x;
  return result;
}

LaneSimulation simulate_lanes(const VehicleModel& model, const std::array<const DampingModel*, motion::kLanes>& damping,
                              const Scenario& scenario) {
  if (scenario.integrator.method != IntegratorSettings::Method::Rk4)
    throw std::invalid_argument("simulate_lanes: an RK4 scenario is needed (adaptive steps are each vehicle's own)");
  for (const DampingModel* d : damping)
    if (!d || d->disturbance_names() != model.disturbance_names())
      throw std::invalid_argument("simulate_lanes: a damping model reading other disturbances than the vehicle's");
  const DampingLanes lane_damping(damping);
  const Plan plan = plan_run(model, scenario, nullptr);
  using LaneState = VehicleModel::LaneState;
  LaneState x = plan.initial.replicate<1, motion::kLanes>();
  ModelInputs inputs = inputs_of(plan.segments[0]);
  auto f = [&](double, const LaneState& state, LaneState& state_dot) {
    model.derivative_lanes(lane_damping, state, inputs, state_dot);
  };
  // simulate()'s steps, each lane's attitude normalised as there.
  auto normalize = [](LaneState& state) {
    motion::Lanes q[4];
    for (int i = 0; i < 4; ++i) q[i] = state.row(state_index::kAttitude + i).transpose();
    motion::normalize(q);
    for (int i = 0; i < 4; ++i) state.row(state_index::kAttitude + i) = q[i].transpose();
  };
  LaneSimulation out;
  out.t_s.reserve(plan.events.size() + 1);
  out.states.reserve(plan.events.size() + 1);
  out.t_s.push_back(0.0);
  out.states.push_back(x);
  Rk4Workspace<LaneState> rk4;
  double t = 0.0;
  for (const Event& event : plan.events) {
    const auto [steps, h] = rk4_steps(event.t - t, scenario.integrator.step_s);
    for (std::size_t k = 0; k < steps; ++k) {
      rk4_step(f, t + static_cast<double>(k) * h, h, x, rk4);
      normalize(x);
    }
    if (!x.allFinite())
      throw InputError(SourceLocation{scenario.file},
                       "a lane's state left the finite numbers between t = " + std::to_string(t) + " s and " +
                           std::to_string(event.t) + " s; run its vehicle alone (simulate) for the details");
    t = event.t;
    if (event.segment != 0) inputs = inputs_of(plan.segments[event.segment]);
    if (event.output) {
      out.t_s.push_back(t);
      out.states.push_back(x);
    }
  }
  // simulate() evaluates the model at every output (make_sample); the next
  // step's first stage does so here, but for the last output: a lookup that
  // fails there fails the run as it does in simulate().
  LaneState unused;
  f(t, x, unused);
  return out;
}

}  // namespace hydrocoef
