// hydrocoef fit: fit a damping law to stored runs and store it;
// hydrocoef fits: list stored fits.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/fit/coefficient_curve.hpp"
#include "src/fit/damping_law.hpp"
#include "src/fit/fit_names.hpp"
#include "src/fit/physical_checks.hpp"
#include "src/pipeline/fit_runs.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

struct FitArgs {
  std::string body;
  std::string dof;
  std::string terms;
  std::string loss = "squared";
  SelectionArgs selection;
  std::optional<std::string> name;
  std::optional<std::string> by;
  std::string curve = "polynomial:2";
  std::vector<std::string> mirror;
  std::vector<std::string> mirror_odd;
  bool no_store = false;
  bool strict = false;
  bool replace = false;
  bool refit = false;
  bool json = false;
};

std::string force_unit(std::size_t dof) { return dof < 3 ? "N" : "N m"; }
std::string velocity_unit(std::size_t component) { return component < 3 ? "m/s" : "rad/s"; }

std::string coefficient_unit(DampingTerm term, std::size_t dof, std::size_t component) {
  const int power = term_power(term);
  if (power == 0) return force_unit(dof);
  std::string out = force_unit(dof) + "/(" + velocity_unit(component) + ")";
  if (power > 1) out += "^" + std::to_string(power);
  return out;
}

nlohmann::json optional_number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

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
                     ") has no disturbance '" + name + "'; expected a velocity component or a disturbance every run has");
  return it->second;
}

struct LawSetup {
  DampingLawSpec spec;
  FitOptions options;
  std::size_t dof = 0;
  std::size_t variable = 0;
  SignConvention sign = SignConvention::OnBody;
  std::string filter_text;
  std::string unconverged;  ///< unconverged_runs_warning of the runs
  MirrorSpec mirror;
  const FitSamples* samples = nullptr;
};


