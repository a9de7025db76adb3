// simulate (include/hydrocoef/simulation.hpp): `hydrocoef simulate` without
// its printing: the vehicle model with its surfaces from a database
// (src/dynamics/surface_source), the library's simulate, and the trajectory's
// CSV columns as numbers.
#include "src/api/internal.hpp"

#include <stdexcept>

namespace hydrocoef {
inline namespace api {
namespace {

/// JSON text rather than a path: it starts with '{' (after blanks) or spans lines.
bool is_json_text(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  return (first != std::string::npos && text[first] == '{') || text.find('\n') != std::string::npos;
}

/// The CSV header's columns split into names and units ("u [m s^-1]" -> "u", "m s^-1").
void split_header(std::vector<std::string>& names, std::vector<std::string>& units) {
  const std::string header = trajectory_csv_header();
  for (std::size_t start = 0; start <= header.size();) {
    const auto comma = header.find(',', start);
    const std::string cell = header.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto bracket = cell.find(" [");
    names.push_back(cell.substr(0, bracket));
    units.push_back(bracket == std::string::npos ? std::string() : cell.substr(bracket + 2, cell.size() - bracket - 3));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
}

}  // namespace

const double* Trajectory::column(std::string_view name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return values.data() + c * rows;
  throw std::out_of_range("hydrocoef::Trajectory: no column '" + std::string(name) + "'");
}

Trajectory simulate(const std::string& vehicle_json, const std::string& scenario_json, const std::string& database) {
  VehicleDescription vehicle =
      is_json_text(vehicle_json) ? parse_vehicle(vehicle_json, "vehicle JSON") : load_vehicle(vehicle_json);
  const Scenario scenario =
      is_json_text(scenario_json) ? parse_scenario(scenario_json, "scenario JSON") : load_scenario(scenario_json);
  if (!database.empty()) resolve_stored_records(vehicle, database);
  if (database.empty() && vehicle.added_mass_from_database)
    throw InputError(SourceLocation{vehicle.file},
                     "key 'added_mass.from_database': no database was given; expected one");
  const VehicleModel model(std::move(vehicle),
                           database.empty() ? SurfaceResolver() : database_surface_resolver(database));
  const SimulationResult result = hydrocoef::simulate(model, scenario);

  Trajectory out;
  split_header(out.columns, out.units);
  out.rows = result.samples.size();
  out.notes = result.notes;
  out.values.resize(out.columns.size() * out.rows);
  // In the order write_trajectory_csv writes a row (src/dynamics/trajectory.cpp);
  // tests/api/api_test.cpp checks the two agree column by column.
  for (std::size_t r = 0; r < out.rows; ++r) {
    const TrajectorySample& s = result.samples[r];
    std::size_t c = 0;
    const auto put = [&](double value) { out.values[c++ * out.rows + r] = value; };
    const auto put_all = [&](const auto& vector) {
      for (Eigen::Index i = 0; i < vector.size(); ++i) put(vector[i]);
    };
    put(s.t_s);
    put_all(s.p_n);
    put_all(s.euler_rad);
    put_all(s.q_nb);
    put_all(s.nu_b);
    put_all(s.forces.nu_r_b);
    put_all(s.forces.control_b);
    put_all(s.forces.damping_b);
    put_all(s.forces.hydrostatic_b);
    put_all(s.forces.coriolis_b);
    if (c != out.columns.size())
      throw std::logic_error("hydrocoef::simulate: " + std::to_string(c) + " values per sample for " +
                             std::to_string(out.columns.size()) + " columns");
  }
  return out;
}

}  // namespace api
}  // namespace hydrocoef
