// hydrocoef simulate: run a scenario on a vehicle with the 6-DOF lookup-table
// model, write the trajectory, compare with a measured one;
// hydrocoef equilibrium: the steady velocity under a constant force.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <numbers>

#include "cli/common.hpp"
#include "src/core/escape.hpp"
#include "src/core/error.hpp"
#include "src/dynamics/equilibrium.hpp"
#include "src/dynamics/experiment.hpp"
#include "src/dynamics/simulation.hpp"
#include "src/dynamics/surface_source.hpp"

namespace hydrocoef::cli {
namespace {

constexpr std::array<const char*, 6> kVelocityUnits{"m/s", "m/s", "m/s", "rad/s", "rad/s", "rad/s"};
constexpr std::array<const char*, 6> kForceUnits{"N", "N", "N", "N m", "N m", "N m"};
constexpr const char* kSignNote = "forces on the body in body axes about CO (SNAME: damping is negative)";

nlohmann::json velocity_json(const Vector6& nu) {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < 6; ++i) out[std::string(kVelocityNames[i])] = nu[static_cast<Eigen::Index>(i)];
  return out;
}

nlohmann::json force_json(const Vector6& tau) {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < 6; ++i) out[std::string(kForceNames[i])] = tau[static_cast<Eigen::Index>(i)];
  return out;
}

nlohmann::json units_json() {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < 6; ++i) {
    out[std::string(kVelocityNames[i])] = kVelocityUnits[i];
    out[std::string(kForceNames[i])] = kForceUnits[i];
  }
  return out;
}

nlohmann::json optional_number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

void print_velocity_table(const Vector6& nu, const ForceBreakdown& forces) {
  std::cout << "  " << std::left << std::setw(4) << "" << std::setw(17) << "velocity" << std::setw(7) << ""
            << std::setw(4) << "" << std::setw(15) << "damping" << std::setw(15) << "control" << "\n";
  for (std::size_t i = 0; i < 6; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    std::cout << "  " << std::setw(4) << kVelocityNames[i] << std::setw(17) << significant(nu[k], 9) << std::setw(7)
              << kVelocityUnits[i] << std::setw(4) << kForceNames[i] << std::setw(15)
              << significant(forces.damping_b[k], 6) << std::setw(15) << significant(forces.control_b[k], 6)
              << kForceUnits[i] << '\n';
  }
  std::cout << std::right;
}

// ---- simulate ---------------------------------------------------------------

struct SimulateArgs {
  std::string vehicle;
  std::string scenario;
  std::optional<std::string> out;
  std::optional<std::string> experiment;
  double steady_fraction = 0.2;
  bool json = false;
};

std::string integrator_text(const IntegratorSettings& s) {
  if (s.method == IntegratorSettings::Method::Rk4) return "rk4, step " + significant(s.step_s, 6) + " s";
  return "dopri5, rtol " + significant(s.relative_tolerance, 3) + ", atol " + significant(s.absolute_tolerance, 3) +
         ", max step " + significant(s.max_step_s, 6) + " s";
}

