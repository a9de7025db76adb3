#include "src/pipeline/run_curation.hpp"

#include <filesystem>

#include "src/core/error.hpp"
#include "src/core/run_selection.hpp"
#include "src/pipeline/fit_runs.hpp"

namespace hydrocoef {
namespace {

/// Whether a run has a force component from `source`: the path as stored, or
/// the same file by canonical path (`canonical` "" when `source` does not exist).
bool from_source(const StoredRun& run, const std::string& source, const std::string& canonical) {
  for (const auto& force : run.tau_b) {
    if (!force) continue;
    if (force->source_path == source) return true;
    std::error_code error;
    if (!canonical.empty() && std::filesystem::exists(force->source_path, error) &&
        std::filesystem::canonical(force->source_path, error).string() == canonical)
      return true;
  }
  return false;
}

}  // namespace

std::vector<std::int64_t> runs_to_delete(RunDatabase& database, const RunDeletion& deletion) {
  if (deletion.ids.empty() && deletion.where.empty() && !deletion.source)
    throw InputError("runs delete: nothing selected; expected run ids, --where CLAUSE or --source FILE");
  std::vector<std::int64_t> ids = deletion.ids;
  if (deletion.where.empty() && !deletion.source) return ids;
  RunFilter filter;
  filter.body = deletion.body;
  auto runs = selected_runs(database, filter, parse_selection(deletion.where, deletion.exclude_runs));
  if (deletion.source) {
    std::error_code error;
    const std::string canonical = std::filesystem::exists(*deletion.source, error)
                                      ? std::filesystem::canonical(*deletion.source, error).string()
                                      : "";
    std::erase_if(runs, [&](const StoredRun& run) { return !from_source(run, *deletion.source, canonical); });
  }
  for (const auto& run : runs) ids.push_back(run.id);
  if (ids.empty())
    throw InputError(SourceLocation{database.path().string()}, "runs delete: no run matches; nothing was deleted");
  return ids;
}

DeleteOutcome delete_selected_runs(RunDatabase& database, const RunDeletion& deletion) {
  return database.delete_runs(runs_to_delete(database, deletion));
}

}  // namespace hydrocoef
