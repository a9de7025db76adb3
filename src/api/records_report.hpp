// How the results of the records' operations (include/hydrocoef/records.hpp,
// database.hpp) are made from the library's own types, with the text and JSON
// the CLI prints: one file a command (import_report.cpp, runs_report.cpp,
// fit_report.cpp).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "src/api/internal.hpp"

#include "hydrocoef/records.hpp"

namespace hydrocoef {
inline namespace api {

/// The runs as read, for RunTable::text(), json() and csv().
struct RunTable::Rendering {
  std::vector<StoredRun> runs;
  std::optional<std::string> body;  ///< the body asked for, if any
  std::string database;
};

struct RunTable::Access {
  static void set(RunTable& table, std::shared_ptr<const Rendering> rendering) {
    table.rendering_ = std::move(rendering);
  }
  static const Rendering& rendering(const RunTable& table);
};

struct ImportSummary::Access {
  static void set(ImportSummary& s, std::string text, std::string summary_line, std::string json) {
    s.text_ = std::move(text);
    s.summary_line_ = std::move(summary_line);
    s.json_ = std::move(json);
  }
};

struct FitSummary::Access {
  static void set(FitSummary& s, std::string text, std::string json) {
    s.text_ = std::move(text);
    s.json_ = std::move(json);
  }
};

struct LevelFits::Access {
  static void set(LevelFits& s, std::string text, std::string json) {
    s.text_ = std::move(text);
    s.json_ = std::move(json);
  }
};

struct RunDetails::Access {
  static void set(RunDetails& s, std::string text, std::string json) {
    s.text_ = std::move(text);
    s.json_ = std::move(json);
  }
};

/// The options of an import as the command line's settings layer
/// (src/pipeline/run_settings.hpp); InputError naming a malformed option.
SettingsLayer command_line_layer(const ImportOptions& options);

}  // namespace api

namespace records {

/// An integrated surface export as `hydrocoef integrate --json` gives it (a JSON text).
std::string surface_run_json_text(const SurfaceRun& run, const ImportedInput& input);

/// What an import did, with `hydrocoef import`'s text and JSON.
ImportSummary import_summary(const ImportResult& result, const std::string& database);

/// One run with its provenance, with `hydrocoef runs show`'s text and JSON.
RunDetails run_details(const StoredRun& run, const std::map<std::int64_t, ImportRecord>& imports);

/// A fit just made, with `hydrocoef fit`'s text and JSON.
FitSummary fit_summary(const FitResult& result, const std::string& body, const std::string& output,
                       const std::string& database);
/// A stored fit, with its entry of `hydrocoef fits` (text) and its object of `fits --json`.
FitSummary fit_summary(const FitRecord& record);

/// A per-level fit, with `hydrocoef fit --by`'s text and JSON.
LevelFits level_fits(const LevelFitResult& result, const LevelFitRequest& request, const std::string& database);

}  // namespace records
}  // namespace hydrocoef
