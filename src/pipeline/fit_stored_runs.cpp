#include "src/pipeline/fit_stored_runs.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"
#include "src/fit/fit_names.hpp"
#include "src/fit/physical_checks.hpp"

namespace hydrocoef {
namespace {

/// Names of the key parts (other velocity components, disturbances) that take
/// more than one value among the runs: the law then mixes conditions.
std::vector<std::string> varying_conditions(const std::vector<StoredRun>& runs, std::size_t variable) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < 6; ++i) {
    if (i == variable) continue;
    std::set<double> values;
    for (const auto& run : runs) values.insert(run.key.nu_b[i]);
    if (values.size() > 1) out.emplace_back(kVelocityNames[i]);
  }
  std::map<std::string, std::set<double>> disturbances;
  for (const auto& run : runs)
    for (const auto& [name, value] : run.key.disturbances) disturbances[name].insert(value);
  for (const auto& [name, values] : disturbances)
    if (values.size() > 1) out.push_back(name);
  return out;
}

/// The value of a velocity component or disturbance in a sample's key.
double condition_value(const RunKey& key, std::int64_t run_id, const std::string& name) {
  if (const auto v = velocity_index(name)) return key.nu_b[*v];
  const auto it = key.disturbances.find(name);
  if (it == key.disturbances.end())
    throw InputError("--by " + name + ": run " + std::to_string(run_id) + " (" + describe(key) +
                     ") has no disturbance '" + name +
                     "'; expected a velocity component or a disturbance every run has");
  return it->second;
}

/// The checked request: law, loss, names, selection, mirror, and the samples.
FitSetup prepare(RunDatabase& database, const FitRequest& request, LossOptions& options) {
  if (request.body.empty() || request.dof.empty() || request.terms.empty())
    throw InputError("fit: --body, --dof and --terms are required (or --refit to make stored fits again)");
  const auto dof = force_index(request.dof);
  if (!dof) throw InputError("--dof '" + request.dof + "': expected one of X Y Z K M N");
  FitSetup setup;
  setup.spec = parse_damping_terms(request.terms);
  options = parse_loss(request.loss);
  setup.dof = *dof;
  setup.variable = *velocity_index(setup.spec.variable);
  if (request.name) check_name(NameKind::Fit, *request.name, {}, "--name");
  check_name(NameKind::Body, request.body, {}, "--body");
  setup.mirror = make_mirror_spec(request.mirror_planes, request.mirror_odd);
  const RunSelection selection = parse_selection(request.where, request.exclude_runs);
  setup.selection = selection.text();
  setup.samples = gather_fit_samples(database, request.body, setup.dof, setup.variable, selection, setup.mirror);
  for (const auto term : setup.spec.terms)
    setup.coefficient_units.push_back(coefficient_unit(term, setup.dof, setup.variable));
  return setup;
}

void add_unconverged_warning(FitSetup& setup) {
  const std::string unconverged = unconverged_runs_warning(setup.samples.runs, setup.dof);
  if (!unconverged.empty()) setup.warnings.push_back({"unconverged-runs", unconverged});
}

}  // namespace

std::vector<std::int64_t> FitResult::run_ids() const {
  std::vector<std::int64_t> out;
  for (const auto& run : setup.samples.runs) out.push_back(run.id);
  return out;
}

FitResult fit_stored_runs(RunDatabase& database, const FitRequest& request) {
  LossOptions options;
  FitResult result;
  result.setup = prepare(database, request, options);
  const FitSamples& samples = result.setup.samples;
  const DampingLawSpec& spec = result.setup.spec;
  std::string weight_note;
  result.fit =
      fit_damping_law(spec, samples.x, samples.y, options, fit_weights(samples, request.weighted, &weight_note));
  if (!weight_note.empty()) result.setup.warnings.push_back({"unweighted", weight_note});
  if (result.fit.weighted && std::isfinite(result.fit.chi2_reduced)) {
    // How far the scatter agrees with the stated uncertainties: chi^2/(n-k)
    // has a standard deviation of about sqrt(2/(n-k)); beyond three of them
    // the disagreement is worth a warning.
    const double spread = 3.0 * std::sqrt(2.0 / static_cast<double>(result.fit.n - spec.terms.size()));
    if (result.fit.chi2_reduced > 1.0 + spread)
      result.setup.warnings.push_back(
          {"scatter-exceeds-uncertainty",
           "reduced chi^2 = " + shortest_number(result.fit.chi2_reduced) +
               ": the runs scatter about the law more than their uncertainties say (the law misses something, "
               "or the uncertainties are understated); the coefficients' covariance is scaled by it (Birge "
               "ratio " +
               shortest_number(std::sqrt(result.fit.chi2_reduced)) + ")"});
    else if (result.fit.chi2_reduced < 1.0 - spread)
      result.setup.warnings.push_back(
          {"scatter-below-uncertainty", "reduced chi^2 = " + shortest_number(result.fit.chi2_reduced) +
                                            ": the runs scatter about the law less than their uncertainties say "
                                            "(the uncertainties are overstated)"});
  }
  result.name = request.name.value_or(
      default_fit_name(request.body, request.dof, format_damping_terms(spec), result.setup.selection));
  result.varying_conditions = varying_conditions(samples.runs, result.setup.variable);
  // Physical checks (src/fit/physical_checks): warnings here, refusals at export-gazebo.
  LawCheckInput check;
  check.spec = spec;
  check.coefficients = result.fit.coefficients;
  check.std_errors = result.fit.std_errors;
  check.sign = samples.sign;
  check.x_min = *std::min_element(samples.x.begin(), samples.x.end());
  check.x_max = *std::max_element(samples.x.begin(), samples.x.end());
  check.x = samples.x;
  check.y = samples.y;
  for (const auto& problem : check_damping_law(check))
    result.setup.warnings.push_back({std::string(law_problem_name(problem.problem)), problem.message});
  add_unconverged_warning(result.setup);
  if (request.store)
    result.fit_id =
        database.save_fit(make_fit_record(result.name, request.body, result.setup.dof, spec, result.fit,
                                          result.setup.selection, result.setup.mirror, samples, samples.run_ids),
                          request.taken);
  return result;
}

