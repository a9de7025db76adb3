// RunDatabase::save_body_reference, body_references and the merge of a
// shard's reference data: tables body_reference and body_reference_area
// (schema/0017_body_reference.sql). Every value read back is checked
// (src/store/checked_row.hpp): a received database is untrusted input.
#include <cmath>
#include <map>
#include <string>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"
#include "src/store/backend.hpp"
#include "src/store/body_reference.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/database.hpp"

namespace hydrocoef {
namespace {

/// The most areas a body may have: a received database with more is refused.
constexpr std::size_t kMaxAreas = 256;

bool positive_finite(double value) { return std::isfinite(value) && value > 0.0; }

double canonical_zero(double value) { return value == 0.0 ? 0.0 : value; }  // folds -0 into 0

std::string quote_name(const std::string& name) { return "'" + printable_text(name, 80) + "'"; }

}  // namespace

bool BodyReferenceRecord::same_data(const BodyReferenceRecord& other) const {
  return body == other.body && length == other.length && areas == other.areas && default_area == other.default_area &&
         draft == other.draft && displaced_volume == other.displaced_volume && moment_point_b == other.moment_point_b;
}

std::string BodyReferenceRecord::problem() const {
  if (length && !positive_finite(*length)) return "the reference length is " + shortest_number(*length);
  if (draft && !positive_finite(*draft)) return "the draft is " + shortest_number(*draft);
  if (displaced_volume && !positive_finite(*displaced_volume))
    return "the displaced volume is " + shortest_number(*displaced_volume);
  if (moment_point_b)
    for (const double x : *moment_point_b)
      if (!std::isfinite(x)) return "the moment reference point has a coordinate " + shortest_number(x);
  if (areas.size() > kMaxAreas)
    return std::to_string(areas.size()) + " areas (at most " + std::to_string(kMaxAreas) + ")";
  for (const auto& [name, area] : areas) {
    if (const auto wrong = name_problem(NameKind::Field, name))
      return "the area name " + quote_name(name) + " " + *wrong;
    if (!positive_finite(area)) return "area " + quote_name(name) + " is " + shortest_number(area);
  }
  if (!default_area.empty() && !areas.count(default_area))
    return "the default area " + quote_name(default_area) + " is not one of the body's areas";
  return "";
}

void RunDatabase::save_body_reference(const BodyReferenceRecord& record) {
  if (read_only_)
    throw InputError(SourceLocation{path_.string()}, "database opened read-only; cannot set body reference data");
  if (const std::string problem = record.problem(); !problem.empty())
    throw InputError(SourceLocation{path_.string()}, "body " + quote_name(record.body) + ": " + problem +
                                                         "; expected positive finite values and areas by name");
  store::Transaction transaction(connection_);
  const std::int64_t body = body_id(record.body, false);
  if (body < 0) {
    std::string list;
    for (const auto& name : bodies()) list += (list.empty() ? "" : ", ") + quote_name(name);
    throw InputError(SourceLocation{path_.string()}, "no body named " + quote_name(record.body) +
                                                         " (bodies: " + (list.empty() ? "none" : list) +
                                                         "); a body is made by importing its runs");
  }
  connection_.prepare("DELETE FROM body_reference_area WHERE body_id = ?").bind(1, body).run();
  connection_.prepare("DELETE FROM body_reference WHERE body_id = ?").bind(1, body).run();
  auto insert = connection_.prepare(
      "INSERT INTO body_reference(body_id, reference_length, draft, displaced_volume, moment_x, moment_y, moment_z, "
      "default_area, updated_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
  insert.bind(1, body).bind(2, record.length).bind(3, record.draft).bind(4, record.displaced_volume);
  for (int i = 0; i < 3; ++i)
    if (record.moment_point_b)
      insert.bind(5 + i, canonical_zero((*record.moment_point_b)[static_cast<std::size_t>(i)]));
    else
      insert.bind_null(5 + i);
  if (record.default_area.empty())
    insert.bind_null(8);
  else
    insert.bind(8, record.default_area);
  insert.bind(9, record.updated_at.empty() ? utc_timestamp_now() : record.updated_at);
  insert.run();
  auto area = connection_.prepare("INSERT INTO body_reference_area(body_id, name, area) VALUES (?, ?, ?)");
  for (const auto& [name, value] : record.areas) {
    area.bind(1, body).bind(2, name).bind(3, value).run();
    area.reset();
  }
  transaction.commit();
  use_wal();
}

std::vector<BodyReferenceRecord> RunDatabase::body_references(const std::optional<std::string>& body) {
  // One state of the database for both tables.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT body_reference.body_id, body.name, reference_length, draft, displaced_volume, moment_x, moment_y, "
      "moment_z, default_area, updated_at FROM body_reference JOIN body ON body.id = body_reference.body_id";
  if (body) sql += " WHERE body.name = ?";
  sql += " ORDER BY body.name";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  std::vector<BodyReferenceRecord> out;
  std::vector<std::int64_t> ids;
  while (select.step()) {
    const std::int64_t id = select.get_int(0);
    const store::CheckedRow row(select, path_.string(), "body_reference", id);
    BodyReferenceRecord record;
    record.body = row.name(1, NameKind::Body);
    record.length = row.optional_positive(2);
    record.draft = row.optional_positive(3);
    record.displaced_volume = row.optional_positive(4);
    const auto x = row.optional_real(5), y = row.optional_real(6), z = row.optional_real(7);
    if (x && y && z)
      record.moment_point_b = std::array<double, 3>{*x, *y, *z};
    else if (x || y || z)
      row.fail(x ? (y ? 7 : 6) : 5, "all three coordinates of the moment reference point, or none");
    if (!select.is_null(8)) {
      record.default_area = row.name(8, NameKind::Field);
    }
    record.updated_at = row.text(9, 64);
    out.push_back(std::move(record));
    ids.push_back(id);
  }
  select.reset();
  auto areas = connection_.prepare("SELECT name, area FROM body_reference_area WHERE body_id = ? ORDER BY name");
  for (std::size_t i = 0; i < out.size(); ++i) {
    areas.bind(1, ids[i]);
    while (areas.step()) {
      const store::CheckedRow row(areas, path_.string(), "body_reference_area", ids[i]);
      if (out[i].areas.size() == kMaxAreas) row.fail_row("more than " + std::to_string(kMaxAreas) + " areas of a body");
      out[i].areas[row.name(0, NameKind::Field)] = row.positive(1);
    }
    areas.reset();
    if (!out[i].default_area.empty() && !out[i].areas.count(out[i].default_area))
      throw InputError(SourceLocation{path_.string()},
                       "table 'body_reference', row " + std::to_string(ids[i]) + ": the default area " +
                           quote_name(out[i].default_area) +
                           " is not one of the body's areas; expected a name of table body_reference_area");
  }
  return out;
}

void RunDatabase::merge_body_references(RunDatabase& shard, MergeOutcome& outcome) {
  std::map<std::string, BodyReferenceRecord> here;
  for (auto& record : body_references()) here.emplace(record.body, std::move(record));
  for (const auto& theirs : shard.body_references()) {
    const auto found = here.find(theirs.body);
    if (found == here.end()) {
      (void)body_id(theirs.body, true);  // made by the shard's runs, merged before this, unless it has none
      save_body_reference(theirs);
      ++outcome.body_references_added;
    } else if (found->second.same_data(theirs)) {
      ++outcome.body_references_already;
    } else {
      throw InputError(SourceLocation{outcome.shard},
                       "body " + quote_name(theirs.body) +
                           " has reference data that differs from the database merged into; expected the same "
                           "(compare 'hydrocoef body show' of both, and set one with 'hydrocoef body set')");
    }
  }
}

}  // namespace hydrocoef
