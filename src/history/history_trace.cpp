#include "src/history/history_trace.hpp"

#include <algorithm>
#include <cmath>

namespace hydrocoef {

HistoryTrace trace_of(const ForceHistory& history) {
  HistoryTrace trace;
  trace.abscissa_name = std::string(abscissa_name(history.abscissa));
  const std::size_t n = history.size();
  trace.samples = n;
  if (n == 0) return trace;
  const std::size_t bins = std::min(n, HistoryTrace::kMaxBins);
  const std::size_t base = n / bins, extra = n % bins;
  trace.abscissa.reserve(bins);
  for (std::size_t b = 0, end = 0; b < bins; ++b) {
    end += base + (b < extra ? 1 : 0);
    trace.abscissa.push_back(history.abscissa_values[end - 1]);
  }
  for (std::size_t c = 0; c < 6; ++c) {
    const auto component = static_cast<HistoryComponent>(c);
    if (!history.has(ForcePart::Total, component)) continue;
    const auto& x = history.values(ForcePart::Total, component);
    auto& low = trace.low[c];
    auto& high = trace.high[c];
    low.reserve(bins);
    high.reserve(bins);
    for (std::size_t b = 0, begin = 0; b < bins; ++b) {
      const std::size_t count = base + (b < extra ? 1 : 0);
      const auto [lo, hi] = std::minmax_element(x.begin() + static_cast<std::ptrdiff_t>(begin),
                                                x.begin() + static_cast<std::ptrdiff_t>(begin + count));
      low.push_back(*lo);
      high.push_back(*hi);
      begin += count;
    }
  }
  return trace;
}

std::string trace_problem(const HistoryTrace& trace) {
  const std::size_t bins = trace.abscissa.size();
  if (trace.abscissa_name != "time" && trace.abscissa_name != "iteration")
    return "its abscissa is '" + trace.abscissa_name + "'; expected time or iteration";
  const std::size_t expected = std::min(trace.samples, HistoryTrace::kMaxBins);
  if (bins != expected)
    return std::to_string(bins) + " bins of " + std::to_string(trace.samples) + " samples; expected " +
           std::to_string(expected);
  for (std::size_t b = 0; b < bins; ++b)
    if (!std::isfinite(trace.abscissa[b]) || (b > 0 && !(trace.abscissa[b] > trace.abscissa[b - 1])))
      return "its abscissa is not finite and increasing at bin " + std::to_string(b + 1);
  bool any = false;
  for (std::size_t c = 0; c < 6; ++c) {
    if (trace.low[c].empty() && trace.high[c].empty()) continue;
    any = true;
    if (trace.low[c].size() != bins || trace.high[c].size() != bins)
      return "component " + std::to_string(c + 1) + " has " + std::to_string(trace.low[c].size()) + " and " +
             std::to_string(trace.high[c].size()) + " values for " + std::to_string(bins) + " bins";
    for (std::size_t b = 0; b < bins; ++b)
      if (!std::isfinite(trace.low[c][b]) || !std::isfinite(trace.high[c][b]) || trace.low[c][b] > trace.high[c][b])
        return "component " + std::to_string(c + 1) + " at bin " + std::to_string(b + 1) +
               " is not two finite values, low <= high";
  }
  if (!any && bins > 0) return "it has bins but no component";
  return "";
}

}  // namespace hydrocoef
