#include "src/pipeline/import_files.hpp"

#include <chrono>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>

#include "importers/case_motion.hpp"
#include "importers/cfx_out.hpp"
#include "importers/force_history_csv.hpp"
#include "importers/force_table.hpp"
#include "importers/openfoam_forces.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"
#include "src/core/parallel.hpp"
#include "src/core/source_file.hpp"
#include "src/core/version.hpp"
#include "src/history/history_trace.hpp"
#include "src/loads/symmetry.hpp"
#include "src/pipeline/given_uncertainty.hpp"
#include "src/pipeline/openfoam_case.hpp"
#include "src/pipeline/openfoam_convergence.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string head_of(const fs::path& file, std::size_t bytes = 4096) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(SourceLocation{file.string()}, "cannot open the file");
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

/// A table whose header names a time or iteration column is a history. The
/// header is the first line that is not blank or a comment, or the last
/// comment before numbers ("# Time Fx Fy Fz").
bool looks_like_time_history(std::string_view head) {
  std::string header;
  std::size_t start = 0;
  while (start < head.size()) {
    const auto end = head.find('\n', start);
    const std::string line(head.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    start = end == std::string_view::npos ? head.size() : end + 1;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    if (line[first] == '#') {
      header = line.substr(first + 1);
      continue;
    }
    const char c = line[first];
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.')) header = line;
    break;
  }
  const auto is_abscissa = [](const std::string& name) {
    std::string compact;
    for (const char c : lower(name.substr(0, name.find('['))))
      if (std::isalnum(static_cast<unsigned char>(c))) compact += c;
    for (const char* known : {"time", "t", "flowtime", "physicaltime", "solutiontime", "iteration", "iter", "step",
                              "timestep", "accumulatedtimestep", "outeriteration"})
      if (compact == known) return true;
    return false;
  };
  std::string cell;
  for (const char c : header + ",") {
    if (c == ',' || c == ';' || c == '\t') {
      if (is_abscissa(cell)) return true;
      cell.clear();
    } else {
      cell += c;
    }
  }
  // Blank-separated: the first word.
  std::string first_word;
  for (const char c : header) {
    if (c == ' ' && !first_word.empty()) break;
    if (c != ' ') first_word += c;
  }
  return is_abscissa(first_word);
}

/// Refuses (or notes) settings an importer cannot apply: refused when the
/// user gave them for this file, noted when a shared folder sidecar did.
void settings_not_applicable(const RunSettings& settings, const std::vector<std::string>& names,
                             const std::string& what, std::vector<std::string>& notes) {
  for (const auto& name : names) {
    const Setting* setting = settings.find(name);
    if (!setting) continue;
    const auto source = setting->origin.source;
    const std::string where =
        setting->origin.where.empty() ? std::string(setting_source_name(source)) : setting->origin.where;
    if (source == SettingSource::CommandLine || source == SettingSource::FileSidecar ||
        source == SettingSource::Manifest)
      throw InputError(where + ": setting '" + name + "' does not apply to " + what + "; expected it left out");
    notes.push_back("setting '" + name + "' from " + where + " does not apply to " + what + " and was not used");
  }
}

/// A CFX inlet with a Normal Speed states the free stream's size, not its
/// direction: the run's velocity must come from another setting, and its
/// size is compared with the speed.
void check_flow_speed(const RunSettings& settings, const RunKey& key, const fs::path& file,
                      std::vector<std::string>& notes) {
  const Setting* stated = settings.find("flow_speed");
  if (!stated) return;
  const double speed = *settings.number("flow_speed");
  char text[64];
  std::snprintf(text, sizeof text, "%.6g m/s", speed);
  const std::string where = stated->origin.where.empty() ? "the case files" : stated->origin.where;
  if (!settings.find("flow") && !settings.find("u") && !settings.find("v") && !settings.find("w"))
    throw InputError(SourceLocation{file.string()},
                     "the case states only the free stream's normal speed, " + std::string(text) + " (" + where +
                         "), not its direction; expected the free stream with --flow x,y,z (CFD axes) or the body "
                         "velocity u, v, w from a sidecar, the manifest or --key-from-name");
  const double body = std::hypot(key.nu_b[0], key.nu_b[1], key.nu_b[2]);
  if (std::abs(body - speed) > 1e-6 * std::max(1.0, speed)) {
    char found[64];
    std::snprintf(found, sizeof found, "%.6g m/s", body);
    notes.push_back("the body's speed, " + std::string(found) + ", is not the inlet's normal speed in the CFX case, " +
                    text + " (" + where + "): check the run's key");
  }
}

/// A case that states no free stream (a pressure-driven CFX case) or only
/// its size (a CFX inlet's Normal Speed) needs the run's velocity from
/// another source; checked once the settings are merged, so that the command
/// line, a sidecar, a manifest row or the name pattern completes the case.
void check_flow_stated(const RunSettings& settings, const fs::path& file) {
  if (settings.find("flow") || settings.find("u") || settings.find("v") || settings.find("w") ||
      settings.find("at_rest"))
    return;
  const char* expected =
      "expected the free stream with --flow x,y,z (CFD axes), or the body velocity u, v, w from a sidecar, the "
      "manifest or --key-from-name (--at-rest for a body at rest)";
  if (const Setting* unstated = settings.find("flow_unstated")) {
    const std::string where = unstated->origin.where.empty() ? file.string() : unstated->origin.where;
    throw InputError(where + ": " + *settings.text("flow_unstated") + "; " + expected);
  }
  if (const Setting* stated = settings.find("flow_speed")) {
    char text[64];
    std::snprintf(text, sizeof text, "%.6g m/s", *settings.number("flow_speed"));
    const std::string where = stated->origin.where.empty() ? "the case files" : stated->origin.where;
    throw InputError(SourceLocation{file.string()}, "the case states only the free stream's normal speed, " +
                                                        std::string(text) + " (" + where + "), not its direction; " +
                                                        expected);
  }
}

Fluid fluid_of(const RunSettings& settings) { return Fluid{settings.number("rho"), settings.number("nu")}; }

SignConvention sign_of(const RunSettings& settings) {
  const auto text = settings.text("sign");
  if (!text) return SignConvention::OnBody;
  try {
    return parse_sign_convention(*text);
  } catch (const InputError& e) {
    throw InputError(settings.find("sign")->origin.where + ": setting 'sign': " + e.what());
  }
}

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

void record_settings(ImportBatch& batch, const RunSettings& settings, const std::string& format, const fs::path& path) {
  nlohmann::json json = settings.provenance_json();
  batch.source.settings = escape::json_text(json);
  batch.source.settings_key = format + " " + settings.effective_text();
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
  batch.source.resolved_path = ec ? fs::absolute(path).lexically_normal().string() : resolved.string();
}

SurfaceRunOptions surface_options(const RunSettings& settings, const std::string& format, const FrameTransform& frame,
                                  const RunKey& key, const Vec3& reference_point_b) {
  SurfaceRunOptions options;
  options.format = format;
  options.key = key;
  options.frame = frame;
  options.reference_point_b = reference_point_b;
  if (const auto locations = settings.texts("locations")) options.locations = *locations;
  options.pressure = settings.text("pressure");
  if (const auto shear = settings.texts("shear")) {
    options.shear = *shear;
    if (options.shear.size() != 1 && options.shear.size() != 3)
      throw InputError(settings.find("shear")->origin.where +
                       ": setting 'shear': expected one vector array, three arrays x,y,z, or none");
  }
  const auto choice = [&](const char* name, std::initializer_list<const char*> allowed) -> std::optional<std::string> {
    const auto text = settings.text(name);
    if (!text) return std::nullopt;
    for (const char* a : allowed)
      if (*text == a) return text;
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : " or ") + std::string(a);
    throw InputError(settings.find(name)->origin.where + ": setting '" + name + "' is '" + printable_text(*text, 40) +
                     "'; expected " + list);
  };
  if (const auto kind = choice("pressure_kind", {"static", "kinematic"}))
    options.pressure_kind = *kind == "static" ? PressureKind::Static : PressureKind::Kinematic;
  if (const auto convention = choice("shear_convention", {"on-wall", "on-fluid"}))
    options.shear_convention = *convention == "on-wall" ? ShearConvention::OnWall : ShearConvention::OnFluid;
  if (const auto normals = choice("normals", {"auto", "as-given", "flip"}))
    options.normals = *normals == "auto"   ? NormalPolicy::Auto
                      : *normals == "flip" ? NormalPolicy::Flip
                                           : NormalPolicy::AsGiven;
  options.density = settings.number("rho");
  options.kinematic_viscosity = settings.number("nu");
  options.reference_pressure = settings.number("p_ref").value_or(0.0);
  options.length_unit = settings.text("length_unit");
  options.pressure_unit = settings.text("pressure_unit");
  if (const auto symmetry = settings.text("symmetry")) options.symmetry = parse_symmetry(*symmetry);
  return options;
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

}  // namespace

