#include "src/report/quality_sections.hpp"

#include <cmath>
#include <optional>

#include "src/plot/history_plot.hpp"
#include "src/plot/plots.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef::report::detail {
namespace {

constexpr std::array<const char*, 6> kUnits{"N", "N", "N", "N m", "N m", "N m"};

/// The run's convergence kind: that of its first averaged component (every
/// component of a run is stored with the run's kind).
const StoredStatistics* first_statistics(const StoredRun& run) {
  for (const auto& force : run.tau_b)
    if (force && force->statistics) return &*force->statistics;
  return nullptr;
}

std::string kind_html(const StoredStatistics& st) {
  if (st.convergence.empty()) return "<span class=\"note\">not recorded (imported by an older hydrocoef)</span>";
  const bool window_mean = st.convergence != "converged";
  return "<strong class=\"kind\">" + html_escape(st.convergence) + "</strong>" +
         (window_mean ? "" : " <span class=\"note\">(final iterate)</span>");
}

/// A GP output's leave-one-out standardized residuals look like N(0, 1):
/// RMS within [0.5, 2] and none beyond 4 (as surface show judges them).
bool gp_calibrated(const GpState& state) {
  return state.loo_rms_z >= 0.5 && state.loo_rms_z <= 2.0 && state.loo_max_z <= 4.0;
}

}  // namespace

