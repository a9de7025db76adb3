// export_forcecoeffs (include/hydrocoef/exports.hpp): `hydrocoef export
// --format openfoam-forcecoeffs`, each selected run's forces as OpenFOAM's
// forceCoeffs coefficient.dat (src/export/openfoam_forcecoeffs), in the
// case's axes the run was imported with, and what the command prints.
#include "src/api/internal.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "hydrocoef/exports.hpp"
#include "src/core/atomic_file.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/sign_convention.hpp"
#include "src/export/openfoam_forcecoeffs.hpp"
#include "src/loads/force_coefficients.hpp"
#include "src/loads/frame.hpp"
#include "src/store/body_reference.hpp"

namespace hydrocoef {
inline namespace api {

void ForceCoeffsExportOptions::validate() const {
  if (output.empty())
    throw InputError("--format openfoam-forcecoeffs writes one file per run into a folder; expected -o FOLDER");
  (void)parse_selection(where, exclude_runs);
  if (!axes.empty()) {
    try {
      (void)parse_axes(axes);
    } catch (const InputError& e) {
      throw InputError(std::string("--axes: ") + e.what());
    }
  }
  if (precision < 1 || precision > 16)
    throw InputError("--precision " + std::to_string(precision) +
                     ": expected 1 to 16 digits after the point (16: every double exactly; OpenFOAM's default "
                     "writePrecision is 6)");
}

namespace {

namespace fs = std::filesystem;

std::string quoted(const std::string& name) { return "'" + printable_text(name, 80) + "'"; }

std::string run_name(std::int64_t id) { return "run " + std::to_string(id); }

/// The case's axes of a run: the --axes given, else those recorded with the
/// import of its forces (the identity when that import was given none).
FrameTransform frame_of(RunDatabase& store, const StoredRun& run, const std::string& axes,
                        const SourceLocation& where) {
  if (!axes.empty()) return parse_axes(axes);
  std::optional<FrameTransform> found;
  std::set<std::int64_t> imports;
  for (const auto& component : run.tau_b)
    if (component) imports.insert(component->import_id);
  for (const std::int64_t id : imports) {
    FrameTransform frame;
    const auto record = id > 0 ? store.import_record(id) : std::nullopt;
    if (!record)
      throw InputError(where, run_name(run.id) +
                                  ": no import of its forces is recorded, so the axes it was imported with are not "
                                  "known; give the case's axes with --axes MAP (e.g. -x,y,-z, as import took them)");
    const auto settings = nlohmann::json::parse(record->settings.empty() ? "{}" : record->settings, nullptr, false);
    if (settings.is_object() && settings.contains("axes")) {
      const auto& value = settings["axes"].is_object() ? settings["axes"]["value"] : settings["axes"];
      if (!value.is_string())
        throw InputError(where, run_name(run.id) + ": the axes recorded with import " + std::to_string(id) +
                                    " are not a text; give the case's axes with --axes MAP");
      frame = parse_axes(value.get<std::string>());
    }
    if (settings.is_object() && settings.contains("origin"))
      throw InputError(where, run_name(run.id) + ": import " + std::to_string(id) +
                                  " moved the body origin (--origin); give the case's axes with --axes MAP and the "
                                  "moment point with 'hydrocoef body set NAME --moment-point x,y,z'");
    if (found && found->axes_text() != frame.axes_text())
      throw InputError(where, run_name(run.id) + ": its forces came from imports with different axes (" +
                                  found->axes_text() + " and " + frame.axes_text() +
                                  "); give the case's axes with --axes MAP");
    found = frame;
  }
  return found.value_or(FrameTransform{});
}

struct Reference {
  std::string area_name;
  double area = 0.0, length = 0.0;
  std::optional<std::array<double, 3>> moment_point;
};

Reference reference_of(const std::string& body, const std::map<std::string, BodyReferenceRecord>& records,
                       const std::string& area, const SourceLocation& where) {
  const std::string fix = "; give it with 'hydrocoef body set NAME ";
  const auto found = records.find(body);
  if (found == records.end() || !found->second.length)
    throw InputError(where, "body " + quoted(body) + " has no reference length (forceCoeffs' lRef)" + fix +
                                "--length L' (and a reference area with --area NAME=A)");
  const BodyReferenceRecord& record = found->second;
  if (record.areas.empty())
    throw InputError(where,
                     "body " + quoted(body) + " has no reference area (forceCoeffs' Aref)" + fix + "--area NAME=A'");
  const std::string name = area.empty() ? record.default_area : area;
  std::string names;
  for (const auto& [n, value] : record.areas) names += (names.empty() ? "" : ", ") + quoted(n);
  if (name.empty())
    throw InputError(where, "body " + quoted(body) + " has several reference areas (" + names +
                                ") and no default; choose one with --area NAME");
  const auto a = record.areas.find(name);
  if (a == record.areas.end())
    throw InputError(where,
                     "--area " + quoted(name) + ": body " + quoted(body) + " has no such area (areas: " + names + ")");
  return {name, a->second, *record.length, record.moment_point_b};
}

struct Planned {
  ForceCoeffsExportRun run;
  fs::path file;
  std::string text;
};

}  // namespace

ForceCoeffsExportResult export_forcecoeffs(const Database& db, const ForceCoeffsExportOptions& options) {
  options.validate();
  const RunSelection selection = parse_selection(options.where, options.exclude_runs);
  auto& impl = Database::Access::impl(db);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.open_store();
  const SourceLocation where{impl.path};
  RunFilter filter;
  if (!options.body.empty()) filter.body = options.body;
  auto runs = store.runs(filter);
  std::erase_if(runs, [&](const StoredRun& run) { return !selection.matches(run.key, run.id); });
  if (runs.empty())
    throw InputError(where, "no runs selected; expected at least one run to write (see hydrocoef runs)");
  std::map<std::string, BodyReferenceRecord> records;
  for (auto& record : store.body_references()) records.emplace(record.body, std::move(record));

  ForceCoeffsExportResult out;
  out.database = impl.path;
  out.directory = options.output;
  out.precision = options.precision;
  std::vector<Planned> planned;
  for (const auto& run : runs) {
    const Reference ref = reference_of(run.key.body, records, options.area, where);
    const double rho = run.fluid.density_kg_m3.value_or(kNaN);
    if (!std::isfinite(rho))
      throw InputError(where, run_name(run.id) +
                                  " has no density, and forceCoeffs' coefficients need it; import "
                                  "the run with --rho RHO (or rho in its settings)");
    const double speed = speed_through_water(run.key.nu_b);
    if (!(speed > 0.0))
      throw InputError(where, run_name(run.id) +
                                  " is at rest (U = |(u, v, w)| = 0): no dynamic pressure, no forceCoeffs "
                                  "coefficient; leave it out with --exclude-run " +
                                  std::to_string(run.id));
    std::string missing;
    for (std::size_t c = 0; c < 6; ++c)
      if (!run.tau_b[c]) missing += std::string(missing.empty() ? "" : ", ") + std::string(kForceNames[c]);
    if (!missing.empty())
      throw InputError(where, run_name(run.id) + " has no " + missing +
                                  ": forceCoeffs writes all six components and none is guessed; import them, or leave "
                                  "the run out with --exclude-run " +
                                  std::to_string(run.id));
    const FrameTransform frame = frame_of(store, run, options.axes, where);
    const std::array<double, 3> point = ref.moment_point.value_or(run.reference_point_b);

    // Rows in body axes, forces on the body, moments about the run's point.
    std::vector<double> time;
    std::array<std::vector<double>, 6> body;
    const auto trace = store.run_trace(run.id);
    bool whole = trace && !options.mean_only && trace->samples == trace->abscissa.size();
    if (whole)
      for (std::size_t c = 0; c < 6; ++c)
        whole = whole && trace->low[c].size() == trace->samples && trace->low[c] == trace->high[c];
    if (whole) {
      time = trace->abscissa;
      for (std::size_t c = 0; c < 6; ++c) body[c] = trace->low[c];
    } else {
      double end = 0.0;
      if (trace && !trace->abscissa.empty())
        end = trace->abscissa.back();
      else if (run.tau_b[0]->statistics)
        end = run.tau_b[0]->statistics->window_last;
      time = {end};
      for (std::size_t c = 0; c < 6; ++c) body[c] = {to_on_body(run.tau_b[c]->value.total, run.tau_b[c]->sign)};
    }

    ForceCoeffsInput input;
    input.rho = rho;
    input.mag_u_inf = speed;
    input.l_ref = ref.length;
    input.a_ref = ref.area;
    input.precision = options.precision;
    const Vec3 cofr = frame.point_to_cfd(point);
    input.cofr = {cofr[0], cofr[1], cofr[2]};
    input.time = time;
    for (auto& column : input.load) column.reserve(time.size());
    for (std::size_t i = 0; i < time.size(); ++i) {
      const std::array<double, 3> force{body[0][i], body[1][i], body[2][i]};
      std::array<double, 3> moment{body[3][i], body[4][i], body[5][i]};
      if (ref.moment_point) moment = moment_about(moment, force, run.reference_point_b, point);
      const Vec3 f = frame.vector_to_cfd({force[0], force[1], force[2]});
      const Vec3 m = frame.vector_to_cfd({moment[0], moment[1], moment[2]});
      for (std::size_t k = 0; k < 3; ++k) {
        input.load[k].push_back(f[k]);
        input.load[3 + k].push_back(m[k]);
      }
    }
    const std::string axes = frame.axes_text();
    input.comments = {"hydrocoef " + run_name(run.id) + " in the case's axes (body x, y, z = " + axes +
                          " of them), forces on the body, moments about CofR",
                      "C = F / (0.5 rho magUInf^2 Aref), Cm = M / (0.5 rho magUInf^2 Aref lRef), rho " +
                          shortest_number(rho) + " kg/m^3 (import with --rho " + shortest_number(rho) + ")"};
    ForceCoeffsText text;
    try {
      text = openfoam_forcecoeffs(input);
    } catch (const InputError& e) {
      throw InputError(where, run_name(run.id) + ": " + e.what());
    }
    Planned p;
    p.run.id = run.id;
    p.run.body = run.key.body;
    p.run.axes = axes;
    p.run.rows_from = whole ? "history" : "stored forces";
    p.run.rows = time.size();
    p.run.rho = rho;
    p.run.mag_u_inf = speed;
    p.run.l_ref = ref.length;
    p.run.a_ref = ref.area;
    p.run.area_name = ref.area_name;
    p.run.cofr = input.cofr;
    for (std::size_t k = 0; k < 6; ++k) p.run.last_coefficients[k] = text.coefficient[k].back();
    const std::string start = whole ? "0" : openfoam_time_name(time.front());
    p.file = fs::path(options.output) / ("run-" + std::to_string(run.id)) / "postProcessing" / "forceCoeffs" / start /
             "coefficient.dat";
    p.run.file = p.file.string();
    p.text = std::move(text.text);
    out.values += text.values;
    out.exact += text.exact;
    out.one_ulp += text.one_ulp;
    planned.push_back(std::move(p));
  }
  // Everything is checked: now the files, each whole or not at all.
  for (auto& p : planned) {
    std::error_code ec;
    fs::create_directories(p.file.parent_path(), ec);
    if (ec)
      throw InputError(SourceLocation{p.file.parent_path().string()},
                       "cannot make the folder (" + ec.message() + "); expected a folder that can be written");
    write_file_atomically(p.file, p.text);
    out.runs.push_back(std::move(p.run));
  }
  if (out.precision < 16)
    out.notes.push_back("precision " + std::to_string(out.precision) +
                        ": coefficients rounded as OpenFOAM writes them; read back they differ from the stored "
                        "forces in the digits left out");
  else if (out.one_ulp > 0)
    out.notes.push_back(std::to_string(out.one_ulp) + " of " + std::to_string(out.values) +
                        " coefficients read back as the double next to the force (no double coefficient times "
                        "1/2 rho U^2 A gives it); the others as the force itself");
  return out;
}

// ---- text, JSON ---------------------------------------------------------------

namespace {

constexpr std::array<const char*, 6> kCoefficientNames = {"Cd", "Cs", "Cl", "CmRoll", "CmPitch", "CmYaw"};
constexpr const char* kConvention =
    "the case's axes (import's --axes map back), forces on the body, moments about CofR; dragDir, sideDir, liftDir = "
    "x, y, z of the case; C = F / (1/2 rho magUInf^2 Aref), Cm = M / (1/2 rho magUInf^2 Aref lRef)";

}  // namespace

std::string ForceCoeffsExportResult::text() const {
  std::ostringstream out;
  out << "wrote " << runs.size() << " forceCoeffs file" << (runs.size() == 1 ? "" : "s") << " (OpenFOAM v1912 "
      << "coefficient.dat, precision " << precision << ") into " << escape::one_line(directory) << '\n';
  for (const auto& r : runs) {
    out << "run " << r.id << " (body '" << escape::one_line(r.body) << "'): " << escape::one_line(r.file) << ", "
        << r.rows << (r.rows == 1 ? " row" : " rows") << " from its " << r.rows_from << "; axes " << r.axes << ", rho "
        << shortest_number(r.rho) << " kg/m^3, magUInf " << shortest_number(r.mag_u_inf) << " m/s, Aref '"
        << escape::one_line(r.area_name) << "' " << shortest_number(r.a_ref) << " m^2, lRef "
        << shortest_number(r.l_ref) << " m; last row";
    for (std::size_t k = 0; k < 6; ++k)
      out << ' ' << kCoefficientNames[k] << ' ' << significant(r.last_coefficients[k], 8);
    out << '\n';
  }
  out << kConvention << '\n';
  for (const auto& note : notes) out << "note: " << escape::one_line(note) << '\n';
  return out.str();
}

std::string ForceCoeffsExportResult::json() const {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& r : runs) {
    nlohmann::json last = nlohmann::json::object();
    for (std::size_t k = 0; k < 6; ++k) last[kCoefficientNames[k]] = r.last_coefficients[k];
    list.push_back({{"id", r.id},
                    {"body", r.body},
                    {"file", r.file},
                    {"axes", r.axes},
                    {"rows_from", r.rows_from},
                    {"rows", r.rows},
                    {"rho", r.rho},
                    {"magUInf", r.mag_u_inf},
                    {"lRef", r.l_ref},
                    {"Aref", r.a_ref},
                    {"area_name", r.area_name},
                    {"CofR", r.cofr},
                    {"last_coefficients", last}});
  }
  return escape::json_text({{"database", database},
                            {"format", "openfoam-forcecoeffs"},
                            {"directory", directory},
                            {"precision", precision},
                            {"convention", kConvention},
                            {"values", values},
                            {"exact", exact},
                            {"one_ulp", one_ulp},
                            {"runs", list},
                            {"notes", notes}},
                           2) +
         '\n';
}

}  // namespace api
}  // namespace hydrocoef
