// A force history reduced to what a run stores: per force component, the
// value and its uncertainty, how they were found (the run's convergence kind
// and each component's window), and flags a user should act on.
//
// The run's convergence kind is decided from its evidence
// (convergence_evidence.hpp) unless a window is given:
// - converged: a steady run whose solver met the case's convergence criteria
//   at the record's last iteration. Each component's value is the final
//   iterate, its standard error the iterative error left in it
//   (iterative_error.hpp). No flags: the solver said it converged and the
//   uncertainty says by how much the value may still move.
// - steady-window: a steady (iteration) record that did not meet criteria, or
//   whose criteria are not known: it oscillates about a mean
//   (pseudo-unsteady), and each component is averaged over its own
//   statistically steady window (MSER-5 on that component, see
//   steady_window.hpp) with the standard error corrected for
//   autocorrelation (statistics.hpp).
// - transient-window: the same over physical time, for a transient run.
// - given-window: an abscissa range T0:T1 (inclusive) or the last N samples,
//   for every component.
// A component that is zero to round-off (a moment about the centre of a
// symmetric body; at most kNegligibleFraction of the largest force, moments
// per metre) gets its statistics but no flags, and sets nothing for the
// others.
//
// Flags (per component; the run's are the union over its components that are
// not negligible and are deciding):
// - no_steady_window: a found window only: MSER-5's minimum lies in the
//   second half of the record (the start-up has not ended, or the record is
//   too short to tell: fewer than kMserMinBatches batches). The statistics are
//   still given, over the first-half truncation.
// - drifting: the trend across the window is significant: |drift| > drift_z
//   times its standard error (3 by default, a 0.3 % false alarm per component
//   for stationary noise). The literal comparison |drift| > standard error of
//   the mean is kept per component (drift_exceeds_standard_error) but is not a
//   test: stationary noise exceeds it about 3 times in 4, since the standard
//   error of the drift is about sqrt(12) times that of the mean.
// - too_few_effective_samples: fewer than min_effective_samples independent
//   samples in the window, or an autocorrelation time the window cannot
//   resolve.
// - uneven_sampling: the abscissa steps in the window differ by more than
//   uneven_step_tolerance (relative): adaptive time steps. Samples are
//   averaged with equal weight, not weighted by their time step.
//
// Cost: O(n) for MSER on every component plus the statistics of every part
// over its window (each O(window) with the bounded constant of
// statistics.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "src/history/convergence_evidence.hpp"
#include "src/history/force_history.hpp"
#include "src/history/iterative_error.hpp"
#include "src/history/statistics.hpp"
#include "src/history/steady_window.hpp"

namespace hydrocoef {

/// Which samples to average.
struct HistoryWindow {
  enum class Kind {
    Automatic,  ///< from the run's evidence: the final iterate, or MSER-5 on each component
    Range,      ///< first <= abscissa <= last
    Last,       ///< the last `count` samples
  };
  Kind kind = Kind::Automatic;
  double first = -std::numeric_limits<double>::infinity();
  double last = std::numeric_limits<double>::infinity();
  std::size_t count = 0;

  static HistoryWindow automatic() { return {}; }
  static HistoryWindow range(double first, double last) { return {Kind::Range, first, last, 0}; }
  static HistoryWindow last_samples(std::size_t count) {
    return {Kind::Last, -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), count};
  }
};

struct HistoryAnalysisOptions {
  HistoryWindow window;
  std::size_t mser_batch_size = 5;
  /// Components whose MSER truncation decides a found window and whose flags
  /// make the run's flags (all by default; a sphere's moments about its
  /// centre, for example, are numerical noise). A component left out still
  /// gets its statistics and its own flags.
  std::array<bool, kHistoryComponents> deciding_components{true, true, true, true, true, true};
  StatisticsOptions statistics;
  double min_effective_samples = 20.0;
  double drift_z = 3.0;
  double uneven_step_tolerance = 0.01;
  /// What the solver's files say (none: the history alone decides, and a
  /// steady run is never taken as converged without its solver's word).
  std::optional<ConvergenceEvidence> evidence;
};