void run_simulate(const SimulateArgs& args, const GlobalOptions& global) {
  const VehicleModel model(load_vehicle(args.vehicle), database_surface_resolver(global.database));
  const Scenario scenario = load_scenario(args.scenario);
  std::optional<MeasuredTrajectory> measured;
  if (args.experiment) measured = read_measured_trajectory(*args.experiment);
  if (!(args.steady_fraction > 0.0 && args.steady_fraction <= 1.0))
    throw InputError("--steady-fraction " + shortest_number(args.steady_fraction) + ": expected a number in (0, 1]");

  // A progress line on a terminal, at most five times a second.
  const bool tty = isatty(STDERR_FILENO) != 0;
  const auto started = std::chrono::steady_clock::now();
  auto last_print = started;
  SimulationProgress progress;
  if (tty)
    progress = [&](double t, double duration) {
      const auto now = std::chrono::steady_clock::now();
      if (now - last_print < std::chrono::milliseconds(200) && t < duration) return;
      last_print = now;
      std::fprintf(stderr, "\rsimulating: t = %.1f of %.1f s (%3.0f %%)", t, duration, 100.0 * t / duration);
    };
  const SimulationResult result = simulate(model, scenario, progress);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (tty && std::chrono::duration<double>(last_print - started).count() > 0.0) std::fprintf(stderr, "\n");
  if (args.out) write_trajectory_csv(*args.out, result.samples);
  std::vector<ComponentComparison> comparison;
  if (measured) {
    ComparisonOptions options;
    options.steady_fraction = args.steady_fraction;
    comparison = compare_with_experiment(*measured, result.samples, options);
  }
  const TrajectorySample& last = result.samples.back();

  if (args.json) {
    nlohmann::json out = {{"vehicle", args.vehicle},
                          {"scenario", args.scenario},
                          {"name", scenario.name},
                          {"duration", scenario.duration_s},
                          {"integrator", integrator_text(scenario.integrator)},
                          {"steps", result.steps},
                          {"rejected_steps", result.rejected_steps},
                          {"evaluations", result.evaluations},
                          {"samples", result.samples.size()},
                          {"wall_time_s", wall_s},
                          {"notes", result.notes},
                          {"trajectory", args.out ? nlohmann::json(*args.out) : nlohmann::json()},
                          {"sign_convention", kSignNote},
                          {"units", units_json()}};
    out["final"] = {{"t", last.t_s},
                    {"position_n", {{"x", last.p_n.x()}, {"y", last.p_n.y()}, {"z", last.p_n.z()}}},
                    {"euler_rad", {{"phi", last.euler_rad[0]}, {"theta", last.euler_rad[1]}, {"psi", last.euler_rad[2]}}},
                    {"velocity", velocity_json(last.nu_b)},
                    {"relative_velocity", velocity_json(last.forces.nu_r_b)},
                    {"forces",
                     {{"control", force_json(last.forces.control_b)},
                      {"damping", force_json(last.forces.damping_b)},
                      {"hydrostatic", force_json(last.forces.hydrostatic_b)},
                      {"coriolis", force_json(last.forces.coriolis_b)}}}};
    if (measured) {
      out["experiment"] = *args.experiment;
      out["comparison"] = nlohmann::json::array();
      for (const auto& c : comparison)
        out["comparison"].push_back({{"component", c.component},
                                     {"samples", c.samples},
                                     {"rms_error", c.rms_error},
                                     {"steady_measured", c.steady_measured},
                                     {"steady_simulated", c.steady_simulated},
                                     {"steady_error", c.steady_error},
                                     {"t63_measured_s", optional_number(c.t63_measured_s)},
                                     {"t63_simulated_s", optional_number(c.t63_simulated_s)}});
    }
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }

  std::cout << "simulate " << (scenario.name.empty() ? args.scenario : scenario.name) << "\n  vehicle "
            << (model.description().name.empty() ? args.vehicle : model.description().name) << " (" << args.vehicle
            << "), scenario " << args.scenario << "\n  " << significant(scenario.duration_s, 6) << " s, "
            << integrator_text(scenario.integrator) << ": " << result.steps << " steps";
  if (result.rejected_steps) std::cout << " (" << result.rejected_steps << " rejected)";
  std::cout << ", " << result.evaluations << " evaluations, " << significant(wall_s, 3) << " s wall\n\n";
  std::cout << "  at t = " << significant(last.t_s, 6) << " s: position (" << significant(last.p_n.x(), 6) << ", "
            << significant(last.p_n.y(), 6) << ", " << significant(last.p_n.z(), 6) << ") m NED, attitude (roll, pitch, yaw) ("
            << significant(last.euler_rad[0] * 180.0 / std::numbers::pi, 5) << ", "
            << significant(last.euler_rad[1] * 180.0 / std::numbers::pi, 5) << ", "
            << significant(last.euler_rad[2] * 180.0 / std::numbers::pi, 5) << ") deg\n";
  print_velocity_table(last.nu_b, last.forces);
  std::cout << "  (" << kSignNote << ")\n";
  for (const auto& note : result.notes) std::cout << "  note: " << note << '\n';
  if (args.out) std::cout << "  trajectory: " << *args.out << " (" << result.samples.size() << " rows)\n";
  if (measured) {
    std::cout << "\n  comparison with " << *args.experiment << " (measured - simulated; steady = mean of the last "
              << significant(100.0 * args.steady_fraction, 3) << " %)\n  " << std::left << std::setw(6) << "" << std::setw(8)
              << "rows" << std::setw(14) << "RMS" << std::setw(14) << "steady meas." << std::setw(14) << "steady sim."
              << std::setw(14) << "steady error" << std::setw(10) << "t63 meas." << "t63 sim. [s]\n";
    for (const auto& c : comparison)
      std::cout << "  " << std::setw(6) << c.component << std::setw(8) << c.samples << std::setw(14)
                << significant(c.rms_error, 4) << std::setw(14) << significant(c.steady_measured, 5) << std::setw(14)
                << significant(c.steady_simulated, 5) << std::setw(14) << significant(c.steady_error, 4) << std::setw(10)
                << significant(c.t63_measured_s, 4) << significant(c.t63_simulated_s, 4) << '\n';
    std::cout << std::right;
  }
}

// ---- equilibrium ------------------------------------------------------------

struct EquilibriumArgs {
  std::string vehicle;
  std::vector<std::string> tau;
  std::vector<std::string> current;
  std::vector<std::string> disturbance;
  std::string attitude = "0,0,0";
  bool json = false;
};

