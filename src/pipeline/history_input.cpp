// Force histories into runs: an OpenFOAM forces function object (its files,
// its folder or its case), a CFX monitor file or a CSV of time and forces,
// read, brought into body axes with moments about the run's reference point,
// and averaged over the statistically steady window (read_history); or
// handed on unaveraged (read_body_history, for src/pipeline/pmm_runs).
#include <algorithm>
#include <charconv>
#include <cmath>

#include "importers/force_history_csv.hpp"
#include "importers/openfoam_forces.hpp"
#include "src/core/error.hpp"
#include "src/core/source_file.hpp"
#include "src/history/history_trace.hpp"
#include "src/loads/symmetry.hpp"
#include "src/pipeline/import_files_internal.hpp"
#include "src/pipeline/openfoam_case.hpp"
#include "src/pipeline/openfoam_convergence.hpp"

namespace hydrocoef {
namespace reading {
namespace {

namespace fs = std::filesystem;

/// The body component fed by each CFD component under a signed-permutation
/// frame: body[i] = sign[i] * cfd[index[i]].
struct Permutation {
  std::array<std::size_t, 3> index{};
  std::array<double, 3> sign{};
};
Permutation permutation_of(const FrameTransform& frame) {
  Permutation p;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      if (frame.rotation[i][j] != 0.0) p.index[i] = j, p.sign[i] = frame.rotation[i][j];
  return p;
}

HistoryWindow window_of(const RunSettings& settings) {
  const auto text = settings.text("window");
  if (!text || *text == "auto") return HistoryWindow::automatic();
  const std::string where = settings.find("window")->origin.where;
  const auto refuse = [&] {
    throw InputError(where + ": setting 'window' is '" + printable_text(*text, 40) +
                     "'; expected auto, T0:T1 (an abscissa range) or last:N (the last N samples)");
  };
  const auto number = [&](std::string_view part) {
    double value = 0.0;
    if (!part.empty() && part.front() == '+') part.remove_prefix(1);
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (part.empty() || ec != std::errc() || end != part.data() + part.size() || !std::isfinite(value)) refuse();
    return value;
  };
  const auto colon = text->find(':');
  if (colon == std::string::npos) refuse();
  if (text->rfind("last:", 0) == 0) {
    const double count = number(std::string_view(*text).substr(5));
    if (count < 2 || count != std::floor(count) || count > 1e15) refuse();
    return HistoryWindow::last_samples(static_cast<std::size_t>(count));
  }
  const double first = number(std::string_view(*text).substr(0, colon));
  const double last = number(std::string_view(*text).substr(colon + 1));
  if (!(first < last)) refuse();
  return HistoryWindow::range(first, last);
}

/// One provenance record for a history read from one or more files: the
/// SHA-256 of the files' hashes (one file: its own hash) and their sizes.
Provenance history_provenance(const ForceHistory& history, const fs::path& path, std::string_view importer,
                              std::string_view version) {
  Provenance p;
  p.path = path.string();
  p.importer = std::string(importer);
  p.importer_version = std::string(version);
  if (history.files.size() == 1) {
    p.sha256 = history.files.front().sha256;
    p.size_bytes = history.files.front().size_bytes;
    return p;
  }
  std::vector<std::string> lines;
  for (const auto& f : history.files) {
    lines.push_back(f.path.lexically_relative(path).generic_string() + " " + f.sha256);
    p.size_bytes += f.size_bytes;
  }
  std::sort(lines.begin(), lines.end());
  std::string all;
  for (const auto& line : lines) all += line + "\n";
  p.sha256 = sha256_hex(all);
  return p;
}

/// The forces function object of an OpenFOAM case: postProcessing/<name>/
/// holding force files. One is taken; several are refused by name.
fs::path case_forces_folder(const fs::path& case_folder) {
  const fs::path post = case_folder / "postProcessing";
  std::vector<fs::path> found;
  std::error_code ec;
  if (fs::is_directory(post, ec)) {
    for (const auto& entry : fs::directory_iterator(post, ec)) {
      if (!entry.is_directory()) continue;
      bool has_forces = false;
      for (const auto& file : fs::recursive_directory_iterator(entry.path(), ec))
        if (file.is_regular_file() &&
            (is_force_history_name(file.path()) || file.path().filename() == "forceCoeffs.dat")) {
          has_forces = true;
          break;
        }
      if (has_forces) found.push_back(entry.path());
    }
  }
  std::sort(found.begin(), found.end());
  if (found.empty())
    throw InputError(SourceLocation{case_folder.string()},
                     "OpenFOAM case without force output: expected postProcessing/<name>/<time>/force.dat (a forces "
                     "or forceCoeffs function object)");
  if (found.size() > 1) {
    // Several function objects: a forces one is preferred to forceCoeffs.
    std::vector<fs::path> forces;
    for (const auto& f : found)
      if (!fs::exists(f / "0" / "coefficient.dat", ec) && f.filename() != "forceCoeffs") forces.push_back(f);
    if (forces.size() == 1) return forces.front();
    std::string names;
    for (const auto& f : found) names += (names.empty() ? "" : ", ") + f.filename().string();
    throw InputError(SourceLocation{case_folder.string()}, "several function objects write forces (" + names +
                                                               "); expected one, or name the folder to import");
  }
  return found.front();
}

}  // namespace

/// A history's samples turned into the run's frame: moments about the
/// reference point, the mirror images of a half or quarter model added, then
/// rotated into body axes.
ForceHistory history_in_body_axes(ForceHistory history, const RunSettings& settings, const FrameTransform& frame,
                                  const Vec3& reference_point_b, std::vector<std::string>& notes) {
  if (history.frame.axes_in_global) history = rotated_to_global_axes(history);
  const std::size_t n = history.size();
  if (history.frame.naming == ComponentNaming::BodyAxes) {
    settings_not_applicable(settings, {"axes", "origin", "cofr", "symmetry"}, "a history in body axes (columns X..N)",
                            notes);
    return history;
  }
  Vec3 centre{};
  if (history.frame.moment_centre) {
    centre = *history.frame.moment_centre;
  } else if (const auto cofr = settings.triple("cofr")) {
    centre = *cofr;
  } else {
    notes.push_back("the history does not state its moment centre; taken as the CFD origin (0 0 0)");
  }
  const Vec3 reference_cfd = frame.point_to_cfd(reference_point_b);
  const Vec3 arm{centre[0] - reference_cfd[0], centre[1] - reference_cfd[1], centre[2] - reference_cfd[2]};
  const bool transfer = arm != Vec3{};
  std::vector<SymmetryPlane> planes;
  if (const auto symmetry = settings.text("symmetry")) planes = parse_symmetry(*symmetry);
  const Permutation to_body = permutation_of(frame);
  for (const auto part : kAllForceParts) {
    const auto p = static_cast<std::size_t>(part);
    auto& s = history.series[p];
    const bool forces = !s[0].empty() && !s[1].empty() && !s[2].empty();
    const bool moments = !s[3].empty() && !s[4].empty() && !s[5].empty();
    const bool any = std::any_of(s.begin(), s.end(), [](const auto& v) { return !v.empty(); });
    if (!any) continue;
    if ((transfer || !planes.empty()) && !(forces && moments))
      throw InputError(SourceLocation{history.files.empty() ? std::string() : history.files.front().path.string()},
                       std::string("the ") + std::string(part_name(part)) +
                           " force or moment lacks components, so its moments cannot be moved to the reference point "
                           "or mirrored; expected all six");
    for (std::size_t i = 0; i < n && (forces && moments); ++i) {
      Vec3 F{s[0][i], s[1][i], s[2][i]}, M{s[3][i], s[4][i], s[5][i]};
      if (transfer) {
        M[0] += arm[1] * F[2] - arm[2] * F[1];
        M[1] += arm[2] * F[0] - arm[0] * F[2];
        M[2] += arm[0] * F[1] - arm[1] * F[0];
      }
      if (!planes.empty()) mirror_force_moment(F, M, reference_cfd, planes);
      for (std::size_t c = 0; c < 3; ++c) s[c][i] = F[c], s[3 + c][i] = M[c];
    }
    // Into body axes: a signed permutation, so missing components stay missing.
    std::array<std::vector<double>, 6> body;
    for (std::size_t c = 0; c < 3; ++c) {
      for (std::size_t offset : {std::size_t{0}, std::size_t{3}}) {
        body[offset + c] = std::move(s[offset + to_body.index[c]]);
        if (to_body.sign[c] < 0)
          for (auto& v : body[offset + c]) v = -v;
      }
    }
    s = std::move(body);
  }
  if (!planes.empty())
    notes.push_back("the whole body's forces from a model cut by the symmetry planes " + symmetry_text(planes) +
                    " (CFD axes): " + vanishing_components(planes) + " vanish");
  history.frame.naming = ComponentNaming::BodyAxes;
  history.frame.moment_centre.reset();
  history.frame.description = "body axes, moments about the run's reference point";
  return history;
}

namespace {

ImportedRun run_from_history(const ForceHistory& history, const HistoryAnalysis& analysis) {
  ImportedRun run;
  RunStatistics statistics;
  statistics.abscissa = std::string(abscissa_name(analysis.abscissa));
  statistics.convergence = std::string(convergence_name(analysis.convergence));
  statistics.convergence_reason = analysis.convergence_reason;
  statistics.flags = flag_names(analysis.flags);
  for (std::size_t c = 0; c < 6; ++c) {
    const auto& component = analysis.components[c];
    if (!component.present) continue;
    const auto& total = component.total();
    ForceComponent force;
    force.total = total.mean;
    if (const auto& p = component.parts[static_cast<std::size_t>(ForcePart::Pressure)]) force.pressure = p->mean;
    if (const auto& v = component.parts[static_cast<std::size_t>(ForcePart::Viscous)]) force.viscous = v->mean;
    run.tau_b[c] = force;
    statistics.components[c] =
        ComponentStatistics{total.standard_error, total.std_dev, total.drift, total.effective_samples};
    statistics.windows[c] = ComponentWindow{component.window_method, component.first_abscissa, component.last_abscissa,
                                            component.sample_count, flag_names(component.flags)};
  }
  run.statistics = std::move(statistics);
  run.trace = trace_of(history);
  return run;
}

/// A history input read and brought into body axes, moments about the
/// run's reference point (what read_history averages and read_body_history returns).
BodyHistory body_history_of(const PlannedInput& input, const std::string& format, RunSettings settings,
                            const ImportRequest& request) {
  BodyHistory out;
  out.format = format;
  const FrameTransform frame = resolve_frame(settings);
  ForceHistory history;
  Provenance provenance;
  if (format == "monitor") {
    CfxMonitorOptions options;
    options.monitors = request.columns.monitors;
    options.units = request.columns.units;
    options.average_last = std::max<std::size_t>(1, request.columns.average_last);
    history = read_cfx_monitor_history(input.path, options);
    provenance = history_provenance(history, input.path, kCfxMonitorImporter, kCfxMonitorImporterVersion);
  } else if (format == "force-history") {
    ForceHistoryCsvOptions options;
    options.columns = request.columns.columns;
    options.units = request.columns.units;
    history = read_force_history_csv(input.path, options);
    provenance = history_provenance(history, input.path, kForceHistoryCsvImporter, kForceHistoryCsvImporterVersion);
  } else {
    OpenFoamForcesOptions options;
    options.rho = settings.number("rho");
    const fs::path source = format == "openfoam-case" ? case_forces_folder(input.path) : input.path;
    history = read_openfoam_forces(source, options);
    provenance = history_provenance(history, source, kOpenFoamForcesImporter, kOpenFoamForcesImporterVersion);
    provenance.path = input.path.string();
  }
  for (const auto& note : history.notes) out.notes.push_back(note);
  // The run's reference point: the one given, else the solver's moment centre.
  Vec3 reference_b{};
  if (settings.find("ref_point") || settings.find("cofr"))
    reference_b = resolve_reference_point(settings, frame);
  else if (history.frame.moment_centre)
    reference_b = frame.point_to_body(*history.frame.moment_centre);
  out.history = history_in_body_axes(std::move(history), settings, frame, reference_b, out.notes);
  out.provenance = std::move(provenance);
  out.frame = frame;
  out.reference_b = reference_b;
  out.key = resolve_key(settings, frame, request.default_body);
  out.settings = std::move(settings);
  return out;
}

/// The OpenFOAM case folder a force input belongs to: the input itself for a
/// case folder, else the folder above its postProcessing/ that has a
/// system/ folder; empty when there is none.
fs::path case_of_forces(const fs::path& input, const std::string& format) {
  if (format == "openfoam-case") return input;
  std::error_code ec;
  fs::path at = input.lexically_normal();
  for (int up = 0; up < 6 && !at.empty() && at != at.parent_path(); ++up, at = at.parent_path())
    if (at.filename() == "postProcessing") {
      const fs::path case_dir = at.has_parent_path() ? at.parent_path() : fs::path(".");
      return fs::is_directory(case_dir / "system", ec) ? case_dir : fs::path();
    }
  return {};
}

}  // namespace

ImportedInput read_history(const PlannedInput& input, const std::string& format, RunSettings settings,
                           const ImportRequest& request) {
  ImportedInput out;
  out.input = input;
  out.format = format;
  // The file is read first, so that a broken file is said before a missing key.
  BodyHistory read = body_history_of(input, format, std::move(settings), request);
  if (request.require_velocity)
    require_velocity(read.settings, input.path.string(), [&] {
      return format == "openfoam-case" ? openfoam_free_stream_search(input.path) : std::string();
    });
  out.notes = std::move(read.notes);
  settings = std::move(read.settings);
  const ForceHistory& body = read.history;
  const Vec3 reference_b = read.reference_b;
  Provenance& provenance = read.provenance;
  HistoryAnalysisOptions analysis_options;
  analysis_options.window = window_of(settings);
  if (format == "openfoam-case" || format == "openfoam-forces")
    if (const fs::path case_dir = case_of_forces(input.path, format);
        !case_dir.empty() && !body.abscissa_values.empty())
      analysis_options.evidence = openfoam_convergence_evidence(case_dir, body.abscissa_values.back(), out.notes);
  // --average-last N on a monitor is the window of its last N iterations.
  if (format == "monitor" && request.columns.average_last > 1 && !settings.find("window"))
    analysis_options.window = HistoryWindow::last_samples(request.columns.average_last);
  // The analysis' own notes (windows, flags, iterative errors) stay with the
  // input (out.history); store_import sums them up by kind over all inputs.
  const HistoryAnalysis analysis = analyze_force_history(body, analysis_options);
  ImportedRun run = run_from_history(body, analysis);
  run.key = read.key;
  check_flow_speed(settings, run.key, input.path, out.notes);
  run.fluid = fluid_of(settings);
  run.reference_point_b = reference_b;
  run.sign = sign_of(settings);
  out.batch.source = provenance;
  out.batch.runs.push_back(std::move(run));
  out.history = analysis;
  record_settings(out.batch, settings, format, input.path);
  out.settings = std::move(settings);
  return out;
}

}  // namespace reading

BodyHistory read_body_history(const PlannedInput& input, const ImportRequest& request) {
  RunSettings settings = reading::input_settings(input, request);
  const std::string format = input_format(input, request.format);
  if (format != "openfoam-forces" && format != "force-history" && format != "openfoam-case" && format != "monitor")
    throw InputError(SourceLocation{input.path.string()},
                     "read as '" + format +
                         "'; expected a force history (OpenFOAM force files or case folder, a CFX "
                         "monitor file, a CSV of time and forces)");
  return reading::body_history_of(input, format, std::move(settings), request);
}

}  // namespace hydrocoef
