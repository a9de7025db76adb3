// The report's quality at a glance (src/report/report.hpp): how each run's
// values were obtained and how sure they are, what each surface says about
// its own uncertainty, and the stored mesh studies. Written into the page by
// write_report; not part of the library's interface.
#pragma once

#include <cstddef>
#include <vector>

#include "src/report/report_page.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::report::detail {

/// Section "quality": a table of the runs averaged from a force history
/// (convergence kind and its reason, flags, each component's value ± its
/// standard error and window), then per run its history figure
/// (src/plot/history_plot.hpp, plots/history-...svg), at most `max_plots` of
/// them (the rest named in a note), each with its trace from `database`
/// (RunDatabase::run_trace). Runs without a history are counted.
void write_run_quality(Page& page, RunDatabase& database, const std::vector<StoredRun>& runs, std::size_t max_plots);

/// A surface's calibration and stated uncertainty, for its table cell: a GP's
/// leave-one-out standardized residuals per output (RMS and largest, with
/// the verdict of surface show: RMS within 0.5..2 and none beyond 4), a grid
/// or RBF surface's leave-one-out part of its stated sd per output, or that
/// it states none.
std::string calibration_html(const SurfaceRecord& surface);

/// The sigma maps of a surface that states a standard deviation (one per
/// output, at most 6; plots/sigma-...svg); nothing for one that states none.
void write_sigma_maps(Page& page, RunDatabase& database, const SurfaceRecord& surface,
                      const std::vector<std::string>& outputs);

/// Section "gci": the stored mesh studies (hydrocoef gci), one row per key
/// and force component.
void write_mesh_studies(Page& page, const std::vector<NumericalUncertaintyRecord>& studies);

}  // namespace hydrocoef::report::detail
