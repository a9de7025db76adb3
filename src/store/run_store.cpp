// RunDatabase::import, the runs read back (runs, find_run, sources,
// import_record) and their removal (delete_runs, and the forces an import
// replaced with --replace): tables run, run_disturbance, run_force,
// run_force_statistics, run_surface, import and source_file. Every value
// read back is checked (src/store/checked_row.hpp): a received database is
// untrusted input.
#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <unordered_map>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/text.hpp"
#include "src/core/version.hpp"
#include "src/store/backend.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/database.hpp"
#include "src/store/run_rows.hpp"

namespace hydrocoef {
namespace {

using store::canonical;

constexpr double kFilterTolerance = 1e-9;

std::string force_name(std::size_t i) { return std::string(kForceNames[i]); }

/// The settings two imports of one file differ in, for the refusal of a
/// re-import with other settings: "rho: 998.2 (command line) then 1025
/// (sidecar a.vtp.json)", at most four of them.
std::string settings_difference(const std::string& before, const std::string& after) {
  if (before.empty()) return "the earlier import's settings are not recorded: it was made by an older hydrocoef";
  const auto old_json = nlohmann::json::parse(before, nullptr, false);
  const auto new_json = nlohmann::json::parse(after.empty() ? "{}" : after, nullptr, false);
  if (!old_json.is_object() || !new_json.is_object()) return "settings differ";
  const auto describe_setting = [](const nlohmann::json& setting) {
    if (!setting.is_object()) return std::string("not set");
    return printable_text(escape::json_text(setting.value("value", nlohmann::json())), 40) + " (" +
           printable_text(setting.value("source", std::string("?")), 40) + ")";
  };
  std::vector<std::string> differences;
  std::set<std::string> keys;
  for (const auto& [key, value] : old_json.items()) keys.insert(key);
  for (const auto& [key, value] : new_json.items()) keys.insert(key);
  for (const auto& key : keys) {
    const auto a = old_json.contains(key) ? old_json.at(key) : nlohmann::json();
    const auto b = new_json.contains(key) ? new_json.at(key) : nlohmann::json();
    const auto value_of = [](const nlohmann::json& s) {
      return s.is_object() ? s.value("value", nlohmann::json()) : nlohmann::json();
    };
    if (value_of(a) == value_of(b)) continue;
    differences.push_back(printable_text(key, 40) + ": " + describe_setting(a) + " then " + describe_setting(b));
  }
  if (differences.empty()) return "the same values from other places";
  std::string out;
  for (std::size_t i = 0; i < differences.size() && i < 4; ++i) out += (i ? "; " : "") + differences[i];
  if (differences.size() > 4) out += "; and " + std::to_string(differences.size() - 4) + " more";
  return out;
}

}  // namespace

double StoredForce::standard_uncertainty() const {
  const double se = statistics ? statistics->values.standard_error : 0.0;
  const double given = value.uncertainty.value_or(0.0);
  return std::hypot(se, given, numerical_uncertainty.value_or(0.0));
}

std::optional<std::int64_t> RunDatabase::find_run_id(std::int64_t body, const RunKey& key) {
  auto find = connection_.prepare(
      "SELECT id FROM run WHERE body_id = ? AND u = ? AND v = ? AND w = ? AND p = ? AND q = ? AND r = ? "
      "AND disturbance_key = ?");
  find.bind(1, body);
  for (int i = 0; i < 6; ++i) find.bind(2 + i, canonical(key.nu_b[static_cast<std::size_t>(i)]));
  find.bind(8, disturbance_signature(key.disturbances));
  if (find.step()) return find.get_int(0);
  return std::nullopt;
}

std::pair<std::int64_t, bool> RunDatabase::find_or_insert_run(store::RunRows& rows, const RunKey& key,
                                                              const Fluid& fluid,
                                                              const std::array<double, 3>& reference_point_b,
                                                              const SourceLocation& where) {
  const std::int64_t body = body_id(key.body, true);
  if (const auto existing = find_run_id(body, key)) {
    rows.check_and_fill(*existing, key, fluid, reference_point_b, where);
    return {*existing, false};
  }
  return {rows.insert(body, key, fluid, reference_point_b), true};
}

std::vector<ImportOutcome> RunDatabase::import(const std::vector<ImportBatch>& batches, ConflictPolicy policy) {
  ImportPolicy options;
  options.components = policy;
  options.replace = policy == ConflictPolicy::Replace;
  return import(batches, options);
}

std::vector<ImportOutcome> RunDatabase::import(const std::vector<ImportBatch>& batches, const ImportPolicy& options) {
  const ConflictPolicy policy = options.components;
  if (!options.also.empty()) check_name(NameKind::Parameter, options.also, {}, "--also");
  std::vector<ImportOutcome> outcomes;
  store::Transaction transaction(connection_);
  const std::string now = utc_timestamp_now();

  auto find_import = connection_.prepare(
      "SELECT id, settings_key, settings, path, imported_at FROM import WHERE source_id = ? AND reading = ?");
  auto insert_import = connection_.prepare(
      "INSERT INTO import(source_id, reading, settings_key, settings, path, resolved_path, importer, importer_version, "
      "hydrocoef_version, imported_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?) RETURNING id");
  store::RunRows rows(connection_);
  auto existing_force = connection_.prepare(
      "SELECT s.path, f.source_line, s.imported_at FROM run_force f JOIN source_file s ON s.id = f.source_id "
      "WHERE f.run_id = ? AND f.component = ?");

  // A component's statistics go with it: a value written without
  // statistics leaves none of an earlier value behind.
  auto drop_statistics = connection_.prepare("DELETE FROM run_force_statistics WHERE run_id = ? AND component = ?");

  for (const auto& batch : batches) {
    ImportOutcome outcome;
    outcome.path = batch.source.path;
    outcome.sha256 = batch.source.sha256;
    outcome.reading = options.also;
    // The file's bytes, once per database.
    const std::int64_t source_id = rows.source_id(batch.source, now);
    // The import: those bytes read with these settings.
    find_import.bind(1, source_id).bind(2, options.also);
    if (find_import.step()) {
      const std::int64_t previous = find_import.get_int(0);
      const std::string previous_key = find_import.get_text(1);
      const std::string previous_settings = find_import.get_text(2);
      outcome.previous_path = find_import.get_text(3);
      outcome.previously_imported_at = find_import.get_text(4);
      find_import.reset();
      if (previous_key == batch.source.settings_key) {
        outcome.already_imported = true;
        outcome.import_id = previous;
        outcomes.push_back(outcome);
        continue;
      }
      if (!options.replace)
        throw InputError(SourceLocation{batch.source.path},
                         "already imported on " + outcome.previously_imported_at + " from '" +
                             printable_text(outcome.previous_path, 80) + "'" +
                             (options.also.empty() ? "" : " as reading '" + options.also + "'") +
                             " with other settings (" + settings_difference(previous_settings, batch.source.settings) +
                             "); give --replace to replace the runs of that import, or --also NAME to keep both "
                             "readings of the file");
      outcome.replaced = true;
      remove_import_forces(previous);
      connection_.prepare("DELETE FROM import WHERE id = ?").bind(1, previous).run();
    } else {
      find_import.reset();
    }
    insert_import.bind(1, source_id)
        .bind(2, options.also)
        .bind(3, batch.source.settings_key)
        .bind(4, batch.source.settings)
        .bind(5, batch.source.path)
        .bind(6, batch.source.resolved_path)
        .bind(7, batch.source.importer)
        .bind(8, batch.source.importer_version)
        .bind(9, std::string_view(kVersion))
        .bind(10, now);
    const std::int64_t import_id = store::returned_id(insert_import);
    outcome.import_id = import_id;

    for (const auto& run : batch.runs) {
      const SourceLocation where{batch.source.path, run.source_line, 0};
      // Names are checked where they enter; the store checks again, so that
      // no caller of the library can store a name that breaks the rule.
      check_name(NameKind::Body, run.key.body, where, "the run's body");
      for (const auto& [name, value] : run.key.disturbances) {
        check_name(NameKind::Parameter, name, where, "a disturbance");
        if (!std::isfinite(value))
          throw InputError(where, "disturbance '" + name + "' is not a finite number; expected one");
      }
      const auto [run_id, created] = find_or_insert_run(rows, run.key, run.fluid, run.reference_point_b, where);
      if (created) ++outcome.runs_created;

      bool extended = false;
      for (std::size_t i = 0; i < 6; ++i) {
        if (!run.tau_b[i]) continue;
        existing_force.bind(1, run_id).bind(2, force_name(i));
        if (existing_force.step()) {
          const std::string previous = existing_force.get_text(0) + ":" + existing_force.get_text(1) + " (imported " +
                                       existing_force.get_text(2) + ")";
          existing_force.reset();
          if (policy == ConflictPolicy::Error)
            throw InputError(where, "run " + describe(run.key) + " already has " + force_name(i) + " from " + previous +
                                        "; give --replace to supersede it");
        } else {
          existing_force.reset();
        }
        const auto& force = *run.tau_b[i];
        rows.write_force(run_id, i, force, run.sign, source_id, run.source_line, import_id);
        drop_statistics.bind(1, run_id).bind(2, force_name(i)).run();
        if (run.statistics && run.statistics->components[i]) {
          const RunStatistics& statistics = *run.statistics;
          const ComponentWindow& window = statistics.windows[i];
          rows.write_statistics(run_id, i,
                                StoredStatistics{statistics.abscissa, window.method, window.first, window.last,
                                                 window.samples, window.flags, *statistics.components[i],
                                                 statistics.convergence, statistics.convergence_reason});
        }
        ++outcome.components_written;
        extended = true;
      }
      if (extended && !created) ++outcome.runs_extended;
      if (run.surface) rows.write_surface(run_id, source_id, *run.surface);
      // The trace of the latest history; a component without one takes an earlier one away.
      if (run.trace && run.statistics)
        rows.write_trace(run_id, *run.trace);
      else if (extended)
        rows.drop_trace(run_id);
    }
    outcomes.push_back(outcome);
  }
  transaction.commit();
  use_wal();
  return outcomes;
}

namespace {

/// A run's key as read: its disturbance_key column must be the canonical text
/// of its run_disturbance rows (the column, with the velocity, keeps each key
/// once in the table; the rows are what every reader uses). A run whose
/// column and rows disagree could be another run's key, and merge into it or
/// be listed as it; it is refused naming its table and row.
void check_run_keys(const std::string& db, const std::vector<StoredRun>& runs, const std::vector<std::string>& keys) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const StoredRun& run = runs[i];
    const std::string signature = disturbance_signature(run.key.disturbances);
    if (keys[i] != signature)
      throw InputError(SourceLocation{db},
                       "table 'run', row " + std::to_string(run.id) + ": column 'disturbance_key' is '" +
                           printable_text(keys[i], 80) + "' but its rows in table 'run_disturbance' give '" +
                           printable_text(signature, 80) +
                           "'; expected the key of its disturbances (a database changed by another program)");
  }
}

}  // namespace

