// RunDatabase::save_surface, RunDatabase::surfaces and RunDatabase::surface: built
// response surfaces (grid, RBF, GP), tables surface and surface_run. Every
// value read back is checked (src/store/checked_row.hpp): a received database
// is untrusted input.
#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/text.hpp"
#include "src/store/backend.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/database.hpp"

namespace hydrocoef {

std::int64_t RunDatabase::save_surface(const SurfaceRecord& surface) {
  check_name(NameKind::Surface, surface.name, {}, "the surface");
  store::Transaction transaction(connection_);
  const std::int64_t body = existing_body_id(surface.body);
  connection_.prepare("DELETE FROM surface WHERE name = ?").bind(1, surface.name).run();
  auto insert = connection_.prepare(
      "INSERT INTO surface(name, body_id, kind, method, definition, data, quality, created_at, stale) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?, 0) RETURNING id");
  insert.bind(1, surface.name)
      .bind(2, body)
      .bind(3, surface.kind)
      .bind(4, surface.method)
      .bind(5, surface.definition)
      .bind_doubles(6, surface.data)
      .bind(7, surface.quality)
      .bind(8, utc_timestamp_now());
  const std::int64_t id = store::returned_id(insert);
  link_runs("surface_run", "surface_id", id, surface.run_ids);
  transaction.commit();
  use_wal();
  return id;
}

std::vector<SurfaceRecord> RunDatabase::load_surfaces(const std::optional<std::string>& body,
                                                      const std::optional<std::string>& name) {
  // One state of the database for all the statements below.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT surface.id, surface.name, body.name, kind, method, definition, data, quality, created_at, stale "
      "FROM surface JOIN body ON body.id = surface.body_id WHERE TRUE";
  if (body) sql += " AND body.name = ?1";
  if (name) sql += " AND surface.name = ?2";
  sql += " ORDER BY surface.name";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  if (name) select.bind(2, *name);
  std::vector<SurfaceRecord> out;
  while (select.step()) {
    const store::CheckedRow row(select, path_.string(), "surface", select.get_int(0));
    SurfaceRecord record;
    record.id = select.get_int(0);
    record.name = row.name(1, NameKind::Surface);
    record.body = row.name(2, NameKind::Body);
    record.kind = row.one_of(3, {"grid", "rbf", "gp"});
    record.method = row.text(4, 64);
    record.definition = row.text(5, kMaxSurfaceDefinitionBytes);
    record.data = row.doubles(6, kMaxSurfaceValues);
    record.quality = row.text(7, kMaxSurfaceDefinitionBytes);
    record.created_at = row.text(8, 64);
    record.stale = row.integer(9, 0, 1) != 0;
    record.database = path_.string();
    record.run_ids = linked_runs("surface_run", "surface_id", record.id);
    out.push_back(std::move(record));
  }
  return out;
}

std::vector<SurfaceRecord> RunDatabase::surfaces(const std::optional<std::string>& body) {
  return load_surfaces(body, std::nullopt);
}

SurfaceRecord RunDatabase::surface(const std::string& name) {
  auto found = load_surfaces(std::nullopt, name);
  if (!found.empty()) return std::move(found.front());
  // Only the names, for the message: no value blobs are read.
  auto select = connection_.prepare("SELECT name FROM surface ORDER BY name");
  std::string names;
  while (select.step()) names += (names.empty() ? "'" : ", '") + printable_text(select.get_text(0), 60) + "'";
  throw InputError("no surface named '" + name + "' in " + path_.string() +
                   "; surfaces there: " + (names.empty() ? "none" : names));
}

}  // namespace hydrocoef
