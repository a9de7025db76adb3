#include "src/history/history_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
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

std::string_view convergence_name(RunConvergence kind) {
  switch (kind) {
    case RunConvergence::Converged: return "converged";
    case RunConvergence::SteadyWindow: return "steady-window";
    case RunConvergence::TransientWindow: return "transient-window";
    case RunConvergence::GivenWindow: return "given-window";
  }
  return "given-window";
}

namespace {

bool is_moment(HistoryComponent c) { return static_cast<std::size_t>(c) >= 3; }

/// Components that are zero to round-off: every value over the record's last
/// quarter at most kNegligibleFraction of the largest force there (moments:
/// of that force times 1 m).
std::array<bool, kHistoryComponents> negligible_components(const ForceHistory& history) {
  const std::size_t n = history.size();
  const std::size_t from = n - std::max<std::size_t>(1, n / 4);
  std::array<double, kHistoryComponents> largest{};
  double force_scale = 0.0;
  for (const HistoryComponent c : kAllHistoryComponents) {
    if (!history.has(ForcePart::Total, c)) continue;
    const auto& x = history.values(ForcePart::Total, c);
    for (std::size_t i = from; i < n; ++i)
      largest[static_cast<std::size_t>(c)] = std::max(largest[static_cast<std::size_t>(c)], std::abs(x[i]));
    if (!is_moment(c)) force_scale = std::max(force_scale, largest[static_cast<std::size_t>(c)]);
  }
  std::array<bool, kHistoryComponents> out{};
  if (!(force_scale > 0.0)) return out;
  for (const HistoryComponent c : kAllHistoryComponents)
    out[static_cast<std::size_t>(c)] =
        history.has(ForcePart::Total, c) && largest[static_cast<std::size_t>(c)] <= kNegligibleFraction * force_scale;
  return out;
}

/// The statistics that describe a final iterate and its iterative error.
SeriesStatistics final_iterate_statistics(const IterativeError& e) {
  SeriesStatistics s;
  s.count = 1;
  s.mean = e.value;
  s.std_dev = e.fluctuation;
  s.standard_error = e.standard_uncertainty;
  s.effective_samples = 1.0;
  s.drift_slope = e.change_per_iteration;
  s.drift = e.change_per_iteration;
  s.constant = e.standard_uncertainty == 0.0;
  return s;
}

/// Whether the evidence says the run converged at the record's end.
bool converged_at_end(const ForceHistory& history, const std::optional<ConvergenceEvidence>& evidence) {
  return evidence && evidence->solver != SolverKind::Transient && evidence->criteria_met_at &&
         history.abscissa == HistoryAbscissa::Iteration &&
         std::abs(*evidence->criteria_met_at - history.abscissa_values.back()) < 0.5;
}

std::string evidence_reason(const ForceHistory& history, const std::optional<ConvergenceEvidence>& evidence,
                            RunConvergence kind) {
  std::string solver;
  if (evidence && evidence->solver != SolverKind::Unknown)
    solver = std::string(evidence->solver == SolverKind::Steady ? "steady" : "transient") + " solver (" +
             evidence->solver_source + ")";
  switch (kind) {
    case RunConvergence::Converged:
      return "the convergence criteria (" + evidence->criteria_source + ") hold at the last iteration, " +
             number(history.abscissa_values.back()) + " (" + evidence->residuals_source +
             (std::isfinite(evidence->residual_rate)
                  ? ", residuals falling by a factor " + number(evidence->residual_rate) + " per iteration"
                  : std::string()) +
             ")" + (solver.empty() ? std::string() : "; " + solver);
    case RunConvergence::GivenWindow: return "the window was given";
    case RunConvergence::TransientWindow:
      return solver.empty() ? "a record over time: averaged over its statistically steady window"
                            : solver + ": averaged over the statistically steady window of each component";
    case RunConvergence::SteadyWindow: break;
  }
  if (evidence && evidence->criteria_stated && !evidence->criteria_missed.empty())
    return "the convergence criteria (" + evidence->criteria_source +
           ") are not met at the last iteration: " + evidence->criteria_missed +
           (evidence->residuals_source.empty() ? "" : " (" + evidence->residuals_source + ")") +
           "; averaged over the statistically steady window of each component";
  if (evidence && evidence->criteria_stated)
    return "the convergence criteria (" + evidence->criteria_source +
           ") cannot be checked: no residuals of the run were found (OpenFOAM: the solverInfo function object); "
           "averaged over the statistically steady window of each component";
  return std::string(solver.empty() ? "no solver files state convergence criteria"
                                    : solver + " with no convergence criteria stated") +
         ": averaged over the statistically steady window of each component";
}

}  // namespace

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
  const auto negligible = negligible_components(history);
  for (const HistoryComponent c : kAllHistoryComponents)
    analysis.components[static_cast<std::size_t>(c)].negligible = negligible[static_cast<std::size_t>(c)];
  const auto deciding = [&](HistoryComponent c) {
    const ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
    return component.present && !component.negligible && options.deciding_components[static_cast<std::size_t>(c)];
  };

  // The kind of run, and the window of each component.
  if (options.window.kind != HistoryWindow::Kind::Automatic)
    analysis.convergence = RunConvergence::GivenWindow;
  else if (converged_at_end(history, options.evidence))
    analysis.convergence = RunConvergence::Converged;
  else if (history.abscissa == HistoryAbscissa::Time ||
           (options.evidence && options.evidence->solver == SolverKind::Transient))
    analysis.convergence = RunConvergence::TransientWindow;
  else
    analysis.convergence = RunConvergence::SteadyWindow;
  analysis.convergence_reason = evidence_reason(history, options.evidence, analysis.convergence);

  std::size_t given_first = 0;
  std::size_t given_count = 0;
  switch (options.window.kind) {
    case HistoryWindow::Kind::Automatic:
      analysis.window_method = analysis.convergence == RunConvergence::Converged
                                   ? std::string("final iterate")
                                   : "MSER-" + std::to_string(options.mser_batch_size) + " (White 1997) per component";
      break;
    case HistoryWindow::Kind::Range: {
      const double t0 = options.window.first;
      const double t1 = options.window.last;
      const auto& t = history.abscissa_values;
      const auto begin = std::lower_bound(t.begin(), t.end(), t0);
      const auto end = std::upper_bound(t.begin(), t.end(), t1);
      given_first = static_cast<std::size_t>(begin - t.begin());
      given_count = end > begin ? static_cast<std::size_t>(end - begin) : 0;
      analysis.window_method = "range " + (std::isfinite(t0) ? number(t0) : std::string()) + ":" +
                               (std::isfinite(t1) ? number(t1) : std::string());
      if (given_count < 2)
        throw InputError("the window " + analysis.window_method + " holds " + std::to_string(given_count) + " sample" +
                         (given_count == 1 ? "" : "s") + " of the history (" + span_text(history) +
                         "); expected at least 2");
      break;
    }
    case HistoryWindow::Kind::Last: {
      given_count = options.window.count;
      analysis.window_method = "last " + std::to_string(given_count) + " samples";
      if (given_count < 2 || given_count > n)
        throw InputError("the window of the last " + std::to_string(given_count) +
                         " samples does not fit the history (" + span_text(history) + "); expected 2 to " +
                         std::to_string(n));
      given_first = n - given_count;
      break;
    }
  }

  const bool converged = analysis.convergence == RunConvergence::Converged;
  for (const HistoryComponent c : kAllHistoryComponents) {
    ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
    if (!component.present) continue;
    if (converged) {
      component.first_sample = n - 1;
      component.sample_count = 1;
      component.window_method = "final iterate";
    } else if (options.window.kind == HistoryWindow::Kind::Automatic) {
      component.first_sample = component.mser.truncation;
      component.sample_count = n - component.first_sample;
      component.window_method = "MSER-" + std::to_string(options.mser_batch_size) + " (White 1997)";
    } else {
      component.first_sample = given_first;
      component.sample_count = given_count;
      component.window_method = analysis.window_method;
    }
    component.first_abscissa = history.abscissa_values[component.first_sample];
    component.last_abscissa = history.abscissa_values[component.first_sample + component.sample_count - 1];
  }

  // The common window: the latest start among the deciding components.
  bool have_common = false;
  for (const HistoryComponent c : kAllHistoryComponents) {
    const ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
    if (!deciding(c)) continue;
    if (!have_common || component.first_sample > analysis.first_sample) {
      analysis.first_sample = component.first_sample;
      analysis.sample_count = component.sample_count;
      if (options.window.kind == HistoryWindow::Kind::Automatic && !converged) analysis.window_set_by = c;
      have_common = true;
    }
  }
  if (!have_common) {  // every component negligible or left out: the widest window
    analysis.first_sample = converged ? n - 1 : given_first;
    analysis.sample_count = converged ? 1 : (given_count ? given_count : n);
  }
  analysis.first_abscissa = history.abscissa_values[analysis.first_sample];
  analysis.last_abscissa = history.abscissa_values[analysis.first_sample + analysis.sample_count - 1];

  bool any_uneven = false;
  for (const HistoryComponent c : kAllHistoryComponents) {
    ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
    if (!component.present) continue;
    if (converged) {
      for (const ForcePart part : kAllForceParts) {
        if (!history.has(part, c)) continue;
        const IterativeError e = iterative_error(history.values(part, c));
        component.parts[static_cast<std::size_t>(part)] = final_iterate_statistics(e);
        if (part == ForcePart::Total) component.iterative = e;
      }
      continue;  // no flags: the solver's criteria held, the error is stated
    }
    const std::size_t first = component.first_sample;
    const std::size_t count = component.sample_count;
    const std::span<const double> t(history.abscissa_values.data() + first, count);
    for (const ForcePart part : kAllForceParts) {
      if (!history.has(part, c)) continue;
      const std::span<const double> values(history.values(part, c).data() + first, count);
      component.parts[static_cast<std::size_t>(part)] = series_statistics(values, t, options.statistics);
    }
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
    const SeriesStatistics& total = component.total();
    component.drift_exceeds_standard_error = std::abs(total.drift) > total.standard_error;
    if (component.negligible) continue;  // zero to round-off: nothing to act on
    HistoryFlags& flags = component.flags;
    if (options.window.kind == HistoryWindow::Kind::Automatic)
      flags.no_steady_window = !component.mser.applicable || !component.mser.settled;
    flags.drifting = !total.constant && std::abs(total.drift) > options.drift_z * total.drift_standard_error;
    flags.too_few_effective_samples =
        !total.constant && (!total.autocorrelation_resolved || total.effective_samples < options.min_effective_samples);
    flags.uneven_sampling = uneven;
    if (deciding(c)) {
      analysis.flags.merge(flags);
      any_uneven = any_uneven || uneven;
    }
  }

  // Notes for people.
  const auto name = [&](HistoryComponent c) { return std::string(component_name(c, history.frame.naming)); };
  std::string negligible_names;
  for (const HistoryComponent c : kAllHistoryComponents)
    if (analysis.components[static_cast<std::size_t>(c)].present &&
        analysis.components[static_cast<std::size_t>(c)].negligible)
      negligible_names += (negligible_names.empty() ? "" : ", ") + name(c);
  if (!negligible_names.empty())
    analysis.notes.push_back(negligible_names + " zero to round-off (at most " + number(kNegligibleFraction) +
                             " of the largest force; moments per metre): no flags of their own");
  if (converged) {
    std::string errors;
    for (const HistoryComponent c : kAllHistoryComponents) {
      const ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
      if (!component.present || component.negligible) continue;
      const IterativeError& e = *component.iterative;
      errors += (errors.empty() ? "" : ", ") + name(c) + " " + number(e.value) + " +- " +
                number(e.standard_uncertainty) +
                (e.value != 0.0 ? " (" + number(100.0 * e.standard_uncertainty / std::abs(e.value)) + " %)" : "");
    }
    analysis.notes.push_back("converged: " + analysis.convergence_reason +
                             "; the final iterate is stored with its iterative error" +
                             (errors.empty() ? std::string() : ": " + errors));
    return analysis;
  }
  if (options.window.kind == HistoryWindow::Kind::Automatic) {
    for (const HistoryComponent c : kAllHistoryComponents) {
      const ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
      if (!component.present || component.negligible || !component.flags.no_steady_window) continue;
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
      if (given_first < component.mser.truncation)
        analysis.notes.push_back("the window starts before MSER-" + std::to_string(options.mser_batch_size) +
                                 " ends the start-up of " + name(c) + " (at " +
                                 abscissa_text(history.abscissa, history.abscissa_values[component.mser.truncation]) +
                                 ")");
    }
  }
  for (const HistoryComponent c : kAllHistoryComponents) {
    const ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
    if (!component.present || component.negligible) continue;
    const SeriesStatistics& total = component.total();
    if (component.flags.drifting)
      analysis.notes.push_back(name(c) + " drifts by " + number(total.drift) + " across its window (" +
                               number(std::abs(total.drift) / total.drift_standard_error) +
                               " times its standard error " + number(total.drift_standard_error) +
                               "; standard error of the mean " + number(total.standard_error) + ")");
    if (component.flags.too_few_effective_samples)
      analysis.notes.push_back(name(c) + ": " +
                               (total.autocorrelation_resolved
                                    ? number(total.effective_samples) + " effective samples in its window"
                                    : std::string("the autocorrelation time is longer than its window can resolve")) +
                               " (expected at least " + number(options.min_effective_samples) + ")");
  }
  if (any_uneven)
    analysis.notes.push_back(
        "the " + std::string(abscissa_name(history.abscissa)) +
        " steps in the window vary (adaptive time steps?): samples are averaged with equal weight");
  return analysis;
}

}  // namespace hydrocoef