std::vector<StoredRun> RunDatabase::load_runs(std::optional<std::int64_t> body, std::optional<std::int64_t> run) {
  // One state of the database for all the statements below.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT run.id, body.name, u, v, w, p, q, r, density, kinematic_viscosity, ref_x, ref_y, ref_z, body.id, "
      "disturbance_key FROM run JOIN body ON body.id = run.body_id WHERE TRUE";
  if (body) sql += " AND run.body_id = ?1";
  if (run) sql += " AND run.id = ?2";
  sql += " ORDER BY body.name, u, v, w, p, q, r, disturbance_key";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  if (run) select.bind(2, *run);

  std::vector<StoredRun> out;
  std::vector<std::string> stored_keys;  // each run's disturbance_key column, by position in out
  std::unordered_map<std::int64_t, std::size_t> index;
  const std::string db = path_.string();
  while (select.step()) {
    const store::CheckedRow row(select, db, "run", select.get_int(0));
    StoredRun stored;
    stored.id = select.get_int(0);
    stored.key.body = store::CheckedRow(select, db, "body", select.get_int(13)).name(1, NameKind::Body);
    for (int i = 0; i < 6; ++i) stored.key.nu_b[static_cast<std::size_t>(i)] = row.real(2 + i);
    stored.fluid.density_kg_m3 = row.optional_positive(8);
    stored.fluid.kinematic_viscosity_m2_s = row.optional_positive(9);
    for (int i = 0; i < 3; ++i) stored.reference_point_b[static_cast<std::size_t>(i)] = row.real(10 + i);
    stored_keys.push_back(row.text(14, std::size_t{1} << 20));
    index[stored.id] = out.size();
    out.push_back(std::move(stored));
  }
  if (out.empty()) return out;

  auto disturbances = connection_.prepare("SELECT run_id, name, value FROM run_disturbance");
  while (disturbances.step()) {
    const auto found = index.find(disturbances.get_int(0));
    if (found == index.end()) continue;
    const store::CheckedRow row(disturbances, db, "run_disturbance", disturbances.get_int(0));
    std::string name = row.name(1, NameKind::Parameter);
    if (std::find(kVelocityNames.begin(), kVelocityNames.end(), name) != kVelocityNames.end())
      row.fail(1, "a disturbance parameter, not a velocity component (u v w p q r are columns of table 'run')");
    out[found->second].key.disturbances[std::move(name)] = row.real(2);
  }
  check_run_keys(db, out, stored_keys);
  auto forces = connection_.prepare(
      "SELECT f.run_id, f.component, f.total, f.pressure, f.viscous, f.sign_convention, f.source_id, s.path, "
      "coalesce(f.source_line, 0), coalesce(f.import_id, 0), f.uncertainty FROM run_force f JOIN source_file s ON "
      "s.id = f.source_id");
  while (forces.step()) {
    const auto found = index.find(forces.get_int(0));
    if (found == index.end()) continue;
    const store::CheckedRow row(forces, db, "run_force", forces.get_int(0));
    const auto component = force_index(row.one_of(1, {"X", "Y", "Z", "K", "M", "N"}));
    StoredForce force;
    force.value.total = row.real(2);
    force.value.pressure = row.optional_real(3);
    force.value.viscous = row.optional_real(4);
    force.sign = parse_sign_convention(row.one_of(5, {"on-body", "opposing"}));
    force.source_id = row.integer(6, 1, std::numeric_limits<std::int64_t>::max());
    force.source_path = row.text(7);
    force.source_line = static_cast<std::size_t>(row.integer(8, 0, std::numeric_limits<std::int64_t>::max()));
    force.import_id = row.integer(9, 0, std::numeric_limits<std::int64_t>::max());
    force.value.uncertainty = row.optional_non_negative(10);
    out[found->second].tau_b[*component] = std::move(force);
  }
  auto statistics = connection_.prepare(
      "SELECT run_id, component, abscissa, window_method, window_first, window_last, samples, flags, standard_error, "
      "spread, drift, effective_samples, convergence, convergence_reason FROM run_force_statistics");
  while (statistics.step()) {
    const auto found = index.find(statistics.get_int(0));
    if (found == index.end()) continue;
    const store::CheckedRow row(statistics, db, "run_force_statistics", statistics.get_int(0));
    const auto component = *force_index(row.one_of(1, {"X", "Y", "Z", "K", "M", "N"}));
    auto& force = out[found->second].tau_b[component];
    if (!force)
      throw InputError(SourceLocation{db}, "table run_force_statistics, run " + std::to_string(statistics.get_int(0)) +
                                               ": statistics of " + force_name(component) +
                                               ", which the run does not have; expected statistics only beside a "
                                               "stored force component");
    StoredStatistics stored;
    stored.abscissa = row.one_of(2, {"time", "iteration"});
    stored.window_method = row.text(3, 1024);
    stored.window_first = row.real(4);
    stored.window_last = row.real(5);
    stored.samples = static_cast<std::size_t>(row.integer(6, 0, std::numeric_limits<std::int64_t>::max()));
    const std::string flags = row.text(7, 1024);
    for (std::size_t start = 0; start < flags.size();) {
      const std::size_t end = std::min(flags.find(',', start), flags.size());
      stored.flags.emplace_back(check_name(NameKind::Field, std::string_view(flags).substr(start, end - start),
                                           SourceLocation{db}, "a convergence flag in table run_force_statistics"));
      start = end + 1;
    }
    stored.values.standard_error = row.non_negative(8);
    stored.values.spread = row.non_negative(9);
    stored.values.drift = row.real(10);
    stored.values.effective_samples = row.non_negative(11);
    stored.convergence = row.one_of(12, {"", "converged", "steady-window", "transient-window", "given-window"});
    stored.convergence_reason = row.text(13, 4096);
    force->statistics = std::move(stored);
  }
  auto surfaces = connection_.prepare(
      "SELECT run_id, faces, area, signed_volume, closed, boundary_edges, degenerate_faces, normals_flipped, "
      "n_dA_x, n_dA_y, n_dA_z, x_cross_n_dA_x, x_cross_n_dA_y, x_cross_n_dA_z, reference_pressure, "
      "pressure_array, shear_array, pressure_kind, shear_convention, axes FROM run_surface");
  while (surfaces.step()) {
    const auto found = index.find(surfaces.get_int(0));
    if (found == index.end()) continue;
    const store::CheckedRow row(surfaces, db, "run_surface", surfaces.get_int(0));
    constexpr std::int64_t kMost = std::numeric_limits<std::int64_t>::max();
    SurfaceIntegrals g;
    g.faces = static_cast<std::size_t>(row.integer(1, 0, kMost));
    g.area = row.non_negative(2);
    g.signed_volume = row.real(3);
    g.closed = row.integer(4, 0, 1) != 0;
    g.boundary_edges = static_cast<std::size_t>(row.integer(5, 0, kMost));
    g.degenerate_faces = static_cast<std::size_t>(row.integer(6, 0, kMost));
    g.normals_flipped = row.integer(7, 0, 1) != 0;
    for (int i = 0; i < 3; ++i) {
      g.integral_n_dA_b[static_cast<std::size_t>(i)] = row.real(8 + i);
      g.integral_x_cross_n_dA_b[static_cast<std::size_t>(i)] = row.real(11 + i);
    }
    g.reference_pressure = row.real(14);
    g.pressure_array = row.text(15, 1024);
    g.shear_array = row.text(16, 1024);
    g.pressure_kind = row.one_of(17, {"static", "kinematic"});
    g.shear_convention = row.one_of(18, {"on-wall", "on-fluid"});
    g.axes = row.text(19, 256);
    out[found->second].surface = std::move(g);
  }
  apply_numerical_uncertainties(out);
  return out;
}

