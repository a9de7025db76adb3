// hydrocoef fit: fit a damping law to stored runs and store it;
// hydrocoef fits: list stored fits.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/fit/damping_law.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

struct FitArgs {
  std::string body;
  std::string dof;
  std::string terms;
  std::string loss = "squared";
  std::vector<std::string> where;
  std::optional<std::string> name;
  bool no_store = false;
  bool json = false;
};

std::string force_unit(std::size_t dof) { return dof < 3 ? "N" : "N m"; }
std::string velocity_unit(std::size_t component) { return component < 3 ? "m/s" : "rad/s"; }

int term_power(DampingTerm term) {
  switch (term) {
    case DampingTerm::Constant: return 0;
    case DampingTerm::Linear:
    case DampingTerm::AbsLinear: return 1;
    case DampingTerm::SignedQuadratic:
    case DampingTerm::Quadratic: return 2;
    case DampingTerm::Cubic: return 3;
  }
  return 0;
}

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

void run_fit(const FitArgs& args, const GlobalOptions& global) {
  const auto dof = force_index(args.dof);
  if (!dof) throw InputError("--dof '" + args.dof + "': expected one of X Y Z K M N");
  const DampingLawSpec spec = parse_damping_terms(args.terms);
  const FitOptions options = parse_loss(args.loss);
  const std::size_t variable = *velocity_index(spec.variable);

  Database database(global.database, Database::OpenMode::MustExist);
  RunFilter filter;
  filter.body = args.body;
  filter.with_force = *dof;
  std::string filter_text;
  for (const auto& text : args.where) {
    filter.equal.insert(parse_assignment(text, "--where"));
    filter_text += (filter_text.empty() ? "" : ",") + text;
  }
  const auto runs = database.runs(filter);
  if (runs.empty())
    throw InputError("no runs of body '" + args.body + "' with " + args.dof +
                     (filter_text.empty() ? "" : " where " + filter_text) + " in " + global.database);

  // Values keep the convention they were imported in when all runs agree;
  // mixed conventions are brought to forces on the body.
  std::set<SignConvention> conventions;
  for (const auto& run : runs) conventions.insert(run.tau_b[*dof]->sign);
  const SignConvention sign = conventions.size() == 1 ? *conventions.begin() : SignConvention::OnBody;
  std::vector<double> x, y;
  std::vector<std::int64_t> run_ids;
  for (const auto& run : runs) {
    const auto& force = *run.tau_b[*dof];
    x.push_back(run.key.nu_b[variable]);
    y.push_back(force.sign == sign ? force.value.total : -force.value.total);
    run_ids.push_back(run.id);
  }
  const DampingLawFit fit = fit_damping_law(spec, x, y, options);
  const std::string terms = format_damping_terms(spec);
  const std::string name =
      args.name.value_or(args.body + ":" + args.dof + "(" + terms + ")" + (filter_text.empty() ? "" : "@" + filter_text));
  const auto varying = varying_conditions(runs, variable);

  std::optional<std::int64_t> fit_id;
  if (!args.no_store) {
    FitRecord record;
    record.name = name;
    record.body = args.body;
    record.dof = args.dof;
    record.variable = spec.variable;
    record.terms = terms;
    record.loss = fit.loss;
    record.run_filter = filter_text;
    record.sign = sign;
    record.n = fit.n;
    record.rmse = fit.rmse;
    record.r2 = fit.r2;
    for (std::size_t k = 0; k < spec.terms.size(); ++k) {
      FitRecord::Coefficient c{term_name(spec.terms[k], spec.variable), fit.coefficients[k], std::nullopt};
      if (std::isfinite(fit.std_errors[k])) c.std_error = fit.std_errors[k];
      record.coefficients.push_back(c);
    }
    record.run_ids = run_ids;
    fit_id = database.save_fit(record);
  }

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
                          {"varying_conditions", varying},
                          {"stored", fit_id.has_value()}};
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
    std::cout << out.dump(2) << '\n';
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
  std::cout << "\n  n = " << fit.n << " runs, RMSE = " << significant(fit.rmse, 4) << " " << force_unit(*dof)
            << ", R^2 = " << significant(fit.r2, 8) << ", loss " << fit.loss << '\n';
  if (!varying.empty()) {
    std::string names;
    for (const auto& v : varying) names += (names.empty() ? "" : ", ") + v;
    std::cout << "  note: the runs differ in " << names << "; add --where NAME=VALUE to fit one condition\n";
  }
  if (fit_id) std::cout << "  stored as fit " << *fit_id << " in " << global.database << '\n';
}

struct FitsArgs {
  std::optional<std::string> body;
  bool json = false;
};

void run_fits(const FitsArgs& args, const GlobalOptions& global) {
  Database database(global.database, Database::OpenMode::MustExist);
  const auto fits = database.fits(args.body);
  if (args.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& fit : fits) {
      nlohmann::json item = {{"id", fit.id},         {"name", fit.name},     {"body", fit.body},
                             {"dof", fit.dof},       {"variable", fit.variable}, {"terms", fit.terms},
                             {"loss", fit.loss},     {"where", fit.run_filter},
                             {"sign_convention", std::string(to_string(fit.sign))},
                             {"n", fit.n},           {"rmse", fit.rmse},     {"r2", fit.r2},
                             {"created_at", fit.created_at}, {"runs", fit.run_ids}};
      item["coefficients"] = nlohmann::json::object();
      item["std_errors"] = nlohmann::json::object();
      for (const auto& c : fit.coefficients) {
        item["coefficients"][c.term] = c.value;
        item["std_errors"][c.term] = c.std_error ? nlohmann::json(*c.std_error) : nlohmann::json();
      }
      out.push_back(item);
    }
    std::cout << out.dump(2) << '\n';
    return;
  }
  if (fits.empty()) {
    std::cout << "no fits in " << global.database << '\n';
    return;
  }
  for (const auto& fit : fits) {
    std::cout << fit.id << "  " << fit.name << "  [" << to_string(fit.sign) << ", n=" << fit.n
              << ", RMSE=" << significant(fit.rmse, 4) << ", R^2=" << significant(fit.r2, 8) << "]\n    ";
    for (const auto& c : fit.coefficients) std::cout << c.term << "=" << significant(c.value, 7) << "  ";
    std::cout << '\n';
  }
}

}  // namespace

void add_fit_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<FitArgs>();
  auto* command = app.add_subcommand(
      "fit", "Fit a damping law F_dof = sum c_k term_k(x) to the runs of a body (Ceres least squares) and store it");
  command->add_option("--body", args->body, "Body whose runs are fitted")->required();
  command->add_option("--dof", args->dof, "Force component: X Y Z K M N")->required();
  command->add_option("--terms", args->terms, "Terms of one velocity component x: 1, x, x|x|, x^2, x^3, |x| "
                                              "(e.g. 1,u,u|u|)")
      ->required();
  command->add_option("--loss", args->loss, "squared, or a robust loss huber:S, cauchy:S, soft-l1:S (S in N or N m)")
      ->capture_default_str();
  command->add_option("--where", args->where, "Only runs with NAME=VALUE (velocity or disturbance; repeatable)");
  command->add_option("--name", args->name, "Name to store the fit under (default body:dof(terms))");
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
