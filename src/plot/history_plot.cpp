#include "src/plot/history_plot.hpp"
#include "src/core/numbers.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/error.hpp"
#include "src/core/sign_convention.hpp"

namespace hydrocoef::plot {
namespace {

/// A y range that shows every drawn value with a margin, never empty (a
/// component with zero spread, error and drift).
std::array<double, 2> y_range(double mean, double half_width) {
  double half = 1.6 * half_width;
  if (!(half > 0.0)) half = std::max(0.05 * std::abs(mean), 1e-9);
  return {mean - half, mean + half};
}

Panel window_panel(const StoredStatistics& st, double mean, const std::string& unit) {
  const ComponentStatistics& v = st.values;
  const double w0 = st.window_first, w1 = st.window_last, span = w1 - w0;
  Panel panel;
  panel.x_range = std::array<double, 2>{w0 - 0.3 * span, w1 + 0.1 * span};
  panel.y_range = y_range(mean, std::max({v.spread, v.standard_error, std::abs(v.drift) / 2.0}));
  panel.shaded.push_back({w0, w1, std::nullopt, std::nullopt});
  panel.shaded_title = "averaging window (" + std::to_string(st.samples) + " samples)";
  panel.series.push_back({"stored value ± standard error " + significant(v.standard_error, 3) + " " + unit,
                          Series::Style::Band,
                          0,
                          {w0, w1},
                          {mean - v.standard_error, mean - v.standard_error},
                          {mean + v.standard_error, mean + v.standard_error}});
  panel.series.push_back({"stored value (window mean) " + significant(mean, 6) + " " + unit,
                          Series::Style::Line,
                          0,
                          {w0, w1},
                          {mean, mean},
                          {}});
  panel.series.push_back({"± spread (standard deviation) " + significant(v.spread, 3) + " " + unit,
                          Series::Style::DashedLine,
                          7,
                          {w0, w1},
                          {mean + v.spread, mean + v.spread},
                          {}});
  panel.series.push_back({"", Series::Style::DashedLine, 7, {w0, w1}, {mean - v.spread, mean - v.spread}, {}});
  panel.series.push_back({"trend across the window (drift " + significant(v.drift, 3) + " " + unit + ")",
                          Series::Style::DashedLine,
                          1,
                          {w0, w1},
                          {mean - v.drift / 2.0, mean + v.drift / 2.0},
                          {}});
  return panel;
}

Panel final_iterate_panel(const StoredStatistics& st, double value, const std::string& unit) {
  const ComponentStatistics& v = st.values;
  const double last = st.window_last;
  const double pad = std::max(1.0, 0.05 * std::abs(last));
  Panel panel;
  panel.x_range = std::array<double, 2>{last - pad, last + pad / 4.0};
  panel.y_range = y_range(value, std::max(v.standard_error, std::abs(v.drift) * pad));
  panel.series.push_back({"± iterative error " + significant(v.standard_error, 3) + " " + unit,
                          Series::Style::Band,
                          0,
                          {last - pad / 2.0, last + pad / 8.0},
                          {value - v.standard_error, value - v.standard_error},
                          {value + v.standard_error, value + v.standard_error}});
  panel.series.push_back({"change per iteration at the end " + significant(v.drift, 3) + " " + unit,
                          Series::Style::DashedLine,
                          1,
                          {last - pad, last},
                          {value - v.drift * pad, value},
                          {}});
  panel.series.push_back({"final iterate (stored value) " + significant(value, 6) + " " + unit,
                          Series::Style::Points,
                          0,
                          {last},
                          {value},
                          {}});
  return panel;
}

/// The panel's history from the trace: its bins' extremes as a band (the
/// samples as a line when the record is kept whole), the x range the whole
/// record, the y range the history from `from` on with the stored value.
void add_trace(Panel& panel, const HistoryTrace& trace, std::size_t c, double from, double value, double half_width) {
  const auto& low = trace.low[c];
  const auto& high = trace.high[c];
  if (low.empty()) return;
  const bool whole = trace.abscissa.size() == trace.samples;
  Series history{
      whole
          ? "history (" + std::to_string(trace.samples) + " samples)"
          : "history: least and largest of each bin of " + std::to_string(trace.samples / trace.abscissa.size()) + "-" +
                std::to_string((trace.samples + trace.abscissa.size() - 1) / trace.abscissa.size()) + " samples",
      whole ? Series::Style::Line : Series::Style::Band,
      6,
      trace.abscissa,
      low,
      whole ? std::vector<double>{} : high};
  panel.series.insert(panel.series.begin(), std::move(history));
  const double first = trace.abscissa.front(), last = trace.abscissa.back();
  const double span = last > first ? last - first : 1.0;
  panel.x_range = std::array<double, 2>{first, last + 0.02 * span};
  double lo = value - half_width, hi = value + half_width;
  for (std::size_t b = 0; b < trace.abscissa.size(); ++b)
    if (trace.abscissa[b] >= from) lo = std::min(lo, low[b]), hi = std::max(hi, high[b]);
  const double margin = hi > lo ? 0.15 * (hi - lo) : std::max(0.05 * std::abs(value), 1e-9);
  panel.y_range = std::array<double, 2>{lo - margin, hi + margin};
}

}  // namespace

bool has_history(const StoredRun& run) {
  return std::any_of(run.tau_b.begin(), run.tau_b.end(),
                     [](const std::optional<StoredForce>& force) { return force && force->statistics; });
}

Figure history_figure(const StoredRun& run, const std::optional<HistoryTrace>& trace) {
  if (!has_history(run))
    throw InputError("run " + std::to_string(run.id) +
                     ": no force component is a mean over a force history (its values came from a force table or a "
                     "surface export): no history to draw");
  std::string kind;
  for (const auto& force : run.tau_b)
    if (force && force->statistics && kind.empty()) kind = force->statistics->convergence;
  Figure figure;
  figure.title =
      "run " + std::to_string(run.id) + " (" + describe(run.key) + "), " +
      (kind.empty() ? std::string("convergence not recorded") : kind) +
      (trace ? ": the history in brief, the window and the stored value"
             : ": the stored window and statistics (stored before histories were kept: the samples are not stored)");
  for (std::size_t i = 0; i < run.tau_b.size(); ++i) {
    const auto& force = run.tau_b[i];
    if (!force || !force->statistics) continue;
    const StoredStatistics& st = *force->statistics;
    const std::string unit = i < 3 ? "N" : "N m";
    const double value = force->value.total;
    const bool final_iterate = st.convergence == "converged" || !(st.window_last > st.window_first);
    Panel panel = final_iterate ? final_iterate_panel(st, value, unit) : window_panel(st, value, unit);
    if (trace) {
      // From the window's start (a converged run: the last half of its record) on.
      const double from = final_iterate ? trace->abscissa[trace->abscissa.size() / 2] : st.window_first;
      add_trace(panel, *trace, i, from, value, st.values.standard_error);
    }
    std::string flags;
    for (const auto& flag : st.flags) flags += (flags.empty() ? "" : ", ") + flag;
    panel.title = std::string(kForceNames[i]) + ": " +
                  (final_iterate ? "final iterate at " + st.abscissa + " " + significant(st.window_last, 8)
                                 : "mean over " + st.abscissa + " " + significant(st.window_first, 8) + " to " +
                                       significant(st.window_last, 8) + " (" + st.window_method + ")") +
                  (flags.empty() ? std::string() : "; flags: " + flags);
    panel.x_label = st.abscissa == "time" ? "time [s]" : st.abscissa;
    panel.y_label = std::string(kForceNames[i]) + " [" + unit + "] (" + std::string(to_string(force->sign)) + ")";
    figure.panels.push_back(std::move(panel));
  }
  return figure;
}

}  // namespace hydrocoef::plot
