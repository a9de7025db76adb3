// RunDatabase::save_pmm and RunDatabase::pmm_records: forced-oscillation analyses
// in tables pmm_run and pmm_coefficient (schema/0012_pmm.sql). Every value
// read back is checked (src/store/checked_row.hpp): a received database is
// untrusted input.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"
#include "src/store/backend.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/database.hpp"
#include "src/store/pmm_record.hpp"

namespace hydrocoef {

std::string pmm_medium_name(PmmMedium medium) {
  return medium == PmmMedium::StillWater ? "still water" : "oscillating stream";
}

namespace {

double canonical_zero(double value) { return value == 0.0 ? 0.0 : value; }  // folds -0 into 0

std::string json_list(const std::vector<double>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out += ',';
    append_shortest_number(out, values[i]);
  }
  return out + "]";
}

}  // namespace

std::vector<PmmSaved> RunDatabase::save_pmm(const std::vector<PmmRecord>& records) {
  store::Transaction transaction(connection_);
  auto find = connection_.prepare(
      "SELECT id FROM pmm_run WHERE body_id = ? AND source_sha256 = ? AND dof = ? AND amplitude = ? AND omega = ? "
      "AND phase = ? AND medium = ?");
  auto drop = connection_.prepare("DELETE FROM pmm_run WHERE id = ?");
  auto drop_coefficients = connection_.prepare("DELETE FROM pmm_coefficient WHERE pmm_run_id = ?");
  auto insert = connection_.prepare(
      "INSERT INTO pmm_run(body_id, u, v, w, p, q, r, dof, amplitude, omega, phase, medium, motion_source, "
      "window_start, window_end, periods, transient_periods, samples, harmonics, size, keulegan_carpenter, "
      "kinematic_viscosity, stokes_number, rho, displaced_volume, source_path, source_sha256, importer, history, "
      "created_at, restoring) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
      "?, "
      "?, ?, ?) "
      "RETURNING id");
  auto insert_coefficient = connection_.prepare(
      "INSERT INTO pmm_coefficient(pmm_run_id, component, mean, added_mass, added_mass_se, damping, damping_se, "
      "explained, harmonics) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
  std::vector<PmmSaved> out;
  for (const auto& record : records) {
    const std::int64_t body = body_id(record.body, true);
    const std::string medium = pmm_medium_name(record.medium);
    PmmSaved saved;
    find.bind(1, body).bind(2, record.source_sha256).bind(3, static_cast<std::int64_t>(record.dof));
    find.bind(4, record.amplitude).bind(5, record.omega).bind(6, canonical_zero(record.phase)).bind(7, medium);
    if (find.step()) {
      const std::int64_t old = find.get_int(0);
      drop_coefficients.bind(1, old).run();
      drop_coefficients.reset();
      drop.bind(1, old).run();
      drop.reset();
      saved.replaced = true;
    }
    find.reset();
    int c = 1;
    insert.bind(c++, body);
    for (const double x : record.nu_b) insert.bind(c++, canonical_zero(x));
    insert.bind(c++, static_cast<std::int64_t>(record.dof));
    insert.bind(c++, record.amplitude);
    insert.bind(c++, record.omega);
    insert.bind(c++, canonical_zero(record.phase));
    insert.bind(c++, medium);
    insert.bind(c++, record.motion_source);
    insert.bind(c++, record.window_start);
    insert.bind(c++, record.window_end);
    insert.bind(c++, static_cast<std::int64_t>(record.periods));
    insert.bind(c++, static_cast<std::int64_t>(record.transient_periods));
    insert.bind(c++, static_cast<std::int64_t>(record.samples));
    insert.bind(c++, static_cast<std::int64_t>(record.harmonics));
    insert.bind(c++, record.size);
    insert.bind(c++, record.keulegan_carpenter);
    insert.bind(c++, record.kinematic_viscosity);
    insert.bind(c++, record.stokes_number);
    insert.bind(c++, record.rho);
    insert.bind(c++, record.displaced_volume);
    insert.bind(c++, record.source_path);
    insert.bind(c++, record.source_sha256);
    insert.bind(c++, record.importer);
    insert.bind_doubles(c++, record.history);
    insert.bind(c++, record.created_at.empty() ? utc_timestamp_now() : record.created_at);
    insert.bind(c++, record.restoring);
    saved.id = store::returned_id(insert);
    for (const auto& coefficient : record.coefficients) {
      insert_coefficient.bind(1, saved.id).bind(2, kForceNames[coefficient.component]);
      insert_coefficient.bind(3, coefficient.mean).bind(4, coefficient.added_mass);
      insert_coefficient.bind(5, coefficient.added_mass_se).bind(6, coefficient.damping);
      insert_coefficient.bind(7, coefficient.damping_se).bind(8, coefficient.explained);
      insert_coefficient.bind(9, json_list(coefficient.harmonics));
      insert_coefficient.run();
      insert_coefficient.reset();
    }
    out.push_back(saved);
  }
  transaction.commit();
  return out;
}

std::vector<PmmRecord> RunDatabase::pmm_records(const std::optional<std::string>& body, bool with_history) {
  // One state of the database for all the statements below.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT pmm_run.id, body.name, u, v, w, p, q, r, dof, amplitude, omega, phase, medium, motion_source, "
      "window_start, window_end, periods, transient_periods, samples, harmonics, size, keulegan_carpenter, "
      "kinematic_viscosity, stokes_number, rho, displaced_volume, source_path, source_sha256, importer, ";
  sql += with_history ? "history" : "NULL";
  sql += ", created_at, restoring FROM pmm_run JOIN body ON body.id = pmm_run.body_id";
  if (body) sql += " WHERE body.name = ?1";
  sql += " ORDER BY body.name, dof, omega, amplitude, pmm_run.id";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  std::vector<PmmRecord> out;
  const std::string db = path_.string();
  const auto max_int = std::numeric_limits<std::int64_t>::max();
  while (select.step()) {
    const std::int64_t id = select.get_int(0);
    const store::CheckedRow row(select, db, "pmm_run", id);
    PmmRecord record;
    record.id = id;
    record.body = row.name(1, NameKind::Body);
    for (int i = 0; i < 6; ++i) record.nu_b[static_cast<std::size_t>(i)] = row.real(2 + i);
    record.dof = static_cast<std::size_t>(row.integer(8, 0, 5));
    record.amplitude = row.positive(9);
    record.omega = row.positive(10);
    record.phase = row.real(11);
    record.medium = row.one_of(12, {"still water", "oscillating stream"}) == "still water"
                        ? PmmMedium::StillWater
                        : PmmMedium::OscillatingStream;
    record.motion_source = row.text(13);
    record.window_start = row.real(14);
    record.window_end = row.real(15);
    if (!(record.window_end > record.window_start)) row.fail(15, "a window end after its start");
    record.periods = static_cast<std::size_t>(row.integer(16, 3, max_int));
    record.transient_periods = static_cast<std::size_t>(row.integer(17, 0, max_int));
    record.samples = static_cast<std::size_t>(row.integer(18, 1, max_int));
    record.harmonics = static_cast<int>(row.integer(19, 1, 10));
    record.size = row.optional_positive(20);
    record.keulegan_carpenter = row.optional_non_negative(21);
    record.kinematic_viscosity = row.optional_positive(22);
    record.stokes_number = row.optional_non_negative(23);
    record.rho = row.optional_positive(24);
    record.displaced_volume = row.optional_positive(25);
    record.source_path = row.text(26);
    record.source_sha256 = row.text(27, 64);
    record.importer = row.text(28, 256);
    if (with_history) {
      record.history = row.doubles(29, kMaxPmmHistoryRows * kPmmHistoryColumns);
      if (record.history.size() % kPmmHistoryColumns != 0)
        row.fail(29, "float64 samples in rows of 7 (t, X, Y, Z, K, M, N)");
    }
    record.created_at = row.text(30, 64);
    record.restoring = row.optional_real(31);
    out.push_back(std::move(record));
  }
  auto coefficients = connection_.prepare(
      "SELECT component, mean, added_mass, added_mass_se, damping, damping_se, explained, harmonics FROM "
      "pmm_coefficient WHERE pmm_run_id = ? ORDER BY CASE component WHEN 'X' THEN 0 WHEN 'Y' THEN 1 WHEN 'Z' THEN 2 "
      "WHEN 'K' THEN 3 WHEN 'M' THEN 4 ELSE 5 END");
  for (auto& record : out) {
    coefficients.bind(1, record.id);
    while (coefficients.step()) {
      const store::CheckedRow row(coefficients, db, "pmm_coefficient", record.id);
      PmmCoefficient coefficient;
      coefficient.component = *force_index(row.one_of(0, {"X", "Y", "Z", "K", "M", "N"}));
      coefficient.mean = row.real(1);
      coefficient.added_mass = row.real(2);
      coefficient.added_mass_se = row.non_negative(3);
      coefficient.damping = row.real(4);
      coefficient.damping_se = row.non_negative(5);
      coefficient.explained = row.real(6);
      coefficient.harmonics = row.real_list(7, 20);
      if (coefficient.harmonics.size() != 2 * static_cast<std::size_t>(record.harmonics))
        row.fail(7, "s1, c1, ... for each of the run's " + std::to_string(record.harmonics) + " harmonics");
      record.coefficients.push_back(std::move(coefficient));
    }
    coefficients.reset();
  }
  return out;
}

std::vector<PmmDeleted> RunDatabase::delete_pmm_runs(const std::vector<std::int64_t>& ids) {
  if (read_only_) throw InputError(SourceLocation{path_.string()}, "database opened read-only; cannot delete from it");
  store::Transaction transaction(connection_);
  auto find = connection_.prepare(
      "SELECT pmm_run.id, body.name, dof, source_path FROM pmm_run JOIN body ON body.id = pmm_run.body_id "
      "WHERE pmm_run.id = ?");
  auto drop_coefficients = connection_.prepare("DELETE FROM pmm_coefficient WHERE pmm_run_id = ?");
  auto drop = connection_.prepare("DELETE FROM pmm_run WHERE id = ?");
  std::vector<PmmDeleted> out;
  for (const std::int64_t id : ids) {
    if (std::any_of(out.begin(), out.end(), [&](const PmmDeleted& d) { return d.id == id; })) continue;
    find.bind(1, id);
    if (!find.step())
      throw InputError(SourceLocation{path_.string()}, "no forced-oscillation run " + std::to_string(id) +
                                                           "; expected an id 'hydrocoef pmm-runs' lists (nothing was "
                                                           "deleted)");
    PmmDeleted deleted;
    deleted.id = id;
    deleted.body = find.column_type(1) == store::ColumnType::Text ? find.get_text(1) : std::string();
    deleted.dof = find.column_type(2) == store::ColumnType::Integer ? find.get_int(2) : -1;
    deleted.source_path = find.column_type(3) == store::ColumnType::Text ? find.get_text(3) : std::string();
    find.reset();
    drop_coefficients.bind(1, id).run();
    drop_coefficients.reset();
    drop.bind(1, id).run();
    drop.reset();
    out.push_back(std::move(deleted));
  }
  transaction.commit();
  return out;
}

}  // namespace hydrocoef
