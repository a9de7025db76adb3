#include "src/history/history_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string abscissa_text(HistoryAbscissa abscissa, double value) {
  return std::string(abscissa == HistoryAbscissa::Time ? "t = " : "iteration ") + number(value) +
         (abscissa == HistoryAbscissa::Time ? " s" : "");
}

std::string span_text(const ForceHistory& history) {
  return std::to_string(history.size()) + " samples from " +
         abscissa_text(history.abscissa, history.abscissa_values.front()) + " to " +
         abscissa_text(history.abscissa, history.abscissa_values.back());
}

}  // namespace

void HistoryFlags::merge(const HistoryFlags& other) {
  no_steady_window = no_steady_window || other.no_steady_window;
  drifting = drifting || other.drifting;
  too_few_effective_samples = too_few_effective_samples || other.too_few_effective_samples;
  uneven_sampling = uneven_sampling || other.uneven_sampling;
}

std::vector<std::string> flag_names(const HistoryFlags& flags) {
  std::vector<std::string> names;
  if (flags.no_steady_window) names.emplace_back("no-steady-window");
  if (flags.drifting) names.emplace_back("drifting");
  if (flags.too_few_effective_samples) names.emplace_back("too-few-effective-samples");
  if (flags.uneven_sampling) names.emplace_back("uneven-sampling");
  return names;
}

