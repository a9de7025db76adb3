#include "src/report/report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

#include "src/core/atomic_file.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/source_file.hpp"
#include "src/fit/fit_names.hpp"
#include "src/plot/plots.hpp"
#include "src/plot/pmm_plot.hpp"
#include "src/pmm/added_mass_assembly.hpp"
#include "src/pmm/imposed_motion.hpp"
#include "src/report/quality_sections.hpp"
#include "src/report/report_page.hpp"
#include "src/store/pmm_record.hpp"
#include "src/surface/stored_surface.hpp"
#include "src/surface/surface_builder.hpp"

namespace hydrocoef::report {

std::string plot_file_stem(const std::string& kind, const std::string& name) {
  // Sanitizing alone maps "S 1" and "S_1" to one file and lets a long
  // non-ASCII name outgrow NAME_MAX; a hash of the whole name keeps them apart.
  constexpr std::size_t kPrefixBytes = 60;
  std::string out = kind + "-";
  for (char c : name) {
    if (out.size() >= kind.size() + 1 + kPrefixBytes) break;
    out += (std::isalnum(static_cast<unsigned char>(c)) && static_cast<unsigned char>(c) < 0x80) || c == '-' ? c : '_';
  }
  return out + "-" + sha256_hex(name).substr(0, 12);
}

namespace {

using detail::num;
using detail::Page;

constexpr const char* kStyle = R"css(
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;margin:0 auto;max-width:1100px;padding:0 1.2em 3em;color:#222;line-height:1.4}
h1{font-size:1.6em;margin-top:1em}h2{border-bottom:2px solid #0072B2;padding-bottom:.2em;margin-top:2em}
h3{font-size:1.05em;margin-bottom:.3em}
nav a{margin-right:1em}
.scroll{overflow-x:auto;max-height:32em;overflow-y:auto;border:1px solid #ddd}
table{border-collapse:collapse;font-size:.9em;width:100%}
th,td{padding:.25em .6em;border-bottom:1px solid #eee;text-align:left;vertical-align:top}
th{background:#f4f6f8;position:sticky;top:0}
td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
figure{margin:1em 0}figure img{max-width:100%;height:auto;border:1px solid #eee}
figcaption{font-size:.85em;color:#555}
.stale{color:#b00;font-weight:bold}.note{color:#555;font-size:.9em}
code{background:#f4f6f8;padding:0 .2em}
)css";

// Records script errors and broken images inside the page itself, so a
// headless browser's DOM dump shows them.
constexpr const char* kCheckScript = R"js(
window.addEventListener('error', function (e) {
  var list = document.getElementById('js-errors');
  var item = document.createElement('li');
  item.className = 'js-error';
  item.textContent = (e.message || 'resource failed to load') + (e.filename ? ' at ' + e.filename + ':' + e.lineno : '');
  list.appendChild(item);
}, true);
window.addEventListener('load', function () {
  var images = document.images, broken = 0;
  for (var i = 0; i < images.length; ++i) if (!images[i].complete || images[i].naturalWidth === 0) ++broken;
  var status = document.getElementById('report-status');
  status.setAttribute('data-images', String(images.length));
  status.setAttribute('data-broken-images', String(broken));
  status.setAttribute('data-ready', 'yes');
});
)js";

/// The stored leave-one-out figures of a surface, per output in its unit.
std::string quality_html(const SurfaceRecord& surface) {
  nlohmann::json q;
  try {
    q = nlohmann::json::parse(surface.quality.empty() ? "{}" : surface.quality);
  } catch (const nlohmann::json::exception&) {
    return html_escape(surface.quality);
  }
  if (!q.is_object()) return html_escape(surface.quality);
  std::vector<std::string> units;
  std::vector<std::string> names;
  try {
    const auto built = surface_from_record(surface);
    names = built.output_names();
    units = built.output_units();
  } catch (const InputError&) {}
  std::ostringstream out;
  const std::string method = q.value("loo_method", "");
  out << "leave-one-out (" << loo_method_description(method) << ", " << q.value("loo_defined", 0) << " of "
      << q.value("runs", 0) << " runs):<br>";
  if (q.contains("outputs") && q["outputs"].is_object())
    for (const auto& item : q["outputs"].items()) {
      const std::string name = item.key();
      const nlohmann::json& entry = item.value();
      auto figure = [&](const char* key) {
        return entry.contains(key) && entry[key].is_number() ? num(entry[key].get<double>(), 4) : std::string("n/a");
      };
      const auto at = std::find(names.begin(), names.end(), name);
      const std::string unit = at == names.end() ? "" : " " + units[static_cast<std::size_t>(at - names.begin())];
      out << html_escape(name) << ": max " << figure("loo_max") << ", RMS " << figure("loo_rms") << html_escape(unit)
          << "<br>";
    }
  if (q.contains("far_from_data") && q["far_from_data"].is_array())
    out << q["far_from_data"].size() << " of " << q.value("grid_points", 0) << " grid points far from every run<br>";
  return out.str();
}

}  // namespace

std::string html_escape(std::string_view text) { return escape::html_text(text); }

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

ReportResult write_report(RunDatabase& database, const std::filesystem::path& dir, const ReportOptions& options) {
  RunFilter filter;
  filter.body = options.body;
  const auto bodies = database.bodies();
  if (options.body && std::find(bodies.begin(), bodies.end(), *options.body) == bodies.end()) {
    std::string list;
    for (const auto& b : bodies) list += (list.empty() ? "" : ", ") + b;
    throw InputError("no body '" + *options.body + "' in " + database.path().string() +
                     "; bodies: " + (list.empty() ? "none" : list));
  }
  auto runs = database.runs(filter);
  std::erase_if(runs, [&](const StoredRun& run) { return !options.selection.matches(run.key, run.id); });
  if (runs.empty())
    throw InputError("database " + database.path().string() + " has no runs" +
                     (options.body ? " of body " + *options.body : std::string()) +
                     (options.selection.empty() ? std::string() : " where " + options.selection.text()) +
                     (options.selection.empty() ? ": import CFD results first (hydrocoef import)" : ""));
  auto fits = database.fits(options.body);
  auto surfaces = database.surfaces(options.body);
  ReportResult result;
  if (!options.selection.empty()) {
    // Fits and surfaces built from the selected runs alone.
    std::set<std::int64_t> selected;
    for (const auto& run : runs) selected.insert(run.id);
    const auto outside = [&](const std::vector<std::int64_t>& ids) {
      return std::any_of(ids.begin(), ids.end(), [&](std::int64_t id) { return !selected.count(id); });
    };
    const std::size_t all_fits = fits.size(), all_surfaces = surfaces.size();
    std::erase_if(fits, [&](const FitRecord& fit) { return outside(fit.run_ids); });
    std::erase_if(surfaces, [&](const SurfaceRecord& surface) { return outside(surface.run_ids); });
    if (all_fits + all_surfaces > fits.size() + surfaces.size())
      result.notes.push_back("runs where " + options.selection.text() + ": " + std::to_string(all_fits - fits.size()) +
                             " fits and " + std::to_string(all_surfaces - surfaces.size()) +
                             " surfaces built from other runs too are left out");
  }

  result.runs = runs.size();
  result.fits = fits.size();
  result.surfaces = surfaces.size();
  std::error_code ec;
  std::filesystem::create_directories(dir / "plots", ec);
  if (ec) throw InputError((dir / "plots").string() + ": cannot create the directory (" + ec.message() + ")");
  result.index = std::filesystem::absolute(dir / "index.html");
  Page page(std::filesystem::absolute(dir / "plots"), result);
  auto& h = page.html;
  const std::string title = "hydrocoef report: " + database.path().filename().string() +
                            (options.body ? " (" + *options.body + ")" : std::string());

  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
       "<meta name=\"viewport\" content=\"width=device-width, "
       "initial-scale=1\">\n<title>"
    << html_escape(title) << "</title>\n<style>" << kStyle << "</style>\n<script>" << kCheckScript
    << "</script>\n</head><body>\n";
  h << "<h1>" << html_escape(title) << "</h1>\n";
  h << "<nav><a href=\"#runs\">Runs</a><a href=\"#quality\">Run quality</a><a href=\"#fits\">Fits</a><a "
       "href=\"#surfaces\">Surfaces</a><a href=\"#gci\">Mesh studies</a>"
       "<a href=\"#pmm\">Forced oscillation</a><a href=\"#simulations\">Simulations</a></nav>\n";

  // ---- summary
  h << "<section id=\"summary\"><h2>Summary</h2>\n<p>Database <code>" << html_escape(database.path().string())
    << "</code>: " << runs.size() << " runs, " << fits.size() << " fits, " << surfaces.size()
    << " surfaces. Body axes x forward, y starboard, z down (SNAME); SI units; "
       "velocities u, v, w in m/s and p, q, r "
       "in rad/s; forces X, Y, Z in N and moments K, M, N in N m. Each fit "
       "states its sign convention "
       "(<em>on-body</em>: the force of the fluid on the body, damping "
       "negative; <em>opposing</em>: a damping "
       "magnitude, positive opposes motion); surfaces hold forces on the "
       "body.</p>\n";
  h << "<div id=\"report-status\" data-ready=\"no\"><ul "
       "id=\"js-errors\"></ul></div>\n</section>\n";

  // ---- runs
  h << "<section id=\"runs\"><h2>Runs</h2>\n<div "
       "class=\"scroll\"><table><thead><tr><th>id</th><th>key</th>";
  for (std::size_t i = 0; i < 6; ++i) h << "<th>" << kForceNames[i] << " [" << kForceUnits[i] << "]</th>";
  h << "<th>source</th></tr></thead><tbody>\n";
  for (std::size_t r = 0; r < runs.size() && r < options.max_run_rows; ++r) {
    const auto& run = runs[r];
    h << "<tr><td class=\"num\">" << run.id << "</td><td>" << html_escape(describe(run.key)) << "</td>";
    std::string source;
    for (const auto& force : run.tau_b) {
      if (!force) {
        h << "<td></td>";
        continue;
      }
      h << "<td class=\"num\">" << num(force->value.total) << (force->sign == SignConvention::OnBody ? "" : " (opp.)")
        << "</td>";
      const std::string file =
          std::filesystem::path(force->source_path).filename().string() + ":" + std::to_string(force->source_line);
      if (source.find(file) == std::string::npos) source += (source.empty() ? "" : " ") + file;
    }
    h << "<td>" << html_escape(source) << "</td></tr>\n";
  }
  h << "</tbody></table></div>\n";
  if (runs.size() > options.max_run_rows)
    h << "<p class=\"note\">" << runs.size() - options.max_run_rows << " more runs not listed.</p>\n";
  h << "</section>\n";

  // ---- run quality: convergence, flags, standard errors, histories
  detail::write_run_quality(page, database, runs, options.max_history_plots);

  // ---- fits
  h << "<section id=\"fits\"><h2>Fits</h2>\n";
  if (fits.empty()) {
    h << "<p>No fits stored (hydrocoef fit).</p>\n";
  } else {
    h << "<div "
         "class=\"scroll\"><table><thead><tr><th>name</th><th>law</"
         "th><th>coefficients (± std. error)</th>"
         "<th>R²</th><th>RMSE</th><th>n</th><th>sign</th><th>runs "
         "used</th></tr></thead><tbody>\n";
    for (const auto& fit : fits) {
      h << "<tr><td>" << html_escape(fit.name) << "</td><td>" << html_escape(fit.dof + "(" + fit.terms + ")")
        << "</td><td>";
      for (const auto& c : fit.coefficients)
        h << html_escape(c.term) << ": " << num(c.value) << (c.std_error ? " ± " + num(*c.std_error, 3) : std::string())
          << "<br>";
      const std::size_t dof = force_index(fit.dof).value_or(0);
      h << "</td><td class=\"num\">" << num(fit.r2, 8) << "</td><td class=\"num\">" << num(fit.rmse, 4) << " "
        << kForceUnits[dof] << "</td><td class=\"num\">" << fit.n << "</td><td>" << to_string(fit.sign) << "</td><td>"
        << html_escape(fit.run_filter.empty() ? "all of " + fit.body : fit.run_filter) << "</td></tr>\n";
    }
    h << "</tbody></table></div>\n";
    std::map<std::string, std::size_t> levels;  // group name -> number of per-level fits in it
    std::vector<std::string> order;
    for (const auto& fit : fits) {
      const std::string g = fit_family_name(fit.name);
      if (std::find(order.begin(), order.end(), g) == order.end()) order.push_back(g);
      if (g != fit.name) ++levels[g];
    }
    for (const auto& g : order) {
      h << "<h3>" << html_escape(g) << "</h3>\n";
      page.figure(plot_file_stem("fit", g), "force against velocity: " + g,
                  [&] { return plot::fit_figure(database, g); });
      if (levels[g] >= 2) {
        const int degree = static_cast<int>(std::min<std::size_t>(2, levels[g] - 1));
        page.figure(
            plot_file_stem("curves", g), "coefficient curves of " + g,
            [&] { return plot::curves_figure(database, g, CurveKind::Polynomial, degree); }, 720);
      }
    }
  }
  h << "</section>\n";

  // ---- surfaces
  h << "<section id=\"surfaces\"><h2>Surfaces</h2>\n";
  if (surfaces.empty()) {
    h << "<p>No surfaces stored (hydrocoef surface build).</p>\n";
  } else {
    h << "<div "
         "class=\"scroll\"><table><thead><tr><th>name</th><th>body</"
         "th><th>kind / method</th><th>runs</th>"
         "<th>leave-one-out quality</th><th>calibration / stated uncertainty</th><th>state</th></tr></thead>"
         "<tbody>\n";
    for (const auto& s : surfaces) {
      h << "<tr><td>" << html_escape(s.name) << "</td><td>" << html_escape(s.body) << "</td><td>" << html_escape(s.kind)
        << " / " << html_escape(s.method) << "</td><td class=\"num\">" << s.run_ids.size() << "</td><td>";
      h << quality_html(s);
      h << "</td><td>" << detail::calibration_html(s) << "</td><td>"
        << (s.stale ? "<span class=\"stale\">stale</span> (rebuild: hydrocoef "
                      "surface rebuild --stale)"
                    : "current")
        << "</td></tr>\n";
    }
    h << "</tbody></table></div>\n";
    for (const auto& s : surfaces) {
      h << "<h3>" << html_escape(s.name) << (s.stale ? " <span class=\"stale\">(stale)</span>" : "") << "</h3>\n";
      std::vector<std::string> outputs;
      try {
        outputs = surface_from_record(s).output_names();
      } catch (const InputError& e) {
        h << "<p class=\"note\">not drawn (" << html_escape(e.what()) << ")</p>\n";
        result.notes.push_back("surface " + s.name + ": " + e.what());
        continue;
      }
      for (std::size_t k = 0; k < outputs.size() && k < 6; ++k) {
        const std::string output = outputs[k];
        page.figure(plot_file_stem("surface", s.name + (outputs.size() > 1 ? "-" + output : std::string())),
                    "surface " + s.name + ", output " + output,
                    [&] { return plot::surface_figure(database, s.name, output); });
      }
      detail::write_sigma_maps(page, database, s, outputs);
    }
  }
  h << "</section>\n";

  // ---- mesh studies (hydrocoef gci)
  detail::write_mesh_studies(page, database.numerical_uncertainties(options.body));

  // ---- forced oscillation (virtual PMM)
  h << "<section id=\"pmm\"><h2>Forced oscillation</h2>\n";
  const auto pmm = database.pmm_records(options.body);
  result.pmm_fits = pmm.size();
  if (pmm.empty()) {
    h << "<p>No forced-oscillation runs stored (hydrocoef pmm).</p>\n";
  } else {
    h << "<p>Added mass and damping in body axes from harmonic fits over whole periods after the start-up "
         "transient; F = −M<sub>A</sub> ẍ − D ẋ on the body; ± standard errors from the period-to-period spread."
         "</p>\n<div class=\"scroll\"><table><thead><tr><th>body</th><th>motion</th><th>medium</th>"
         "<th>periods kept</th><th>KC</th><th>M<sub>A</sub> (diagonal entry)</th><th>D (diagonal entry)</th>"
         "<th>variance explained</th><th>source</th></tr></thead><tbody>\n";
    for (const auto& r : pmm) {
      const PmmCoefficient* own = nullptr;
      for (const auto& c : r.coefficients)
        if (c.component == r.dof) own = &c;
      h << "<tr><td>" << html_escape(r.body) << "</td><td>" << html_escape(std::string(dof_name(r.dof))) << " "
        << num(r.amplitude, 4) << (r.dof < 3 ? " m" : " rad") << ", T = " << num(2.0 * std::numbers::pi / r.omega, 4)
        << " s</td><td>" << html_escape(pmm_medium_name(r.medium)) << "</td><td class=\"num\">" << r.periods
        << "</td><td class=\"num\">" << (r.keulegan_carpenter ? num(*r.keulegan_carpenter, 3) : "–") << "</td>";
      if (own)
        h << "<td class=\"num\">" << num(own->added_mass, 5) << " ± " << num(own->added_mass_se, 2)
          << "</td><td class=\"num\">" << num(own->damping, 5) << " ± " << num(own->damping_se, 2)
          << "</td><td class=\"num\">" << num(100.0 * own->explained, 5) << " %</td>";
      else
        h << "<td>–</td><td>–</td><td>–</td>";
      h << "<td>" << html_escape(r.source_path) << "</td></tr>\n";
    }
    h << "</tbody></table></div>\n";
    std::vector<std::string> pmm_bodies;
    for (const auto& r : pmm)
      if (std::find(pmm_bodies.begin(), pmm_bodies.end(), r.body) == pmm_bodies.end()) pmm_bodies.push_back(r.body);
    for (const auto& body : pmm_bodies)
      for (const double omega : pmm_frequencies(body, pmm)) {  // a matrix per frequency: never mixed
        AddedMassOptions at_frequency;
        at_frequency.period = 2.0 * std::numbers::pi / omega;
        const AddedMassAssembly a = assemble_added_mass(body, pmm, at_frequency);
        h << "<h3>Added mass of " << html_escape(body) << " at period " << num(*at_frequency.period, 6)
          << " s</h3>\n<div class=\"scroll\"><table><thead><tr><th></th>";
        for (std::size_t j = 0; j < 6; ++j) h << "<th>" << dof_name(j) << "</th>";
        h << "</tr></thead><tbody>\n";
        for (std::size_t i = 0; i < 6; ++i) {
          h << "<tr><th>" << dof_name(i) << "</th>";
          for (std::size_t j = 0; j < 6; ++j) {
            const auto ii = static_cast<Eigen::Index>(i), jj = static_cast<Eigen::Index>(j);
            h << "<td class=\"num\">"
              << (a.known[i][j]
                      ? num(a.added_mass(ii, jj), 5) +
                            (a.added_mass_se(ii, jj) > 0.0 ? " ± " + num(a.added_mass_se(ii, jj), 2) : std::string())
                      : std::string("missing"))
              << "</td>";
          }
          h << "</tr>\n";
        }
        h << "</tbody></table></div>\n<p>kg, kg m, kg m² (hydrocoef added-mass " << html_escape(body) << " --period "
          << num(*at_frequency.period, 6) << "); "
          << (a.positive_definite ? "positive definite" : "not positive definite")
          << " over the measured degrees of freedom";
        if (!a.missing.empty()) h << "; " << a.missing.size() << " entries missing (no run of their DOF)";
        h << ".</p>\n";
      }
    for (const auto& r : pmm)
      page.figure(plot_file_stem("pmm", r.body + "-" + std::string(dof_name(r.dof)) + "-" + std::to_string(r.id)),
                  "force history and harmonic fit: " + r.body + ", " + std::string(dof_name(r.dof)) + " run " +
                      std::to_string(r.id),
                  [&] { return plot::pmm_figure(r); });
  }
  h << "</section>\n";

  // ---- simulations
  h << "<section id=\"simulations\"><h2>Simulations</h2>\n";
  if (options.trajectories.empty())
    h << "<p>No trajectories given (hydrocoef report --trajectory FILE, from "
         "hydrocoef simulate --out).</p>\n";
  for (const auto& trajectory : options.trajectories) {
    const std::string stem = trajectory.stem().string();
    page.figure(plot_file_stem("simulation", stem + "-" + options.component),
                options.component + " against time: " + trajectory.filename().string(),
                [&] { return plot::simulation_figure(trajectory, options.experiment, options.component); });
  }
  h << "</section>\n";
  h << "<p class=\"note\">Written by hydrocoef; plots drawn by gnuplot; this "
       "page needs no network access.</p>\n"
       "</body></html>\n";

  write_file_atomically(result.index, h.str());
  return result;
}

}  // namespace hydrocoef::report