std::string input_format(const PlannedInput& input, const std::string& requested) {
  static const std::vector<std::string> known = {"auto", "cfdpost", "vtk", "monitor", "table", "history", "cfx-out"};
  if (std::find(known.begin(), known.end(), requested) == known.end())
    throw InputError("--format '" + requested +
                     "': expected one of auto, table, monitor, history, cfdpost, vtk, cfx-out");
  if (input.kind == InputKind::OpenFoamCase) return "openfoam-case";
  std::error_code ec;
  if (fs::is_directory(input.path, ec)) return "openfoam-forces";  // a function object's folder
  if (requested == "history") {
    const std::string name = lower(input.path.filename().string());
    return is_force_history_name(input.path) || name == "forcecoeffs.dat" || name.rfind("moment", 0) == 0
               ? "openfoam-forces"
               : "force-history";
  }
  if (requested != "auto") return requested;
  const std::string extension = lower(input.path.extension().string());
  if (extension == ".out") return "cfx-out";  // a CFX solver output read for its wall force summary
  if (extension == ".csv" || extension == ".txt" || extension == ".tsv" || extension == ".dat") {
    const std::string head = head_of(input.path);
    if (is_force_history_name(input.path) || lower(input.path.filename().string()) == "forcecoeffs.dat" ||
        looks_like_openfoam_forces(head))
      return "openfoam-forces";
    const std::string format = detect_format(input.path, "auto");
    if (format != "table") return format;
    return looks_like_time_history(head) ? "force-history" : "table";
  }
  return detect_format(input.path, "auto");
}

