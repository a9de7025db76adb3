// The import (include/hydrocoef/database.hpp, records.hpp): `hydrocoef import`
// without its printing. The library plans and reads the inputs and stores
// them in one transaction (src/pipeline/import_files.hpp: read_import,
// store_import), in two steps so that a caller can read before it opens a
// database. The report of an import is src/api/import_report.cpp.
#include "src/api/internal.hpp"
#include "src/api/records_report.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"
#include "src/loads/frame.hpp"
#include "src/loads/symmetry.hpp"
#include "src/pipeline/given_uncertainty.hpp"
#include "src/store/body_reference.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

namespace hydrocoef {
inline namespace api {

struct PreparedImport::Impl {
  ImportResult result;
  ImportPolicy policy;
  bool stored = false;
};

struct PreparedImport::Access {
  static PreparedImport make(std::unique_ptr<Impl> impl) { return PreparedImport(std::move(impl)); }
  static Impl& impl(PreparedImport& prepared) {
    if (!prepared.impl_) throw std::invalid_argument("hydrocoef::import_prepared: a moved-from PreparedImport");
    return *prepared.impl_;
  }
};

PreparedImport::PreparedImport(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PreparedImport::PreparedImport(PreparedImport&&) noexcept = default;
PreparedImport& PreparedImport::operator=(PreparedImport&&) noexcept = default;
PreparedImport::~PreparedImport() = default;

namespace {

double finite_part(const std::string& text, const std::string& option, const std::string& whole) {
  const auto value = parse_finite_number(text);
  if (!value) throw InputError(option + " '" + whole + "': found '" + text + "', expected a finite number");
  return *value;
}

/// "x,y,z" as three finite numbers, refused naming the option.
std::vector<double> triple(const std::string& text, const std::string& option) {
  std::vector<double> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto comma = text.find(',', start);
    if ((i < 2) == (comma == std::string::npos))
      throw InputError(option + " '" + text + "': expected three comma-separated numbers x,y,z");
    out.push_back(
        finite_part(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start), option, text));
    start = comma + 1;
  }
  return out;
}

}  // namespace

/// The options of `hydrocoef import` as the command line's settings layer:
/// each option given becomes the setting of the same meaning, remembered as
/// coming from that option; then the `settings` map, read as a sidecar's keys are.
SettingsLayer command_line_layer(const ImportOptions& options) {
  SettingsLayer layer;
  layer.origin = SettingOrigin{SettingSource::CommandLine, "command line"};
  const auto set_text = [&](const char* name, const std::optional<std::string>& value, const char* option) {
    if (value) layer.set(name, *value, option);
  };
  const auto set_number = [&](const char* name, const std::optional<double>& value, const char* option) {
    if (!value) return;
    if (!std::isfinite(*value)) throw InputError(std::string(option) + ": expected a finite number");
    layer.set(name, *value, option);
  };
  const auto set_triple = [&](const char* name, const std::optional<std::string>& value, const char* option) {
    if (value) layer.set(name, triple(*value, option), option);
  };
  if (!options.body.empty())
    layer.set("body", std::string(check_name(NameKind::Body, options.body, {}, "--body")), "--body");
  if (!options.locations.empty()) {
    for (const auto& name : options.locations) check_name(NameKind::Field, name, {}, "--location");
    layer.set("locations", options.locations, "--location");
  }
  set_text("pressure", options.pressure, "--pressure");
  if (options.shear) {
    std::vector<std::string> names;
    std::stringstream list(*options.shear);
    for (std::string name; std::getline(list, name, ',');) names.push_back(name);
    if (names.size() != 1 && names.size() != 3)
      throw InputError("--shear '" + *options.shear + "': expected one vector array, three arrays x,y,z, or none");
    layer.set("shear", names, "--shear");
  }
  set_text("pressure_kind", options.pressure_kind, "--pressure-kind");
  set_text("shear_convention", options.shear_convention, "--shear-convention");
  set_number("rho", options.rho, "--rho");
  set_number("nu", options.nu, "--nu");
  set_number("p_ref", options.p_ref, "--p-ref");
  set_triple("ref_point", options.ref_point, "--ref-point");
  set_text("length_unit", options.length_unit, "--length-unit");
  set_text("pressure_unit", options.pressure_unit, "--pressure-unit");
  if (options.axes) {
    parse_axes(*options.axes);  // refused here, naming the option, rather than later
    layer.set("axes", *options.axes, "--axes");
  }
  set_triple("origin", options.origin, "--origin");
  set_triple("flow", options.flow, "--flow");
  set_text("normals", options.normals, "--normals");
  if (options.symmetry) {
    parse_symmetry(*options.symmetry);
    layer.set("symmetry", *options.symmetry, "--symmetry");
  }
  set_text("window", options.window, "--window");
  if (!options.uncertainty.empty()) {
    const std::string text = join(options.uncertainty, ",");
    (void)parse_given_uncertainty(text, "--uncertainty");  // refused here, naming the option
    layer.set("uncertainty", text, "--uncertainty");
  }
  if (options.at_rest) layer.set("at_rest", std::string("yes"), "--at-rest");
  for (const auto& text : options.set) {
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0) throw InputError("--set '" + text + "': expected NAME=VALUE");
    const std::string name = text.substr(0, equals);
    const double value = finite_part(text.substr(equals + 1), "--set", text);
    if (velocity_index(name)) {
      layer.set(name, value, "--set");
    } else {
      check_name(NameKind::Parameter, name, {}, "--set");
      layer.set("disturbance." + name, value, "--set");
    }
  }
  if (options.sign) layer.set("sign", *options.sign, "--sign");
  if (options.density) {
    if (options.rho) throw InputError("--rho and --density both give the density; expected one of them");
    set_number("rho", options.density, "--density");
  }