HistoryAnalysis analyze_force_history(const ForceHistory& history, const HistoryAnalysisOptions& options) {
  check_force_history(history);
  const std::size_t n = history.size();
  HistoryAnalysis analysis;
  analysis.abscissa = history.abscissa;
  analysis.window_kind = options.window.kind;
  analysis.error_method = standard_error_method(options.statistics);

  bool any_total = false;
  for (const HistoryComponent c : kAllHistoryComponents) {
    ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
    component.present = history.has(ForcePart::Total, c);
    if (!component.present) continue;
    any_total = true;
    component.mser = mser_truncation(history.values(ForcePart::Total, c), options.mser_batch_size);
  }
  if (!any_total || n == 0)
    throw InputError("the force history has no total force or moment component; expected at least one");
  const auto deciding = [&](HistoryComponent c) {
    return analysis.components[static_cast<std::size_t>(c)].present &&
           options.deciding_components[static_cast<std::size_t>(c)];
  };

  // The window.
  std::size_t first = 0;
  std::size_t count = 0;  // set by every case below
  switch (options.window.kind) {
    case HistoryWindow::Kind::Automatic: {
      analysis.window_method = "MSER-" + std::to_string(options.mser_batch_size) + " (White 1997), latest component";
      for (const HistoryComponent c : kAllHistoryComponents) {
        if (!deciding(c)) continue;
        const MserResult& mser = analysis.components[static_cast<std::size_t>(c)].mser;
        if (!analysis.window_set_by || mser.truncation > first) {
          first = mser.truncation;
          analysis.window_set_by = c;
        }
      }
      count = n - first;
      break;
    }
    case HistoryWindow::Kind::Range: {
      const double t0 = options.window.first;
      const double t1 = options.window.last;
      const auto& t = history.abscissa_values;
      const auto begin = std::lower_bound(t.begin(), t.end(), t0);
      const auto end = std::upper_bound(t.begin(), t.end(), t1);
      first = static_cast<std::size_t>(begin - t.begin());
      count = end > begin ? static_cast<std::size_t>(end - begin) : 0;
      analysis.window_method = "range " + (std::isfinite(t0) ? number(t0) : std::string()) + ":" +
                               (std::isfinite(t1) ? number(t1) : std::string());
      if (count < 2)
        throw InputError("the window " + analysis.window_method + " holds " + std::to_string(count) + " sample" +
                         (count == 1 ? "" : "s") + " of the history (" + span_text(history) + "); expected at least 2");
      break;
    }
    case HistoryWindow::Kind::Last: {
      count = options.window.count;
      analysis.window_method = "last " + std::to_string(count) + " samples";
      if (count < 2 || count > n)
        throw InputError("the window of the last " + std::to_string(count) + " samples does not fit the history (" +
                         span_text(history) + "); expected 2 to " + std::to_string(n));
      first = n - count;
      break;
    }
  }
  analysis.first_sample = first;
  analysis.sample_count = count;
  analysis.first_abscissa = history.abscissa_values[first];
  analysis.last_abscissa = history.abscissa_values[first + count - 1];
  const std::span<const double> t(history.abscissa_values.data() + first, count);

  // Steps of the abscissa in the window.
  bool uneven = false;
  if (count >= 3) {
    double low = t[1] - t[0];
    double high = low;
    for (std::size_t i = 2; i < count; ++i) {
      const double step = t[i] - t[i - 1];
      low = std::min(low, step);
      high = std::max(high, step);
    }
    const double mean_step = (t[count - 1] - t[0]) / static_cast<double>(count - 1);
    uneven = (high - low) > options.uneven_step_tolerance * mean_step;
  }

  for (const HistoryComponent c : kAllHistoryComponents) {
    ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
    if (!component.present) continue;
    for (const ForcePart part : kAllForceParts) {
      if (!history.has(part, c)) continue;
      const std::span<const double> values(history.values(part, c).data() + first, count);
      component.parts[static_cast<std::size_t>(part)] = series_statistics(values, t, options.statistics);
    }
    const SeriesStatistics& total = component.total();
    HistoryFlags& flags = component.flags;
    if (options.window.kind == HistoryWindow::Kind::Automatic)
      flags.no_steady_window = !component.mser.applicable || !component.mser.settled;
    component.drift_exceeds_standard_error = std::abs(total.drift) > total.standard_error;
    flags.drifting = !total.constant && std::abs(total.drift) > options.drift_z * total.drift_standard_error;
    flags.too_few_effective_samples =
        !total.constant && (!total.autocorrelation_resolved || total.effective_samples < options.min_effective_samples);
    flags.uneven_sampling = uneven;
    if (deciding(c)) analysis.flags.merge(flags);
  }

  // Notes for people.
  const auto name = [&](HistoryComponent c) { return std::string(component_name(c, history.frame.naming)); };
  if (options.window.kind == HistoryWindow::Kind::Automatic) {
    if (analysis.window_set_by)
      analysis.notes.push_back("the window starts at " + abscissa_text(history.abscissa, analysis.first_abscissa) +
                               " (" + sample_location(history, first, *analysis.window_set_by) + "), where MSER-" +
                               std::to_string(options.mser_batch_size) + " ends the start-up of " +
                               name(*analysis.window_set_by) + "; " + std::to_string(count) + " of " +
                               std::to_string(n) + " samples kept");
    for (const HistoryComponent c : kAllHistoryComponents) {
      const ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
      if (!component.present || !component.flags.no_steady_window) continue;
      if (!component.mser.applicable)
        analysis.notes.push_back(name(c) + ": the record is too short to find a steady window (" + std::to_string(n) +
                                 " samples; MSER-" + std::to_string(options.mser_batch_size) + " needs at least " +
                                 std::to_string(kMserMinBatches * options.mser_batch_size) + ")");
      else
        analysis.notes.push_back(
            name(c) +
            ": no steady window: its start-up does not end in the first half of the record "
            "(MSER-" +
            std::to_string(options.mser_batch_size) + " minimum at " +
            abscissa_text(history.abscissa, history.abscissa_values[component.mser.unrestricted_truncation]) + ")");
    }
  } else {
    for (const HistoryComponent c : kAllHistoryComponents) {
      const ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
      if (!component.present || !component.mser.applicable || !deciding(c)) continue;
      if (first < component.mser.truncation)
        analysis.notes.push_back("the window starts before MSER-" + std::to_string(options.mser_batch_size) +
                                 " ends the start-up of " + name(c) + " (at " +
                                 abscissa_text(history.abscissa, history.abscissa_values[component.mser.truncation]) +
                                 ")");
    }
  }
  for (const HistoryComponent c : kAllHistoryComponents) {
    const ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
    if (!component.present) continue;
    const SeriesStatistics& total = component.total();
    if (component.flags.drifting)
      analysis.notes.push_back(name(c) + " drifts by " + number(total.drift) + " across the window (" +
                               number(std::abs(total.drift) / total.drift_standard_error) +
                               " times its standard error " + number(total.drift_standard_error) +
                               "; standard error of the mean " + number(total.standard_error) + ")");
    if (component.flags.too_few_effective_samples)
      analysis.notes.push_back(name(c) + ": " +
                               (total.autocorrelation_resolved
                                    ? number(total.effective_samples) + " effective samples in the window"
                                    : std::string("the autocorrelation time is longer than the window can resolve")) +
                               " (expected at least " + number(options.min_effective_samples) + ")");
  }
  if (uneven)
    analysis.notes.push_back(
        "the " + std::string(abscissa_name(history.abscissa)) +
        " steps in the window vary (adaptive time steps?): samples are averaged with equal weight");
  return analysis;
}

}  // namespace hydrocoef
