#include "src/pipeline/run_settings.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

constexpr std::string_view kDisturbancePrefix = "disturbance.";

bool is_translation(std::string_view name) { return name == "u" || name == "v" || name == "w" || name == "flow"; }

enum class Kind { Number, Text, Triple, Texts };

Kind kind_of(std::string_view name) {
  if (velocity_index(name) || name.rfind(kDisturbancePrefix, 0) == 0 || name == "rho" || name == "nu" ||
      name == "p_ref" || name == "flow_speed")
    return Kind::Number;
  if (name == "flow" || name == "ref_point" || name == "cofr" || name == "origin") return Kind::Triple;
  if (name == "shear" || name == "locations") return Kind::Texts;
  return Kind::Text;
}

std::string where_text(const Setting& setting) {
  return setting.origin.where.empty() ? std::string(setting_source_name(setting.origin.source)) : setting.origin.where;
}

[[noreturn]] void wrong_type(const Setting& setting, std::string_view name, const char* expected) {
  throw InputError(where_text(setting) + ": setting '" + std::string(name) + "': expected " + expected);
}

nlohmann::json value_json(const SettingValue& value) {
  return std::visit([](const auto& v) { return nlohmann::json(v); }, value);
}

std::string value_text(const SettingValue& value) {
  if (const auto* number = std::get_if<double>(&value)) return shortest_number(*number);
  if (const auto* text = std::get_if<std::string>(&value)) return escape::json_text(nlohmann::json(*text));
  std::string out = "[";
  if (const auto* numbers = std::get_if<std::vector<double>>(&value)) {
    for (std::size_t i = 0; i < numbers->size(); ++i) out += (i ? "," : "") + shortest_number((*numbers)[i]);
  } else {
    const auto& texts = std::get<std::vector<std::string>>(value);
    for (std::size_t i = 0; i < texts.size(); ++i) out += (i ? "," : "") + escape::json_text(nlohmann::json(texts[i]));
  }
  return out + "]";
}

double finite_number(const nlohmann::json& value, const SourceLocation& where, const std::string& key) {
  if (!value.is_number())
    throw InputError(where,
                     "key '" + key + "': expected a number, found " + printable_text(escape::json_text(value), 40));
  const double x = value.get<double>();
  if (!std::isfinite(x)) throw InputError(where, "key '" + key + "': expected a finite number");
  return x;
}

std::string json_text(const nlohmann::json& value, const SourceLocation& where, const std::string& key) {
  if (!value.is_string())
    throw InputError(where,
                     "key '" + key + "': expected a string, found " + printable_text(escape::json_text(value), 40));
  return value.get<std::string>();
}

}  // namespace

std::string_view setting_source_name(SettingSource source) {
  switch (source) {
    case SettingSource::CommandLine: return "command line";
    case SettingSource::FileSidecar: return "sidecar";
    case SettingSource::Manifest: return "manifest";
    case SettingSource::FolderSidecar: return "folder sidecar";
    case SettingSource::CaseFiles: return "case files";
    case SettingSource::NamePattern: return "name pattern";
    case SettingSource::Default: return "default";
  }
  return "unknown";
}

const std::vector<std::string>& sidecar_keys() {
  static const std::vector<std::string> keys = {"body",
                                                "u",
                                                "v",
                                                "w",
                                                "p",
                                                "q",
                                                "r",
                                                "flow",
                                                "disturbances",
                                                "rho",
                                                "nu",
                                                "p_ref",
                                                "ref_point",
                                                "cofr",
                                                "axes",
                                                "origin",
                                                "pressure",
                                                "shear",
                                                "pressure_kind",
                                                "shear_convention",
                                                "length_unit",
                                                "pressure_unit",
                                                "normals",
                                                "locations",
                                                "window",
                                                "symmetry",
                                                "sign",
                                                "uncertainty",
                                                "at_rest"};
  return keys;
}

void SettingsLayer::set(const std::string& name, SettingValue value, std::string where) {
  SettingOrigin setting_origin = origin;
  if (!where.empty()) setting_origin.where = std::move(where);
  values[name] = Setting{std::move(value), std::move(setting_origin)};
}

const Setting* RunSettings::find(std::string_view name) const {
  const auto it = values.find(std::string(name));
  return it == values.end() ? nullptr : &it->second;
}

std::optional<double> RunSettings::number(std::string_view name) const {
  const Setting* s = find(name);
  if (!s) return std::nullopt;
  if (const auto* x = std::get_if<double>(&s->value)) return *x;
  wrong_type(*s, name, "a number");
}

