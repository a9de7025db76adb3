// How `hydrocoef gci` reports a study: a readable table (one row per key and
// force component, with the notes) or JSON.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "src/pipeline/grid_convergence_runs.hpp"

namespace hydrocoef::cli {

/// The study as JSON; `stored` says whether it was stored.
nlohmann::json study_json(const GridConvergenceStudy& study, bool stored);
/// The study as a table.
void print_study(const GridConvergenceStudy& study, const GridConvergenceRequest& request, bool stored);
/// Either, with what storing it made stale (nullopt: not stored).
void print_gci(const GridConvergenceStudy& study, const GridConvergenceRequest& request,
               const std::optional<StoredStudy>& stored, bool json);

}  // namespace hydrocoef::cli
