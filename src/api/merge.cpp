// Whole databases (include/hydrocoef/records.hpp): `hydrocoef merge` (shards
// into one, src/store/merge.cpp), `copy` (every row into an empty database,
// src/store/copy.cpp) and `migrate` (the schema versions), with what each prints.
#include "hydrocoef/records.hpp"
#include "src/api/internal.hpp"
#include "src/core/escape.hpp"

#include <nlohmann/json.hpp>
#include "src/core/text.hpp"

#include <sstream>

namespace hydrocoef {
inline namespace api {

void MergeOptions::validate() const {
  if (shards.empty()) throw InputError("merge: expected at least one shard database");
}

MergeSummary merge_databases(Database& into, const MergeOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(into);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.writable_store("a merge");
  MergeSummary out;
  for (const MergeOutcome& o : store.merge(options.shards, options.progress))
    out.shards.push_back({o.shard, o.imports_added, o.imports_already, o.runs_created, o.runs_extended, o.components,
                          o.fits_added, o.fits_already, o.surfaces_added, o.surfaces_already, o.mesh_studies_added,
                          o.mesh_studies_already, o.pmm_added, o.pmm_already, o.body_references_added,
                          o.body_references_already, o.derivative_models_added, o.derivative_models_already});
  out.into = store.path().string();
  return out;
}

std::string MergeSummary::json() const {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& o : shards)
    out.push_back({{"shard", o.shard},
                   {"imports_added", o.imports_added},
                   {"imports_already", o.imports_already},
                   {"runs_created", o.runs_created},
                   {"runs_extended", o.runs_extended},
                   {"components", o.components},
                   {"fits_added", o.fits_added},
                   {"fits_already", o.fits_already},
                   {"surfaces_added", o.surfaces_added},
                   {"surfaces_already", o.surfaces_already},
                   {"mesh_studies_added", o.mesh_studies_added},
                   {"mesh_studies_already", o.mesh_studies_already},
                   {"pmm_added", o.pmm_added},
                   {"pmm_already", o.pmm_already},
                   {"body_references_added", o.body_references_added},
                   {"body_references_already", o.body_references_already},
                   {"derivative_models_added", o.derivative_models_added},
                   {"derivative_models_already", o.derivative_models_already}});
  return escape::json_text({{"into", into}, {"shards", out}}, 2) + '\n';
}

std::string MergeSummary::text() const {
  std::ostringstream out;
  std::size_t imports = 0, runs = 0, components = 0;
  for (const auto& o : shards) {
    out << printable_text(o.shard, 120) << ": " << o.imports_added << " imports added";
    if (o.imports_already) out << " (" << o.imports_already << " here already)";
    out << ", " << o.runs_created << " runs created, " << o.runs_extended << " extended, " << o.components
        << " force components";
    if (o.fits_added + o.surfaces_added + o.mesh_studies_added + o.pmm_added + o.body_references_added +
        o.derivative_models_added)
      out << "; " << o.fits_added << " fits, " << o.surfaces_added << " surfaces, " << o.mesh_studies_added
          << " mesh-study rows, " << o.pmm_added << " forced-oscillation runs, " << o.body_references_added
          << " bodies' reference data, " << o.derivative_models_added << " derivative models";
    out << '\n';
    imports += o.imports_added;
    runs += o.runs_created;
    components += o.components;
  }
  out << "merged " << shards.size() << " shard(s) into " << printable_text(into, 120)
      << " in one transaction: " << imports << " imports, " << runs << " new runs, " << components
      << " force components\n";
  return out.str();
}

CopySummary copy_database(const Database& from, Database& to) {
  if (&from == &to) throw InputError(SourceLocation{from.path()}, "copy: the source and the target are one database");
  auto& source = Database::Access::impl(from);
  auto& target = Database::Access::impl(to);
  const std::scoped_lock lock(source.mutex, target.mutex);
  auto& writable = target.writable_store("a copy");
  auto& readable = source.open_store();
  CopySummary out;
  out.rows = writable.copy_from(readable);
  out.from = readable.path().string();
  out.to = writable.path().string();
  return out;
}

std::string CopySummary::json() const {
  nlohmann::json tables = nlohmann::json::object();
  for (const auto& [table, n] : rows) tables[table] = n;
  return escape::json_text({{"from", from}, {"to", to}, {"rows", tables}}, 2) + '\n';
}

std::string CopySummary::text() const {
  std::size_t total = 0;
  for (const auto& [table, n] : rows) total += n;
  std::ostringstream out;
  out << "copied " << total << " rows from " << printable_text(from, 120) << " to " << printable_text(to, 120) << ":";
  for (const auto& [table, n] : rows)
    if (n) out << ' ' << table << ' ' << n;
  out << '\n';
  return out.str();
}

MigrationSummary migration(const Database& database) {
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.open_store();
  return {store.path().string(), store.opened_at_version(), store.schema_version()};
}

std::string MigrationSummary::json() const {
  return escape::json_text({{"database", database}, {"from", from}, {"to", to}}, 2) + '\n';
}

std::string MigrationSummary::text() const {
  return printable_text(database, 120) + ": " +
         (from == to ? "at schema version " + std::to_string(to) + " already; nothing changed\n"
                     : "schema version " + std::to_string(from) + " upgraded to " + std::to_string(to) + '\n');
}

}  // namespace api
}  // namespace hydrocoef
