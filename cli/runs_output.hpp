// How the CLI shows runs (text table, CSV, JSON) and one run with its provenance.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "src/store/database.hpp"

namespace hydrocoef::cli {

/// The runs as CSV (RFC 4180; names through escape::csv_text): id, body,
/// u..r, one column per disturbance any run has, X..N (forces on the body,
/// SI), the force sources. Empty cells where a run has no such value.
void print_runs_csv(const std::vector<StoredRun>& runs);
/// One run as JSON: key, fluid, reference point, forces with statistics, flags.
nlohmann::json run_json(const StoredRun& run);
/// The runs table: the velocity and force columns some run uses, history flags, disturbances.
void print_runs_table(const std::vector<StoredRun>& runs, const std::optional<std::string>& body,
                      const std::string& database);
/// runs show: one run with its forces, statistics and the imports they came from.
void print_run(const StoredRun& run, const std::map<std::int64_t, ImportRecord>& imports, bool json);

}  // namespace hydrocoef::cli