void run_equilibrium(const EquilibriumArgs& args, const GlobalOptions& global) {
  const VehicleModel model(load_vehicle(args.vehicle), database_surface_resolver(global.database));
  EquilibriumInputs in;
  for (const auto& text : args.tau) {
    const auto [name, value] = parse_assignment(text, "--tau");
    const auto dof = force_index(name);
    if (!dof) throw InputError("--tau '" + text + "': expected X, Y, Z, K, M or N =VALUE [N or N m]");
    in.tau_b[static_cast<Eigen::Index>(*dof)] = value;
  }
  const auto attitude = parse_triple(args.attitude, "--attitude-deg");
  in.q_nb = quaternion_from_euler(Vector3(attitude[0], attitude[1], attitude[2]) * (std::numbers::pi / 180.0));
  Vector3 current_b = Vector3::Zero();
  for (const auto& text : args.current) {
    const auto [name, value] = parse_assignment(text, "--current");
    const auto component = velocity_index(name);
    if (!component || *component > 2) throw InputError("--current '" + text + "': expected u, v or w =VALUE [m/s]");
    current_b[static_cast<Eigen::Index>(*component)] = value;
  }
  in.current_n = rotation_body_to_ned(in.q_nb) * current_b;
  in.disturbances.assign(model.disturbance_names().size(), 0.0);
  for (const auto& text : args.disturbance) {
    const auto [name, value] = parse_assignment(text, "--disturbance");
    const auto& names = model.disturbance_names();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw InputError("--disturbance '" + text + "': the vehicle's surfaces read " + (list.empty() ? "none" : list));
    }
    in.disturbances[static_cast<std::size_t>(it - names.begin())] = value;
  }

  const EquilibriumResult eq = solve_equilibrium(model, in);
  if (!eq.converged) {
    std::size_t worst = 0;
    eq.residual_b.cwiseAbs().maxCoeff(&worst);
    throw InputError("no steady state for this force: the residual stays at " + significant(eq.residual_b[static_cast<Eigen::Index>(worst)], 3) +
                     " " + kForceUnits[worst] + " in " + std::string(kForceNames[worst]) +
                     " (a DOF with a force but no damping, or a coupling that only a change of attitude could balance)");
  }
  if (args.json) {
    nlohmann::json out = {{"vehicle", args.vehicle},
                          {"tau", force_json(in.tau_b)},
                          {"velocity", velocity_json(eq.nu_b)},
                          {"relative_velocity", velocity_json(eq.forces.nu_r_b)},
                          {"damping", force_json(eq.forces.damping_b)},
                          {"residual", force_json(eq.residual_b)},
                          {"converged", eq.converged},
                          {"iterations", eq.iterations},
                          {"attitude_deg", {{"phi", attitude[0]}, {"theta", attitude[1]}, {"psi", attitude[2]}}},
                          {"units", units_json()},
                          {"sign_convention", kSignNote}};
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::cout << "equilibrium of " << (model.description().name.empty() ? args.vehicle : model.description().name)
            << " under";
  for (std::size_t i = 0; i < 6; ++i)
    if (in.tau_b[static_cast<Eigen::Index>(i)] != 0.0)
      std::cout << " " << kForceNames[i] << " = " << significant(in.tau_b[static_cast<Eigen::Index>(i)], 6) << " "
                << kForceUnits[i];
  if (in.tau_b.isZero()) std::cout << " no force";
  std::cout << " (attitude held; " << eq.iterations << " iterations, largest residual "
            << significant(eq.residual_b.cwiseAbs().maxCoeff(), 3) << ")\n";
  print_velocity_table(eq.nu_b, eq.forces);
  std::cout << "  (" << kSignNote << ")\n";
}

}  // namespace

void add_simulate_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<SimulateArgs>();
  auto* command = app.add_subcommand(
      "simulate", "Run a scenario on a vehicle with the 6-DOF lookup-table model (RK4 or Dormand-Prince)");
  command->add_option("--vehicle", args->vehicle, "Vehicle description (JSON)")->required();
  command->add_option("--scenario", args->scenario, "Scenario (JSON): inputs over time, duration, output rate")->required();
  command->add_option("--out", args->out, "Write the trajectory (time, pose, velocity, forces) to this CSV");
  command->add_option("--experiment", args->experiment,
                      "Measured trajectory CSV (t and velocity columns) to compare with: RMS, steady error, 63 % time");
  command->add_option("--steady-fraction", args->steady_fraction,
                      "Fraction of the compared record at its end taken as steady state")
      ->capture_default_str();
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_simulate(*args, global); });
}

void add_equilibrium_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<EquilibriumArgs>();
  auto* command = app.add_subcommand("equilibrium", "Steady body velocity under a constant force (attitude held)");
  command->add_option("--vehicle", args->vehicle, "Vehicle description (JSON)")->required();
  command->add_option("--tau", args->tau, "Force on the body NAME=VALUE, NAME one of X Y Z [N], K M N [N m] (repeatable)");
  command->add_option("--current", args->current, "Water velocity u|v|w=VALUE in body axes [m/s] (repeatable)");
  command->add_option("--disturbance", args->disturbance, "Disturbance parameter NAME=VALUE read by surfaces (repeatable)");
  command->add_option("--attitude-deg", args->attitude, "Attitude held: roll,pitch,yaw [deg]")->capture_default_str();
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_equilibrium(*args, global); });
}

}  // namespace hydrocoef::cli
