// Which stored runs a correction removes: by id, by selection and by the file
// their forces came from (`hydrocoef runs delete`, the public API).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/store/database.hpp"

namespace hydrocoef {

struct RunDeletion {
  std::vector<std::int64_t> ids;           ///< runs named by id
  std::optional<std::string> body;         ///< with `where`/`source`: only this body's runs
  std::vector<std::string> where;          ///< selection clauses (src/core/run_selection.hpp)
  std::vector<std::int64_t> exclude_runs;  ///< left out of the selection
  /// Runs with a force component from this file: the path as stored, or the
  /// same file (by canonical path) when both exist.
  std::optional<std::string> source;
};

/// The ids to delete: `ids` and, when `where` or `source` is given, the runs
/// they select. InputError when nothing is selected at all, or a selection
/// matches no run.
std::vector<std::int64_t> runs_to_delete(RunDatabase& database, const RunDeletion& deletion);

/// runs_to_delete, then RunDatabase::delete_runs in one transaction.
DeleteOutcome delete_selected_runs(RunDatabase& database, const RunDeletion& deletion);

}  // namespace hydrocoef