std::optional<std::string> RunSettings::text(std::string_view name) const {
  const Setting* s = find(name);
  if (!s) return std::nullopt;
  if (const auto* x = std::get_if<std::string>(&s->value)) return *x;
  wrong_type(*s, name, "a text");
}

std::optional<Vec3> RunSettings::triple(std::string_view name) const {
  const Setting* s = find(name);
  if (!s) return std::nullopt;
  if (const auto* x = std::get_if<std::vector<double>>(&s->value); x && x->size() == 3)
    return Vec3{(*x)[0], (*x)[1], (*x)[2]};
  wrong_type(*s, name, "three numbers x,y,z");
}

std::optional<std::vector<std::string>> RunSettings::texts(std::string_view name) const {
  const Setting* s = find(name);
  if (!s) return std::nullopt;
  if (const auto* x = std::get_if<std::vector<std::string>>(&s->value)) return *x;
  if (const auto* x = std::get_if<std::string>(&s->value)) return std::vector<std::string>{*x};
  wrong_type(*s, name, "a list of names");
}

std::map<std::string, double> RunSettings::disturbances() const {
  std::map<std::string, double> out;
  for (const auto& [name, setting] : values) {
    if (name.rfind(kDisturbancePrefix, 0) != 0) continue;
    const auto* x = std::get_if<double>(&setting.value);
    if (!x) wrong_type(setting, name, "a number");
    out[name.substr(kDisturbancePrefix.size())] = *x;
  }
  return out;
}

nlohmann::json RunSettings::provenance_json() const {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, setting] : values)
    out[name] = {{"value", value_json(setting.value)},
                 {"source", setting_source_name(setting.origin.source)},
                 {"where", setting.origin.where}};
  return out;
}

std::string RunSettings::effective_text() const {
  std::string out = "{";
  bool first = true;
  for (const auto& [name, setting] : values) {  // std::map: sorted by name
    out += (first ? "" : ",") + escape::json_text(nlohmann::json(name)) + ":" + value_text(setting.value);
    first = false;
  }
  return out + "}";
}

RunSettings merge_settings(const std::vector<SettingsLayer>& layers) {
  RunSettings merged;
  // The body's translation comes whole from the first layer that states any of it.
  const SettingsLayer* translation = nullptr;
  for (const auto& layer : layers) {
    for (const auto& [name, setting] : layer.values) {
      if (is_translation(name)) {
        if (!translation) translation = &layer;
        if (translation != &layer) continue;
      }
      merged.values.emplace(name, setting);  // emplace keeps the first (highest) layer's value
    }
  }
  return merged;
}

FrameTransform resolve_frame(const RunSettings& settings) {
  FrameTransform frame;
  if (const auto axes = settings.text("axes")) {
    try {
      frame = parse_axes(*axes);
    } catch (const InputError& e) {
      throw InputError(where_text(*settings.find("axes")) + ": setting 'axes': " + e.what());
    }
  }
  if (const auto origin = settings.triple("origin")) frame.origin_cfd = *origin;
  return frame;
}

RunKey resolve_key(const RunSettings& settings, const FrameTransform& frame, const std::string& default_body) {
  RunKey key;
  key.body = settings.text("body").value_or(default_body);
  for (std::size_t i = 0; i < 6; ++i)
    if (const auto x = settings.number(kVelocityNames[i])) key.nu_b[i] = *x;
  if (const auto flow = settings.triple("flow")) {
    for (std::size_t i = 0; i < 3; ++i)
      if (settings.find(kVelocityNames[i]))
        throw InputError(where_text(*settings.find("flow")) + ": settings 'flow' and '" +
                         std::string(kVelocityNames[i]) + "' both state the body's velocity; expected one of them");
    // The free stream past a fixed body is the body moving at its negative.
    const Vec3 flow_b = frame.vector_to_body(*flow);
    for (std::size_t i = 0; i < 3; ++i) key.nu_b[i] = flow_b[i] == 0.0 ? 0.0 : -flow_b[i];
  }
  key.disturbances = settings.disturbances();
  return key;
}

