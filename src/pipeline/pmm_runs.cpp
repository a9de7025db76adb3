#include "src/pipeline/pmm_runs.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <mutex>
#include <numbers>
#include <sstream>
#include <system_error>

#include "importers/case_motion.hpp"
#include "importers/cfx_ccl.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/parallel.hpp"
#include "src/core/sign_convention.hpp"
#include "src/pmm/added_mass_assembly.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef {
namespace fs = std::filesystem;

namespace {

std::string restoring_unit(std::size_t dof) { return dof < 3 ? "N/m" : "N m/rad"; }

std::string motion_text(const HarmonicMotion& m) {
  return std::string(dof_name(m.dof)) + " amplitude " + shortest_number(m.amplitude) + (m.dof < 3 ? " m" : " rad") +
         ", period " + shortest_number(m.period()) + " s, phase " + shortest_number(m.phase) + " rad";
}

bool same_motion(const HarmonicMotion& a, const HarmonicMotion& b) {
  const auto close = [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y)); };
  return a.dof == b.dof && close(a.amplitude, b.amplitude) && close(a.omega, b.omega) &&
         std::abs(std::remainder(a.phase - b.phase, 2.0 * std::numbers::pi)) <= 1e-9;
}

/// The OpenFOAM case an input belongs to: the case folder itself, or the
/// nearest folder above a postProcessing file or folder that holds constant/.
std::optional<fs::path> openfoam_case_of(const fs::path& path, const std::string& format) {
  if (format == "openfoam-case") return path;
  if (format != "openfoam-forces") return std::nullopt;
  std::error_code ec;
  fs::path folder = fs::absolute(path, ec);
  for (int up = 0; up < 5 && folder.has_parent_path() && folder != folder.parent_path(); ++up) {
    folder = folder.parent_path();
    if (fs::is_directory(folder / "constant", ec)) return folder;
  }
  return std::nullopt;
}

std::optional<CaseOscillation> ccl_motion(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(SourceLocation{file.string()}, "cannot read the file; expected a CCL or CFX solver output");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  if (const auto excerpt = ccl_from_solver_output(text))
    return cfx_motion(parse_ccl(excerpt->text, file.string(), excerpt->first_line));
  return cfx_motion(parse_ccl(text, file.string()));
}

/// The motion of one input: the options', checked against the case's when
/// the case states one too; else the case's.
std::pair<HarmonicMotion, std::string> motion_of(const PmmRequest& request, const fs::path& path,
                                                 const BodyHistory& read, std::vector<std::string>& notes) {
  std::optional<CaseOscillation> stated;
  if (request.ccl) {
    stated = ccl_motion(*request.ccl);
    if (!stated)
      throw InputError(SourceLocation{request.ccl->string()},
                       "states no mesh motion; expected a Specified Displacement of the form A*sin(omega*t)");
  } else if (read.format == "monitor" && path.extension() == ".out") {
    stated = ccl_motion(path);
  } else if (const auto root = openfoam_case_of(path, read.format)) {
    stated = read_openfoam_motion(*root);
  }
  std::optional<HarmonicMotion> from_case;
  if (stated) from_case = body_motion(*stated, read.frame);
  if (request.motion) {
    if (from_case && !same_motion(*from_case, *request.motion))
      throw InputError(SourceLocation{path.string()},
                       "the case states " + motion_text(*from_case) + " (" + stated->where + ": " +
                           stated->description + "), the options " + motion_text(*request.motion) +
                           "; expected the same motion (leave the options out to use the case's)");
    if (from_case) notes.push_back("the motion options agree with the case (" + stated->where + ")");
    return {*request.motion, "--motion"};
  }
  if (!from_case)
    throw InputError(SourceLocation{path.string()},
                     "found no imposed motion (no constant/dynamicMeshDict with a solidBody oscillation, no CCL); "
                     "expected --motion DOF --amplitude A --period T, or --ccl FILE for a CFX case");
  return {*from_case, stated->where + " (" + stated->description + ")"};
}

/// Every number a record stores is finite (a database holding an infinity
/// is refused by every later reader).
void check_finite(const PmmRecord& r, const std::string& where) {
  const auto need = [&](double value, const std::string& what) {
    if (!std::isfinite(value))
      throw InputError(SourceLocation{where}, what + " is " + shortest_number(value) + "; expected a finite number");
  };
  const auto maybe = [&](const std::optional<double>& value, const std::string& what) {
    if (value) need(*value, what);
  };
  need(r.window_start, "the window start");
  need(r.window_end, "the window end");
  maybe(r.keulegan_carpenter, "the Keulegan-Carpenter number");
  maybe(r.stokes_number, "the Stokes number");
  maybe(r.restoring, "--restoring");
  for (const double v : r.history) need(v, "a sample of the kept history");
  for (const auto& c : r.coefficients) {
    const std::string name(kForceNames[c.component]);
    need(c.mean, name + " mean");
    need(c.added_mass, name + " added mass");
    need(c.added_mass_se, name + " added mass standard error");
    need(c.damping, name + " damping");
    need(c.damping_se, name + " damping standard error");
    need(c.explained, name + " explained variance");
    for (const double h : c.harmonics) need(h, name + " harmonic");
  }
}

