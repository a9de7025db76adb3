// Database::import_files (include/hydrocoef/database.hpp): `hydrocoef import`
// without its printing. The library plans and reads the inputs
// and stores them in one transaction (src/pipeline/import_files.hpp: read_import,
// store_import), as the CLI does.
#include "src/api/internal.hpp"

#include <nlohmann/json.hpp>

namespace hydrocoef {
inline namespace api {
namespace {

/// The caller's settings as the command line's layer: each value is JSON, or
/// a plain text when it is not ("-x,y,-z"), read as a sidecar's keys are.
SettingsLayer command_line_layer(const ImportOptions& options) {
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [key, text] : options.settings) {
    auto value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    object[key] = value.is_discarded() ? nlohmann::json(text) : std::move(value);
  }
  SettingsLayer layer = settings_from_json(object, SettingOrigin{SettingSource::CommandLine, "import settings"});
  if (!options.body.empty()) {
    if (layer.values.count("body"))
      throw InputError("import: the body is given twice (as the body option and in the settings); expected one");
    layer.set("body", std::string(check_name(NameKind::Body, options.body, {}, "the import's body")), "body");
  }
  return layer;
}

}  // namespace

ImportSummary Database::import_files(const std::vector<std::string>& paths, const ImportOptions& options) {
  {
    const std::lock_guard lock(impl_->mutex);
    impl_->writable_store("an import");  // refused before anything is read
  }
  ImportRequest request;
  for (const auto& path : paths) request.inputs.emplace_back(path);
  request.command_line = command_line_layer(options);
  request.format = options.format;
  request.columns.columns = options.columns;
  request.columns.units = options.units;
  request.columns.disturbance_columns = options.disturbance_columns;
  request.columns.ignored_columns = options.ignored_columns;
  request.columns.monitors = options.monitors;
  request.columns.average_last = options.average_last;
  request.jobs = options.jobs;
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

  // Everything is read before the database is touched: a bad input leaves it as it was.
  ImportResult result = read_import(request);
  ImportPolicy store_options;
  store_options.components = options.replace ? ConflictPolicy::Replace : ConflictPolicy::Error;
  store_options.replace = options.replace;
  store_options.also = options.also;
  {
    const std::lock_guard lock(impl_->mutex);
    store_import(impl_->writable_store("an import"), result, store_options);
  }
  const auto& plan = result.plan;
  const auto& inputs = result.inputs;
  const auto& outcomes = result.outcomes;

  ImportSummary summary;
  summary.notes = plan.notes;
  summary.excluded = plan.excluded;
  for (std::size_t i = 0; i < outcomes.size() && i < inputs.size(); ++i) {
    const ImportOutcome& o = outcomes[i];
    summary.files.push_back({o.path, inputs[i].format, inputs[i].batch.runs.size(), o.runs_created, o.runs_extended,
                             o.already_imported, o.replaced, inputs[i].notes});
  }
  summary.runs_created = result.runs_created;
  summary.runs_extended = result.runs_extended;
  summary.already_imported = result.already_imported;
  return summary;
}

}  // namespace api
}  // namespace hydrocoef
