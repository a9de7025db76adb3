// `hydrocoef report` (include/hydrocoef/records.hpp): the self-contained HTML
// page of a database (src/report/report.hpp) and what the command prints.
#include "hydrocoef/records.hpp"
#include "src/api/internal.hpp"
#include "src/core/escape.hpp"

#include <nlohmann/json.hpp>
#include "src/report/report.hpp"

#include <sstream>

namespace hydrocoef {
inline namespace api {

void ReportOptions::validate() const {
  if (output.empty()) throw InputError("report: expected the directory to write the report into (-o DIR)");
  (void)parse_selection(where, exclude_runs);
}

ReportSummary write_report(const Database& database, const ReportOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.open_store();
  report::ReportOptions report_options;
  if (!options.body.empty()) report_options.body = options.body;
  report_options.selection = parse_selection(options.where, options.exclude_runs);
  for (const auto& t : options.trajectories) report_options.trajectories.emplace_back(t);
  if (!options.experiment.empty()) report_options.experiment = options.experiment;
  report_options.component = options.component;
  const auto result = report::write_report(store, options.output, report_options);
  ReportSummary out;
  out.database = impl.path;
  out.index = result.index.string();
  for (const auto& plot : result.plots) out.plots.push_back(plot.string());
  out.notes = result.notes;
  out.runs = result.runs;
  out.fits = result.fits;
  out.surfaces = result.surfaces;
  out.histories = result.histories;
  out.sigma_maps = result.sigma_maps;
  out.mesh_study_rows = result.mesh_study_rows;
  out.pmm_fits = result.pmm_fits;
  return out;
}

std::string ReportSummary::json() const {
  nlohmann::json out = {{"index", index},
                        {"runs", runs},
                        {"fits", fits},
                        {"surfaces", surfaces},
                        {"histories", histories},
                        {"sigma_maps", sigma_maps},
                        {"mesh_study_rows", mesh_study_rows},
                        {"pmm_fits", pmm_fits},
                        {"notes", notes},
                        {"plots", plots}};
  return escape::json_text(out, 2) + '\n';
}

std::string ReportSummary::text() const {
  // The database's name, the paths and the notes (which quote names from
  // the database) are printed through escape::one_line.
  std::ostringstream out;
  out << "report of " << escape::one_line(database) << ": " << runs << " runs (" << histories
      << " force histories drawn), " << fits << " fits, " << surfaces << " surfaces (" << sigma_maps << " sigma maps), "
      << mesh_study_rows << " mesh-study rows, " << pmm_fits << " forced-oscillation fits, " << plots.size()
      << " plots\n  page " << escape::one_line(index)
      << " (self-contained: open it in any browser, no network needed)\n  plots and their values in "
      << escape::one_line((std::filesystem::path(index).parent_path() / "plots").string()) << "\n";
  for (const auto& note : notes) out << "  note: " << escape::one_line(note) << '\n';
  return out.str();
}

}  // namespace api
}  // namespace hydrocoef