/// A component at most this fraction of the largest force component (a
/// moment: of the largest force times 1 m) is zero to round-off.
inline constexpr double kNegligibleFraction = 1e-5;

/// How a run's values were obtained (stored with each component).
enum class RunConvergence { Converged, SteadyWindow, TransientWindow, GivenWindow };

/// "converged", "steady-window", "transient-window", "given-window".
std::string_view convergence_name(RunConvergence kind);

struct HistoryFlags {
  bool no_steady_window = false;
  bool drifting = false;
  bool too_few_effective_samples = false;
  bool uneven_sampling = false;

  /// A flag that says the mean may not be the converged value.
  bool not_converged() const { return no_steady_window || drifting || too_few_effective_samples; }
  bool any() const { return not_converged() || uneven_sampling; }
  void merge(const HistoryFlags& other);
};

/// Short names of the flags set ("no-steady-window", "drifting",
/// "too-few-effective-samples", "uneven-sampling"), for output and storage.
std::vector<std::string> flag_names(const HistoryFlags& flags);

struct ComponentAnalysis {
  bool present = false;     ///< the history has this component's total
  bool negligible = false;  ///< zero to round-off: no flags, sets nothing
  /// This component's window: samples [first_sample, first_sample +
  /// sample_count); for a converged run the final iterate alone.
  std::string window_method;
  std::size_t first_sample = 0;
  std::size_t sample_count = 0;
  double first_abscissa = 0.0;
  double last_abscissa = 0.0;
  /// Statistics of each part over the window, indexed by ForcePart; empty
  /// where the history lacks the part. For a converged run: mean = the final
  /// iterate, standard_error = its iterative error, std_dev = the
  /// fluctuation about the tail's trend, drift = the change per iteration at
  /// the end, count = effective_samples = 1.
  std::array<std::optional<SeriesStatistics>, kForceParts> parts;
  /// A converged run: the total's iterative error.
  std::optional<IterativeError> iterative;
  /// MSER-5 on this component's total over the whole record (for a given
  /// window too, for comparison).
  MserResult mser;
  bool drift_exceeds_standard_error = false;  ///< |drift| > standard error of the mean (informative)
  HistoryFlags flags;

  const SeriesStatistics& total() const { return *parts[static_cast<std::size_t>(ForcePart::Total)]; }
};

struct HistoryAnalysis {
  HistoryAbscissa abscissa = HistoryAbscissa::Time;
  HistoryWindow::Kind window_kind = HistoryWindow::Kind::Automatic;
  RunConvergence convergence = RunConvergence::SteadyWindow;
  /// Why: the evidence in words with its files and lines.
  std::string convergence_reason;
  std::string window_method;  ///< e.g. "MSER-5 (White 1997) per component", "range 601:1000", "final iterate"
  /// The window every non-negligible deciding component's window contains
  /// (the latest start among them): samples [first_sample, first_sample +
  /// sample_count). Each component's own is in `components`.
  std::size_t first_sample = 0;
  std::size_t sample_count = 0;
  double first_abscissa = 0.0;
  double last_abscissa = 0.0;
  /// For found windows: the component whose window starts latest.
  std::optional<HistoryComponent> window_set_by;
  std::array<ComponentAnalysis, kHistoryComponents> components;
  HistoryFlags flags;        ///< union over the present deciding components
  std::string error_method;  ///< standard_error_method() of the options used
  /// Sentences for people: what set the window, what each flag means here.
  std::vector<std::string> notes;
};

/// Analyses a history (check_force_history must hold; std::invalid_argument
/// otherwise). Throws InputError when a given window holds fewer than 2
/// samples or asks for more samples than the record has, naming the record's
/// span, and when the history has no total component at all.
HistoryAnalysis analyze_force_history(const ForceHistory& history, const HistoryAnalysisOptions& options = {});

}  // namespace hydrocoef