std::vector<double> kept_history(const ForceHistory& history, const HarmonicAnalysis& analysis) {
  const auto& t = history.abscissa_values;
  const std::size_t first =
      static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), analysis.window_start) - t.begin());
  const std::size_t last =
      static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), analysis.window_end) - t.begin());
  const std::size_t n = last > first ? last - first : 0;
  const std::size_t stride = std::max<std::size_t>(1, (n + kMaxPmmHistoryRows - 1) / kMaxPmmHistoryRows);
  std::vector<double> out;
  out.reserve((n / stride + 1) * kPmmHistoryColumns);
  for (std::size_t i = first; i < last; i += stride) {
    out.push_back(t[i]);
    for (const auto component : kAllHistoryComponents) {
      const auto& values = history.values(ForcePart::Total, component);
      out.push_back(values.empty() ? 0.0 : values[i]);
    }
  }
  return out;
}

PmmRun analyse_one(const PlannedInput& input, const PmmRequest& request) {
  PmmRun run;
  run.path = input.path;
  BodyHistory read = read_body_history(input, request.import);
  run.format = read.format;
  run.notes = read.notes;
  const std::string where = input.path.string();
  if (read.history.abscissa != HistoryAbscissa::Time)
    throw InputError(SourceLocation{where},
                     "the history counts iterations (a steady run); expected time in seconds "
                     "of a transient forced-oscillation run");
  if (const auto sign = read.settings.text("sign");
      sign && parse_sign_convention(*sign) == SignConvention::OpposingMotion)
    for (auto& part : read.history.series)
      for (auto& values : part)
        for (double& v : values) v = -v;
  const auto [motion, source] = motion_of(request, input.path, read, run.notes);
  // The displacement must stand well above the round-off of the positions it
  // is added to (a body's coordinates of about its size, at least 1 m).
  const double smallest_amplitude =
      kMinRelativeAmplitude * (motion.dof < 3 ? std::max(1.0, request.size.value_or(1.0)) : 1.0);
  if (!(motion.amplitude >= smallest_amplitude))
    throw InputError(SourceLocation{where}, "the motion's amplitude " + shortest_number(motion.amplitude) +
                                                (motion.dof < 3 ? " m" : " rad") + " (from " + source +
                                                ") is at the round-off of the positions; expected at least " +
                                                shortest_number(smallest_amplitude) + (motion.dof < 3 ? " m" : " rad"));
  const auto inline_component = kAllHistoryComponents[motion.dof];
  if (request.restoring) {
    if (request.medium == PmmMedium::OscillatingStream)
      throw InputError(SourceLocation{where},
                       "--restoring with --stream: a body held in a stream is not displaced; "
                       "expected a restoring force only for a body that moves");
    auto& values = read.history.values(ForcePart::Total, inline_component);
    if (values.empty())
      throw InputError(SourceLocation{where}, "--restoring: the history has no " +
                                                  std::string(kForceNames[motion.dof]) + " component to remove the " +
                                                  std::string(dof_name(motion.dof)) + " restoring force from");
    const auto& t = read.history.abscissa_values;
    for (std::size_t i = 0; i < values.size(); ++i) {
      values[i] += *request.restoring * motion.displacement(t[i]);  // F - (-C x)
      if (!std::isfinite(values[i]))
        throw InputError(SourceLocation{where}, "--restoring " + shortest_number(*request.restoring) +
                                                    ": removing -C x from sample " + std::to_string(i + 1) +
                                                    " gives a non-finite force; expected a finite result");
    }
    run.notes.push_back("the restoring force -C x, C = " + shortest_number(*request.restoring) + " " +
                        restoring_unit(motion.dof) + ", was removed from " + std::string(kForceNames[motion.dof]) +
                        " before the fit");
  }
  std::array<std::span<const double>, 6> forces;
  for (std::size_t c = 0; c < 6; ++c) forces[c] = read.history.values(ForcePart::Total, kAllHistoryComponents[c]);
  try {
    run.analysis = analyse_forced_oscillation(read.history.abscissa_values, forces, motion, request.fit);
  } catch (const InputError& e) {
    throw InputError(SourceLocation{where}, e.what());
  }
  const auto rho = read.settings.number("rho");
  const auto nu = read.settings.number("nu");
  PmmRecord& record = run.record;
  record.body = read.key.body;
  record.nu_b = read.key.nu_b;
  record.dof = motion.dof;
  record.amplitude = motion.amplitude;
  record.omega = motion.omega;
  record.phase = motion.phase;
  record.medium = request.medium;
  record.motion_source = source;
  record.window_start = run.analysis.window_start;
  record.window_end = run.analysis.window_end;
  record.periods = run.analysis.periods;
  record.transient_periods = run.analysis.transient_periods;
  record.samples = run.analysis.samples;
  record.harmonics = request.fit.harmonics;
  record.size = request.size;
  record.kinematic_viscosity = nu;
  record.rho = rho;
  record.displaced_volume = request.displaced_volume;
  record.restoring = request.restoring;
  if (request.size && motion.dof < 3) record.keulegan_carpenter = keulegan_carpenter(motion.amplitude, *request.size);
  if (request.size && nu) record.stokes_number = stokes_number(*request.size, motion.period(), *nu);
  record.source_path = read.provenance.path;
  record.source_sha256 = read.provenance.sha256;
  record.importer = read.provenance.importer + " " + read.provenance.importer_version;
  record.history = kept_history(read.history, run.analysis);
  const bool stream = request.medium == PmmMedium::OscillatingStream;
  if (stream) {
    if (motion.dof >= 3)
      throw InputError(SourceLocation{where}, "an oscillating stream of " + std::string(dof_name(motion.dof)) +
                                                  "; expected a translation (surge, sway or heave)");
    if (!rho || !request.displaced_volume)
      throw InputError(SourceLocation{where}, std::string("an oscillating stream needs ") +
                                                  (!rho ? "the density (--set rho=...)" : "") +
                                                  (!rho && !request.displaced_volume ? " and " : "") +
                                                  (!request.displaced_volume ? "the displaced volume (--volume)" : "") +
                                                  " to remove the Froude-Krylov force rho V a");
    run.notes.push_back("an oscillating stream: the Froude-Krylov force rho V x'' = " +
                        shortest_number(*rho * *request.displaced_volume) + " kg x'' was removed from " +
                        std::string(kForceNames[motion.dof]));
  }
  for (std::size_t c = 0; c < 6; ++c) {
    const HarmonicComponent& fit = run.analysis.components[c];
    if (!fit.present) continue;
    PmmCoefficient coefficient;
    coefficient.component = c;
    coefficient.mean = fit.mean;
    coefficient.added_mass = fit.added_mass;
    coefficient.damping = fit.damping;
    if (stream) {
      coefficient.added_mass = -fit.added_mass - (c == motion.dof ? *rho * *request.displaced_volume : 0.0);
      coefficient.damping = -fit.damping;
    }
    coefficient.added_mass_se = fit.added_mass_se;
    coefficient.damping_se = fit.damping_se;
    coefficient.explained = fit.explained;
    for (std::size_t k = 0; k < fit.in_phase.size(); ++k) {
      coefficient.harmonics.push_back(fit.in_phase[k]);
      coefficient.harmonics.push_back(fit.quadrature[k]);
    }
    record.coefficients.push_back(std::move(coefficient));
  }
  for (const auto& coefficient : record.coefficients)
    if (coefficient.component == motion.dof && coefficient.added_mass < 0.0)
      throw InputError(SourceLocation{where},
                       added_mass_entry_name(motion.dof, motion.dof) + " = " + shortest_number(coefficient.added_mass) +
                           " " + (motion.dof < 3 ? "kg" : "kg m^2") +
                           " is negative; expected a positive added mass: a restoring force in phase with the "
                           "displacement (a floating body's hydrostatics: give --restoring C), or a wrong phase or "
                           "sign of the motion (check --axes and --phase)");
  check_finite(record, where);
  return run;
}

}  // namespace