ImportPlan plan_request(const ImportRequest& request) { return plan_import(request.inputs, request.plan); }

namespace {

/// Names compared as CFX compares them: runs of blanks as one space, any case.
std::string cfx_name_key(std::string_view name) {
  std::string out;
  bool blank = false;
  for (const char c : name) {
    if (c == ' ' || c == '\t') {
      blank = true;
      continue;
    }
    if (blank && !out.empty()) out += ' ';
    blank = false;
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

/// The loads of the locations a CFX run's forces are taken from: the one
/// domain group's totals by default, else the boundaries or groups named
/// with --location (summed). `what` says which, for notes.
CfxWallLoads cfx_summary_loads(const CfxWallForceSummary& summary, const RunSettings& settings, std::string& what) {
  const SourceLocation at{summary.file, summary.line, 0};
  std::string available;
  for (const auto& group : summary.groups) {
    for (const auto& [name, loads] : group.boundaries) available += (available.empty() ? "" : ", ") + name;
    available += ", " + group.name + " (the domain group's totals)";
  }
  available = printable_text(available, 400);
  const auto names = settings.texts("locations");
  if (!names || names->empty()) {
    if (summary.groups.size() != 1)
      throw InputError(at, std::to_string(summary.groups.size()) +
                               " domain groups in the wall force summary; expected one, or --location NAME of "
                               "the one to import: " +
                               available);
    what = "the totals of domain group '" + printable_text(summary.groups.front().name, 80) + "'";
    return summary.groups.front().totals;
  }
  CfxWallLoads sum;
  bool first = true;
  const auto add = [&](std::optional<Vec3>& total, const std::optional<Vec3>& part) {
    if (first) {
      total = part;
    } else if (total && part) {
      for (std::size_t i = 0; i < 3; ++i) (*total)[i] += (*part)[i];
    } else {
      total.reset();  // a part one location lacks is not known for the sum
    }
  };
  for (const auto& name : *names) {
    const CfxWallLoads* found = nullptr;
    std::size_t matches = 0;
    for (const auto& group : summary.groups) {
      if (cfx_name_key(group.name) == cfx_name_key(name)) found = &group.totals, ++matches;
      for (const auto& [boundary, loads] : group.boundaries)
        if (cfx_name_key(boundary) == cfx_name_key(name)) found = &loads, ++matches;
    }
    if (matches == 0)
      throw InputError(at, "no location '" + printable_text(name, 80) +
                               "' (--location) in the wall force summary; expected one of: " + available);
    if (matches > 1)
      throw InputError(at, "location '" + printable_text(name, 80) +
                               "' (--location) names several boundaries or groups of the wall force summary; "
                               "expected a name found once");
    add(sum.pressure_force, found->pressure_force);
    add(sum.viscous_force, found->viscous_force);
    add(sum.pressure_moment, found->pressure_moment);
    add(sum.viscous_moment, found->viscous_moment);
    if (first) sum.line = found->line;
    first = false;
    what += (what.empty() ? "" : " + ") + printable_text(name, 80);
  }
  return sum;
}

/// A CFX run from the wall force summary of its solver output: the chosen
/// location's pressure and viscous force and moment, one sample brought into
/// body axes by the transform a history's samples go through (moments to the
/// reference point, mirrored for symmetry planes, rotated).
ImportedInput read_cfx_summary(const PlannedInput& input, RunSettings settings, const ImportRequest& request) {
  ImportedInput out;
  out.input = input;
  out.format = "cfx-out";
  settings_not_applicable(
      settings,
      {"window", "pressure", "shear", "pressure_kind", "shear_convention", "length_unit", "pressure_unit", "normals"},
      "the wall force summary of a CFX solver output", out.notes);
  const SourceFile file = load_source_file(input.path);
  const CfxWallForceSummary summary = parse_cfx_wall_forces(file.bytes, input.path.string());
  std::string what;
  const CfxWallLoads loads = cfx_summary_loads(summary, settings, what);

  ForceHistory history;
  history.abscissa = HistoryAbscissa::Iteration;
  history.abscissa_values = {1.0};
  history.files.push_back(HistorySourceFile{input.path, std::string(kCfxOutImporter), file.sha256,
                                            static_cast<std::uint64_t>(file.bytes.size()), 1, 1});
  const auto put = [&](ForcePart part, std::size_t offset, const std::optional<Vec3>& v) {
    if (!v) return;
    for (std::size_t c = 0; c < 3; ++c) history.series[static_cast<std::size_t>(part)][offset + c] = {(*v)[c]};
  };
  put(ForcePart::Pressure, 0, loads.pressure_force);
  put(ForcePart::Viscous, 0, loads.viscous_force);
  put(ForcePart::Pressure, 3, loads.pressure_moment);
  put(ForcePart::Viscous, 3, loads.viscous_moment);
  for (std::size_t c = 0; c < 6; ++c) {
    const auto& p = history.series[static_cast<std::size_t>(ForcePart::Pressure)][c];
    const auto& v = history.series[static_cast<std::size_t>(ForcePart::Viscous)][c];
    if (!p.empty() || !v.empty())
      history.series[static_cast<std::size_t>(ForcePart::Total)][c] = {(p.empty() ? 0.0 : p[0]) +
                                                                       (v.empty() ? 0.0 : v[0])};
  }
  const auto origin = SampleOrigin{0, static_cast<std::uint32_t>(loads.line)};
  if (loads.pressure_force || loads.viscous_force) history.force_origin = {origin};
  if (loads.pressure_moment || loads.viscous_moment) history.moment_origin = {origin};
  history.frame.description = "the CFX solver's global axes";

  const FrameTransform frame = resolve_frame(settings);
  const Vec3 reference_b = resolve_reference_point(settings, frame);
  const ForceHistory body = history_in_body_axes(std::move(history), settings, frame, reference_b, out.notes);
  ImportedRun run;
  for (std::size_t c = 0; c < 6; ++c) {
    const auto& total = body.series[static_cast<std::size_t>(ForcePart::Total)][c];
    if (total.empty()) continue;
    ForceComponent force;
    force.total = total[0];
    if (const auto& p = body.series[static_cast<std::size_t>(ForcePart::Pressure)][c]; !p.empty())
      force.pressure = p[0];
    if (const auto& v = body.series[static_cast<std::size_t>(ForcePart::Viscous)][c]; !v.empty()) force.viscous = v[0];
    run.tau_b[c] = force;
  }
  run.key = resolve_key(settings, frame, request.default_body);
  check_flow_speed(settings, run.key, input.path, out.notes);
  run.fluid = fluid_of(settings);
  run.reference_point_b = reference_b;
  run.sign = SignConvention::OnBody;
  run.source_line = loads.line;
  out.notes.push_back(input.path.string() + ": forces of " + what + " from the wall force summary at line " +
                      std::to_string(summary.line) +
                      (summary.summaries > 1 ? " (the last of " + std::to_string(summary.summaries) + ")" : "") +
                      ": the solver's values at the end of the run, pressure and viscous parts kept apart; no "
                      "history, so no steady window or standard error");
  out.batch.source.path = input.path.string();
  out.batch.source.sha256 = file.sha256;
  out.batch.source.size_bytes = file.bytes.size();
  out.batch.source.importer = std::string(kCfxOutImporter);
  out.batch.source.importer_version = std::string(kCfxOutImporterVersion);
  out.batch.runs.push_back(std::move(run));
  record_settings(out.batch, settings, "cfx-out", input.path);
  out.settings = std::move(settings);
  return out;
}

/// A forced-oscillation case (an imposed harmonic motion in
/// constant/dynamicMeshDict) is not a run at one velocity: `hydrocoef pmm`
/// reads it. A motion that is not an oscillation gives a note.
void refuse_forced_oscillation(const fs::path& case_dir, std::vector<std::string>& notes) {
  std::optional<CaseOscillation> motion;
  try {
    motion = read_openfoam_motion(case_dir);
  } catch (const InputError& e) {
    notes.push_back(case_dir.string() +
                    ": constant/dynamicMeshDict moves the mesh in a way that is not a forced oscillation (" + e.what() +
                    "); imported as a run at the velocity of its settings: check its key");
    return;
  }
  if (!motion) return;
  throw InputError(motion->where + ": a forced-oscillation case (" + motion->description +
                   "), not a run at one velocity; expected `hydrocoef pmm " + case_dir.string() +
                   "`, which reads forced-oscillation runs, or a case without an imposed motion");
}

/// The runs of one input as its format gives them, with its settings.
ImportedInput read_input_values(const PlannedInput& input, const ImportRequest& request) {
  std::vector<SettingsLayer> layers;
  if (!request.command_line.empty()) layers.push_back(request.command_line);
  layers.insert(layers.end(), input.layers.begin(), input.layers.end());
  RunSettings settings = merge_settings(layers);
  check_flow_stated(settings, input.path);
  const std::string format = input_format(input, request.format);
  if (format == "openfoam-case") {
    std::vector<std::string> motion_notes;
    refuse_forced_oscillation(input.path, motion_notes);
    ImportedInput out = read_history(input, format, std::move(settings), request);
    out.notes.insert(out.notes.end(), motion_notes.begin(), motion_notes.end());
    return out;
  }
  if (format == "openfoam-forces" || format == "force-history" || format == "monitor")
    return read_history(input, format, std::move(settings), request);
  if (format == "cfx-out") return read_cfx_summary(input, std::move(settings), request);

  ImportedInput out;
  out.input = input;
  out.format = format;
  const FrameTransform frame = resolve_frame(settings);
  const RunKey key = resolve_key(settings, frame, request.default_body);
  check_flow_speed(settings, key, input.path, out.notes);
  const Vec3 reference_b = resolve_reference_point(settings, frame);
  if (format == "cfdpost" || format == "vtk") {
    settings_not_applicable(settings, {"window", "sign"}, "a surface export", out.notes);
    SurfaceRunOptions options = surface_options(settings, format, frame, key, reference_b);
    out.surface = import_surface_run(input.path, options);
    // After the file is read, so that a broken file is said before a missing key.
    if (request.require_velocity) require_velocity(settings, input.path.string());
    out.batch = out.surface->batch;
    for (const auto& w : out.surface->warnings) out.notes.push_back(w);
  } else if (format == "table") {
    settings_not_applicable(
        settings,
        {"flow", "axes", "origin", "cofr", "symmetry", "window", "pressure", "shear", "pressure_kind",
         "shear_convention", "length_unit", "pressure_unit", "normals", "locations"},
        "a force table (its rows are in body axes)", out.notes);
    ForceTableOptions options;
    options.body = key.body;
    options.velocity_b = key.nu_b;
    options.disturbances = key.disturbances;
    options.columns = request.columns.columns;
    options.units = request.columns.units;
    options.disturbance_columns = request.columns.disturbance_columns;
    options.ignored_columns = request.columns.ignored_columns;
    options.sign = sign_of(settings);
    options.fluid = fluid_of(settings);
    options.reference_point_b = reference_b;
    out.batch = read_force_table(input.path, options);
  } else {
    throw InputError(SourceLocation{input.path.string()}, "no importer for format '" + format + "'");
  }
  record_settings(out.batch, settings, format, input.path);
  out.settings = std::move(settings);
  return out;
}

}  // namespace

BodyHistory read_body_history(const PlannedInput& input, const ImportRequest& request) {
  std::vector<SettingsLayer> layers;
  if (!request.command_line.empty()) layers.push_back(request.command_line);
  layers.insert(layers.end(), input.layers.begin(), input.layers.end());
  RunSettings settings = merge_settings(layers);
  check_flow_stated(settings, input.path);
  const std::string format = input_format(input, request.format);
  if (format != "openfoam-forces" && format != "force-history" && format != "openfoam-case" && format != "monitor")
    throw InputError(SourceLocation{input.path.string()},
                     "read as '" + format +
                         "'; expected a force history (OpenFOAM force files or case folder, a CFX "
                         "monitor file, a CSV of time and forces)");
  return body_history_of(input, format, std::move(settings), request);
}

ImportedInput read_input(const PlannedInput& input, const ImportRequest& request) {
  ImportedInput out = read_input_values(input, request);
  if (const auto text = out.settings.text("uncertainty"))
    apply_given_uncertainty(out.batch, parse_given_uncertainty(*text, out.settings.find("uncertainty")->origin.where));
  return out;
}

std::vector<ImportedInput> read_inputs(const ImportPlan& plan, const ImportRequest& request) {
  // Files in plan order on request.jobs threads (0: every core); the first
  // file that cannot be read, in plan order, is the error (src/core/parallel.hpp).
  const std::size_t count = plan.inputs.size();
  std::vector<std::optional<ImportedInput>> results(count);
  std::atomic<std::size_t> done{0};
  std::mutex progress_mutex;
  parallel_for(count, request.jobs, [&](std::size_t i) {
    results[i] = read_input(plan.inputs[i], request);
    const std::size_t finished = ++done;
    if (request.progress) {
      const std::lock_guard<std::mutex> lock(progress_mutex);
      request.progress(finished, count, plan.inputs[i].path);
    }
  });
  std::vector<ImportedInput> out;
  out.reserve(count);
  for (auto& r : results) out.push_back(std::move(*r));
  return out;
}

namespace {
double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool is_key_setting(const std::string& name) {
  return velocity_index(name) || name == "flow" || name.rfind("disturbance.", 0) == 0;
}

/// True when the input states its runs' keys (a table's rows, or a velocity
/// or disturbance from any source), false when its key is only the default.
bool states_key(const ImportedInput& input) {
  if (input.format == "table") return true;
  return std::any_of(input.settings.values.begin(), input.settings.values.end(),
                     [](const auto& entry) { return is_key_setting(entry.first); });
}

/// A file and where its run's key came from, for collision messages.
std::string key_origin(const ImportedInput& input, const ImportedRun& run) {
  const std::string file = printable_text(input.input.path.string(), 200);
  if (input.format == "table") return file + " (its row at line " + std::to_string(run.source_line) + ")";
  std::string parts;
  for (const auto& [name, setting] : input.settings.values) {
    if (!is_key_setting(name)) continue;
    parts +=
        (parts.empty() ? "" : ", ") + name + " from the " + std::string(setting_source_name(setting.origin.source));
    if (!setting.origin.where.empty()) parts += " " + printable_text(setting.origin.where, 120);
  }
  return file + " (" + (parts.empty() ? std::string("no velocity stated by any source") : parts) + ")";
}

/// Two inputs of one import that give the same component of the same run:
/// refused before anything is stored, naming both files and where each key
/// came from. Superseding is for a later import (--replace); within one
/// import it would keep whichever file was stored last.
void check_key_collisions(const std::vector<ImportedInput>& inputs) {
  std::map<std::string, std::pair<std::size_t, std::size_t>> seen;  // key and component -> input, run
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto& runs = inputs[i].batch.runs;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const RunKey& key = runs[r].key;
      std::string text = key.body + "\n" + disturbance_signature(key.disturbances);
      for (const double v : key.nu_b) text += "\n" + shortest_number(v);
      for (std::size_t c = 0; c < 6; ++c) {
        if (!runs[r].tau_b[c]) continue;
        const auto [it, inserted] = seen.try_emplace(text + "\n" + std::string(kForceNames[c]), i, r);
        if (inserted || it->second.first == i) continue;
        const ImportedInput& earlier = inputs[it->second.first];
        const ImportedRun& earlier_run = earlier.batch.runs[it->second.second];
        const bool neither = !states_key(earlier) && !states_key(inputs[i]);
        throw InputError(
            SourceLocation{inputs[i].input.path.string()},
            "run " + printable_text(describe(key), 200) + " gets " + std::string(kForceNames[c]) +
                " from two files of this import: " + key_origin(earlier, earlier_run) + " and " +
                key_origin(inputs[i], runs[r]) + "; " +
                (neither ? "neither states its run's velocity; expected each file's key with --key-from-name PATTERN "
                           "(file names and folder contents alike), --manifest or a sidecar FILE.json"
                         : "expected one file per run and component (a file meant to supersede another is "
                           "imported on its own, in a later import with --replace)"));
      }
    }
  }
}
}  // namespace

