// The rows of one run as RunDatabase::import and RunDatabase::merge write them:
// the run with its disturbances, a force component with its statistics, the
// integrals of the surface it came from. Statements are prepared once per
// transaction. Only src/store includes this header.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/core/run.hpp"
#include "src/store/connection.hpp"

namespace hydrocoef {
struct StoredStatistics;  // src/store/database.hpp
}  // namespace hydrocoef

namespace hydrocoef::store {

/// -0 stored as 0, so that a key is one row whatever the sign of its zeros.
inline double canonical(double value) { return value == 0.0 ? 0.0 : value; }

/// Equal to 1e-12 of the larger magnitude (at least 1): one fluid or point given twice.
bool same_value(double a, double b);

class RunRows {
 public:
  explicit RunRows(Connection& connection);

  /// A run that exists already gets more components from another source: its
  /// moment reference point must be the same and its fluid properties may
  /// not differ (InputError at `where`); properties it lacked are filled in.
  void check_and_fill(std::int64_t run_id, const RunKey& key, const Fluid& fluid,
                      const std::array<double, 3>& reference_point_b, const SourceLocation& where);
  /// The id of the source_file row of these bytes (by their SHA-256), added
  /// with `imported_at` when there is none.
  std::int64_t source_id(const Provenance& file, const std::string& imported_at);
  /// A new run and its disturbances; its id.
  std::int64_t insert(std::int64_t body_id, const RunKey& key, const Fluid& fluid,
                      const std::array<double, 3>& reference_point_b);
  /// A force component (replacing one of the run's), without statistics.
  void write_force(std::int64_t run_id, std::size_t component, const ForceComponent& value, SignConvention sign,
                   std::int64_t source_id, std::size_t source_line, std::optional<std::int64_t> import_id);
  /// The statistics of a component that is a mean over a force history.
  void write_statistics(std::int64_t run_id, std::size_t component, const StoredStatistics& statistics);
  /// The integrals of the surface the run's forces came from (replacing the run's).
  void write_surface(std::int64_t run_id, std::int64_t source_id, const SurfaceIntegrals& g);
  /// The run's force history in brief (schema/0016_run_force_trace.sql), replacing any it had.
  void write_trace(std::int64_t run_id, const HistoryTrace& trace);
  /// Takes a run's trace away (a component written without a history).
  void drop_trace(std::int64_t run_id);

 private:
  Statement find_source_, insert_source_, details_, update_fluid_, insert_run_, insert_disturbance_, force_,
      statistics_, surface_, trace_, drop_trace_;
};

}  // namespace hydrocoef::store
