// RunDatabase::save_numerical_uncertainties and RunDatabase::numerical_uncertainties:
// the numerical uncertainty of a force from a mesh study (hydrocoef gci),
// table numerical_uncertainty (schema/0011), and how it reaches the runs it
// applies to (the finest mesh of its physical key). Every value read back is
// checked (src/store/checked_row.hpp): a received database is untrusted input.
#include <algorithm>
#include <limits>
#include <set>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"
#include "src/store/backend.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/database.hpp"
#include "src/store/run_rows.hpp"

namespace hydrocoef {

using store::canonical;
using store::same_value;

std::map<std::string, double> physical_disturbances(const std::map<std::string, double>& disturbances,
                                                    const std::string& mesh_parameter) {
  std::map<std::string, double> out = disturbances;
  out.erase(mesh_parameter);
  out.erase(std::string(kCellCountParameter));
  out.erase(std::string(kCellSizeParameter));
  return out;
}

void RunDatabase::apply_numerical_uncertainties(std::vector<StoredRun>& runs) {
  if (runs.empty()) return;
  std::optional<std::string> body;
  if (std::all_of(runs.begin(), runs.end(), [&](const StoredRun& r) { return r.key.body == runs.front().key.body; }))
    body = runs.front().key.body;
  const auto records = numerical_uncertainties(body);
  if (records.empty()) return;
  for (StoredRun& run : runs) {
    for (const auto& record : records) {
      if (!record.numerical_uncertainty || record.key.body != run.key.body) continue;
      auto& force = run.tau_b[record.component];
      if (!force) continue;
      const auto level = run.key.disturbances.find(record.mesh_parameter);
      if (level == run.key.disturbances.end() || !same_value(level->second, record.fine_level)) continue;
      bool same = true;
      for (std::size_t i = 0; i < 6; ++i) same = same && canonical(run.key.nu_b[i]) == record.key.nu_b[i];
      if (!same) continue;
      if (disturbance_signature(physical_disturbances(run.key.disturbances, record.mesh_parameter)) !=
          disturbance_signature(record.key.disturbances))
        continue;
      force->numerical_uncertainty = record.numerical_uncertainty;
    }
  }
}

void RunDatabase::save_numerical_uncertainties(const std::vector<NumericalUncertaintyRecord>& records) {
  store::Transaction transaction(connection_);
  // The numerical uncertainty of every force of the bodies concerned, before
  // and after: fits of a force whose uncertainty changed, and the body's
  // surfaces, become stale (a weighted fit or a GP surface would differ).
  std::set<std::string> bodies;
  for (const auto& record : records) bodies.insert(record.key.body);
  const auto snapshot = [&] {
    std::map<std::pair<std::int64_t, std::size_t>, std::optional<double>> out;
    for (const auto& name : bodies) {
      const std::int64_t id = body_id(name, false);
      if (id < 0) continue;
      for (const auto& run : load_runs(id, std::nullopt))
        for (std::size_t c = 0; c < 6; ++c)
          if (run.tau_b[c]) out[{run.id, c}] = run.tau_b[c]->numerical_uncertainty;
    }
    return out;
  };
  const auto before = snapshot();
  auto drop = connection_.prepare(
      "DELETE FROM numerical_uncertainty WHERE body_id = ? AND u = ? AND v = ? AND w = ? AND p = ? AND q = ? AND "
      "r = ? AND disturbance_key = ?");
  auto insert = connection_.prepare(
      "INSERT INTO numerical_uncertainty(body_id, u, v, w, p, q, r, disturbance_key, component, mesh_parameter, "
      "fine_level, levels, h1, h2, h3, phi1, phi2, phi3, convergence, apparent_order, extrapolated, relative_error, "
      "extrapolated_relative_error, gci_fine, numerical_uncertainty, note, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, "
      "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  std::set<std::pair<std::int64_t, std::string>> cleared;
  for (const auto& record : records) {
    const std::int64_t body = existing_body_id(record.key.body);
    const std::string signature = disturbance_signature(record.key.disturbances);
    std::string identity = signature;
    for (const double x : record.key.nu_b) identity += ' ' + shortest_number(canonical(x));
    if (cleared.insert({body, identity}).second) {
      drop.bind(1, body);
      for (int i = 0; i < 6; ++i) drop.bind(2 + i, canonical(record.key.nu_b[static_cast<std::size_t>(i)]));
      drop.bind(8, signature).run();
      drop.reset();
    }
    int c = 1;
    insert.bind(c++, body);
    for (const double x : record.key.nu_b) insert.bind(c++, canonical(x));
    insert.bind(c++, signature);
    insert.bind(c++, std::string(kForceNames[record.component]));
    insert.bind(c++, record.mesh_parameter);
    insert.bind(c++, record.fine_level);
    insert.bind(c++, static_cast<std::int64_t>(record.levels));
    for (const double h : record.h) insert.bind(c++, h);
    for (const double phi : record.phi) insert.bind(c++, phi);
    insert.bind(c++, record.convergence);
    insert.bind(c++, record.apparent_order);
    insert.bind(c++, record.extrapolated);
    insert.bind(c++, record.relative_error);
    insert.bind(c++, record.extrapolated_relative_error);
    insert.bind(c++, record.gci_fine);
    insert.bind(c++, record.numerical_uncertainty);
    insert.bind(c++, record.note);
    insert.bind(c++, record.created_at.empty() ? utc_timestamp_now() : record.created_at);
    insert.run();
    insert.reset();
  }
  auto stale_fits = connection_.prepare(
      "UPDATE fit SET stale = 1 WHERE dof = ? AND id IN (SELECT fit_id FROM fit_run WHERE run_id = ?)");
  auto stale_surfaces =
      connection_.prepare("UPDATE surface SET stale = 1 WHERE body_id = (SELECT body_id FROM run WHERE id = ?)");
  for (const auto& [force, uncertainty] : snapshot()) {
    const auto old = before.find(force);
    if (old != before.end() && old->second == uncertainty) continue;
    stale_fits.bind(1, std::string(kForceNames[force.second])).bind(2, force.first).run();
    stale_fits.reset();
    stale_surfaces.bind(1, force.first).run();
    stale_surfaces.reset();
  }
  transaction.commit();
  use_wal();
}

std::vector<NumericalUncertaintyRecord> RunDatabase::numerical_uncertainties(const std::optional<std::string>& body) {
  // One state of the database for all the statements below.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT n.body_id, body.name, u, v, w, p, q, r, disturbance_key, component, mesh_parameter, fine_level, "
      "levels, h1, h2, h3, phi1, phi2, phi3, convergence, apparent_order, extrapolated, relative_error, "
      "extrapolated_relative_error, gci_fine, numerical_uncertainty, note, created_at FROM numerical_uncertainty n "
      "JOIN body ON body.id = n.body_id";
  if (body) sql += " WHERE body.name = ?1";
  sql += " ORDER BY body.name, u, v, w, p, q, r, disturbance_key, component";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  std::vector<NumericalUncertaintyRecord> out;
  const std::string db = path_.string();
  std::int64_t row_number = 0;
  while (select.step()) {
    const store::CheckedRow row(select, db, "numerical_uncertainty", ++row_number);
    NumericalUncertaintyRecord record;
    record.key.body = row.name(1, NameKind::Body);
    for (int i = 0; i < 6; ++i) record.key.nu_b[static_cast<std::size_t>(i)] = row.real(2 + i);
    const std::string signature = row.text(8);
    for (const std::string_view entry : split(signature, ';')) {
      if (entry.empty()) continue;
      const auto equals = entry.find('=');
      const auto value =
          equals == std::string_view::npos ? std::nullopt : parse_finite_number(entry.substr(equals + 1));
      if (!value) row.fail(8, "the canonical text of disturbances, name=value;...");
      record.key.disturbances[std::string(check_name(NameKind::Parameter, entry.substr(0, equals), SourceLocation{db},
                                                     "a disturbance in table numerical_uncertainty"))] = *value;
    }
    record.component = *force_index(row.one_of(9, {"X", "Y", "Z", "K", "M", "N"}));
    record.mesh_parameter = row.name(10, NameKind::Parameter);
    record.fine_level = row.real(11);
    record.levels = static_cast<std::size_t>(row.integer(12, 3, std::numeric_limits<std::int64_t>::max()));
    for (int i = 0; i < 3; ++i) {
      record.h[static_cast<std::size_t>(i)] = row.positive(13 + i);
      record.phi[static_cast<std::size_t>(i)] = row.real(16 + i);
    }
    record.convergence = row.one_of(19, {"monotonic", "oscillatory", "converged", "not found"});
    record.apparent_order = row.optional_real(20);
    record.extrapolated = row.optional_real(21);
    record.relative_error = row.optional_real(22);
    record.extrapolated_relative_error = row.optional_real(23);
    record.gci_fine = row.optional_non_negative(24);
    record.numerical_uncertainty = row.optional_non_negative(25);
    record.note = row.text(26);
    record.created_at = row.text(27, 64);
    out.push_back(std::move(record));
  }
  return out;
}

}  // namespace hydrocoef
