// RunDatabase::save_derivative_model, derivative_models and
// delete_derivative_model: derivative models of several variables in tables
// derivative_model, derivative_coefficient and derivative_model_run
// (schema/0018_derivative_models.sql). Names and terms are bound as
// parameters, never written into SQL. Every value read back is checked
// (src/store/checked_row.hpp): a received database is untrusted input.
#include "src/store/derivative_store.hpp"

#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/store/backend.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/database.hpp"

namespace hydrocoef {
namespace {

/// The most terms a stored model may have (its covariance has the square).
constexpr std::size_t kMaxStoredTerms = 256;

std::string warnings_json(const std::vector<DerivativeModelRecord::Warning>& warnings) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& w : warnings) list.push_back({{"kind", w.kind}, {"message", w.message}});
  return escape::json_text(list);
}

std::vector<DerivativeModelRecord::Warning> read_warnings(const store::CheckedRow& row, int column) {
  const std::string expected = "a JSON list of {\"kind\": text, \"message\": text}";
  const nlohmann::json list = nlohmann::json::parse(row.text(column, 1 << 20), nullptr, false);
  if (list.is_discarded() || !list.is_array()) row.fail(column, expected);
  std::vector<DerivativeModelRecord::Warning> out;
  for (const auto& item : list) {
    if (!item.is_object() || !item.contains("kind") || !item.contains("message") || !item.at("kind").is_string() ||
        !item.at("message").is_string())
      row.fail(column, expected);
    out.push_back({item.at("kind").get<std::string>(), item.at("message").get<std::string>()});
  }
  return out;
}

std::string model_names(store::Connection& connection) {
  auto select = connection.prepare("SELECT name FROM derivative_model ORDER BY name");
  std::string names;
  while (select.step()) names += (names.empty() ? "'" : ", '") + escape::one_line(select.get_text(0)) + "'";
  return names.empty() ? std::string("(no derivative models stored)") : names;
}

}  // namespace

std::int64_t RunDatabase::save_derivative_model(const DerivativeModelRecord& model, NameTaken taken) {
  check_name(NameKind::Fit, model.name, {}, "the derivative model");
  if (model.coefficients.size() > kMaxStoredTerms)
    throw InputError("derivative model '" + escape::one_line(model.name) +
                     "': " + std::to_string(model.coefficients.size()) + " terms; expected at most " +
                     std::to_string(kMaxStoredTerms) + " in a stored model (give --no-store to fit it only)");
  store::Transaction transaction(connection_);
  auto existing = connection_.prepare("SELECT id, created_at FROM derivative_model WHERE name = ?");
  existing.bind(1, model.name);
  if (existing.step()) {
    if (taken == NameTaken::Refuse)
      throw InputError(SourceLocation{path_.string()}, "a derivative model named '" + escape::one_line(model.name) +
                                                           "' exists (model " + std::to_string(existing.get_int(0)) +
                                                           ", made " + existing.get_text(1) +
                                                           "); give --replace to replace it, or another --name");
    const std::int64_t old = existing.get_int(0);
    existing.reset();
    connection_.prepare("DELETE FROM derivative_model WHERE id = ?").bind(1, old).run();
  }
  const std::int64_t body = existing_body_id(model.body);
  auto insert = connection_.prepare(
      "INSERT INTO derivative_model(name, body_id, output, terms, model_template, selection, candidates, run_filter, "
      "weighting, n, rmse, r2, condition_number, chi2_reduced, covariance_scale, interval_factor, covariance, "
      "warnings, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?) RETURNING id");
  insert.bind(1, model.name).bind(2, body).bind(3, model.output).bind(4, model.terms).bind(5, model.model_template);
  insert.bind(6, model.selection).bind(7, model.candidates).bind(8, model.run_filter).bind(9, model.weighting);
  insert.bind(10, static_cast<std::int64_t>(model.n)).bind(11, model.rmse).bind(12, model.r2);
  insert.bind(13, model.condition_number).bind(14, model.chi2_reduced).bind(15, model.covariance_scale);
  insert.bind(16, model.interval_factor);
  insert.bind(17, model.covariance.empty() ? std::string() : escape::json_text(nlohmann::json(model.covariance)));
  insert.bind(18, warnings_json(model.warnings));
  insert.bind(19, model.created_at.empty() ? utc_timestamp_now() : model.created_at);
  const std::int64_t id = store::returned_id(insert);
  auto coefficient = connection_.prepare(
      "INSERT INTO derivative_coefficient(model_id, position, term, value, std_error, interval_low, interval_high, "
      "vif) VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < model.coefficients.size(); ++i) {
    const auto& c = model.coefficients[i];
    coefficient.bind(1, id).bind(2, static_cast<std::int64_t>(i)).bind(3, c.term).bind(4, c.value);
    coefficient.bind(5, c.std_error).bind(6, c.interval_low).bind(7, c.interval_high).bind(8, c.vif);
    coefficient.run();
    coefficient.reset();
  }
  link_runs("derivative_model_run", "model_id", id, model.run_ids);
  transaction.commit();
  use_wal();
  return id;
}

