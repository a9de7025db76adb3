// One run with its provenance (`hydrocoef runs show`) and the deletion of
// runs (`hydrocoef runs delete`): include/hydrocoef/records.hpp.
#include "src/api/internal.hpp"
#include "src/api/records_report.hpp"
#include "src/core/escape.hpp"

#include <nlohmann/json.hpp>
#include "src/pipeline/run_curation.hpp"

#include <algorithm>
#include <sstream>

namespace hydrocoef {
inline namespace api {

RunDetails show_run(const Database& database, std::int64_t id) {
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.open_store();
  const auto all = store.runs();
  const auto found = std::find_if(all.begin(), all.end(), [&](const StoredRun& run) { return run.id == id; });
  if (found == all.end())
    throw InputError(SourceLocation{impl.path}, "no run " + std::to_string(id) + "; 'hydrocoef runs' lists them");
  std::map<std::int64_t, ImportRecord> imports;
  for (const auto& force : found->tau_b)
    if (force && force->import_id && !imports.count(force->import_id))
      if (auto record = store.import_record(force->import_id)) imports.emplace(force->import_id, std::move(*record));
  return records::run_details(*found, imports);
}

void DeleteRunsOptions::validate() const { (void)parse_selection(where, exclude_runs); }

DeleteSummary delete_runs(Database& database, const DeleteRunsOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.writable_store("runs delete");
  const DeleteOutcome outcome = delete_selected_runs(
      store, RunDeletion{options.ids, options.body.empty() ? std::nullopt : std::optional<std::string>(options.body),
                         options.where, options.exclude_runs,
                         options.source.empty() ? std::nullopt : std::optional<std::string>(options.source)});
  return {impl.path,
          outcome.runs,
          outcome.components,
          outcome.fits_made_stale,
          outcome.surfaces_made_stale,
          outcome.imports_removed};
}

std::string DeleteSummary::json() const {
  return escape::json_text({{"deleted_runs", runs},
                            {"deleted_components", components},
                            {"fits_made_stale", fits_made_stale},
                            {"surfaces_made_stale", surfaces_made_stale},
                            {"imports_removed", imports_removed}},
                           2) +
         '\n';
}

std::string DeleteSummary::text() const {
  std::ostringstream out;
  out << "deleted " << runs << (runs == 1 ? " run" : " runs") << " (" << components << " force components) from "
      << escape::one_line(database) << "; " << fits_made_stale << " fits and " << surfaces_made_stale
      << " surfaces became stale (hydrocoef fits / surface list show them; "
      << "surface rebuild --stale builds the surfaces again)\n";
  return out.str();
}

}  // namespace api
}  // namespace hydrocoef