namespace {

/// One line per kind of convergence and per kind of flag over the inputs'
/// force histories (not one note per run and component): what a user should
/// act on, and where to look.
std::vector<std::string> history_summary(const std::vector<ImportedInput>& inputs) {
  std::map<std::string, std::size_t> kinds;
  std::map<std::string, std::map<std::string, std::size_t>> flagged;  // flag -> component -> runs
  std::map<std::string, std::size_t> negligible;                      // component -> runs
  std::size_t histories = 0;
  for (const auto& input : inputs) {
    if (!input.history) continue;
    ++histories;
    const HistoryAnalysis& a = *input.history;
    ++kinds[std::string(convergence_name(a.convergence))];
    for (std::size_t c = 0; c < kHistoryComponents; ++c) {
      const ComponentAnalysis& component = a.components[c];
      if (!component.present) continue;
      const std::string name = std::string(kForceNames[c]);
      if (component.negligible) ++negligible[name];
      for (const auto& flag : flag_names(component.flags)) ++flagged[flag][name];
    }
  }
  std::vector<std::string> out;
  if (histories == 0) return out;
  std::string line = "force histories: ";
  bool first = true;
  for (const auto& [kind, count] : kinds) {
    line += (first ? "" : ", ") + std::to_string(count) + " " + kind;
    first = false;
  }
  if (kinds.count("converged")) line += " (converged: the final iterate, with its iterative error as standard error)";
  out.push_back(line + "; 'runs show ID' says why, with the files");
  if (!negligible.empty()) {
    std::string names;
    for (const auto& [name, count] : negligible)
      names += (names.empty() ? "" : ", ") + name + " of " + std::to_string(count);
    out.push_back("zero to round-off, never flagged: " + names + " run(s)");
  }
  for (const auto& [flag, components] : flagged) {
    std::string where;
    for (const auto& [name, count] : components)
      where += (where.empty() ? "" : ", ") + name + " of " + std::to_string(count);
    out.push_back(flag + ": " + where +
                  " run(s); 'runs show ID' gives the windows and the import's --json the "
                  "details");
  }
  return out;
}

}  // namespace

