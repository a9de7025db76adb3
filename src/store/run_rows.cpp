#include "src/store/run_rows.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/sign_convention.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::store {

bool same_value(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max({1.0, std::abs(a), std::abs(b)}); }

RunRows::RunRows(Connection& connection)
    : find_source_(connection.prepare("SELECT id FROM source_file WHERE sha256 = ?")),
      insert_source_(connection.prepare(
          "INSERT INTO source_file(path, sha256, size_bytes, importer, importer_version, imported_at) "
          "VALUES (?, ?, ?, ?, ?, ?) RETURNING id")),
      details_(connection.prepare("SELECT density, kinematic_viscosity, ref_x, ref_y, ref_z FROM run WHERE id = ?")),
      update_fluid_(connection.prepare(
          "UPDATE run SET density = coalesce(density, ?), kinematic_viscosity = coalesce(kinematic_viscosity, ?) "
          "WHERE id = ?")),
      insert_run_(connection.prepare(
          "INSERT INTO run(body_id, u, v, w, p, q, r, disturbance_key, density, kinematic_viscosity, ref_x, ref_y, "
          "ref_z) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?) RETURNING id")),
      insert_disturbance_(connection.prepare("INSERT INTO run_disturbance(run_id, name, value) VALUES (?, ?, ?)")),
      force_(connection.prepare(
          "INSERT INTO run_force(run_id, component, total, pressure, viscous, sign_convention, source_id, "
          "source_line, import_id, uncertainty) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT (run_id, component) "
          "DO UPDATE SET total = excluded.total, pressure = excluded.pressure, viscous = excluded.viscous, "
          "sign_convention = excluded.sign_convention, source_id = excluded.source_id, "
          "source_line = excluded.source_line, import_id = excluded.import_id, uncertainty = excluded.uncertainty")),
      statistics_(connection.prepare(
          "INSERT INTO run_force_statistics(run_id, component, abscissa, window_method, window_first, window_last, "
          "samples, flags, standard_error, spread, drift, effective_samples, convergence, convergence_reason) VALUES "
          "(?, "
          "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")),
      surface_(connection.prepare(
          "INSERT INTO run_surface(run_id, source_id, faces, area, signed_volume, closed, boundary_edges, "
          "degenerate_faces, normals_flipped, n_dA_x, n_dA_y, n_dA_z, x_cross_n_dA_x, x_cross_n_dA_y, "
          "x_cross_n_dA_z, reference_pressure, pressure_array, shear_array, pressure_kind, shear_convention, axes) "
          "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT (run_id) DO UPDATE SET "
          "source_id = excluded.source_id, faces = excluded.faces, area = excluded.area, "
          "signed_volume = excluded.signed_volume, closed = excluded.closed, boundary_edges = excluded.boundary_edges, "
          "degenerate_faces = excluded.degenerate_faces, normals_flipped = excluded.normals_flipped, "
          "n_dA_x = excluded.n_dA_x, n_dA_y = excluded.n_dA_y, n_dA_z = excluded.n_dA_z, "
          "x_cross_n_dA_x = excluded.x_cross_n_dA_x, x_cross_n_dA_y = excluded.x_cross_n_dA_y, "
          "x_cross_n_dA_z = excluded.x_cross_n_dA_z, reference_pressure = excluded.reference_pressure, "
          "pressure_array = excluded.pressure_array, shear_array = excluded.shear_array, "
          "pressure_kind = excluded.pressure_kind, shear_convention = excluded.shear_convention, axes = "
          "excluded.axes")),
      trace_(connection.prepare(
          "INSERT INTO run_force_trace(run_id, abscissa, samples, components, data) VALUES (?, ?, ?, ?, ?) "
          "ON CONFLICT (run_id) DO UPDATE SET abscissa = excluded.abscissa, samples = excluded.samples, "
          "components = excluded.components, data = excluded.data")),
      drop_trace_(connection.prepare("DELETE FROM run_force_trace WHERE run_id = ?")) {}

void RunRows::check_and_fill(std::int64_t run_id, const RunKey& key, const Fluid& fluid,
                             const std::array<double, 3>& reference_point_b, const SourceLocation& where) {
  details_.bind(1, run_id);
  details_.step();
  const auto density = details_.get_optional_double(0);
  const auto viscosity = details_.get_optional_double(1);
  const std::array<double, 3> ref{details_.get_double(2), details_.get_double(3), details_.get_double(4)};
  details_.reset();
  for (std::size_t i = 0; i < 3; ++i)
    if (!same_value(ref[i], reference_point_b[i]))
      throw InputError(where, "run " + describe(key) +
                                  " already exists with another moment reference point; expected the same "
                                  "reference point for every source of one run");
  if ((density && fluid.density_kg_m3 && !same_value(*density, *fluid.density_kg_m3)) ||
      (viscosity && fluid.kinematic_viscosity_m2_s && !same_value(*viscosity, *fluid.kinematic_viscosity_m2_s)))
    throw InputError(where,
                     "run " + describe(key) + " already exists with other fluid properties (density or viscosity)");
  update_fluid_.bind(1, fluid.density_kg_m3).bind(2, fluid.kinematic_viscosity_m2_s).bind(3, run_id).run();
}

