// RunDatabase::save_fits and RunDatabase::fits: fitted coefficient models, tables
// fit, fit_coefficient and fit_run. Every value read back is checked
// (src/store/checked_row.hpp): a received database is untrusted input.
#include <limits>
#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/store/backend.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/database.hpp"

namespace hydrocoef {

std::int64_t RunDatabase::save_fit(const FitRecord& fit, NameTaken taken) { return save_fits({fit}, taken).front(); }

std::vector<std::int64_t> RunDatabase::save_fits(const std::vector<FitRecord>& fits, NameTaken taken) {
  for (const auto& fit : fits) check_name(NameKind::Fit, fit.name, {}, "the fit");
  store::Transaction transaction(connection_);
  if (taken == NameTaken::Refuse) {
    auto existing = connection_.prepare("SELECT id, created_at FROM fit WHERE name = ?");
    for (const auto& fit : fits) {
      existing.bind(1, fit.name);
      if (existing.step()) {
        const std::string message = "a fit named '" + escape::one_line(fit.name) + "' exists (fit " +
                                    std::to_string(existing.get_int(0)) + ", made " + existing.get_text(1) +
                                    "); give --replace to replace it, or another --name";
        throw InputError(SourceLocation{path_.string()}, message);
      }
      existing.reset();
    }
  }
  std::vector<std::int64_t> ids;
  for (const auto& fit : fits) ids.push_back(insert_fit(fit));
  transaction.commit();
  use_wal();
  return ids;
}

std::int64_t RunDatabase::insert_fit(const FitRecord& fit) {
  const std::int64_t body = existing_body_id(fit.body);
  connection_.prepare("DELETE FROM fit WHERE name = ?").bind(1, fit.name).run();
  auto insert = connection_.prepare(
      "INSERT INTO fit(name, body_id, dof, variable, terms, loss, run_filter, sign_convention, n, rmse, r2, "
      "created_at, mirror, weighting, chi2_reduced, covariance) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
      "?) RETURNING id");
  insert.bind(1, fit.name)
      .bind(2, body)
      .bind(3, fit.dof)
      .bind(4, fit.variable)
      .bind(5, fit.terms)
      .bind(6, fit.loss)
      .bind(7, fit.run_filter)
      .bind(8, to_string(fit.sign))
      .bind(9, static_cast<std::int64_t>(fit.n))
      .bind(10, fit.rmse)
      .bind(11, fit.r2)
      .bind(12, utc_timestamp_now())
      .bind(13, fit.mirror)
      .bind(14, fit.weighting)
      .bind(15, fit.chi2_reduced)
      .bind(16, fit.covariance.empty() ? std::string() : escape::json_text(nlohmann::json(fit.covariance)));
  const std::int64_t id = store::returned_id(insert);
  auto coefficient = connection_.prepare(
      "INSERT INTO fit_coefficient(fit_id, position, term, value, std_error) VALUES (?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < fit.coefficients.size(); ++i) {
    const auto& c = fit.coefficients[i];
    coefficient.bind(1, id).bind(2, static_cast<std::int64_t>(i)).bind(3, c.term).bind(4, c.value).bind(5, c.std_error);
    coefficient.run();
  }
  link_runs("fit_run", "fit_id", id, fit.run_ids);
  return id;
}

std::vector<FitRecord> RunDatabase::fits(const std::optional<std::string>& body) {
  // One state of the database for all the statements below.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT fit.id, fit.name, body.name, dof, variable, terms, loss, run_filter, sign_convention, n, rmse, r2, "
      "created_at, stale, mirror, weighting, chi2_reduced, covariance FROM fit JOIN body ON body.id = fit.body_id";
  if (body) sql += " WHERE body.name = ?1";
  sql += " ORDER BY fit.name";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  std::vector<FitRecord> out;
  while (select.step()) {
    const store::CheckedRow row(select, path_.string(), "fit", select.get_int(0));
    constexpr double kAbsent = std::numeric_limits<double>::quiet_NaN();
    FitRecord fit;
    fit.id = select.get_int(0);
    fit.name = row.name(1, NameKind::Fit);
    fit.body = row.name(2, NameKind::Body);
    fit.dof = row.one_of(3, {"X", "Y", "Z", "K", "M", "N"});
    fit.variable = row.one_of(4, {"u", "v", "w", "p", "q", "r"});
    fit.terms = row.text(5, 1024);
    fit.loss = row.text(6, 256);
    fit.run_filter = row.text(7);
    fit.sign = parse_sign_convention(row.one_of(8, {"on-body", "opposing"}));
    fit.n = static_cast<std::size_t>(row.integer(9, 0, std::int64_t{1} << 40));
    fit.rmse = row.optional_non_negative(10).value_or(kAbsent);
    fit.r2 = row.optional_real(11).value_or(kAbsent);
    fit.created_at = row.text(12, 64);
    fit.stale = row.integer(13, 0, 1) != 0;
    fit.mirror = row.text(14, 256);
    fit.weighting = row.one_of(15, {"none", "uncertainty"});
    fit.chi2_reduced = row.optional_non_negative(16);
    fit.covariance = row.real_list(17, 36 * 36);
    out.push_back(std::move(fit));
  }
  auto coefficients =
      connection_.prepare("SELECT term, value, std_error FROM fit_coefficient WHERE fit_id = ? ORDER BY position");
  for (auto& fit : out) {
    coefficients.bind(1, fit.id);
    while (coefficients.step()) {
      const store::CheckedRow row(coefficients, path_.string(), "fit_coefficient", fit.id);
      fit.coefficients.push_back({row.text(0, 256), row.real(1), row.optional_non_negative(2)});
    }
    coefficients.reset();
    if (!fit.covariance.empty() && fit.covariance.size() != fit.coefficients.size() * fit.coefficients.size())
      throw InputError(SourceLocation{path_.string()},
                       "table 'fit', row " + std::to_string(fit.id) + ": column 'covariance' holds " +
                           std::to_string(fit.covariance.size()) + " numbers; expected " +
                           std::to_string(fit.coefficients.size() * fit.coefficients.size()) +
                           " (one per pair of its coefficients) or none");
    fit.run_ids = linked_runs("fit_run", "fit_id", fit.id);
  }
  return out;
}

}  // namespace hydrocoef