  // The settings map: each value JSON, or a plain text when it is not ("-x,y,-z").
  if (!options.settings.empty()) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [key, text] : options.settings) {
      auto value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
      object[key] = value.is_discarded() ? nlohmann::json(text) : std::move(value);
    }
    const SettingsLayer map = settings_from_json(object, SettingOrigin{SettingSource::CommandLine, "import settings"});
    for (const auto& [name, setting] : map.values) {
      if (layer.values.count(name))
        throw InputError(name == "body" ? std::string("import: the body is given twice (as the body option and in the "
                                                      "settings); expected one")
                                        : "import: the setting '" + name +
                                              "' is given twice (as an option and in the settings); expected one");
      layer.values[name] = setting;
    }
  }
  return layer;
}

namespace {

/// The captive-table options checked: a known form and convention, positive
/// finite values, and none of them with another format.
void check_captive_options(const ImportOptions& options) {
  const bool captive = options.format == "captive-table";
  const auto only_captive = [&](bool given, const char* option) {
    if (given && !captive)
      throw InputError(std::string(option) + " is for captive-test tables; expected --format captive-table with it");
  };
  only_captive(options.form.has_value(), "--form");
  only_captive(options.drift_convention.has_value(), "--drift-convention");
  only_captive(options.density.has_value(), "--density");
  const std::array<std::pair<const std::optional<double>*, const char*>, 7> values{{{&options.length, "--length"},
                                                                                    {&options.speed, "--speed"},
                                                                                    {&options.density, "--density"},
                                                                                    {&options.draft, "--draft"},
                                                                                    {&options.mass, "--mass"},
                                                                                    {&options.volume, "--volume"},
                                                                                    {&options.gravity, "--gravity"}}};
  for (const auto& [value, option] : values) {
    only_captive(value->has_value(), option);
    if (*value && !(std::isfinite(**value) && **value > 0.0))
      throw InputError(std::string(option) + " must be a finite number above 0, not " + shortest_number(**value));
  }
  if (options.form && *options.form != "prime" && *options.form != "bis" && *options.form != "mmg")
    throw InputError("--form '" + printable_text(*options.form, 40) +
                     "': expected prime (SNAME 1950), bis (Norrbin 1971) or mmg (Yasukawa and Yoshimura 2015)");
  if (options.drift_convention && *options.drift_convention != "mmg" && *options.drift_convention != "fossen")
    throw InputError("--drift-convention '" + printable_text(*options.drift_convention, 40) +
                     "': expected mmg (beta = atan2(-v, u)) or fossen (beta = atan2(v, u))");
}

CaptiveTableOptions captive_options(const ImportOptions& options) {
  CaptiveTableOptions out;
  out.form = options.form;
  out.drift_convention = options.drift_convention;
  out.length = {options.length, "--length"};
  out.speed = {options.speed, "--speed"};
  out.draft = {options.draft, "--draft"};
  out.mass = {options.mass, "--mass"};
  out.volume = {options.volume, "--volume"};
  out.gravity = {options.gravity, "--gravity"};
  return out;  // the density comes with each input's settings (--rho, --density, sidecars)
}

/// The bodies' stored reference data, for captive-test tables.
std::map<std::string, CaptiveBodyReference> stored_body_references(RunDatabase& store) {
  std::map<std::string, CaptiveBodyReference> out;
  for (const auto& record : store.body_references())
    out[record.body] = CaptiveBodyReference{record.length, record.draft, record.displaced_volume};
  return out;
}

/// From options.reference_database, for a captive-table import; none when it
/// cannot be opened read-only (a database not made yet).
std::map<std::string, CaptiveBodyReference> reference_database_bodies(const ImportOptions& options) {
  if (options.format != "captive-table" || options.reference_database.empty()) return {};
  std::error_code ec;
  const bool url = options.reference_database.find("://") != std::string::npos;
  if (!url && !std::filesystem::exists(options.reference_database, ec)) return {};
  try {
    const Database database = Database::open(options.reference_database, OpenMode::ReadOnly);
    auto& impl = Database::Access::impl(database);
    const std::lock_guard lock(impl.mutex);
    return stored_body_references(impl.open_store());
  } catch (const InputError&) {
    return {};  // a database that cannot be read says so when the runs are stored
  }
}

PreparedImport prepare(const std::vector<std::string>& paths, const ImportOptions& options,
                       std::map<std::string, CaptiveBodyReference> body_references);

}  // namespace

