// A force history reduced to what a run stores: the window of the record that
// is statistically steady, and per component its mean, spread, standard error
// of the mean (corrected for autocorrelation), drift, and flags for a run that
// has not converged.
//
// The window is either found (MSER-5 on each total component, see
// steady_window.hpp; the window starts where the last component settles) or
// given: an abscissa range T0:T1 (inclusive) or the last N samples. The
// statistics of each part (total, pressure, viscous, porous) over the window
// are those of statistics.hpp.
//
// Flags (per component, and for the run as the union over components):
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
// over the window (each O(window) with the bounded constant of
// statistics.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "src/history/force_history.hpp"
#include "src/history/statistics.hpp"
#include "src/history/steady_window.hpp"

namespace hydrocoef {

/// Which samples to average.
struct HistoryWindow {
  enum class Kind {
    Automatic,  ///< MSER-5 on each total component
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
};

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
  bool present = false;  ///< the history has this component's total
  /// Statistics of each part over the window, indexed by ForcePart; empty
  /// where the history lacks the part.
  std::array<std::optional<SeriesStatistics>, kForceParts> parts;
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
  std::string window_method;  ///< e.g. "MSER-5 (White 1997)", "range 601:1000", "last 100 samples"
  std::size_t first_sample = 0;
  std::size_t sample_count = 0;  ///< the window is samples [first_sample, first_sample + sample_count)
  double first_abscissa = 0.0;
  double last_abscissa = 0.0;
  /// For a found window: the component whose truncation started it.
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