ImportResult read_import(const ImportRequest& request) {
  ImportResult result;
  auto start = std::chrono::steady_clock::now();
  result.plan = plan_request(request);
  result.plan_s = seconds_since(start);
  start = std::chrono::steady_clock::now();
  result.inputs = read_inputs(result.plan, request);
  check_key_collisions(result.inputs);
  result.read_s = seconds_since(start);
  return result;
}

void store_import(Database& database, ImportResult& result, const ImportOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<ImportBatch> batches;
  for (const auto& input : result.inputs) batches.push_back(input.batch);
  result.outcomes = database.import(batches, options);
  result.store_s = seconds_since(start);
  result.notes.clear();
  const auto add_note = [&](const std::string& note) {
    for (auto& [text, count] : result.notes)
      if (text == note) return void(++count);
    result.notes.emplace_back(note, 1);
  };
  for (const auto& note : result.plan.notes) add_note(note);
  for (const auto& input : result.inputs)
    for (const auto& note : input.notes) add_note(note);
  for (const auto& note : history_summary(result.inputs)) add_note(note);
  result.runs = result.runs_created = result.runs_extended = result.already_imported = result.replaced = 0;
  for (std::size_t i = 0; i < result.outcomes.size(); ++i) {
    const auto& outcome = result.outcomes[i];
    result.runs_created += outcome.runs_created;
    result.runs_extended += outcome.runs_extended;
    result.already_imported += outcome.already_imported ? 1 : 0;
    result.replaced += outcome.replaced ? 1 : 0;
    result.runs += result.inputs[i].batch.runs.size();
  }
}

ImportResult import_into(Database& database, const ImportRequest& request, const ImportOptions& options) {
  ImportResult result = read_import(request);
  store_import(database, result, options);
  return result;
}

}  // namespace hydrocoef
