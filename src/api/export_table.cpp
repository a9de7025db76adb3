// export_surface (include/hydrocoef/exports.hpp): `hydrocoef export`, a stored
// gridded surface written for another tool (src/export/), and what the
// command prints about it.
#include "src/api/internal.hpp"
#include "src/api/runtime_file.hpp"
#include "src/api/surface_report.hpp"

#include <algorithm>
#include <optional>
#include <sstream>

#include "src/api/vehicle_inputs.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/export/export.hpp"
#include "src/export/runtime_export.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef {
inline namespace api {

void TableExportOptions::validate() const {
  if (name.empty())
    throw InputError(
        "export: no surface named; expected 'hydrocoef export NAME --format F -o FILE' (runs are "
        "written with --format openfoam-forcecoeffs)");
  const ExportFormat parsed = parse_export_format(format);
  if (single_precision && parsed != ExportFormat::CHeader)
    throw InputError("--float applies to --format c only; expected it with c (got --format " + format + ")");
  if (!identifier.empty() && parsed != ExportFormat::CHeader)
    throw InputError("--identifier applies to --format c only; expected it with c (got --format " + format + ")");
  if (!surfaces.empty() && parsed != ExportFormat::Runtime)
    throw InputError("--surface applies to --format runtime only; expected it with runtime (got --format " + format +
                     ")");
  if (!vehicle.empty() && parsed != ExportFormat::Runtime)
    throw InputError("--vehicle applies to --format runtime only; expected it with runtime (got --format " + format +
                     ")");
}

namespace {

// The database's location for a file's provenance, without a URL's user and password.
std::string location_without_credentials(const std::string& location) {
  const auto scheme = location.find("://");
  if (scheme == std::string::npos) return location;
  const auto at = location.find('@', scheme + 3);
  const auto slash = location.find('/', scheme + 3);
  if (at == std::string::npos || (slash != std::string::npos && at > slash)) return location;
  return location.substr(0, scheme + 3) + location.substr(at + 1);
}

std::string run_list(const std::vector<std::int64_t>& runs) {
  std::string out;
  for (std::size_t i = 0; i < runs.size(); ++i) out += (i ? "," : "") + std::to_string(runs[i]);
  return out;
}

// Where a runtime surface's table comes from: the stored grid, or an RBF
// surface tabulated on a grid by `surface build --resample` (its quality
// figures then count the grid's nodes and those far from every run).
std::string runtime_source(const SurfaceRecord& record) {
  const auto quality = nlohmann::json::parse(record.quality.empty() ? "{}" : record.quality, nullptr, false);
  if (quality.is_object() && quality.contains("grid_points")) {
    const std::size_t far =
        quality.contains("far_from_data") && quality["far_from_data"].is_array() ? quality["far_from_data"].size() : 0;
    return "an RBF surface tabulated on a grid by surface build --resample (" + quality["grid_points"].dump() +
           " nodes, " + std::to_string(far) +
           " of them far from every run: extrapolation), as hydrocoef "
           "evaluates the stored grid";
  }
  return "the stored grid table, as hydrocoef evaluates it";
}

}  // namespace

std::string runtime_file_of(const Database& db, const std::vector<std::string>& names, const RuntimeTexts& extra,
                            std::vector<StoredSurface>& stored, const RuntimeVehicle* vehicle,
                            const std::string& vehicle_body) {
  {
    auto& impl = Database::Access::impl(db);
    const std::lock_guard lock(impl.mutex);
    for (const std::string& name : names) stored.push_back(load_surface(impl.open_store(), name));
  }
  const std::string body = vehicle ? vehicle_body : stored.front().record.body;
  std::vector<RuntimeSurface> surfaces;
  std::string listed;
  for (const StoredSurface& s : stored) {
    if (vehicle && s.record.body != body)
      throw InputError("surface '" + s.record.name + "' belongs to body '" + s.record.body +
                       "'; expected surfaces of body '" + body + "' (the body named with --vehicle)");
    if (s.record.body != stored.front().record.body)
      throw InputError("surface '" + s.record.name + "' belongs to body '" + s.record.body + "', surface '" +
                       stored.front().record.name + "' to body '" + stored.front().record.body +
                       "'; expected the surfaces of one body in a runtime file");
    surfaces.push_back(runtime_surface(
        s.record.name, s.surface,
        {{"content_sha256", content_sha256(s.record)},
         {"runs", run_list(s.record.run_ids)},
         {"created_at", s.record.created_at},
         {"stale", s.record.stale ? "true" : "false"},
         {"source", runtime_source(s.record)},
         {"quality", s.record.quality},
         {"sigma", s.surface.has_standard_deviation() ? "runs' sigma interpolated (clamped), at least 0, in "
                                                        "quadrature with the leave-one-out RMS"
                                                      : "none"}}));
    listed += (listed.empty() ? "" : ",") + s.record.name;
  }
  RuntimeTexts given = {{"database", location_without_credentials(db.path())},
                        {"body", body},
                        {"created_at", utc_timestamp_now()},
                        {"surfaces", listed}};
  given.insert(given.end(), extra.begin(), extra.end());
  return runtime_file_bytes(runtime_model_texts(std::move(given), vehicle != nullptr), surfaces, vehicle);
}

namespace {

// The runtime file: `name` and options.surfaces, all of one body; with a
// vehicle, the surfaces its damping reads and options.surfaces, all of body
// `name`, and the vehicle (resolved through the database as simulate does).
void write_runtime_file(const Database& db, const TableExportOptions& options, std::vector<StoredSurface>& stored,
                        std::string& vehicle_name) {
  std::optional<VehicleModel> vehicle;
  std::vector<std::string> names;
  if (options.vehicle.empty()) {
    names.push_back(options.name);
  } else {
    vehicle.emplace(load_vehicle_model(options.vehicle, db.path()));
    for (const DofDamping& d : vehicle->description().damping)
      if (d.kind == DofDamping::Kind::Surface && std::find(names.begin(), names.end(), d.surface) == names.end())
        names.push_back(d.surface);
    vehicle_name = vehicle->description().name.empty() ? options.name : vehicle->description().name;
  }
  for (const std::string& name : options.surfaces)
    if (std::find(names.begin(), names.end(), name) == names.end() || options.vehicle.empty()) names.push_back(name);
  if (!vehicle) {
    write_file_atomically(options.output, runtime_file_of(db, names, {}, stored));
    return;
  }
  const std::string& file = vehicle->description().file;
  const RuntimeVehicle runtime_vehicle{&*vehicle,
                                       {{"name", vehicle_name}, {"file", file.empty() ? "JSON text" : file}}};
  write_file_atomically(options.output, runtime_file_of(db, names, {}, stored, &runtime_vehicle, options.name));
}

}  // namespace

TableExportResult export_surface(const Database& db, const TableExportOptions& options) {
  options.validate();
  const ExportFormat format = parse_export_format(options.format);
  std::vector<StoredSurface> all;
  TableExportResult out;
  if (format == ExportFormat::Runtime) {
    write_runtime_file(db, options, all, out.vehicle);
    out.files.push_back(options.output);
    if (all.empty()) {  // a vehicle whose damping reads no surface
      out.body = options.name;
      out.format = std::string(export_format_name(format));
      return out;
    }
  } else {
    auto& impl = Database::Access::impl(db);
    const std::lock_guard lock(impl.mutex);
    all.push_back(load_surface(impl.open_store(), options.name));
  }
  const StoredSurface& stored = all.front();
  for (const StoredSurface& s : all) out.surfaces.push_back(s.record.name);
  const ExportMetadata metadata = metadata_from_record(stored.record, stored.surface);
  const GridTable& table = *stored.surface.grid();
  ExportOptions writing;
  writing.single_precision = options.single_precision;
  writing.c_identifier = options.identifier;

  if (format != ExportFormat::Runtime) {
    for (const auto& file : export_table(table, metadata, format, options.output, writing))
      out.files.push_back(file.string());
  }
  out.surface = metadata.surface_name;
  out.body = metadata.body;
  out.format = std::string(export_format_name(format));
  out.method = std::string(interpolation_name(table.method()));
  out.content_sha256 = metadata.content_sha256;
  out.runs = metadata.run_ids;
  out.stale = metadata.stale;
  out.nodes = table.node_count();
  for (std::size_t a = 0; a < table.axis_count(); ++a) {
    const GridAxis& axis = table.axes()[a];
    const double lower = axis.breakpoints.front(), upper = axis.breakpoints.back();
    out.axes.push_back({axis.name, metadata.axis_units[a], axis.breakpoints.size(), lower, upper,
                        std::string(extrapolation_name(axis.extrapolation))});
    // A table whose range leaves out zero on an axis that refuses values
    // outside it fails at rest (u = 0) in the controller: say so, once per axis.
    if (axis.extrapolation == Extrapolation::Error && (lower > 0.0 || upper < 0.0))
      out.notes.push_back("axis " + axis.name + " covers [" + shortest_number(lower) + ", " + shortest_number(upper) +
                          "] and refuses values outside it (policy error): a query at " + axis.name +
                          " = 0 (at rest) fails; build the surface with --extrapolate " + axis.name + "=clamp or " +
                          axis.name + "=linear if the controller will ask there");
  }
  out.outputs = table.outputs();
  out.output_units = metadata.output_units;
  return out;
}

std::string TableExportResult::json() const {
  nlohmann::json out = {{"surface", surface},
                        {"body", body},
                        {"format", format},
                        {"method", method},
                        {"content_sha256", content_sha256},
                        {"runs", runs},
                        {"stale", stale},
                        {"nodes", nodes}};
  out["files"] = files;
  out["surfaces"] = surfaces;
  if (!vehicle.empty()) out["vehicle"] = vehicle;
  for (const auto& axis : axes)
    out["axes"].push_back({{"name", axis.name},
                           {"unit", axis.unit},
                           {"breakpoints", axis.breakpoints},
                           {"valid_range", {axis.lower, axis.upper}},
                           {"extrapolation", axis.extrapolation}});
  for (std::size_t k = 0; k < outputs.size(); ++k)
    out["outputs"].push_back({{"name", outputs[k]}, {"unit", output_units[k]}});
  out["notes"] = notes;
  return escape::json_text(out, 2) + '\n';
}

std::string TableExportResult::text() const {
  std::ostringstream out;
  if (!vehicle.empty())
    out << "exported vehicle " << escape::one_line(vehicle) << " of body " << escape::one_line(body) << " ("
        << surfaces.size() << " surfaces) as runtime\n";
  if (surface.empty()) {
    for (const auto& file : files) out << "  wrote " << escape::one_line(file) << '\n';
    return out.str();
  }
  out << "exported surface " << escape::one_line(surface) << " (" << method << ", " << nodes << " nodes) as " << format
      << "\n";
  for (const auto& axis : axes)
    out << "  axis " << escape::one_line(axis.name) << " [" << escape::one_line(axis.unit) << "] in ["
        << shortest_number(axis.lower) << ", " << shortest_number(axis.upper) << "], outside: " << axis.extrapolation
        << '\n';
  out << "  outputs";
  for (std::size_t k = 0; k < outputs.size(); ++k)
    out << ' ' << escape::one_line(outputs[k]) << " [" << escape::one_line(output_units[k]) << "]";
  out << ", forces on the body\n  content sha256 " << escape::one_line(content_sha256) << '\n';
  if (surfaces.size() > 1) {
    out << "  surfaces";
    for (const auto& name : surfaces) out << ' ' << escape::one_line(name);
    out << '\n';
  }
  for (const auto& file : files) out << "  wrote " << escape::one_line(file) << '\n';
  for (const auto& note : notes) out << "  note: " << escape::one_line(note) << '\n';
  if (stale)
    out << "  note: the body's forces changed since this surface was built; rebuild it with "
           "hydrocoef surface rebuild "
        << escape::one_line(surface) << '\n';
  return out.str();
}

}  // namespace api
}  // namespace hydrocoef