void ImportOptions::validate() const {
  check_captive_options(*this);
  (void)command_line_layer(*this);
}

PreparedImport prepare_import(const std::vector<std::string>& paths, const ImportOptions& options) {
  check_captive_options(options);
  return prepare(paths, options, reference_database_bodies(options));
}

namespace {

PreparedImport prepare(const std::vector<std::string>& paths, const ImportOptions& options,
                       std::map<std::string, CaptiveBodyReference> body_references) {
  ImportRequest request;
  request.captive = captive_options(options);
  request.body_references = std::move(body_references);
  for (const auto& path : paths) request.inputs.emplace_back(path);
  request.command_line = command_line_layer(options);  // validates the options
  request.format = options.format;
  request.columns.columns = options.columns;
  request.columns.units = options.units;
  request.columns.disturbance_columns = options.disturbance_columns;
  request.columns.ignored_columns = options.ignored_columns;
  request.columns.monitors = options.monitors;
  request.columns.average_last = options.average_last;
  request.jobs = options.jobs;
  if (options.progress)
    request.progress = [&options](std::size_t done, std::size_t total, const std::filesystem::path& path) {
      options.progress(done, total, path.string());
    };
  std::optional<Manifest> manifest;
  std::optional<NamePattern> pattern;
  if (!options.manifest.empty()) manifest = Manifest::read(options.manifest);
  if (!options.key_from_name.empty()) pattern.emplace(options.key_from_name);
  request.plan.include = options.include;
  request.plan.exclude = options.exclude;
  request.plan.manifest = manifest ? &*manifest : nullptr;
  request.plan.key_pattern = pattern ? &*pattern : nullptr;
  request.plan.use_sidecars = options.use_sidecars;
  request.plan.prefer_surfaces = options.prefer_surfaces;

  auto impl = std::make_unique<PreparedImport::Impl>();
  impl->result = read_import(request);
  impl->policy.components = options.replace ? ConflictPolicy::Replace : ConflictPolicy::Error;
  impl->policy.replace = options.replace;
  impl->policy.also = options.also;
  return PreparedImport::Access::make(std::move(impl));
}

}  // namespace

ImportSummary import_prepared(Database& database, PreparedImport&& prepared) {
  auto& p = PreparedImport::Access::impl(prepared);
  auto& impl = Database::Access::impl(database);
  const std::lock_guard lock(impl.mutex);
  auto& store = impl.writable_store("an import");
  if (p.stored) throw InputError("import: these inputs were stored already; prepare the import again");
  p.stored = true;
  store_import(store, p.result, p.policy);
  return records::import_summary(p.result, impl.path);
}

ImportSummary Database::import_files(const std::vector<std::string>& paths, const ImportOptions& options) {
  check_captive_options(options);
  std::map<std::string, CaptiveBodyReference> bodies;
  {
    const std::lock_guard lock(impl_->mutex);
    RunDatabase& store = impl_->writable_store("an import");  // refused before anything is read
    if (options.format == "captive-table") bodies = stored_body_references(store);
  }
  return import_prepared(*this, prepare(paths, options, std::move(bodies)));
}

}  // namespace api
}  // namespace hydrocoef