std::vector<StoredRun> RunDatabase::runs(const RunFilter& filter) {
  std::optional<std::int64_t> body;
  if (filter.body) {
    body = body_id(*filter.body, false);
    if (*body < 0) return {};
  }
  auto all = load_runs(body, std::nullopt);
  std::erase_if(all, [&](const StoredRun& run) {
    if (filter.with_force && !run.tau_b[*filter.with_force]) return true;
    for (const auto& [name, wanted] : filter.equal) {
      double value = 0.0;
      if (const auto i = velocity_index(name)) {
        value = run.key.nu_b[*i];
      } else if (const auto found = run.key.disturbances.find(name); found != run.key.disturbances.end()) {
        value = found->second;
      } else {
        return true;
      }
      if (std::abs(value - wanted) > kFilterTolerance * std::max(1.0, std::abs(wanted))) return true;
    }
    return false;
  });
  return all;
}

std::optional<StoredRun> RunDatabase::find_run(const RunKey& key) {
  const std::int64_t body = body_id(key.body, false);
  if (body < 0) return std::nullopt;
  const auto id = find_run_id(body, key);
  if (!id) return std::nullopt;
  auto found = load_runs(body, *id);
  if (found.empty()) return std::nullopt;
  return std::move(found.front());
}

std::vector<SourceRecord> RunDatabase::sources() {
  auto select = connection_.prepare(
      "SELECT id, path, sha256, size_bytes, importer, importer_version, imported_at FROM source_file ORDER BY id");
  std::vector<SourceRecord> out;
  while (select.step()) {
    const store::CheckedRow row(select, path_.string(), "source_file", select.get_int(0));
    SourceRecord record;
    record.id = select.get_int(0);
    record.provenance.path = row.text(1);
    record.provenance.sha256 = row.text(2, 64);
    record.provenance.size_bytes =
        static_cast<std::uint64_t>(row.integer(3, 0, std::numeric_limits<std::int64_t>::max()));
    record.provenance.importer = row.text(4, 256);
    record.provenance.importer_version = row.text(5, 256);
    record.imported_at = row.text(6, 64);
    out.push_back(std::move(record));
  }
  return out;
}

