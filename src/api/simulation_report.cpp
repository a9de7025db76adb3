// How a simulation and an equilibrium report themselves (what `hydrocoef
// simulate` and `equilibrium` print): the final state with its forces and the
// comparison with an experiment as text, or JSON.
#include "src/api/simulation_report.hpp"

#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"
#include "src/core/run.hpp"

namespace hydrocoef {
namespace {

constexpr const char* kSignNote = "forces on the body in body axes about CO (SNAME: damping is negative)";
constexpr const char* kSamplingNote =
    "each draw holds one sample of the uncertain damping (laws from their covariance, GP surfaces from their "
    "posterior) for the whole run: parameter uncertainty, not per-step noise";

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

void print_velocity_table(std::ostream& out, const Vector6& nu, const ForceBreakdown& forces) {
  out << "  " << std::left << std::setw(4) << "" << std::setw(17) << "velocity" << std::setw(7) << "" << std::setw(4)
      << "" << std::setw(15) << "damping" << std::setw(15) << "control"
      << "\n";
  for (std::size_t i = 0; i < 6; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    out << "  " << std::setw(4) << kVelocityNames[i] << std::setw(17) << significant(nu[k], 9) << std::setw(7)
        << kVelocityUnits[i] << std::setw(4) << kForceNames[i] << std::setw(15) << significant(forces.damping_b[k], 6)
        << std::setw(15) << significant(forces.control_b[k], 6) << kForceUnits[i] << '\n';
  }
  out << std::right;
}

std::string integrator_text(const IntegratorSettings& s) {
  if (s.method == IntegratorSettings::Method::Rk4) return "rk4, step " + significant(s.step_s, 6) + " s";
  return "dopri5, rtol " + significant(s.relative_tolerance, 3) + ", atol " + significant(s.absolute_tolerance, 3) +
         ", max step " + significant(s.max_step_s, 6) + " s";
}

nlohmann::json draws_json(const DampingDraws& draws, std::uint64_t seed, std::size_t requested, std::size_t used,
                          const EnsembleFailures& failures, double wall_s, const std::vector<double>& percentiles) {
  return {{"requested", requested},           {"used", used},         {"failed", failures.count},
          {"first_failures", failures.first}, {"seed", seed},         {"percentiles", percentiles},
          {"drawn", draws.drawn()},           {"held", draws.held()}, {"notes", draws.notes()},
          {"sampling", kSamplingNote},        {"wall_time_s", wall_s}};
}

void print_draws(std::ostream& out, const DampingDraws& draws, std::uint64_t seed, std::size_t requested,
                 std::size_t used, const EnsembleFailures& failures, double wall_s) {
  out << "\n  Monte Carlo: " << used << " of " << requested << " draws (seed " << seed << ", " << significant(wall_s, 3)
      << " s wall); " << kSamplingNote << '\n';
  // The lines name fits and surfaces of a database someone else may have made.
  for (const auto& line : draws.drawn()) out << "    drawn: " << escape::one_line(line) << '\n';
  for (const auto& line : draws.held()) out << "    held:  " << escape::one_line(line) << '\n';
  for (const auto& line : draws.notes()) out << "    note:  " << escape::one_line(line) << '\n';
  if (failures.count) {
    out << "    FAILED: " << failures.count << " draws (the bands are those of the others); first:\n";
    for (const auto& line : failures.first) out << "      " << escape::one_line(line) << '\n';
  }
}

std::string percentile_label(double p) { return "p" + shortest_number(p); }

void print_bands(std::ostream& out, const SimulationReport& r) {
  const TrajectoryBands& b = *r.bands;
  print_draws(out, *r.draws, r.seed, b.samples + b.failures.count, b.samples, b.failures, r.samples_wall_s);
  const std::size_t last = b.t_s.size() - 1;
  out << "  at t = " << significant(b.t_s[last], 6) << " s, percentiles over the draws:\n  " << std::left
      << std::setw(7) << "";
  for (const double p : b.percentiles) out << std::setw(14) << percentile_label(p);
  out << "unit\n";
  for (std::size_t q = 0; q < b.quantities.size(); ++q) {
    // Quantities that do not move in any draw are left out of the table.
    if (b.value(q, 0, last) == b.value(q, b.percentiles.size() - 1, last) && b.value(q, 0, last) == 0.0) continue;
    out << "  " << std::setw(7) << escape::one_line(b.quantities[q]);
    for (std::size_t j = 0; j < b.percentiles.size(); ++j) out << std::setw(14) << significant(b.value(q, j, last), 6);
    out << escape::one_line(b.units[q]) << '\n';
  }
  out << std::right;
  if (r.measured && b.percentiles.size() >= 2) {
    for (std::size_t i = 0; i < 6; ++i) {
      if (r.measured->nu_b[i].empty()) continue;
      const double share = share_inside_band(b, kVelocityNames[i], r.measured->t_s, r.measured->nu_b[i]);
      if (std::isfinite(share))
        out << "  measured " << kVelocityNames[i] << " inside the " << percentile_label(b.percentiles.front()) << "-"
            << percentile_label(b.percentiles.back()) << " band: " << significant(100.0 * share, 3)
            << " % of its samples\n";
    }
  }
}

nlohmann::json bands_json(const SimulationReport& r) {
  const TrajectoryBands& b = *r.bands;
  nlohmann::json out = draws_json(*r.draws, r.seed, b.samples + b.failures.count, b.samples, b.failures,
                                  r.samples_wall_s, b.percentiles);
  const std::size_t last = b.t_s.size() - 1;
  nlohmann::json final_values = nlohmann::json::object();
  for (std::size_t q = 0; q < b.quantities.size(); ++q) {
    nlohmann::json values = nlohmann::json::object();
    for (std::size_t j = 0; j < b.percentiles.size(); ++j)
      values[percentile_label(b.percentiles[j])] = b.value(q, j, last);
    final_values[b.quantities[q]] = values;
  }
  out["final"] = {{"t", b.t_s[last]}, {"percentiles", final_values}};
  if (r.measured && b.percentiles.size() >= 2) {
    nlohmann::json inside = nlohmann::json::object();
    for (std::size_t i = 0; i < 6; ++i)
      if (!r.measured->nu_b[i].empty())
        inside[std::string(kVelocityNames[i])] =
            optional_number(share_inside_band(b, kVelocityNames[i], r.measured->t_s, r.measured->nu_b[i]));
    out["measured_inside_band"] = inside;
  }
  return out;
}

}  // namespace

std::string simulation_json(const SimulationReport& r) {
  const TrajectorySample& last = r.result.samples.back();
  nlohmann::json out = {{"vehicle", r.vehicle},
                        {"scenario", r.scenario_path},
                        {"name", r.scenario.name},
                        {"duration", r.scenario.duration_s},
                        {"integrator", integrator_text(r.scenario.integrator)},
                        {"steps", r.result.steps},
                        {"rejected_steps", r.result.rejected_steps},
                        {"evaluations", r.result.evaluations},
                        {"samples", r.result.samples.size()},
                        {"wall_time_s", r.wall_s},
                        {"notes", r.result.notes},
                        {"trajectory", r.out ? nlohmann::json(*r.out) : nlohmann::json()},
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
  if (r.experiment) {
    out["experiment"] = *r.experiment;
    out["comparison"] = nlohmann::json::array();
    for (const auto& c : r.comparison)
      out["comparison"].push_back({{"component", c.component},
                                   {"samples", c.samples},
                                   {"rms_error", c.rms_error},
                                   {"steady_measured", c.steady_measured},
                                   {"steady_simulated", c.steady_simulated},
                                   {"steady_error", c.steady_error},
                                   {"t63_measured_s", optional_number(c.t63_measured_s)},
                                   {"t63_simulated_s", optional_number(c.t63_simulated_s)}});
  }
  if (r.bands) out["monte_carlo"] = bands_json(r);
  return escape::json_text(out, 2) + '\n';
}

std::string simulation_text(const SimulationReport& r) {
  const TrajectorySample& last = r.result.samples.back();
  std::ostringstream out;
  out << "simulate " << escape::one_line(r.scenario.name.empty() ? r.scenario_path : r.scenario.name) << "\n  vehicle "
      << escape::one_line(r.vehicle_name.empty() ? r.vehicle : r.vehicle_name) << " (" << escape::one_line(r.vehicle)
      << "), scenario " << escape::one_line(r.scenario_path) << "\n  " << significant(r.scenario.duration_s, 6)
      << " s, " << integrator_text(r.scenario.integrator) << ": " << r.result.steps << " steps";
  if (r.result.rejected_steps) out << " (" << r.result.rejected_steps << " rejected)";
  out << ", " << r.result.evaluations << " evaluations, " << significant(r.wall_s, 3) << " s wall\n\n";
  out << "  at t = " << significant(last.t_s, 6) << " s: position (" << significant(last.p_n.x(), 6) << ", "
      << significant(last.p_n.y(), 6) << ", " << significant(last.p_n.z(), 6)
      << ") m NED, attitude (roll, pitch, yaw) (" << significant(last.euler_rad[0] * 180.0 / std::numbers::pi, 5)
      << ", " << significant(last.euler_rad[1] * 180.0 / std::numbers::pi, 5) << ", "
      << significant(last.euler_rad[2] * 180.0 / std::numbers::pi, 5) << ") deg\n";
  print_velocity_table(out, last.nu_b, last.forces);
  out << "  (" << kSignNote << ")\n";
  for (const auto& note : r.result.notes) out << "  note: " << escape::one_line(note) << '\n';
  if (r.out) out << "  trajectory: " << escape::one_line(*r.out) << " (" << r.result.samples.size() << " rows)\n";
  if (r.experiment) {
    out << "\n  comparison with " << escape::one_line(*r.experiment)
        << " (measured - simulated; steady = mean of the last " << significant(100.0 * r.steady_fraction, 3)
        << " %)\n  " << std::left << std::setw(6) << "" << std::setw(8) << "rows" << std::setw(14) << "RMS"
        << std::setw(14) << "steady meas." << std::setw(14) << "steady sim." << std::setw(14) << "steady error"
        << std::setw(10) << "t63 meas."
        << "t63 sim. [s]\n";
    for (const auto& c : r.comparison)
      out << "  " << std::setw(6) << escape::one_line(c.component) << std::setw(8) << c.samples << std::setw(14)
          << significant(c.rms_error, 4) << std::setw(14) << significant(c.steady_measured, 5) << std::setw(14)
          << significant(c.steady_simulated, 5) << std::setw(14) << significant(c.steady_error, 4) << std::setw(10)
          << significant(c.t63_measured_s, 4) << significant(c.t63_simulated_s, 4) << '\n';
    out << std::right;
  }
  if (r.bands) print_bands(out, r);
  return out.str();
}

std::string equilibrium_json(const EquilibriumReport& r) {
  nlohmann::json out = {{"vehicle", r.vehicle},
                        {"tau", force_json(r.in.tau_b)},
                        {"velocity", velocity_json(r.eq.nu_b)},
                        {"relative_velocity", velocity_json(r.eq.forces.nu_r_b)},
                        {"damping", force_json(r.eq.forces.damping_b)},
                        {"residual", force_json(r.eq.residual_b)},
                        {"converged", r.eq.converged},
                        {"iterations", r.eq.iterations},
                        {"continuation_s", r.eq.continuation_s},
                        {"attitude_deg", {{"phi", r.attitude[0]}, {"theta", r.attitude[1]}, {"psi", r.attitude[2]}}},
                        {"units", units_json()},
                        {"sign_convention", kSignNote}};
  if (r.samples) {
    const EquilibriumSamples& m = *r.samples;
    nlohmann::json mc = draws_json(*r.draws, r.seed, m.samples + m.failures.count, m.samples, m.failures,
                                   r.samples_wall_s, m.percentiles);
    mc["mean"] = velocity_json(m.mean);
    mc["standard_deviation"] = velocity_json(m.standard_deviation);
    nlohmann::json values = nlohmann::json::object();
    for (std::size_t j = 0; j < m.percentiles.size(); ++j)
      values[percentile_label(m.percentiles[j])] = velocity_json(m.percentile_values[j]);
    mc["velocity_percentiles"] = values;
    out["monte_carlo"] = mc;
  }
  return escape::json_text(out, 2) + '\n';
}

std::string equilibrium_text(const EquilibriumReport& r) {
  std::ostringstream out;
  out << "equilibrium of " << escape::one_line(r.vehicle_name.empty() ? r.vehicle : r.vehicle_name) << " under";
  for (std::size_t i = 0; i < 6; ++i)
    if (r.in.tau_b[static_cast<Eigen::Index>(i)] != 0.0)
      out << " " << kForceNames[i] << " = " << significant(r.in.tau_b[static_cast<Eigen::Index>(i)], 6) << " "
          << kForceUnits[i];
  if (r.in.tau_b.isZero()) out << " no force";
  out << " (attitude held; " << r.eq.iterations << " iterations";
  if (r.eq.continuation_s > 0.0)
    out << ", from where a simulation of " << significant(r.eq.continuation_s, 3) << " s got to";
  out << ", largest residual " << significant(r.eq.residual_b.cwiseAbs().maxCoeff(), 3) << ")\n";
  print_velocity_table(out, r.eq.nu_b, r.eq.forces);
  out << "  (" << kSignNote << ")\n";
  if (!r.samples) return out.str();
  const EquilibriumSamples& m = *r.samples;
  print_draws(out, *r.draws, r.seed, m.samples + m.failures.count, m.samples, m.failures, r.samples_wall_s);
  out << "  steady velocity over the draws:\n  " << std::left << std::setw(4) << "" << std::setw(14) << "mean"
      << std::setw(14) << "std. dev.";
  for (const double p : m.percentiles) out << std::setw(14) << percentile_label(p);
  out << "unit\n";
  for (std::size_t i = 0; i < 6; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    if (m.standard_deviation[k] == 0.0 && m.mean[k] == 0.0) continue;
    out << "  " << std::setw(4) << kVelocityNames[i] << std::setw(14) << significant(m.mean[k], 6) << std::setw(14)
        << significant(m.standard_deviation[k], 4);
    for (std::size_t j = 0; j < m.percentiles.size(); ++j)
      out << std::setw(14) << significant(m.percentile_values[j][k], 6);
    out << kVelocityUnits[i] << '\n';
  }
  out << std::right;
  return out.str();
}

}  // namespace hydrocoef