std::vector<PmmRun> analyse_pmm_runs(const PmmRequest& request) {
  if (request.size && !(std::isfinite(*request.size) && *request.size > 0.0))
    throw InputError("--size " + shortest_number(*request.size) + ": expected a body size > 0 (m)");
  if (request.displaced_volume && !(std::isfinite(*request.displaced_volume) && *request.displaced_volume > 0.0))
    throw InputError("--volume " + shortest_number(*request.displaced_volume) + ": expected a volume > 0 (m^3)");
  if (request.restoring && !std::isfinite(*request.restoring))
    throw InputError("--restoring " + shortest_number(*request.restoring) +
                     ": expected a finite restoring coefficient C (N/m, or N m/rad for a rotation)");
  if (request.fit.harmonics < 1 || request.fit.harmonics > 10)
    throw InputError("--harmonics " + std::to_string(request.fit.harmonics) + ": expected 1 to 10");
  const ImportPlan plan = plan_request(request.import);
  const std::size_t count = plan.inputs.size();
  std::vector<std::optional<PmmRun>> results(count);
  std::atomic<std::size_t> done{0};
  std::mutex progress_mutex;
  parallel_for(count, request.import.jobs, [&](std::size_t i) {
    results[i] = analyse_one(plan.inputs[i], request);
    const std::size_t finished = ++done;
    if (request.import.progress) {
      const std::lock_guard<std::mutex> lock(progress_mutex);
      request.import.progress(finished, count, plan.inputs[i].path);
    }
  });
  std::vector<PmmRun> out;
  for (auto& result : results) out.push_back(std::move(*result));
  return out;
}

std::vector<PmmSaved> store_pmm_runs(RunDatabase& database, const std::vector<PmmRun>& runs) {
  std::vector<PmmRecord> records;
  for (const auto& run : runs) records.push_back(run.record);
  return database.save_pmm(records);
}

}  // namespace hydrocoef