std::vector<std::string> run_flags(const StoredRun& run) {
  std::vector<std::string> out;
  for (const auto& force : run.tau_b)
    if (force && force->statistics)
      for (const auto& flag : force->statistics->flags)
        if (std::find(out.begin(), out.end(), flag) == out.end()) out.push_back(flag);
  return out;
}

void RunDatabase::remove_import_forces(std::int64_t import_id) {
  std::vector<std::int64_t> runs;
  auto touched = connection_.prepare("SELECT DISTINCT run_id FROM run_force WHERE import_id = ?");
  touched.bind(1, import_id);
  while (touched.step()) runs.push_back(touched.get_int(0));
  touched.reset();
  connection_
      .prepare(
          "DELETE FROM run_surface WHERE source_id = (SELECT source_id FROM import WHERE id = ?1) AND run_id IN "
          "(SELECT run_id FROM run_force WHERE import_id = ?1)")
      .bind(1, import_id)
      .run();
  connection_
      .prepare(
          "DELETE FROM run_force_statistics WHERE EXISTS (SELECT 1 FROM run_force f WHERE f.import_id = ? AND "
          "f.run_id = run_force_statistics.run_id AND f.component = run_force_statistics.component)")
      .bind(1, import_id)
      .run();
  connection_.prepare("DELETE FROM run_force_trace WHERE run_id IN (SELECT run_id FROM run_force WHERE import_id = ?)")
      .bind(1, import_id)
      .run();
  connection_.prepare("DELETE FROM run_force WHERE import_id = ?").bind(1, import_id).run();
  // A run left with no force component is no run.
  auto remaining = connection_.prepare("SELECT count(*) FROM run_force WHERE run_id = ?");
  auto drop_surface = connection_.prepare("DELETE FROM run_surface WHERE run_id = ?");
  auto drop_run = connection_.prepare("DELETE FROM run WHERE id = ?");
  for (const auto run : runs) {
    remaining.bind(1, run);
    remaining.step();
    const bool empty = remaining.get_int(0) == 0;
    remaining.reset();
    if (!empty) continue;
    drop_surface.bind(1, run).run();
    drop_run.bind(1, run).run();
  }
}