/// hydrocoef fit --by NAME: the law at each level of NAME, then each
/// coefficient as a curve of the level (the paper's Fig. 7 and 10).
void run_fit_by_level(const FitArgs& args, const GlobalOptions& global, Database& database, const LawSetup& law) {
  const FitSamples& samples = *law.samples;
  const auto& x = samples.x;
  const auto& y = samples.y;
  const auto& run_ids = samples.run_ids;
  std::vector<double> levels;
  for (std::size_t i = 0; i < samples.keys.size(); ++i)
    levels.push_back(condition_value(samples.keys[i], samples.run_ids[i], *args.by));
  const auto [kind, degree] = parse_curve(args.curve);
  if (*args.by == law.spec.variable)
    throw InputError("--by " + *args.by + " is the law's own variable; expected another velocity component or a "
                     "disturbance");
  // A level with too few runs for the law is left out with a note (the
  // sweep's other levels are still fitted), or refuses the whole fit with --strict.
  std::vector<SkippedLevel> skipped;
  const auto fits = fit_per_level(law.spec, x, y, levels, law.options, args.strict ? nullptr : &skipped);
  const auto curves = fit_coefficient_curves(fits, kind, degree);
  const std::string terms = format_damping_terms(law.spec);
  const std::string base = args.name.value_or(default_fit_name(args.body, args.dof, terms, law.filter_text));
  std::vector<std::optional<std::int64_t>> ids(fits.size());
  std::vector<std::string> names;
  std::vector<FitRecord> records;
  for (const auto& level : fits) {
    names.push_back(per_level_fit_name(base, *args.by, level.level));
    if (args.no_store) continue;
    // The level's selection: the fit's own and the level, as one selection
    // that `fit --refit` reads back.
    const std::string selection = (law.filter_text.empty() ? "" : law.filter_text + " ") + *args.by + "=" + number(level.level);
    std::vector<std::int64_t> level_runs;
    for (std::size_t i = 0; i < levels.size(); ++i)
      if (levels[i] == level.level) level_runs.push_back(run_ids[i]);
    records.push_back(make_fit_record(names.back(), args.body, law.dof, law.spec, level.fit, selection, law.mirror,
                                      samples, level_runs));
  }
  // Every level's fit in one transaction: all stored, or (on any failure) none.
  if (!args.no_store) {
    const auto stored =
        database.save_fits(records, args.replace ? Database::NameTaken::Replace : Database::NameTaken::Refuse);
    for (std::size_t l = 0; l < stored.size(); ++l) ids[l] = stored[l];
  }

  if (args.json) {
    nlohmann::json out = {{"name", base},          {"body", args.body},  {"dof", args.dof},
                          {"variable", law.spec.variable}, {"terms", terms}, {"by", *args.by},
                          {"curve", args.curve},   {"where", law.filter_text},
                          {"sign_convention", std::string(to_string(law.sign))}};
    out["levels"] = nlohmann::json::array();
    for (std::size_t l = 0; l < fits.size(); ++l) {
      nlohmann::json item = {{"level", fits[l].level}, {"name", names[l]},      {"n", fits[l].fit.n},
                             {"rmse", fits[l].fit.rmse}, {"r2", optional_number(fits[l].fit.r2)},
                             {"stored", ids[l].has_value()}};
      for (std::size_t k = 0; k < law.spec.terms.size(); ++k) {
        const std::string term = term_name(law.spec.terms[k], law.spec.variable);
        item["coefficients"][term] = fits[l].fit.coefficients[k];
        item["std_errors"][term] = optional_number(fits[l].fit.std_errors[k]);
      }
      if (ids[l]) item["fit_id"] = *ids[l];
      out["levels"].push_back(item);
    }
    out["warnings"] = nlohmann::json::array();
    if (!law.unconverged.empty())
      out["warnings"].push_back({{"kind", "unconverged-runs"}, {"message", law.unconverged}});
    out["skipped_levels"] = nlohmann::json::array();
    for (const auto& level : skipped)
      out["skipped_levels"].push_back({{"level", level.level}, {"runs", level.runs}, {"reason", level.reason}});
    out["curves"] = nlohmann::json::array();
    for (std::size_t k = 0; k < curves.size(); ++k)
      out["curves"].push_back({{"term", curves[k].term},
                               {"kind", curves[k].kind == CurveKind::Pchip ? "pchip" : "polynomial"},
                               {"degree", curves[k].degree},
                               {"polynomial", curves[k].polynomial},
                               {"levels", curves[k].levels},
                               {"values", curves[k].values},
                               {"rmse", curves[k].rmse},
                               {"unit", coefficient_unit(law.spec.terms[k], law.dof, law.variable)}});
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  std::cout << "fit " << base << " at each level of " << *args.by << " (" << fits.size() << " levels)\n\n  "
            << std::left << std::setw(12) << *args.by;
  for (std::size_t k = 0; k < law.spec.terms.size(); ++k)
    std::cout << std::setw(16) << term_name(law.spec.terms[k], law.spec.variable);
  std::cout << std::setw(6) << "n" << "R^2\n";
  for (const auto& level : fits) {
    std::cout << "  " << std::setw(12) << significant(level.level, 6);
    for (double c : level.fit.coefficients) std::cout << std::setw(16) << significant(c, 7);
    std::cout << std::setw(6) << level.fit.n << significant(level.fit.r2, 6) << '\n';
  }
  std::cout << "\n  coefficient curves over " << *args.by << " (" << args.curve << "):\n";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    std::cout << "    " << std::setw(8) << curves[k].term;
    if (curves[k].kind == CurveKind::Pchip) {
      std::cout << "PCHIP through the " << curves[k].levels.size() << " per-level values";
    } else {
      for (std::size_t j = 0; j < curves[k].polynomial.size(); ++j) {
        const double c = curves[k].polynomial[j];
        std::cout << (j == 0 ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ")) << significant(std::abs(c), 6);
        if (j >= 1) std::cout << " " << *args.by;
        if (j >= 2) std::cout << "^" << j;
      }
      std::cout << "   (RMSE " << significant(curves[k].rmse, 3) << ")";
    }
    std::cout << "  [" << coefficient_unit(law.spec.terms[k], law.dof, law.variable) << "]\n";
  }
  for (const auto& level : skipped)
    std::cout << "  note: level " << *args.by << "=" << significant(level.level, 6) << " skipped: " << level.reason
              << " (--strict refuses the fit instead)\n";
  if (!law.unconverged.empty()) std::cout << "  warning (unconverged-runs): " << law.unconverged << '\n';
  if (!args.no_store) std::cout << "  stored " << fits.size() << " per-level fits in " << global.database << '\n';
}

/// hydrocoef fit --refit: the stored fits made again from the runs their
/// selections pick now (all stale fits, or the one named).
void run_refit(const FitArgs& args, const GlobalOptions& global) {
  Database database(global.database, Database::OpenMode::MustExist);
  std::vector<FitRecord> chosen;
  for (auto& fit : database.fits(args.body.empty() ? std::nullopt : std::optional<std::string>(args.body)))
    if (args.name ? fit.name == *args.name : fit.stale) chosen.push_back(std::move(fit));
  if (args.name && chosen.empty())
    throw InputError(SourceLocation{global.database}, "no fit named '" + escape::one_line(*args.name) +
                                                          "'; 'hydrocoef fits' lists them");
  std::vector<FitRecord> made;
  for (const auto& fit : chosen) made.push_back(refit(database, fit));
  if (!made.empty()) database.save_fits(made, Database::NameTaken::Replace);
  if (args.json) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i = 0; i < made.size(); ++i) {
      nlohmann::json item = {{"name", made[i].name}, {"n", made[i].n}, {"runs", made[i].run_ids},
                             {"rmse", made[i].rmse}, {"r2", optional_number(made[i].r2)}};
      for (const auto& c : made[i].coefficients) item["coefficients"][c.term] = c.value;
      for (const auto& c : chosen[i].coefficients) item["previous_coefficients"][c.term] = c.value;
      out.push_back(item);
    }
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  if (made.empty()) {
    std::cout << "no stale fits in " << global.database << "; nothing to fit again\n";
    return;
  }
  for (std::size_t i = 0; i < made.size(); ++i) {
    std::cout << "fit " << made[i].name << " made again from " << made[i].run_ids.size() << " runs (was "
              << chosen[i].run_ids.size() << ")\n   ";
    for (std::size_t k = 0; k < made[i].coefficients.size(); ++k) {
      const auto& c = made[i].coefficients[k];
      std::cout << " " << c.term << " = " << significant(c.value, 7);
      if (k < chosen[i].coefficients.size()) std::cout << " (was " << significant(chosen[i].coefficients[k].value, 7) << ")";
    }
    std::cout << '\n';
  }
  std::cout << made.size() << (made.size() == 1 ? " fit" : " fits") << " stored in " << global.database << '\n';
}

