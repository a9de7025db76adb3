// A shareable report of a run database: one self-contained HTML page (no
// network access needed: inline CSS, plots embedded as SVG data URIs) with the
// runs, the quality of each run averaged from a force history (its
// convergence kind and why, its flags, each component's standard error, and
// its history figure: the stored window and statistics,
// src/plot/history_plot.hpp), the fitted laws with their coefficients and R²,
// the coefficient surfaces with their leave-one-out errors, calibration,
// sigma maps and stale flags, the stored mesh studies (GCI), the
// forced-oscillation fits, and the plots of src/plot (fits, coefficient
// curves, surfaces, simulations).
//
// Layout of DIR: index.html (the page; it alone is enough to share) and
// plots/NAME.svg with NAME.dat and NAME.gp (the plotted values and the gnuplot
// script, as src/plot writes them). Each embedded figure is a <figure
// id="NAME">; a run's history is plots/history-run-ID-HASH.svg
// (plot_file_stem("history", "run-ID")), a surface's sigma map
// plots/sigma-....svg.
//
// The page's sections have the ids "summary", "runs", "quality", "fits",
// "surfaces", "gci", "pmm" and "simulations". A small inline script records JavaScript errors and images
// that failed to load in the page itself (element "report-status":
// data-ready, data-images, data-broken-images, and li.js-error entries), so a
// headless browser can check the page.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/run_selection.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::report {

struct ReportOptions {
  std::optional<std::string> body;  ///< only this body's runs, fits and surfaces
  /// Only the runs it selects, and the fits and surfaces built from those
  /// runs alone (others are left out with a note).
  RunSelection selection;
  /// Simulated trajectories (hydrocoef simulate --out) to plot, component
  /// `component` against time, with `experiment` overlaid when given.
  std::vector<std::filesystem::path> trajectories;
  std::optional<std::filesystem::path> experiment;
  std::string component = "r";
  std::size_t max_run_rows = 1000;  ///< longer run tables are cut, with a note
  /// At most this many runs' history figures (gnuplot runs once per figure);
  /// the rest are named in a note.
  std::size_t max_history_plots = 200;
};

struct ReportResult {
  std::filesystem::path index;               ///< DIR/index.html
  std::vector<std::filesystem::path> plots;  ///< the SVG files embedded
  std::vector<std::string> notes;            ///< plots that could not be drawn, and why
  std::size_t runs = 0, fits = 0, surfaces = 0;
  std::size_t histories = 0;        ///< runs' history figures drawn
  std::size_t sigma_maps = 0;       ///< surfaces' standard-deviation figures drawn
  std::size_t mesh_study_rows = 0;  ///< rows of the mesh-study (GCI) table
  std::size_t pmm_fits = 0;         ///< forced-oscillation analyses listed
};

/// The file stem of a report plot (plots/STEM.svg) for a fit, surface or run
/// name: KIND-, at most 60 bytes of the name with every byte outside
/// [A-Za-z0-9-] as '_', then '-' and 12 hex digits of the name's SHA-256, so
/// names that sanitize alike get different files and every stem fits a file
/// name.
std::string plot_file_stem(const std::string& kind, const std::string& name);

/// Writes the report into `dir` (created if needed; index.html replaced).
/// InputError when the database (or the body) has no runs, naming the bodies
/// there are, or when a file cannot be written. A plot that cannot be drawn
/// (e.g. a 3-axis surface) is left out with a note on the page and in notes.
ReportResult write_report(RunDatabase& database, const std::filesystem::path& dir, const ReportOptions& options = {});

/// Text made safe for HTML element content and attribute values.
std::string html_escape(std::string_view text);
/// RFC 4648 base64.
std::string base64(std::string_view bytes);

}  // namespace hydrocoef::report
