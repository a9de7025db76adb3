// Forced oscillation (include/hydrocoef/analysis.hpp): `hydrocoef pmm`,
// `pmm-runs`, `pmm-runs delete` and `added-mass` without their printing. The
// analysis is src/pipeline/pmm_runs, the assembly src/pmm/added_mass_assembly;
// their numbers become the public results here, whose text and JSON are
// src/api/analysis_pmm_report.cpp.
#include "src/api/internal.hpp"

#include <cmath>
#include <numbers>

#include "hydrocoef/analysis.hpp"
#include "src/api/analysis_format.hpp"
#include "src/core/numbers.hpp"
#include "src/loads/frame.hpp"
#include "src/pipeline/pmm_runs.hpp"
#include "src/pmm/added_mass_assembly.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef {
inline namespace api {

/// What store_pmm stores: the records analyse_pmm made, kept with the result.
struct PmmAnalysis::Access {
  static void keep(PmmAnalysis& analysis, std::shared_ptr<const std::vector<PmmRecord>> records) {
    analysis.records_ = std::move(records);
  }
  static const std::vector<PmmRecord>* records(const PmmAnalysis& analysis) {
    return static_cast<const std::vector<PmmRecord>*>(analysis.records_.get());
  }
};

namespace {

std::string added_mass_unit(std::size_t i, std::size_t j) {
  const int rotations = int(i >= 3) + int(j >= 3);
  return rotations == 0 ? "kg" : rotations == 1 ? "kg m" : "kg m^2";
}

std::string damping_unit(std::size_t i, std::size_t j) {
  const int rotations = int(i >= 3) + int(j >= 3);
  return rotations == 0 ? "N s/m" : rotations == 1 ? "N s" : "N m s";
}

/// The command line's settings layer of `hydrocoef pmm`, each value
/// remembered as coming from its option (as cli/surface_options does it).
SettingsLayer settings_of(const PmmOptions& options) {
  SettingsLayer layer;
  layer.origin = SettingOrigin{SettingSource::CommandLine, "command line"};
  const auto set_number = [&](const char* name, const std::optional<double>& value, const char* option) {
    if (!value) return;
    if (!std::isfinite(*value)) throw InputError(std::string(option) + ": expected a finite number");
    layer.set(name, *value, option);
  };
  const auto set_triple = [&](const char* name, const std::optional<std::array<double, 3>>& value, const char* option) {
    if (!value) return;
    for (const double x : *value)
      if (!std::isfinite(x)) throw InputError(std::string(option) + ": expected three finite numbers x,y,z");
    layer.set(name, std::vector<double>(value->begin(), value->end()), option);
  };
  if (!options.body.empty())
    layer.set("body", std::string(check_name(NameKind::Body, options.body, {}, "--body")), "--body");
  set_number("rho", options.rho, "--rho");
  set_number("nu", options.nu, "--nu");
  set_triple("ref_point", options.ref_point, "--ref-point");
  if (!options.axes.empty()) {
    parse_axes(options.axes);  // refused here, naming the option, rather than later
    layer.set("axes", options.axes, "--axes");
  }
  set_triple("origin", options.origin, "--origin");
  for (const auto& [name, value] : options.set) {
    if (!std::isfinite(value))
      throw InputError("--set '" + name + "=" + shortest_number(value) + "': expected a finite number");
    if (velocity_index(name)) {
      layer.set(name, value, "--set");
    } else {
      check_name(NameKind::Parameter, name, {}, "--set");
      layer.set("disturbance." + name, value, "--set");
    }
  }
  if (options.sign) layer.set("sign", *options.sign, "--sign");
  return layer;
}

std::optional<HarmonicMotion> motion_of(const PmmOptions& options) {
  const int given =
      int(options.motion.has_value()) + int(options.amplitude.has_value()) + int(options.period.has_value());
  if (given != 0 && given != 3)
    throw InputError("--motion, --amplitude and --period: found " + std::to_string(given) +
                     " of them; expected all three or none (none: the motion stated by the case)");
  if (given == 0) return std::nullopt;
  return motion_from_options(*options.motion, *options.amplitude, *options.period, options.phase);
}

PmmRequest request_of(const std::vector<std::string>& inputs, const PmmOptions& options) {
  PmmRequest request;
  for (const auto& input : inputs) request.import.inputs.emplace_back(input);
  request.import.command_line = settings_of(options);
  request.import.format = "auto";  // read_body_history refuses what is not a history
  request.import.columns.columns = options.columns;
  request.import.columns.units = options.units;
  request.import.jobs = options.jobs;
  if (options.progress)
    request.import.progress = [progress = options.progress](std::size_t done, std::size_t total,
                                                            const std::filesystem::path& path) {
      progress(done, total, path.string());
    };
  request.motion = motion_of(options);
  if (options.ccl) request.ccl = *options.ccl;
  request.fit.harmonics = options.harmonics;
  request.fit.start_time = options.start;
  request.medium = options.stream ? PmmMedium::OscillatingStream : PmmMedium::StillWater;
  request.size = options.size;
  request.displaced_volume = options.volume;
  request.restoring = options.restoring;
  return request;
}

PmmRunResult run_result(const PmmRun& run) {
  const PmmRecord& r = run.record;
  PmmRunResult out;
  out.path = run.path.string();
  out.format = run.format;
  out.body = r.body;
  out.velocity = r.nu_b;
  out.dof = std::string(dof_name(r.dof));
  out.amplitude = r.amplitude;
  out.omega = r.omega;
  out.period = 2.0 * std::numbers::pi / r.omega;
  out.phase = r.phase;
  out.motion_source = r.motion_source;
  out.medium = pmm_medium_name(r.medium);
  out.window_start = r.window_start;
  out.window_end = r.window_end;
  out.periods = r.periods;
  out.transient_periods = r.transient_periods;
  out.samples = r.samples;
  out.harmonics = r.harmonics;
  out.size = r.size;
  out.keulegan_carpenter = r.keulegan_carpenter;
  out.stokes_number = r.stokes_number;
  out.rho = r.rho;
  out.displaced_volume = r.displaced_volume;
  out.restoring = r.restoring;
  out.notes = run.notes;
  for (const auto& c : r.coefficients) {
    PmmComponent component;
    component.component = std::string(kForceNames[c.component]);
    component.mean = c.mean;
    component.added_mass = c.added_mass;
    component.added_mass_se = c.added_mass_se;
    component.added_mass_unit = added_mass_unit(c.component, r.dof);
    component.damping = c.damping;
    component.damping_se = c.damping_se;
    component.damping_unit = damping_unit(c.component, r.dof);
    component.explained = c.explained;
    component.harmonics = c.harmonics;
    if (c.component == r.dof && r.rho && r.displaced_volume && r.dof < 3)
      component.added_mass_coefficient = c.added_mass / (*r.rho * *r.displaced_volume);
    // The cycle-to-cycle spread: standard deviations of s1 and c1 fitted period by period.
    const HarmonicComponent& fit = run.analysis.components[c.component];
    component.in_phase_spread = fit.in_phase_spread;
    component.quadrature_spread = fit.quadrature_spread;
    out.components.push_back(std::move(component));
  }
  return out;
}

AddedMassOptions assembly_options(const AddedMassMatrixOptions& options) {
  return added_mass_options(options.same, options.zero, options.period);
}

Matrix6x6 matrix_of(const Matrix6& m) {
  Matrix6x6 out{};
  for (Eigen::Index i = 0; i < 6; ++i)
    for (Eigen::Index j = 0; j < 6; ++j) out[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = m(i, j);
  return out;
}

AddedMassMatrix matrix_result(const AddedMassAssembly& a) {
  AddedMassMatrix out;
  out.body = a.body;
  out.omega = a.omega;
  out.period = 2.0 * std::numbers::pi / a.omega;
  out.records = a.records;
  out.other_frequency_records = a.other_frequency_records;
  out.added_mass = matrix_of(a.added_mass);
  out.added_mass_se = matrix_of(a.added_mass_se);
  out.damping = matrix_of(a.damping);
  out.damping_se = matrix_of(a.damping_se);
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j) {
      const PmmEntry& e = a.measured[i][j];
      if (!e.runs) continue;
      out.entries.push_back({std::string(dof_name(i)), std::string(dof_name(j)), added_mass_entry_name(i, j),
                             added_mass_unit(i, j), e.runs, e.added_mass, e.added_mass_se, e.added_mass_spread,
                             e.damping, e.damping_se, e.omega_min, e.omega_max, e.kc_min, e.kc_max, e.record_ids});
    }
  out.missing = a.missing;
  out.notes = a.notes;
  out.positive_definite = a.positive_definite;
  out.smallest_eigenvalue = a.smallest_eigenvalue;
  for (const auto& q : a.quadratic)
    out.quadratic_damping.push_back({std::string(dof_name(q.dof)), q.omega, q.amplitudes, q.fit.linear, q.fit.linear_se,
                                     q.fit.quadratic, q.fit.quadratic_se});
  for (const auto& f : a.by_frequency)
    out.by_frequency.push_back({std::string(dof_name(f.dof)), f.omega, 2.0 * std::numbers::pi / f.omega, f.runs,
                                f.amplitude_min, f.amplitude_max, f.added_mass, f.added_mass_se, f.damping,
                                f.damping_se, f.omega == a.omega});
  return out;
}

}  // namespace

void PmmOptions::validate() const {
  (void)settings_of(*this);
  (void)motion_of(*this);
  if (size && !(std::isfinite(*size) && *size > 0.0))
    throw InputError("--size " + shortest_number(*size) + ": expected a body size > 0 (m)");
  if (volume && !(std::isfinite(*volume) && *volume > 0.0))
    throw InputError("--volume " + shortest_number(*volume) + ": expected a volume > 0 (m^3)");
  if (restoring && !std::isfinite(*restoring))
    throw InputError("--restoring " + shortest_number(*restoring) +
                     ": expected a finite restoring coefficient C (N/m, or N m/rad for a rotation)");
  if (harmonics < 1 || harmonics > 10)
    throw InputError("--harmonics " + std::to_string(harmonics) + ": expected 1 to 10");
}

PmmAnalysis analyse_pmm(const std::vector<std::string>& inputs, const PmmOptions& options) {
  options.validate();
  const std::vector<PmmRun> runs = analyse_pmm_runs(request_of(inputs, options));
  PmmAnalysis out;
  auto records = std::make_shared<std::vector<PmmRecord>>();
  for (const PmmRun& run : runs) {
    out.runs.push_back(run_result(run));
    records->push_back(run.record);
  }
  PmmAnalysis::Access::keep(out, std::move(records));
  return out;
}

void store_pmm(Database& database, PmmAnalysis& analysis) {
  const auto* records = PmmAnalysis::Access::records(analysis);
  if (!records || records->size() != analysis.runs.size())
    throw std::invalid_argument("hydrocoef::store_pmm: the analysis was not made by analyse_pmm");
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  const std::vector<PmmSaved> saved = impl.writable_store("storing forced-oscillation runs").save_pmm(*records);
  for (std::size_t k = 0; k < saved.size() && k < analysis.runs.size(); ++k) {
    analysis.runs[k].stored_id = saved[k].id;
    analysis.runs[k].replaced = saved[k].replaced;
  }
  analysis.stored = !saved.empty();
  analysis.database = impl.path;
}

PmmRunList pmm_runs(const Database& database, const std::string& body) {
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  const auto records =
      impl.open_store().pmm_records(body.empty() ? std::nullopt : std::optional<std::string>(body), false);
  PmmRunList out;
  for (const PmmRecord& r : records) {
    PmmRunSummary s;
    s.id = r.id;
    s.body = r.body;
    s.dof = std::string(dof_name(r.dof));
    s.amplitude = r.amplitude;
    s.amplitude_unit = r.dof < 3 ? "m" : "rad";
    s.period = 2.0 * std::numbers::pi / r.omega;
    s.omega = r.omega;
    s.medium = pmm_medium_name(r.medium);
    s.restoring = r.restoring;
    for (const auto& c : r.coefficients)
      if (c.component == r.dof) {
        s.added_mass = c.added_mass;
        s.damping = c.damping;
        break;
      }
    s.added_mass_unit = added_mass_unit(r.dof, r.dof);
    s.damping_unit = damping_unit(r.dof, r.dof);
    s.source_path = r.source_path;
    s.created_at = r.created_at;
    out.runs.push_back(std::move(s));
  }
  return out;
}

PmmDeletion delete_pmm_runs(Database& database, const std::vector<std::int64_t>& ids) {
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  PmmDeletion out;
  for (const PmmDeleted& d : impl.writable_store("deleting forced-oscillation runs").delete_pmm_runs(ids))
    out.deleted.push_back(
        {d.id, d.body, d.dof >= 0 && d.dof < 6 ? std::string(dof_name(static_cast<std::size_t>(d.dof))) : std::string(),
         d.source_path});
  out.database = impl.path;
  return out;
}

void AddedMassMatrixOptions::validate() const { (void)assembly_options(*this); }

AddedMassMatrix added_mass_matrix(const Database& database, const AddedMassMatrixOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  const AddedMassAssembly assembly =
      assemble_added_mass(options.body, impl.open_store().pmm_records(options.body, false), assembly_options(options));
  if (!assembly.positive_definite && !options.allow_indefinite)
    throw InputError("body '" + printable_text(options.body, 80) +
                     "': the assembled M_A is not positive definite (smallest eigenvalue " +
                     analysis_format::significant(assembly.smallest_eigenvalue, 6) +
                     " over the DOFs with a non-zero diagonal); expected positive definite: check the runs' "
                     "signs and phases (pmm --axes) and restoring forces (pmm --restoring), or give "
                     "--allow-indefinite to print it");
  return matrix_result(assembly);
}

}  // namespace api
}  // namespace hydrocoef