std::int64_t RunRows::source_id(const Provenance& file, const std::string& imported_at) {
  find_source_.bind(1, file.sha256);
  if (find_source_.step()) {
    const std::int64_t id = find_source_.get_int(0);
    find_source_.reset();
    return id;
  }
  find_source_.reset();
  insert_source_.bind(1, file.path)
      .bind(2, file.sha256)
      .bind(3, static_cast<std::int64_t>(file.size_bytes))
      .bind(4, file.importer)
      .bind(5, file.importer_version)
      .bind(6, imported_at);
  return returned_id(insert_source_);
}

std::int64_t RunRows::insert(std::int64_t body_id, const RunKey& key, const Fluid& fluid,
                             const std::array<double, 3>& reference_point_b) {
  insert_run_.bind(1, body_id);
  for (int i = 0; i < 6; ++i) insert_run_.bind(2 + i, canonical(key.nu_b[static_cast<std::size_t>(i)]));
  insert_run_.bind(8, disturbance_signature(key.disturbances))
      .bind(9, fluid.density_kg_m3)
      .bind(10, fluid.kinematic_viscosity_m2_s)
      .bind(11, reference_point_b[0])
      .bind(12, reference_point_b[1])
      .bind(13, reference_point_b[2]);
  const std::int64_t id = returned_id(insert_run_);
  for (const auto& [name, value] : key.disturbances)
    insert_disturbance_.bind(1, id).bind(2, name).bind(3, canonical(value)).run();
  return id;
}

void RunRows::write_force(std::int64_t run_id, std::size_t component, const ForceComponent& value, SignConvention sign,
                          std::int64_t source_id, std::size_t source_line, std::optional<std::int64_t> import_id) {
  force_.bind(1, run_id)
      .bind(2, std::string(kForceNames[component]))
      .bind(3, value.total)
      .bind(4, value.pressure)
      .bind(5, value.viscous)
      .bind(6, to_string(sign))
      .bind(7, source_id)
      .bind(8, static_cast<std::int64_t>(source_line));
  if (import_id)
    force_.bind(9, *import_id);
  else
    force_.bind_null(9);
  force_.bind(10, value.uncertainty).run();
}

void RunRows::write_statistics(std::int64_t run_id, std::size_t component, const StoredStatistics& s) {
  std::string flag_list;
  for (const auto& flag : s.flags) flag_list += (flag_list.empty() ? "" : ",") + flag;
  statistics_.bind(1, run_id)
      .bind(2, std::string(kForceNames[component]))
      .bind(3, s.abscissa)
      .bind(4, s.window_method)
      .bind(5, s.window_first)
      .bind(6, s.window_last)
      .bind(7, static_cast<std::int64_t>(s.samples))
      .bind(8, flag_list)
      .bind(9, s.values.standard_error)
      .bind(10, s.values.spread)
      .bind(11, s.values.drift)
      .bind(12, s.values.effective_samples)
      .bind(13, s.convergence)
      .bind(14, s.convergence_reason)
      .run();
}

void RunRows::write_surface(std::int64_t run_id, std::int64_t source_id, const SurfaceIntegrals& g) {
  surface_.bind(1, run_id)
      .bind(2, source_id)
      .bind(3, static_cast<std::int64_t>(g.faces))
      .bind(4, g.area)
      .bind(5, g.signed_volume)
      .bind(6, static_cast<std::int64_t>(g.closed))
      .bind(7, static_cast<std::int64_t>(g.boundary_edges))
      .bind(8, static_cast<std::int64_t>(g.degenerate_faces))
      .bind(9, static_cast<std::int64_t>(g.normals_flipped));
  for (int i = 0; i < 3; ++i) {
    surface_.bind(10 + i, g.integral_n_dA_b[static_cast<std::size_t>(i)]);
    surface_.bind(13 + i, g.integral_x_cross_n_dA_b[static_cast<std::size_t>(i)]);
  }
  surface_.bind(16, g.reference_pressure)
      .bind(17, g.pressure_array)
      .bind(18, g.shear_array)
      .bind(19, g.pressure_kind)
      .bind(20, g.shear_convention)
      .bind(21, g.axes)
      .run();
}

void RunRows::write_trace(std::int64_t run_id, const HistoryTrace& trace) {
  if (trace.samples == 0) {
    drop_trace(run_id);
    return;
  }
  std::string components;
  std::vector<double> data = trace.abscissa;
  for (std::size_t c = 0; c < 6; ++c) {
    if (trace.low[c].empty()) continue;
    components += (components.empty() ? "" : ",") + std::string(kForceNames[c]);
    data.insert(data.end(), trace.low[c].begin(), trace.low[c].end());
    data.insert(data.end(), trace.high[c].begin(), trace.high[c].end());
  }
  trace_.bind(1, run_id)
      .bind(2, trace.abscissa_name)
      .bind(3, static_cast<std::int64_t>(trace.samples))
      .bind(4, components)
      .bind_doubles(5, data)
      .run();
}

void RunRows::drop_trace(std::int64_t run_id) { drop_trace_.bind(1, run_id).run(); }

}  // namespace hydrocoef::store