void run_fit(const FitArgs& args, const GlobalOptions& global) {
  if (args.refit) {
    if (!args.dof.empty() || !args.terms.empty() || args.by || !args.selection.where.empty() ||
        !args.selection.exclude_runs.empty() || !args.mirror.empty())
      throw InputError("--refit makes stored fits again as they were made; expected only --name, --body and --json with it");
    run_refit(args, global);
    return;
  }
  if (args.body.empty() || args.dof.empty() || args.terms.empty())
    throw InputError("fit: --body, --dof and --terms are required (or --refit to make stored fits again)");
  const auto dof = force_index(args.dof);
  if (!dof) throw InputError("--dof '" + args.dof + "': expected one of X Y Z K M N");
  const DampingLawSpec spec = parse_damping_terms(args.terms);
  const FitOptions options = parse_loss(args.loss);
  const std::size_t variable = *velocity_index(spec.variable);
  if (args.name) check_name(NameKind::Fit, *args.name, {}, "--name");
  check_name(NameKind::Body, args.body, {}, "--body");
  const MirrorSpec mirror = make_mirror_spec(args.mirror, args.mirror_odd);

  Database database(global.database, Database::OpenMode::MustExist);
  const RunSelection selection = parse_selection(args.selection.where, args.selection.exclude_runs);
  const std::string filter_text = selection.text();
  const FitSamples samples = gather_fit_samples(database, args.body, *dof, variable, selection, mirror);
  const auto& runs = samples.runs;
  const SignConvention sign = samples.sign;
  const auto& x = samples.x;
  const auto& y = samples.y;
  const std::string terms = format_damping_terms(spec);
  if (args.by) {
    LawSetup law{spec, options, *dof, variable, sign, filter_text, unconverged_runs_warning(runs, *dof), mirror, &samples};
    run_fit_by_level(args, global, database, law);
    return;
  }
  const DampingLawFit fit = fit_damping_law(spec, x, y, options);
  const std::string name = args.name.value_or(default_fit_name(args.body, args.dof, terms, filter_text));
  const auto varying = varying_conditions(runs, variable);
  // Physical checks (src/fit/physical_checks): warnings here, refusals at export-gazebo.
  LawCheckInput check;
  check.spec = spec;
  check.coefficients = fit.coefficients;
  check.std_errors = fit.std_errors;
  check.sign = sign;
  check.x_min = *std::min_element(x.begin(), x.end());
  check.x_max = *std::max_element(x.begin(), x.end());
  check.x = x;
  check.y = y;
  const auto problems = check_damping_law(check);
  const std::string unconverged = unconverged_runs_warning(runs, *dof);

  std::optional<std::int64_t> fit_id;
  if (!args.no_store)
    fit_id = database.save_fit(make_fit_record(name, args.body, *dof, spec, fit, filter_text, mirror, samples, samples.run_ids),
                               args.replace ? Database::NameTaken::Replace : Database::NameTaken::Refuse);
  std::vector<std::int64_t> run_ids;
  for (const auto& run : runs) run_ids.push_back(run.id);
  const std::size_t images = samples.keys.size() - runs.size();

  if (args.json) {
    nlohmann::json out = {{"name", name},
                          {"body", args.body},
                          {"dof", args.dof},
                          {"variable", spec.variable},
                          {"terms", terms},
                          {"loss", fit.loss},
                          {"where", filter_text},
                          {"sign_convention", std::string(to_string(sign))},
                          {"rmse", fit.rmse},
                          {"r2", optional_number(fit.r2)},
                          {"n", fit.n},
                          {"runs", run_ids},
                          {"mirror", mirror.text()},
                          {"mirror_images", images},
                          {"varying_conditions", varying},
                          {"stored", fit_id.has_value()}};
    out["warnings"] = nlohmann::json::array();
    for (const auto& problem : problems)
      out["warnings"].push_back({{"kind", std::string(law_problem_name(problem.problem))}, {"message", problem.message}});
    if (!unconverged.empty()) out["warnings"].push_back({{"kind", "unconverged-runs"}, {"message", unconverged}});
    out["coefficients"] = nlohmann::json::object();
    out["std_errors"] = nlohmann::json::object();
    out["units"] = nlohmann::json::object();
    for (std::size_t k = 0; k < spec.terms.size(); ++k) {
      const std::string term = term_name(spec.terms[k], spec.variable);
      out["coefficients"][term] = fit.coefficients[k];
      out["std_errors"][term] = optional_number(fit.std_errors[k]);
      out["units"][term] = coefficient_unit(spec.terms[k], *dof, variable);
    }
    if (fit_id) out["fit_id"] = *fit_id;
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }

  std::ostringstream law;
  law << args.dof << "(" << spec.variable << ") =";
  for (std::size_t k = 0; k < spec.terms.size(); ++k) {
    const double c = fit.coefficients[k];
    law << (k == 0 ? (c < 0 ? " -" : " ") : (c < 0 ? " - " : " + ")) << significant(std::abs(c), 6);
    if (spec.terms[k] != DampingTerm::Constant) law << " " << term_name(spec.terms[k], spec.variable);
  }
  std::cout << "fit " << name << "\n  " << law.str() << "\n  sign convention: "
            << (sign == SignConvention::OnBody ? "force on the body (damping is negative)"
                                               : "as tabulated, positive opposes motion")
            << "\n\n";
  std::cout << std::left << "  " << std::setw(8) << "term" << std::setw(16) << "coefficient" << std::setw(14)
            << "std. error" << "unit\n";
  for (std::size_t k = 0; k < spec.terms.size(); ++k)
    std::cout << "  " << std::setw(8) << term_name(spec.terms[k], spec.variable) << std::setw(16)
              << significant(fit.coefficients[k], 7) << std::setw(14)
              << (std::isfinite(fit.std_errors[k]) ? significant(fit.std_errors[k], 3) : "n/a")
              << coefficient_unit(spec.terms[k], *dof, variable) << '\n';
  if (images > 0 || samples.images_skipped > 0)
    std::cout << "\n  mirror " << mirror.text() << ": " << runs.size() << " runs and " << images
              << " mirror images (never stored as runs)"
              << (samples.images_skipped ? "; " + std::to_string(samples.images_skipped) +
                                               " images left out at the keys of measured runs"
                                         : std::string())
              << '\n';
  std::cout << "\n  n = " << fit.n << " samples, RMSE = " << significant(fit.rmse, 4) << " " << force_unit(*dof)
            << ", R^2 = " << significant(fit.r2, 8)
            << (std::isnan(fit.r2) ? " (the force does not vary over these runs)" : "") << ", loss " << fit.loss
            << '\n';
  if (!varying.empty()) {
    std::string names;
    for (const auto& v : varying) names += (names.empty() ? "" : ", ") + v;
    std::cout << "  note: the runs differ in " << names << "; add --where NAME=VALUE to fit one condition\n";
  }
  for (const auto& problem : problems)
    std::cout << "  warning (" << law_problem_name(problem.problem) << "): " << problem.message << '\n';
  if (!unconverged.empty()) std::cout << "  warning (unconverged-runs): " << unconverged << '\n';
  if (fit_id) std::cout << "  stored as fit " << *fit_id << " in " << global.database << '\n';
}

