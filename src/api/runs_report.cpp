// What `hydrocoef runs` prints (RunTable::text, json, csv) and `runs show`
// (RunDetails): the runs table, CSV and JSON, and one run with its provenance.
#include "src/api/internal.hpp"
#include "src/api/records_format.hpp"
#include "src/api/records_report.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/sign_convention.hpp"

#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace hydrocoef {
namespace records {
namespace {

/// A table cell of at least `width` characters that never runs into the next
/// one: a longer text ("4.94066e-324", a long body name) gets one space after it.
std::string cell(const std::string& text, std::size_t width) {
  return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

nlohmann::json import_json(const ImportRecord& record) {
  nlohmann::json out = {{"import_id", record.id},
                        {"path", record.path},
                        {"resolved_path", record.resolved_path},
                        {"sha256", record.sha256},
                        {"size_bytes", record.size_bytes},
                        {"reading", record.reading},
                        {"importer", record.importer},
                        {"importer_version", record.importer_version},
                        {"hydrocoef_version", record.hydrocoef_version},
                        {"imported_at", record.imported_at}};
  const auto settings = nlohmann::json::parse(record.settings.empty() ? "{}" : record.settings, nullptr, false);
  out["settings"] = settings.is_discarded() ? nlohmann::json(record.settings) : settings;
  return out;
}

/// One run as JSON: key, fluid, reference point, forces with statistics, flags.
nlohmann::json run_json(const StoredRun& run) {
  nlohmann::json out = key_json(run.key);
  out["id"] = run.id;
  out["density"] = run.fluid.density_kg_m3 ? nlohmann::json(*run.fluid.density_kg_m3) : nlohmann::json();
  out["kinematic_viscosity"] =
      run.fluid.kinematic_viscosity_m2_s ? nlohmann::json(*run.fluid.kinematic_viscosity_m2_s) : nlohmann::json();
  out["reference_point"] = run.reference_point_b;
  out["forces"] = nlohmann::json::object();
  for (std::size_t i = 0; i < 6; ++i) {
    if (!run.tau_b[i]) continue;
    const auto& f = *run.tau_b[i];
    out["forces"][std::string(kForceNames[i])] = {
        {"total", f.value.total},
        {"pressure", f.value.pressure ? nlohmann::json(*f.value.pressure) : nlohmann::json()},
        {"viscous", f.value.viscous ? nlohmann::json(*f.value.viscous) : nlohmann::json()},
        {"sign_convention", std::string(to_string(f.sign))},
        {"source", f.source_path},
        {"source_line", f.source_line},
        {"given_uncertainty", f.value.uncertainty ? nlohmann::json(*f.value.uncertainty) : nlohmann::json()},
        {"numerical_uncertainty",
         f.numerical_uncertainty ? nlohmann::json(*f.numerical_uncertainty) : nlohmann::json()},
        {"standard_uncertainty", f.standard_uncertainty()}};
    if (f.statistics) {
      const auto& st = *f.statistics;
      out["forces"][std::string(kForceNames[i])]["statistics"] = {{"abscissa", st.abscissa},
                                                                  {"window_method", st.window_method},
                                                                  {"window", {st.window_first, st.window_last}},
                                                                  {"samples", st.samples},
                                                                  {"standard_error", st.values.standard_error},
                                                                  {"spread", st.values.spread},
                                                                  {"drift", st.values.drift},
                                                                  {"effective_samples", st.values.effective_samples},
                                                                  {"flags", st.flags},
                                                                  {"convergence", st.convergence}};
      out["convergence"] = st.convergence;
      out["convergence_reason"] = st.convergence_reason;
    }
  }
  out["flags"] = run_flags(run);
  return out;
}

std::string runs_json(const std::vector<StoredRun>& runs) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& run : runs) out.push_back(run_json(run));
  return escape::json_text(out, 2) + '\n';
}

std::string runs_csv(const std::vector<StoredRun>& runs) {
  std::set<std::string> disturbance_names;
  for (const auto& run : runs)
    for (const auto& [name, value] : run.key.disturbances) disturbance_names.insert(name);
  std::string out = "id,body";
  for (const auto name : kVelocityNames) out += "," + std::string(name);
  for (const auto& name : disturbance_names) out += "," + escape::csv_text(name);
  for (const auto name : kForceNames) out += "," + std::string(name);
  out += ",sources\n";
  for (const auto& run : runs) {
    out += std::to_string(run.id) + "," + escape::csv_text(run.key.body);
    // Numbers are appended in place (GCC 12 at -O3 warned falsely on "," + a temporary string here).
    for (const double v : run.key.nu_b) {
      out += ',';
      append_shortest_number(out, v);
    }
    for (const auto& name : disturbance_names) {
      out += ',';
      if (const auto found = run.key.disturbances.find(name); found != run.key.disturbances.end())
        append_shortest_number(out, found->second);
    }
    std::set<std::string> sources;
    for (const auto& force : run.tau_b) {
      out += ',';
      if (!force) continue;
      // Forces on the body: a damping magnitude as tabulated is negated.
      append_shortest_number(out, to_on_body(force->value.total, force->sign));
      sources.insert(force->source_path);
    }
    std::string list;
    for (const auto& source : sources) list += (list.empty() ? "" : ";") + source;
    out += "," + escape::csv_text(list) + "\n";
  }
  return out;
}

std::string runs_table(const std::vector<StoredRun>& runs, const std::optional<std::string>& body,
                       const std::string& database) {
  if (runs.empty())
    return "no runs" + (body ? " of body '" + escape::one_line(*body) + "'" : std::string()) + " in " +
           escape::one_line(database) + '\n';
  // Only the velocity and force columns some run uses are shown.
  std::array<bool, 6> velocity_used{}, force_used{};
  bool any_history = false, any_tabulated = false;
  for (const auto& run : runs)
    for (const auto& force : run.tau_b) {
      any_history = any_history || (force && force->statistics);
      any_tabulated = any_tabulated || (force && force->sign == SignConvention::OpposingMotion);
    }
  for (const auto& run : runs)
    for (std::size_t i = 0; i < 6; ++i) {
      velocity_used[i] = velocity_used[i] || run.key.nu_b[i] != 0.0;
      force_used[i] = force_used[i] || run.tau_b[i].has_value();
    }
  std::ostringstream table;
  table << std::left << std::setw(6) << "id" << std::setw(12) << "body";
  for (std::size_t i = 0; i < 6; ++i)
    if (velocity_used[i]) table << std::setw(11) << kVelocityNames[i];
  for (std::size_t i = 0; i < 6; ++i)
    if (force_used[i]) table << std::setw(13) << kForceNames[i];
  if (any_history) table << std::setw(12) << "history";
  table << "disturbances\n";
  for (const auto& run : runs) {
    table << cell(std::to_string(run.id), 6) << cell(escape::one_line(run.key.body), 12);
    for (std::size_t i = 0; i < 6; ++i)
      if (velocity_used[i]) table << cell(significant(run.key.nu_b[i], 6), 11);
    for (std::size_t i = 0; i < 6; ++i) {
      if (!force_used[i]) continue;
      std::string text = run.tau_b[i] ? significant(run.tau_b[i]->value.total, 6) : "-";
      if (run.tau_b[i] && run.tau_b[i]->sign == SignConvention::OpposingMotion) text += "*";
      table << cell(text, 13);
    }
    if (any_history) {
      // A run averaged from a force history: "ok" when it converged, else its flags.
      bool averaged = false;
      for (const auto& force : run.tau_b) averaged = averaged || (force && force->statistics);
      std::string flags;
      for (const auto& flag : run_flags(run)) flags += (flags.empty() ? "" : ",") + flag;
      std::string kind;
      for (const auto& force : run.tau_b)
        if (force && force->statistics && !force->statistics->convergence.empty())
          kind = force->statistics->convergence;
      table << cell(escape::one_line(!averaged             ? "-"
                                     : !flags.empty()      ? flags
                                     : kind == "converged" ? "converged"
                                                           : "ok"),
                    12);
    }
    std::string disturbances;
    for (const auto& [name, value] : run.key.disturbances)
      disturbances += (disturbances.empty() ? "" : " ") + name + "=" + significant(value, 6);
    table << escape::one_line(disturbances) << '\n';
  }
  table << runs.size() << (runs.size() == 1 ? " run" : " runs") << "; SI units (m/s, rad/s, N, N m); forces on the body"
        << (any_tabulated ? "; * = as tabulated, positive opposes motion" : "")
        << (any_history ? "; history: from a force history, 'converged' when its solver met the case's criteria (final "
                          "iterate), 'ok' for a window mean with nothing to act on, else its flags ('runs show ID' "
                          "gives the windows, standard errors and why)"
                        : "")
        << '\n';
  return table.str();
}

std::string run_text(const StoredRun& run, const std::map<std::int64_t, ImportRecord>& imports) {
  std::ostringstream out;
  // Text read back from the database (bodies, paths, versions, flags) is printed through escape::one_line.
  out << "run " << run.id << ": " << escape::one_line(describe(run.key)) << '\n';
  out << "  fluid: rho "
      << (run.fluid.density_kg_m3 ? significant(*run.fluid.density_kg_m3, 6) + " kg m^-3" : "not given") << ", nu "
      << (run.fluid.kinematic_viscosity_m2_s ? significant(*run.fluid.kinematic_viscosity_m2_s, 6) + " m^2 s^-1"
                                             : "not given")
      << "; moment reference point (" << significant(run.reference_point_b[0], 6) << ", "
      << significant(run.reference_point_b[1], 6) << ", " << significant(run.reference_point_b[2], 6)
      << ") m, body axes\n";
  for (std::size_t i = 0; i < 6; ++i) {
    if (!run.tau_b[i]) continue;
    const auto& f = *run.tau_b[i];
    out << "  " << kForceNames[i] << " = " << significant(f.value.total, 8) << (i < 3 ? " N" : " N m") << " ("
        << to_string(f.sign) << "), from " << escape::one_line(f.source_path)
        << (f.source_line ? ":" + std::to_string(f.source_line) : "")
        << (f.import_id ? ", import " + std::to_string(f.import_id) : std::string()) << '\n';
    if (f.statistics) {
      const auto& st = *f.statistics;
      const std::string unit = i < 3 ? " N" : " N m";
      std::string flags;
      for (const auto& flag : st.flags) flags += (flags.empty() ? "" : ", ") + flag;
      if (st.convergence == "converged")
        out << "      final iterate, " << escape::one_line(st.abscissa) << " " << significant(st.window_last, 8)
            << ": iterative error " << significant(st.values.standard_error, 3) << unit << " (change per "
            << "iteration " << significant(st.values.drift, 3) << unit << ", fluctuation "
            << significant(st.values.spread, 3) << unit << ")\n";
      else
        out << "      mean over " << escape::one_line(st.abscissa) << " " << significant(st.window_first, 8) << " to "
            << significant(st.window_last, 8) << " (" << st.samples << " samples, "
            << escape::one_line(st.window_method) << "): standard error " << significant(st.values.standard_error, 3)
            << unit << " (" << significant(st.values.effective_samples, 3) << " effective samples), spread "
            << significant(st.values.spread, 3) << unit << ", drift " << significant(st.values.drift, 3) << unit
            << (flags.empty() ? "" : ", flags: " + escape::one_line(flags)) << '\n';
    }
  }
  for (const auto& force : run.tau_b)
    if (force && force->statistics) {
      const auto& st = *force->statistics;
      out << "  convergence: "
          << (st.convergence.empty()
                  ? std::string("not recorded (imported by an older hydrocoef)")
                  : escape::one_line(st.convergence) + (st.convergence_reason.empty()
                                                            ? std::string()
                                                            : ": " + escape::one_line(st.convergence_reason)))
          << '\n';
      break;
    }
  for (const auto& [id, record] : imports) {
    // One line of database text: every field through escape::one_line at once.
    out << "  import " << id << ": "
        << escape::one_line(
               record.path + " (" + (record.resolved_path.empty() ? "path not resolved" : record.resolved_path) +
               "), sha256 " + record.sha256.substr(0, 16) + "..., " + record.importer + " " + record.importer_version +
               ", hydrocoef " + (record.hydrocoef_version.empty() ? "(older)" : record.hydrocoef_version) + ", " +
               record.imported_at + (record.reading.empty() ? "" : ", reading '" + record.reading + "'"))
        << '\n';
    const auto settings = nlohmann::json::parse(record.settings.empty() ? "{}" : record.settings, nullptr, false);
    if (settings.is_object())
      for (const auto& [name, setting] : settings.items())
        if (setting.is_object())
          out << "    " << escape::one_line(name) << " = "
              << escape::json_text(setting.value("value", nlohmann::json())) << "  ("
              << escape::one_line(setting.value("source", std::string()))
              << (setting.contains("where") ? ": " + escape::one_line(setting.value("where", std::string())) : "")
              << ")\n";
  }
  return out.str();
}

}  // namespace