void write_run_quality(Page& page, RunDatabase& database, const std::vector<StoredRun>& runs, std::size_t max_plots) {
  auto& h = page.html;
  h << "<section id=\"quality\"><h2>Run quality</h2>\n";
  std::vector<const StoredRun*> averaged;
  for (const auto& run : runs)
    if (plot::has_history(run)) averaged.push_back(&run);
  const std::size_t without = runs.size() - averaged.size();
  if (averaged.empty()) {
    h << "<p>No run was averaged from a force history: every value came from a force table or a surface export, "
         "which state no window or standard error.</p>\n</section>\n";
    return;
  }
  h << "<p>How each run's values were obtained from its force history: <em>converged</em> (a steady run whose "
       "solver met its convergence criteria: the final iterate, ± its iterative error), <em>steady-window</em> "
       "and <em>transient-window</em> (the mean over each component's statistically steady window, ± the "
       "standard error of the mean corrected for autocorrelation), <em>given-window</em> (the mean over the "
       "window given at import). Flags say what to act on (no-steady-window, drifting, "
       "too-few-effective-samples, uneven-sampling). Values as stored (on-body or as tabulated).";
  if (without > 0)
    h << " " << without << (without == 1 ? " run has" : " runs have")
      << " no history (a force table or a surface export) and " << (without == 1 ? "is" : "are") << " not listed.";
  h << "</p>\n<div class=\"scroll\"><table><thead><tr><th>run</th><th>key</th><th>convergence</th><th>why</th>"
       "<th>flags</th>";
  for (std::size_t i = 0; i < 6; ++i) h << "<th>" << kForceNames[i] << " ± std. error [" << kUnits[i] << "]</th>";
  h << "</tr></thead><tbody>\n";
  for (const StoredRun* run : averaged) {
    const StoredStatistics& first = *first_statistics(*run);
    std::string flags;
    for (const auto& flag : run_flags(*run)) flags += (flags.empty() ? "" : ", ") + flag;
    h << "<tr id=\"quality-run-" << run->id << "\"><td class=\"num\"><a href=\"#history-run-" << run->id << "\">"
      << run->id << "</a></td><td>" << html_escape(describe(run->key)) << "</td><td>" << kind_html(first)
      << "</td><td class=\"reason\">" << html_escape(first.convergence_reason) << "</td><td>"
      << (flags.empty() ? std::string("none") : "<span class=\"stale\">" + html_escape(flags) + "</span>") << "</td>";
    for (const auto& force : run->tau_b) {
      if (!force) {
        h << "<td></td>";
        continue;
      }
      h << "<td class=\"num\">" << num(force->value.total);
      if (force->statistics) {
        const StoredStatistics& st = *force->statistics;
        h << " ± " << num(st.values.standard_error, 3) << "<br><span class=\"note\">"
          << (st.convergence == "converged"
                  ? html_escape(st.abscissa) + " " + num(st.window_last, 8)
                  : html_escape(st.abscissa) + " " + num(st.window_first, 8) + "–" + num(st.window_last, 8) + ", " +
                        std::to_string(st.samples) + " samples")
          << "</span>";
      } else {
        h << "<br><span class=\"note\">no history</span>";
      }
      h << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</tbody></table></div>\n";
  std::size_t drawn = 0;
  for (const StoredRun* run : averaged) {
    if (drawn == max_plots) {
      const std::string note = std::to_string(averaged.size() - drawn) + " more runs' histories not drawn";
      h << "<p class=\"note\">" << note << ".</p>\n";
      page.result().notes.push_back(note);
      break;
    }
    const StoredStatistics& first = *first_statistics(*run);
    std::size_t panels = 0;
    for (const auto& force : run->tau_b) panels += force && force->statistics ? 1 : 0;
    h << "<h3 id=\"history-run-" << run->id << "\">Run " << run->id << ": " << html_escape(describe(run->key))
      << "</h3>\n<p>" << kind_html(first)
      << (first.convergence_reason.empty() ? std::string() : ": " + html_escape(first.convergence_reason)) << "</p>\n";
    if (page.figure(
            report::plot_file_stem("history", "run-" + std::to_string(run->id)),
            "force history of run " + std::to_string(run->id) +
                ": the history in brief (each bin's least and largest value), the averaging window, the stored "
                "value (window mean or final iterate) with its standard error, the spread and the trend",
            [&] { return plot::history_figure(*run, database.run_trace(run->id)); },
            static_cast<int>(std::min<std::size_t>(3600, 200 + 260 * panels))))
      ++page.result().histories;
    ++drawn;
  }
  h << "</section>\n";
}

std::string calibration_html(const SurfaceRecord& record) {
  std::optional<CoefficientSurface> built;
  try {
    built = surface_from_record(record);
  } catch (const InputError& e) {
    return "not read (" + html_escape(e.what()) + ")";
  }
  const CoefficientSurface& surface = *built;
  std::string out;
  if (const GpSurfaces* gp = surface.gp()) {
    out += "Gaussian process; leave-one-out standardized residuals (expected RMS about 1, none beyond 4):<br>";
    for (std::size_t k = 0; k < surface.output_count(); ++k) {
      const GpState& state = gp->output(k).state();
      out += html_escape(surface.output_names()[k]) + ": ";
      if (!std::isfinite(state.loo_rms_z)) {
        out += "not known (stored before it was kept: surface rebuild computes it)<br>";
        continue;
      }
      out += "RMS " + num(state.loo_rms_z, 3) + ", largest " + num(state.loo_max_z, 3) + ", stated sd × " +
             num(state.sd_factor, 3) +
             (gp_calibrated(state) ? std::string(" (calibrated)")
                                   : std::string(" <span class=\"stale\">not calibrated: the stated sd does not "
                                                 "describe the runs held out</span>")) +
             "<br>";
    }
    return out;
  }
  if (!surface.has_standard_deviation())
    return "states no standard deviation (stored by an older hydrocoef: surface rebuild gives it one)";
  out += "stated sd² = (runs' uncertainty interpolated)² + leave-one-out RMS²; leave-one-out part:<br>";
  const auto& loo = surface.loo_standard_deviation();
  for (std::size_t k = 0; k < surface.output_count() && k < loo.size(); ++k)
    out += html_escape(surface.output_names()[k]) + ": " + num(loo[k], 4) + " " +
           html_escape(surface.output_units()[k]) + "<br>";
  return out;
}

void write_sigma_maps(Page& page, RunDatabase& database, const SurfaceRecord& record,
                      const std::vector<std::string>& outputs) {
  bool states = false;
  try {
    states = surface_from_record(record).has_standard_deviation();
  } catch (const InputError&) {
    return;  // the surface's own figure says why it cannot be drawn
  }
  if (!states) {
    page.html << "<p class=\"note\">" << html_escape(record.name)
              << " states no standard deviation: no sigma map.</p>\n";
    return;
  }
  for (std::size_t k = 0; k < outputs.size() && k < 6; ++k) {
    const std::string& output = outputs[k];
    if (page.figure(report::plot_file_stem("sigma", record.name + (outputs.size() > 1 ? "-" + output : std::string())),
                    "standard deviation of surface " + record.name + ", output " + output + " over its range",
                    [&] { return plot::surface_sigma_figure(database, record.name, output); }))
      ++page.result().sigma_maps;
  }
}

void write_mesh_studies(Page& page, const std::vector<NumericalUncertaintyRecord>& studies) {
  auto& h = page.html;
  h << "<section id=\"gci\"><h2>Mesh studies</h2>\n";
  if (studies.empty()) {
    h << "<p>No mesh study stored (hydrocoef gci).</p>\n</section>\n";
    return;
  }
  h << "<p>Grid convergence index (Celik et al. 2008, safety factor 1.25) of each key's three finest meshes, fine "
       "(1) to coarse (3); u<sub>num</sub> = GCI<sub>fine</sub> |φ<sub>1</sub>| / 2, the standard uncertainty "
       "applied to the runs on the finest mesh.</p>\n"
       "<div class=\"scroll\"><table><thead><tr><th>key</th><th>F</th><th>mesh levels</th><th>h1, h2, h3 [m]</th>"
       "<th>φ1, φ2, φ3</th><th>convergence</th><th>p</th><th>φ<sub>ext</sub></th><th>e<sub>a</sub></th>"
       "<th>e<sub>ext</sub></th><th>GCI<sub>fine</sub></th><th>u<sub>num</sub></th><th>note</th></tr></thead>"
       "<tbody>\n";
  auto optional = [](const std::optional<double>& v, int digits) { return v ? num(*v, digits) : std::string("–"); };
  for (const auto& s : studies) {
    const std::size_t c = std::min<std::size_t>(s.component, 5);
    h << "<tr class=\"gci-row\"><td>" << html_escape(describe(s.key)) << "</td><td>" << kForceNames[c] << "</td><td>"
      << html_escape(s.mesh_parameter) << " (finest " << num(s.fine_level) << "), " << s.levels
      << " levels</td><td class=\"num\">" << num(s.h[0], 4) << ", " << num(s.h[1], 4) << ", " << num(s.h[2], 4)
      << "</td><td class=\"num\">" << num(s.phi[0]) << ", " << num(s.phi[1]) << ", " << num(s.phi[2]) << " "
      << kUnits[c] << "</td><td>" << html_escape(s.convergence) << "</td><td class=\"num\">"
      << optional(s.apparent_order, 4) << "</td><td class=\"num\">" << optional(s.extrapolated, 6)
      << "</td><td class=\"num\">" << optional(s.relative_error, 3) << "</td><td class=\"num\">"
      << optional(s.extrapolated_relative_error, 3) << "</td><td class=\"num\">" << optional(s.gci_fine, 3)
      << "</td><td class=\"num\">" << optional(s.numerical_uncertainty, 3) << "</td><td>" << html_escape(s.note)
      << "</td></tr>\n";
  }
  h << "</tbody></table></div>\n</section>\n";
  page.result().mesh_study_rows = studies.size();
}

}  // namespace hydrocoef::report::detail