struct FitsArgs {
  std::optional<std::string> body;
  bool json = false;
};

void run_fits(const FitsArgs& args, const GlobalOptions& global) {
  Database database(global.database, Database::OpenMode::ReadOnly);
  const auto fits = database.fits(args.body);
  if (args.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& fit : fits) {
      nlohmann::json item = {{"id", fit.id},         {"name", fit.name},     {"body", fit.body},
                             {"dof", fit.dof},       {"variable", fit.variable}, {"terms", fit.terms},
                             {"loss", fit.loss},     {"where", fit.run_filter},
                             {"sign_convention", std::string(to_string(fit.sign))},
                             {"n", fit.n},           {"rmse", fit.rmse},     {"r2", fit.r2},
                             {"created_at", fit.created_at}, {"runs", fit.run_ids}, {"stale", fit.stale},
                             {"mirror", fit.mirror}};
      item["coefficients"] = nlohmann::json::object();
      item["std_errors"] = nlohmann::json::object();
      for (const auto& c : fit.coefficients) {
        item["coefficients"][c.term] = c.value;
        item["std_errors"][c.term] = c.std_error ? nlohmann::json(*c.std_error) : nlohmann::json();
      }
      out.push_back(item);
    }
    std::cout << escape::json_text(out, 2) << '\n';
    return;
  }
  if (fits.empty()) {
    std::cout << "no fits in " << global.database << '\n';
    return;
  }
  for (const auto& fit : fits) {
    std::cout << fit.id << "  " << fit.name << "  [" << to_string(fit.sign) << ", n=" << fit.n
              << ", RMSE=" << significant(fit.rmse, 4) << ", R^2=" << significant(fit.r2, 8) << "]"
              << (fit.stale ? "  STALE: a force of its runs changed or was deleted since; fit --refit makes it again"
                            : "")
              << "\n    from " << fit.run_ids.size() << (fit.run_ids.size() == 1 ? " run" : " runs")
              << (fit.run_filter.empty() ? "" : " where " + fit.run_filter)
              << (fit.mirror.empty() ? "" : ", with mirror images (" + fit.mirror + ")") << "\n    ";
    for (const auto& c : fit.coefficients) std::cout << c.term << "=" << significant(c.value, 7) << "  ";
    std::cout << '\n';
  }
}

}  // namespace