LevelFitResult fit_stored_runs_by_level(RunDatabase& database, const LevelFitRequest& request) {
  LossOptions options;
  LevelFitResult result;
  result.setup = prepare(database, request.fit, options);
  const FitSamples& samples = result.setup.samples;
  const DampingLawSpec& spec = result.setup.spec;
  if (request.by == spec.variable)
    throw InputError("--by " + request.by +
                     " is the law's own variable; expected another velocity component or a "
                     "disturbance");
  const auto [kind, degree] = parse_curve(request.curve);
  std::vector<double> levels;
  for (std::size_t i = 0; i < samples.keys.size(); ++i)
    levels.push_back(condition_value(samples.keys[i], samples.run_ids[i], request.by));
  // A level with too few runs for the law is left out with a note (the
  // sweep's other levels are still fitted), or refuses the whole fit when strict.
  result.levels =
      fit_per_level(spec, samples.x, samples.y, levels, options, request.strict ? nullptr : &result.skipped);
  result.curves = fit_coefficient_curves(result.levels, kind, degree);
  add_unconverged_warning(result.setup);
  result.base_name = request.fit.name.value_or(
      default_fit_name(request.fit.body, request.fit.dof, format_damping_terms(spec), result.setup.selection));
  result.ids.resize(result.levels.size());
  std::vector<FitRecord> records;
  for (const auto& level : result.levels) {
    result.names.push_back(per_level_fit_name(result.base_name, request.by, level.level));
    // The level's selection: the fit's own and the level, as one selection that a refit reads back.
    const std::string selection = (result.setup.selection.empty() ? "" : result.setup.selection + " ") + request.by +
                                  "=" + shortest_number(level.level);
    std::vector<std::int64_t> level_runs;
    for (std::size_t i = 0; i < levels.size(); ++i)
      if (levels[i] == level.level) level_runs.push_back(samples.run_ids[i]);
    records.push_back(make_fit_record(result.names.back(), request.fit.body, result.setup.dof, spec, level.fit,
                                      selection, result.setup.mirror, samples, level_runs));
  }
  // Every level's fit in one transaction: all stored, or (on any failure) none.
  if (request.fit.store) {
    const auto stored = database.save_fits(records, request.fit.taken);
    for (std::size_t l = 0; l < stored.size(); ++l) result.ids[l] = stored[l];
  }
  return result;
}

RefitResult refit_stored_fits(RunDatabase& database, const std::optional<std::string>& name,
                              const std::optional<std::string>& body) {
  RefitResult result;
  for (auto& fit : database.fits(body))
    if (name ? fit.name == *name : fit.stale) result.previous.push_back(std::move(fit));
  if (name && result.previous.empty())
    throw InputError(SourceLocation{database.path().string()},
                     "no fit named '" + escape::one_line(*name) + "'; 'hydrocoef fits' lists them");
  for (const auto& fit : result.previous) result.made.push_back(refit(database, fit));
  if (!result.made.empty()) database.save_fits(result.made, RunDatabase::NameTaken::Replace);
  return result;
}

std::vector<FitRecord> fits_made_from(RunDatabase& database, const std::string& body, const RunSelection& selection) {
  const auto bodies = database.bodies();
  if (std::find(bodies.begin(), bodies.end(), body) == bodies.end()) {
    std::string names;
    for (const auto& name : bodies) names += (names.empty() ? "" : ", ") + name;
    throw InputError("no body '" + body + "' in " + database.path().string() +
                     "; expected one of: " + (names.empty() ? "(none)" : names));
  }
  auto fits = database.fits(body);
  if (selection.empty()) return fits;
  const std::string wanted = selection.text();
  std::erase_if(fits, [&](const FitRecord& fit) {
    try {
      return parse_selection_text(fit.run_filter).text() != wanted;
    } catch (const InputError&) {
      return true;  // a selection this version cannot read is no match
    }
  });
  if (fits.empty())
    throw InputError("no fits of body '" + body + "' made from the runs where " + wanted + " in " +
                     database.path().string() + "; 'hydrocoef fits' shows each fit's selection");
  return fits;
}

std::pair<CurveKind, int> parse_curve(const std::string& text) {
  if (text == "pchip") return {CurveKind::Pchip, 3};
  if (text.rfind("polynomial:", 0) == 0) {
    const std::string degree = text.substr(11);
    if (degree.size() == 1 && degree[0] >= '0' && degree[0] <= '9') return {CurveKind::Polynomial, degree[0] - '0'};
  }
  throw InputError("--curve '" + text + "': expected polynomial:D (D a degree 0 to 9) or pchip");
}

std::string coefficient_unit(DampingTerm term, std::size_t dof, std::size_t variable) {
  const int power = term_power(term);
  if (power == 0) return force_unit(dof);
  std::string out = force_unit(dof) + "/(" + velocity_unit(variable) + ")";
  if (power > 1) out += "^" + std::to_string(power);
  return out;
}

}  // namespace hydrocoef
