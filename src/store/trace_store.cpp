// RunDatabase::run_trace: a run's force history in brief, table run_force_trace
// (schema/0016_run_force_trace.sql; written by src/store/run_rows.cpp).
// Every size and value read back is checked: a received database is
// untrusted input.
#include <algorithm>
#include <string>

#include "src/core/error.hpp"
#include "src/core/text.hpp"
#include "src/history/history_trace.hpp"
#include "src/store/backend.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/database.hpp"

namespace hydrocoef {

std::optional<HistoryTrace> RunDatabase::run_trace(std::int64_t run_id) {
  auto select = connection_.prepare("SELECT abscissa, samples, components, data FROM run_force_trace WHERE run_id = ?");
  select.bind(1, run_id);
  if (!select.step()) return std::nullopt;
  const store::CheckedRow row(select, path_.string(), "run_force_trace", run_id);
  HistoryTrace trace;
  trace.abscissa_name = row.one_of(0, {"time", "iteration"});
  trace.samples = static_cast<std::size_t>(row.integer(1, 1, std::int64_t{1} << 50));
  const std::string components = row.text(2, 64);
  std::vector<std::size_t> present;
  if (!components.empty())
    for (const auto name : split(components, ',')) {
      std::size_t c = 0;
      while (c < 6 && kForceNames[c] != name) ++c;
      if (c == 6 || std::find(present.begin(), present.end(), c) != present.end())
        row.fail(2, "a list of distinct force components X, Y, Z, K, M, N");
      present.push_back(c);
    }
  const std::size_t bins = std::min(trace.samples, HistoryTrace::kMaxBins);
  const std::vector<double> data = row.doubles(3, bins * (1 + 2 * present.size()));
  if (data.size() != bins * (1 + 2 * present.size()))
    row.fail(3, std::to_string(bins * (1 + 2 * present.size())) + " float64 values for " + std::to_string(bins) +
                    " bins and " + std::to_string(present.size()) + " components");
  const auto part = [&](std::size_t index) {
    return std::vector<double>(data.begin() + static_cast<std::ptrdiff_t>(index * bins),
                               data.begin() + static_cast<std::ptrdiff_t>((index + 1) * bins));
  };
  trace.abscissa = part(0);
  for (std::size_t i = 0; i < present.size(); ++i) {
    trace.low[present[i]] = part(1 + 2 * i);
    trace.high[present[i]] = part(2 + 2 * i);
  }
  if (const std::string problem = trace_problem(trace); !problem.empty()) row.fail_row(problem);
  return trace;
}

}  // namespace hydrocoef