DeleteOutcome RunDatabase::delete_runs(const std::vector<std::int64_t>& ids) {
  store::Transaction transaction(connection_);
  const auto count = [&](const char* sql) {
    auto statement = connection_.prepare(sql);
    statement.step();
    return static_cast<std::size_t>(statement.get_int(0));
  };
  const std::size_t stale_fits = count("SELECT count(*) FROM fit WHERE stale = 1");
  const std::size_t stale_surfaces = count("SELECT count(*) FROM surface WHERE stale = 1");
  const std::size_t imports = count("SELECT count(*) FROM import");
  DeleteOutcome outcome;
  auto exists = connection_.prepare("SELECT count(*) FROM run WHERE id = ?");
  auto components = connection_.prepare("SELECT count(*) FROM run_force WHERE run_id = ?");
  std::set<std::int64_t> done;
  for (const auto id : ids) {
    if (!done.insert(id).second) continue;
    exists.bind(1, id);
    exists.step();
    const bool found = exists.get_int(0) != 0;
    exists.reset();
    if (!found)
      throw InputError(SourceLocation{path_.string()}, "no run " + std::to_string(id) + "; nothing was deleted");
    components.bind(1, id);
    components.step();
    outcome.components += static_cast<std::size_t>(components.get_int(0));
    components.reset();
    connection_.prepare("DELETE FROM run_force_statistics WHERE run_id = ?").bind(1, id).run();
    connection_.prepare("DELETE FROM run_force_trace WHERE run_id = ?").bind(1, id).run();
    connection_.prepare("DELETE FROM run_force WHERE run_id = ?").bind(1, id).run();
    connection_.prepare("DELETE FROM run_surface WHERE run_id = ?").bind(1, id).run();
    connection_.prepare("DELETE FROM run WHERE id = ?").bind(1, id).run();
    ++outcome.runs;
  }
  // Imports and files that no longer give any run.
  connection_.execute(
      "DELETE FROM import WHERE id NOT IN (SELECT import_id FROM run_force WHERE import_id IS NOT NULL)");
  connection_.execute(
      "DELETE FROM source_file WHERE id NOT IN (SELECT source_id FROM import) AND id NOT IN (SELECT source_id FROM "
      "run_force) AND id NOT IN (SELECT source_id FROM run_surface)");
  outcome.fits_made_stale = count("SELECT count(*) FROM fit WHERE stale = 1") - stale_fits;
  outcome.surfaces_made_stale = count("SELECT count(*) FROM surface WHERE stale = 1") - stale_surfaces;
  outcome.imports_removed = imports - count("SELECT count(*) FROM import");
  transaction.commit();
  use_wal();
  return outcome;
}