RunDetails run_details(const StoredRun& run, const std::map<std::int64_t, ImportRecord>& imports) {
  RunDetails details;
  details.id = run.id;
  details.body = run.key.body;
  details.velocity = run.key.nu_b;
  details.disturbances = std::map<std::string, double>(run.key.disturbances.begin(), run.key.disturbances.end());
  details.density = run.fluid.density_kg_m3.value_or(kNaN);
  details.kinematic_viscosity = run.fluid.kinematic_viscosity_m2_s.value_or(kNaN);
  for (std::size_t i = 0; i < 3; ++i) details.reference_point[i] = run.reference_point_b[i];
  for (std::size_t i = 0; i < 6; ++i) {
    details.force[i] = kNaN;
    details.force_std_error[i] = kNaN;
    if (!run.tau_b[i]) continue;
    const auto& f = *run.tau_b[i];
    details.force[i] = f.value.total;
    if (f.statistics) details.force_std_error[i] = f.statistics->values.standard_error;
    details.sign_convention[i] = std::string(to_string(f.sign));
    details.source[i] = f.source_path;
  }
  details.flags = run_flags(run);
  for (const auto& [id, record] : imports)
    details.imports.push_back({id, record.path, record.sha256, record.importer, record.imported_at, record.reading});

  nlohmann::json json = run_json(run);
  json["imports"] = nlohmann::json::array();
  for (const auto& [id, record] : imports) json["imports"].push_back(import_json(record));
  RunDetails::Access::set(details, run_text(run, imports), escape::json_text(json, 2) + '\n');
  return details;
}

}  // namespace records

inline namespace api {

const RunTable::Rendering& RunTable::Access::rendering(const RunTable& table) {
  if (!table.rendering_)
    throw std::invalid_argument("hydrocoef::RunTable: text(), json() and csv() need a table made by Database::runs");
  return *table.rendering_;
}

std::string RunTable::text() const {
  const auto& r = Access::rendering(*this);
  return records::runs_table(r.runs, r.body, r.database);
}
std::string RunTable::json() const { return records::runs_json(Access::rendering(*this).runs); }
std::string RunTable::csv() const { return records::runs_csv(Access::rendering(*this).runs); }

std::string RunDetails::text() const { return text_; }
std::string RunDetails::json() const { return json_; }

}  // namespace api
}  // namespace hydrocoef