void add_fit_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<FitArgs>();
  auto* command = app.add_subcommand(
      "fit", "Fit a damping law F_dof = sum c_k term_k(x) to the runs of a body (Ceres least squares) and store it");
  command->add_option("--body", args->body, "Body whose runs are fitted (required unless --refit)");
  command->add_option("--dof", args->dof, "Force component: X Y Z K M N (required unless --refit)");
  command->add_option("--terms", args->terms, "Terms of one velocity component x: 1, x, x|x|, x^2, x^3, |x| "
                                              "(e.g. 1,u,u|u|; required unless --refit)");
  command->add_option("--loss", args->loss, "squared, or a robust loss huber:S, cauchy:S, soft-l1:S (S in N or N m)")
      ->capture_default_str();
  add_selection_options(*command, args->selection);
  command->add_option("--name", args->name,
                      "Name to store the fit under (default body:dof(terms), then @selection; a level of --by "
                      "adds [by=level])");
  command->add_flag("--replace", args->replace, "Replace a stored fit of the same name (otherwise refused)");
  command->add_flag("--refit", args->refit,
                    "Make stored fits again from the runs their selections pick now: every stale fit, or the one "
                    "given with --name (--body limits them)");
  add_mirror_options(*command, args->mirror, args->mirror_odd);
  command->add_option("--by", args->by,
                      "Fit the law separately at each level of this velocity component or disturbance, then each "
                      "coefficient as a curve of the level");
  command->add_option("--curve", args->curve, "With --by: polynomial:D (least squares, degree D) or pchip")
      ->capture_default_str();
  command->add_flag("--strict", args->strict,
                    "With --by: refuse the fit when a level has too few runs for the law (default: skip it with a "
                    "note)");
  command->add_flag("--no-store", args->no_store, "Do not store the fit");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_fit(*args, global); });

  auto fits_args = std::make_shared<FitsArgs>();
  auto* list = app.add_subcommand("fits", "List stored damping-law fits");
  list->add_option("--body", fits_args->body, "Only fits of this body");
  list->add_flag("--json", fits_args->json, "Print JSON");
  list->callback([fits_args, &global] { run_fits(*fits_args, global); });
}


}  // namespace hydrocoef::cli