std::vector<DerivativeModelRecord> RunDatabase::derivative_models(const std::optional<std::string>& body) {
  // One state of the database for all the statements below.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT derivative_model.id, derivative_model.name, body.name, output, terms, model_template, selection, "
      "candidates, run_filter, weighting, n, rmse, r2, condition_number, chi2_reduced, covariance_scale, "
      "interval_factor, covariance, warnings, created_at, stale FROM derivative_model JOIN body ON body.id = "
      "derivative_model.body_id";
  if (body) sql += " WHERE body.name = ?1";
  sql += " ORDER BY derivative_model.name";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  std::vector<DerivativeModelRecord> out;
  const std::string db = path_.string();
  while (select.step()) {
    const store::CheckedRow row(select, db, "derivative_model", select.get_int(0));
    DerivativeModelRecord model;
    model.id = select.get_int(0);
    model.name = row.name(1, NameKind::Fit);
    model.body = row.name(2, NameKind::Body);
    model.output = row.one_of(3, {"X", "Y", "Z", "K", "M", "N"});
    model.terms = row.text(4, 16384);
    model.model_template = row.text(5, 64);
    model.selection = row.text(6, 64);
    model.candidates = row.text(7, 16384);
    model.run_filter = row.text(8);
    model.weighting = row.one_of(9, {"none", "uncertainty"});
    model.n = static_cast<std::size_t>(row.integer(10, 1, std::int64_t{1} << 40));
    model.rmse = row.non_negative(11);
    model.r2 = row.optional_real(12);
    model.condition_number = row.real(13);
    if (!(model.condition_number >= 1.0)) row.fail(13, "a number >= 1");
    model.chi2_reduced = row.optional_non_negative(14);
    model.covariance_scale = row.positive(15);
    model.interval_factor = row.optional_positive(16);
    model.covariance = row.real_list(17, kMaxStoredTerms * kMaxStoredTerms);
    model.warnings = read_warnings(row, 18);
    model.created_at = row.text(19, 64);
    model.stale = row.integer(20, 0, 1) != 0;
    out.push_back(std::move(model));
  }
  auto coefficients = connection_.prepare(
      "SELECT term, value, std_error, interval_low, interval_high, vif FROM derivative_coefficient WHERE model_id = ? "
      "ORDER BY position");
  for (auto& model : out) {
    coefficients.bind(1, model.id);
    while (coefficients.step()) {
      const store::CheckedRow row(coefficients, db, "derivative_coefficient", model.id);
      if (model.coefficients.size() == kMaxStoredTerms)
        row.fail_row("more than " + std::to_string(kMaxStoredTerms) + " coefficients; expected at most that many");
      model.coefficients.push_back({row.text(0, 256), row.real(1), row.optional_non_negative(2), row.optional_real(3),
                                    row.optional_real(4), row.optional_real(5)});
    }
    coefficients.reset();
    const std::size_t m = model.coefficients.size();
    if (m == 0 || (!model.covariance.empty() && model.covariance.size() != m * m))
      throw InputError(SourceLocation{db}, "table 'derivative_model', row " + std::to_string(model.id) + ": " +
                                               std::to_string(m) + " coefficients and " +
                                               std::to_string(model.covariance.size()) +
                                               " covariance numbers; expected at least one coefficient and one "
                                               "covariance number per pair of them, or none");
    model.run_ids = linked_runs("derivative_model_run", "model_id", model.id);
  }
  return out;
}

void RunDatabase::delete_derivative_model(const std::string& name) {
  store::Transaction transaction(connection_);
  auto find = connection_.prepare("SELECT id FROM derivative_model WHERE name = ?");
  find.bind(1, name);
  if (!find.step())
    throw InputError(SourceLocation{path_.string()}, "no derivative model '" + escape::one_line(name) +
                                                         "'; expected one of: " + model_names(connection_));
  const std::int64_t id = find.get_int(0);
  find.reset();
  connection_.prepare("DELETE FROM derivative_model WHERE id = ?").bind(1, id).run();
  transaction.commit();
  use_wal();
}

}  // namespace hydrocoef