std::optional<ImportRecord> RunDatabase::import_record(std::int64_t id) {
  auto select = connection_.prepare(
      "SELECT i.id, i.source_id, s.sha256, i.reading, i.settings, i.settings_key, i.path, i.resolved_path, i.importer, "
      "i.importer_version, i.hydrocoef_version, i.imported_at, s.size_bytes FROM import i JOIN source_file s ON "
      "s.id = i.source_id WHERE i.id = ?");
  select.bind(1, id);
  if (!select.step()) return std::nullopt;
  const store::CheckedRow row(select, path_.string(), "import", id);
  ImportRecord record;
  record.id = id;
  record.source_id = select.get_int(1);
  record.sha256 = row.text(2, 64);
  record.reading = row.text(3, 256);
  record.settings = row.text(4, 1 << 20);
  record.settings_key = row.text(5, 1 << 20);
  record.path = row.text(6);
  record.resolved_path = row.text(7);
  record.importer = row.text(8, 256);
  record.importer_version = row.text(9, 256);
  record.hydrocoef_version = row.text(10, 256);
  record.imported_at = row.text(11, 64);
  record.size_bytes = static_cast<std::uint64_t>(row.integer(12, 0, std::numeric_limits<std::int64_t>::max()));
  return record;
}

}  // namespace hydrocoef
