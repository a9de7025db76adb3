// One input's settings as its reader applies them: merged, checked for a
// stated free stream, refused or noted where an importer cannot apply them,
// and recorded with the import (src/pipeline/import_files_internal.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/pipeline/import_files_internal.hpp"

namespace hydrocoef::reading {

namespace fs = std::filesystem;

RunSettings input_settings(const PlannedInput& input, const ImportRequest& request) {
  std::vector<SettingsLayer> layers;
  if (!request.command_line.empty()) layers.push_back(request.command_line);
  layers.insert(layers.end(), input.layers.begin(), input.layers.end());
  RunSettings settings = merge_settings(layers);
  check_flow_stated(settings, input.path);
  return settings;
}

void settings_not_applicable(const RunSettings& settings, const std::vector<std::string>& names,
                             const std::string& what, std::vector<std::string>& notes) {
  for (const auto& name : names) {
    const Setting* setting = settings.find(name);
    if (!setting) continue;
    const auto source = setting->origin.source;
    const std::string where =
        setting->origin.where.empty() ? std::string(setting_source_name(source)) : setting->origin.where;
    if (source == SettingSource::CommandLine || source == SettingSource::FileSidecar ||
        source == SettingSource::Manifest)
      throw InputError(where + ": setting '" + name + "' does not apply to " + what + "; expected it left out");
    notes.push_back("setting '" + name + "' from " + where + " does not apply to " + what + " and was not used");
  }
}

void check_flow_speed(const RunSettings& settings, const RunKey& key, const fs::path& file,
                      std::vector<std::string>& notes) {
  const Setting* stated = settings.find("flow_speed");
  if (!stated) return;
  const double speed = *settings.number("flow_speed");
  char text[64];
  std::snprintf(text, sizeof text, "%.6g m/s", speed);
  const std::string where = stated->origin.where.empty() ? "the case files" : stated->origin.where;
  if (!settings.find("flow") && !settings.find("u") && !settings.find("v") && !settings.find("w"))
    throw InputError(SourceLocation{file.string()},
                     "the case states only the free stream's normal speed, " + std::string(text) + " (" + where +
                         "), not its direction; expected the free stream with --flow x,y,z (CFD axes) or the body "
                         "velocity u, v, w from a sidecar, the manifest or --key-from-name");
  const double body = std::hypot(key.nu_b[0], key.nu_b[1], key.nu_b[2]);
  if (std::abs(body - speed) > 1e-6 * std::max(1.0, speed)) {
    char found[64];
    std::snprintf(found, sizeof found, "%.6g m/s", body);
    notes.push_back("the body's speed, " + std::string(found) + ", is not the inlet's normal speed in the CFX case, " +
                    text + " (" + where + "): check the run's key");
  }
}

void check_flow_stated(const RunSettings& settings, const fs::path& file) {
  if (settings.find("flow") || settings.find("u") || settings.find("v") || settings.find("w") ||
      settings.find("at_rest"))
    return;
  const char* expected =
      "expected the free stream with --flow x,y,z (CFD axes), or the body velocity u, v, w from a sidecar, the "
      "manifest or --key-from-name (--at-rest for a body at rest)";
  if (const Setting* unstated = settings.find("flow_unstated")) {
    const std::string where = unstated->origin.where.empty() ? file.string() : unstated->origin.where;
    throw InputError(where + ": " + *settings.text("flow_unstated") + "; " + expected);
  }
  if (const Setting* stated = settings.find("flow_speed")) {
    char text[64];
    std::snprintf(text, sizeof text, "%.6g m/s", *settings.number("flow_speed"));
    const std::string where = stated->origin.where.empty() ? "the case files" : stated->origin.where;
    throw InputError(SourceLocation{file.string()}, "the case states only the free stream's normal speed, " +
                                                        std::string(text) + " (" + where + "), not its direction; " +
                                                        expected);
  }
}

Fluid fluid_of(const RunSettings& settings) { return Fluid{settings.number("rho"), settings.number("nu")}; }

SignConvention sign_of(const RunSettings& settings) {
  const auto text = settings.text("sign");
  if (!text) return SignConvention::OnBody;
  try {
    return parse_sign_convention(*text);
  } catch (const InputError& e) {
    throw InputError(settings.find("sign")->origin.where + ": setting 'sign': " + e.what());
  }
}

void record_settings(ImportBatch& batch, const RunSettings& settings, const std::string& format, const fs::path& path) {
  nlohmann::json json = settings.provenance_json();
  batch.source.settings = escape::json_text(json);
  batch.source.settings_key = format + " " + settings.effective_text();
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
  batch.source.resolved_path = ec ? fs::absolute(path).lexically_normal().string() : resolved.string();
}

}  // namespace hydrocoef::reading
