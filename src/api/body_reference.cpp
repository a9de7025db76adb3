// A body's reference data (`hydrocoef body set`, `body show`):
// include/hydrocoef/reference.hpp, stored by src/store/body_reference_store.cpp.
#include "src/store/body_reference.hpp"
#include "src/api/internal.hpp"
#include "src/core/escape.hpp"
#include "src/core/numbers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string_view>

namespace hydrocoef {
inline namespace api {
namespace {

std::string quote_name(const std::string& name) { return "'" + printable_text(name, 80) + "'"; }

bool positive_finite(double value) { return std::isfinite(value) && value > 0.0; }

void check_positive(const std::optional<double>& value, const char* option, const char* unit) {
  if (value && !positive_finite(*value))
    throw InputError(std::string(option) + " must be a positive finite number [" + unit + "], not " +
                     shortest_number(*value));
}

void check_area_name(const std::string& name, const char* option) {
  if (const auto problem = name_problem(NameKind::Field, name))
    throw InputError(std::string(option) + ": the area name " + quote_name(name) + " " + *problem +
                     "; expected printable text of 1 to 256 characters without leading or trailing spaces");
}

std::string area_list(const std::map<std::string, double>& areas) {
  if (areas.empty()) return "none";
  std::string out;
  for (const auto& [name, value] : areas) out += (out.empty() ? "" : ", ") + quote_name(name);
  return out;
}

/// InputError listing the database's bodies when `body` is not one of them.
void require_body(RunDatabase& store, const std::string& body, const std::string& database) {
  const auto names = store.bodies();
  if (std::find(names.begin(), names.end(), body) != names.end()) return;
  std::string list;
  for (const auto& name : names) list += (list.empty() ? "" : ", ") + quote_name(name);
  throw InputError(SourceLocation{database}, "no body named " + quote_name(body) +
                                                 " (bodies: " + (list.empty() ? "none" : list) +
                                                 "); a body is made by importing its runs");
}

constexpr std::array<std::string_view, 4> kUnsettable = {"length", "draft", "volume", "moment-point"};

BodyReference public_reference(const BodyReferenceRecord& record) {
  BodyReference out;
  out.body = record.body;
  out.length = record.length.value_or(kNaN);
  out.areas = record.areas;
  out.default_area = record.default_area;
  out.draft = record.draft.value_or(kNaN);
  out.displaced_volume = record.displaced_volume.value_or(kNaN);
  if (record.moment_point_b) out.moment_reference_point = *record.moment_point_b;
  out.updated_at = record.updated_at;
  return out;
}

}  // namespace

void BodyReferenceOptions::validate() const {
  if (body.empty()) throw InputError("give the body's name: hydrocoef body set NAME ...");
  check_positive(length, "--length", "m");
  check_positive(draft, "--draft", "m");
  check_positive(displaced_volume, "--volume", "m^3");
  if (moment_reference_point)
    for (const double x : *moment_reference_point)
      if (!std::isfinite(x)) throw InputError("--moment-point must be three finite numbers x,y,z [m]");
  for (const auto& [name, area] : areas) {
    check_area_name(name, "--area");
    if (!positive_finite(area))
      throw InputError("--area " + printable_text(name, 80) +
                       "=...: the area must be a positive finite number [m^2], not " + shortest_number(area));
  }
  for (const auto& name : remove_areas) {
    check_area_name(name, "--remove-area");
    if (areas.count(name)) throw InputError("--area and --remove-area both name the area " + quote_name(name));
  }
  if (!default_area.empty()) {
    check_area_name(default_area, "--default-area");
    if (std::find(remove_areas.begin(), remove_areas.end(), default_area) != remove_areas.end())
      throw InputError("--default-area names the area " + quote_name(default_area) + ", which --remove-area removes");
  }
  for (const auto& what : unset) {
    if (std::find(kUnsettable.begin(), kUnsettable.end(), what) == kUnsettable.end())
      throw InputError("--unset " + quote_name(what) + ": expected length, draft, volume or moment-point");
    if ((what == "length" && length) || (what == "draft" && draft) || (what == "volume" && displaced_volume) ||
        (what == "moment-point" && moment_reference_point))
      throw InputError("--unset " + what + " and a value for it both given");
  }
  if (!length && areas.empty() && remove_areas.empty() && default_area.empty() && !draft && !displaced_volume &&
      !moment_reference_point && unset.empty())
    throw InputError(
        "nothing to set; give --length, --area NAME=A, --default-area, --draft, --volume, --moment-point, "
        "--remove-area or --unset");
}

BodyReference set_body_reference(Database& database, const BodyReferenceOptions& options) {
  options.validate();
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.writable_store("body set");
  require_body(store, options.body, impl.path);
  const auto stored = store.body_references(options.body);
  BodyReferenceRecord record;
  if (!stored.empty()) record = stored.front();
  record.body = options.body;
  record.updated_at.clear();
  const std::string was_default = record.default_area;
  const auto where = SourceLocation{impl.path};
  for (const auto& name : options.remove_areas) {
    if (!record.areas.erase(name))
      throw InputError(where, "--remove-area " + quote_name(name) + ": body " + quote_name(options.body) +
                                  " has no such area (areas: " + area_list(record.areas) + ")");
    if (name == record.default_area) record.default_area.clear();
  }
  for (const auto& [name, area] : options.areas) record.areas[name] = area;
  if (!options.default_area.empty()) {
    if (!record.areas.count(options.default_area))
      throw InputError(where, "--default-area " + quote_name(options.default_area) + " is not an area of body " +
                                  quote_name(options.body) + " (areas: " + area_list(record.areas) +
                                  "); give it with --area NAME=A");
    record.default_area = options.default_area;
  }
  if (record.default_area.empty() && record.areas.size() == 1) record.default_area = record.areas.begin()->first;
  if (record.default_area.empty() && !was_default.empty() && !record.areas.empty())
    throw InputError(where, "--remove-area removes the default area " + quote_name(was_default) + " of body " +
                                quote_name(options.body) +
                                "; name another with --default-area (areas: " + area_list(record.areas) + ")");
  if (options.length) record.length = options.length;
  if (options.draft) record.draft = options.draft;
  if (options.displaced_volume) record.displaced_volume = options.displaced_volume;
  if (options.moment_reference_point) record.moment_point_b = options.moment_reference_point;
  for (const auto& what : options.unset) {
    if (what == "length") record.length.reset();
    if (what == "draft") record.draft.reset();
    if (what == "volume") record.displaced_volume.reset();
    if (what == "moment-point") record.moment_point_b.reset();
  }
  store.save_body_reference(record);
  const auto saved = store.body_references(options.body);
  if (saved.empty()) throw std::logic_error("body reference data stored but not read back");
  return public_reference(saved.front());
}

BodyReferences body_references(const Database& database, const std::string& body) {
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.open_store();
  if (!body.empty()) require_body(store, body, impl.path);
  const auto names = store.bodies();
  std::map<std::string, BodyReferenceRecord> stored;
  for (auto& record : store.body_references(body.empty() ? std::nullopt : std::optional<std::string>(body)))
    stored.emplace(record.body, std::move(record));
  BodyReferences out;
  out.database = impl.path;
  for (const auto& name : names) {
    if (!body.empty() && name != body) continue;
    const auto found = stored.find(name);
    if (found != stored.end()) {
      out.bodies.push_back(public_reference(found->second));
    } else {
      BodyReference none;
      none.body = name;
      out.bodies.push_back(std::move(none));
    }
  }
  return out;
}

// ---- text and JSON ----------------------------------------------------------------

namespace {

nlohmann::json optional_json(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(); }

nlohmann::json reference_json(const BodyReference& r) {
  nlohmann::json areas = nlohmann::json::object();
  for (const auto& [name, value] : r.areas) areas[name] = value;
  const bool point = std::isfinite(r.moment_reference_point[0]);
  return {{"body", r.body},
          {"length", optional_json(r.length)},
          {"areas", areas},
          {"default_area", r.default_area.empty() ? nlohmann::json() : nlohmann::json(r.default_area)},
          {"draft", optional_json(r.draft)},
          {"displaced_volume", optional_json(r.displaced_volume)},
          {"moment_reference_point", point ? nlohmann::json(r.moment_reference_point) : nlohmann::json()},
          {"updated_at", r.updated_at.empty() ? nlohmann::json() : nlohmann::json(r.updated_at)}};
}

std::string value_text(double value, const char* unit) {
  return std::isfinite(value) ? significant(value, 8) + " " + unit : "not given";
}

}  // namespace

std::string BodyReference::text() const {
  std::string out = "body '" + escape::one_line(body) + "'";
  if (updated_at.empty())
    return out + ": no reference data (give it with: hydrocoef body set NAME --length L --area NAME=A ...)\n";
  out += ", reference data (SI; body axes x forward, y starboard, z down):\n";
  out += "  reference length L: " + value_text(length, "m") + "\n";
  out += "  reference areas: ";
  if (areas.empty()) out += "none";
  bool first = true;
  for (const auto& [name, value] : areas) {
    out += (first ? "" : ", ") + ("'" + escape::one_line(name) + "' ") + significant(value, 8) + " m^2" +
           (name == default_area ? " (default)" : "");
    first = false;
  }
  out += "\n  draft: " + value_text(draft, "m") + "\n";
  out += "  displaced volume: " + value_text(displaced_volume, "m^3") + "\n";
  out += "  moment reference point: ";
  if (std::isfinite(moment_reference_point[0]))
    out += "(" + significant(moment_reference_point[0], 8) + ", " + significant(moment_reference_point[1], 8) + ", " +
           significant(moment_reference_point[2], 8) + ") m\n";
  else
    out += "not given (moments about each run's own reference point)\n";
  out += "  updated: " + escape::one_line(updated_at) + "\n";
  return out;
}

std::string BodyReference::json() const { return escape::json_text(reference_json(*this), 2) + '\n'; }

std::string BodyReferences::text() const {
  if (bodies.empty()) return "no bodies in " + escape::one_line(database) + "\n";
  std::string out;
  for (const auto& body : bodies) out += body.text();
  return out;
}

std::string BodyReferences::json() const {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& body : bodies) list.push_back(reference_json(body));
  return escape::json_text({{"database", database}, {"bodies", list}}, 2) + '\n';
}

}  // namespace api
}  // namespace hydrocoef