void require_velocity(const RunSettings& settings, const std::string& file,
                      const std::function<std::string()>& looked) {
  const Setting* velocity = settings.find("flow");
  for (std::size_t i = 0; i < 6 && !velocity; ++i) velocity = settings.find(kVelocityNames[i]);
  const Setting* at_rest = settings.find("at_rest");
  if (velocity && at_rest)
    throw InputError(SourceLocation{file}, where_text(*at_rest) + " says the body is at rest and " +
                                               where_text(*velocity) + " gives its velocity; expected one of them");
  if (velocity || at_rest || settings.find("flow_speed")) return;
  const std::string where = looked ? looked() : std::string();
  throw InputError(SourceLocation{file},
                   "no body velocity found (" +
                       (where.empty() ? std::string("no file of this kind states it") : where) +
                       "); expected it from --flow U,V,W (the free stream, CFD axes), --set u=... (body axes), a "
                       "sidecar FILE.json {\"u\": ...}, a manifest row or --key-from-name, or --at-rest for a body "
                       "at rest");
}

Vec3 resolve_reference_point(const RunSettings& settings, const FrameTransform& frame) {
  if (const auto point = settings.triple("ref_point")) return *point;
  if (const auto cofr = settings.triple("cofr")) return frame.point_to_body(*cofr);
  return Vec3{};
}

SettingsLayer settings_from_json(const nlohmann::json& object, SettingOrigin origin) {
  const SourceLocation where{origin.where};
  if (!object.is_object()) throw InputError(where, "expected a JSON object of run settings");
  SettingsLayer layer;
  layer.origin = origin;
  const auto& keys = sidecar_keys();
  std::string key_list;
  for (const auto& k : keys) key_list += (key_list.empty() ? "" : ", ") + k;
  for (const auto& [key, value] : object.items()) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end())
      throw InputError(where, "unknown key '" + printable_text(key, 40) + "'; expected some of " + key_list);
    if (key == "disturbances") {
      if (!value.is_object()) throw InputError(where, "key 'disturbances': expected an object {name: value}");
      for (const auto& [name, x] : value.items()) {
        check_name(NameKind::Parameter, name, where, "key 'disturbances'");
        if (velocity_index(name))
          throw InputError(where,
                           "key 'disturbances': '" + name + "' is a velocity component; give it as key '" + name + "'");
        layer.set(std::string(kDisturbancePrefix) + name, finite_number(x, where, "disturbances." + name));
      }
      continue;
    }
    switch (kind_of(key)) {
      case Kind::Number: layer.set(key, finite_number(value, where, key)); break;
      case Kind::Text: {
        if (key == "at_rest") {  // true, as JSON says yes
          if (!value.is_boolean() || !value.get<bool>())
            throw InputError(where, "key 'at_rest': expected true (leave it out when the body moves)");
          layer.set(key, std::string("yes"));
          break;
        }
        std::string text = json_text(value, where, key);
        if (key == "body") check_name(NameKind::Body, text, where, "key 'body'");
        layer.set(key, std::move(text));
        break;
      }
      case Kind::Triple: {
        if (!value.is_array() || value.size() != 3)
          throw InputError(where, "key '" + key + "': expected an array of three numbers");
        std::vector<double> xyz;
        for (const auto& x : value) xyz.push_back(finite_number(x, where, key));
        layer.set(key, std::move(xyz));
        break;
      }
      case Kind::Texts: {
        std::vector<std::string> names;
        if (value.is_string()) {
          names.push_back(value.get<std::string>());
        } else if (value.is_array()) {
          for (const auto& x : value) names.push_back(json_text(x, where, key));
        } else {
          throw InputError(where, "key '" + key + "': expected a name or a list of names");
        }
        for (const auto& name : names) check_name(NameKind::Field, name, where, "key '" + key + "'");
        layer.set(key, std::move(names));
        break;
      }
    }
  }
  return layer;
}

SettingsLayer read_settings_file(const std::filesystem::path& file, SettingSource source) {
  const std::string where = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(SourceLocation{where}, "cannot read the settings file");
  // Sidecars are small; a huge one is not a sidecar.
  constexpr std::size_t kMaxBytes = 1 << 20;
  std::string bytes;
  bytes.resize(kMaxBytes + 1);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (bytes.size() > kMaxBytes)
    throw InputError(SourceLocation{where}, "settings file is larger than 1 MiB; expected a small JSON object");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(bytes);
  } catch (const nlohmann::json::exception& error) {
    throw InputError(SourceLocation{where}, std::string("not valid JSON: ") + error.what());
  }
  return settings_from_json(json, SettingOrigin{source, where});
}

}  // namespace hydrocoef
