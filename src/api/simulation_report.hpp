// How a simulation and an equilibrium report themselves: the text `hydrocoef
// simulate` and `equilibrium` print, and their JSON (src/api/simulation.cpp,
// src/api/equilibrium.cpp make the public outcomes with them).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/dynamics/damping_draws.hpp"
#include "src/dynamics/ensemble.hpp"
#include "src/dynamics/equilibrium.hpp"
#include "src/dynamics/experiment.hpp"
#include "src/dynamics/simulation.hpp"

namespace hydrocoef {

/// What a simulate command ran and got.
struct SimulationReport {
  const std::string& vehicle;       ///< the vehicle file
  const std::string& vehicle_name;  ///< its name ("" when it gives none)
  const std::string& scenario_path;
  const Scenario& scenario;
  const SimulationResult& result;
  double wall_s = 0.0;
  const std::optional<std::string>& out;         ///< the trajectory CSV written, if any
  const std::optional<std::string>& experiment;  ///< the measured trajectory compared with, if any
  double steady_fraction = 0.2;
  const std::vector<ComponentComparison>& comparison;
  /// A Monte Carlo run (--samples): its bands and what was drawn; null otherwise.
  const TrajectoryBands* bands = nullptr;
  const DampingDraws* draws = nullptr;
  std::uint64_t seed = 0;
  double samples_wall_s = 0.0;
  /// The measured record, for the share of it inside the outer band.
  const MeasuredTrajectory* measured = nullptr;
};

/// What an equilibrium command solved.
struct EquilibriumReport {
  const std::string& vehicle;
  const std::string& vehicle_name;
  const EquilibriumInputs& in;
  const EquilibriumResult& eq;
  const std::array<double, 3>& attitude;  ///< roll, pitch, yaw held [deg]
  /// A Monte Carlo run (--samples): its distribution and what was drawn; null otherwise.
  const EquilibriumSamples* samples = nullptr;
  const DampingDraws* draws = nullptr;
  std::uint64_t seed = 0;
  double samples_wall_s = 0.0;
};

std::string simulation_text(const SimulationReport& report);
std::string simulation_json(const SimulationReport& report);
std::string equilibrium_text(const EquilibriumReport& report);
std::string equilibrium_json(const EquilibriumReport& report);

}  // namespace hydrocoef
