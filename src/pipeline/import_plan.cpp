#include "src/pipeline/import_plan.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <map>
#include <set>

#include "src/core/error.hpp"
#include "src/pipeline/openfoam_case.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool is_data_extension(const std::string& extension) {
  static const std::set<std::string> known = {".csv", ".txt", ".tsv", ".dat", ".vtp", ".vtu",
                                              ".vtk", ".vtm", ".case", ".encas", ".cgns"};
  return known.count(extension) > 0;
}

constexpr const char* kFolderSidecar = "hydrocoef-run.json";

/// The layers of one input: its own sidecar, the manifest row, the folder
/// sidecars from its folder up to `root`, the name pattern.
std::vector<SettingsLayer> layers_for(const fs::path& path, const fs::path& relative, const fs::path& root,
                                      bool names_a_file, const ImportPlanOptions& options) {
  std::vector<SettingsLayer> layers;
  if (options.use_sidecars) {
    fs::path own = path;
    own += ".json";
    if (names_a_file && fs::is_regular_file(own)) layers.push_back(read_settings_file(own, SettingSource::FileSidecar));
  }
  if (options.manifest)
    if (const SettingsLayer* row = options.manifest->find(path)) layers.push_back(*row);
  if (options.use_sidecars) {
    // From the input's own folder (a case folder's sidecar is its own) up to
    // the imported folder, nearest first.
    fs::path folder = names_a_file ? path.parent_path() : path;
    const fs::path stop = root.empty() ? folder : root;
    for (;;) {
      const fs::path sidecar = (folder.empty() ? fs::path(".") : folder) / kFolderSidecar;
      if (fs::is_regular_file(sidecar)) layers.push_back(read_settings_file(sidecar, SettingSource::FolderSidecar));
      if (folder == stop || folder.empty() || !folder.has_relative_path() || folder == folder.parent_path()) break;
      folder = folder.parent_path();
    }
  }
  if (options.key_pattern && !relative.empty())
    if (auto layer = options.key_pattern->match(relative, names_a_file)) layers.push_back(std::move(*layer));
  return layers;
}

/// The layers of an OpenFOAM case folder: layers_for's, with what the case's
/// own dictionaries state ranked below every sidecar and the manifest and
/// above the name pattern.
std::vector<SettingsLayer> case_layers(const fs::path& folder, const fs::path& relative, const fs::path& root,
                                       const ImportPlanOptions& options, std::vector<std::string>& notes) {
  auto layers = layers_for(folder, relative, root, false, options);
  OpenFoamCaseSettings case_settings = openfoam_case_settings(folder);
  notes.insert(notes.end(), case_settings.notes.begin(), case_settings.notes.end());
  if (!case_settings.layer.empty()) {
    const auto pattern = std::find_if(layers.begin(), layers.end(), [](const SettingsLayer& layer) {
      return layer.origin.source == SettingSource::NamePattern;
    });
    layers.insert(pattern, std::move(case_settings.layer));
  }
  return layers;
}

bool filtered_in(const fs::path& relative, const ImportPlanOptions& options) {
  if (!options.include.empty() &&
      std::none_of(options.include.begin(), options.include.end(),
                   [&](const std::string& p) { return glob_matches(p, relative); }))
    return false;
  return std::none_of(options.exclude.begin(), options.exclude.end(),
                      [&](const std::string& p) { return glob_matches(p, relative); });
}

}  // namespace

bool is_force_history_name(const fs::path& file) {
  const std::string name = lower(file.filename().string());
  if (name == "force.dat" || name == "forces.dat" || name == "coefficient.dat") return true;
  for (const char* stem : {"force_", "forces_", "coefficient_"})
    if (name.rfind(stem, 0) == 0 && name.size() > std::string(stem).size() + 4 && name.ends_with(".dat")) return true;
  return false;
}

bool is_openfoam_case(const fs::path& folder) {
  std::error_code ec;
  return fs::is_regular_file(folder / "system" / "controlDict", ec) && fs::is_directory(folder / "constant", ec);
}

bool glob_matches(const std::string& pattern, const fs::path& relative) {
  const std::string text = pattern.find('/') == std::string::npos ? relative.filename().string() : relative.generic_string();
  return fnmatch(pattern.c_str(), text.c_str(), 0) == 0;
}

ImportPlan plan_import(const std::vector<fs::path>& inputs, const ImportPlanOptions& options) {
  ImportPlan plan;
  for (const auto& input : inputs) {
    std::error_code ec;
    if (!fs::exists(input, ec))
      throw InputError(SourceLocation{input.string()}, "no such file or folder; expected a CFD result file, a folder of "
                                                       "them or a case folder");
    if (!fs::is_directory(input, ec)) {
      plan.inputs.push_back({input, {}, InputKind::File, layers_for(input, {}, {}, true, options)});
      continue;
    }
    if (is_openfoam_case(input)) {
      plan.inputs.push_back({input, {}, InputKind::OpenFoamCase, case_layers(input, {}, input, options, plan.notes)});
      continue;
    }
    // A walk that does not enter case folders and keeps the order stable.
    std::vector<fs::path> files, cases;
    for (auto it = fs::recursive_directory_iterator(input, fs::directory_options::skip_permission_denied, ec);
         it != fs::recursive_directory_iterator(); it.increment(ec)) {
      if (ec) throw InputError(SourceLocation{it->path().string()}, "cannot read the folder: " + ec.message());
      const fs::path& path = it->path();
      if (it->is_directory(ec)) {
        if (is_openfoam_case(path)) {
          cases.push_back(path);
          it.disable_recursion_pending();
        }
        continue;
      }
      if (!it->is_regular_file(ec) || !is_data_extension(lower(path.extension().string()))) continue;
      files.push_back(path);
    }
    std::sort(files.begin(), files.end());
    std::sort(cases.begin(), cases.end());

    // Twins and partners, decided per folder.
    std::set<fs::path> dropped;
    std::map<std::pair<fs::path, std::string>, std::vector<fs::path>> by_stem;
    for (const auto& file : files) {
      const std::string extension = lower(file.extension().string());
      if (extension == ".vtp" || extension == ".vtu" || extension == ".vtk")
        by_stem[{file.parent_path(), file.stem().string()}].push_back(file);
      if (extension == ".vtm" && fs::is_directory(file.parent_path() / file.stem(), ec)) {
        dropped.insert(file);
        plan.notes.push_back(file.string() + ": left out; its blocks are read from " +
                             (file.parent_path() / file.stem()).string() + "/");
      }
      if (file.filename() == "moment.dat" && fs::is_regular_file(file.parent_path() / "force.dat", ec))
        dropped.insert(file);  // read with force.dat
    }
    // A history and surfaces in one folder: one run read twice.
    std::map<fs::path, std::pair<std::vector<fs::path>, std::vector<fs::path>>> kinds;  // histories, surfaces
    for (const auto& file : files) {
      if (dropped.count(file)) continue;
      const std::string extension = lower(file.extension().string());
      if (is_force_history_name(file)) kinds[file.parent_path()].first.push_back(file);
      else if (extension != ".csv" && extension != ".txt" && extension != ".tsv" && extension != ".dat")
        kinds[file.parent_path()].second.push_back(file);
    }
    for (const auto& [folder, found] : kinds) {
      const auto& [histories, surfaces] = found;
      if (histories.empty() || surfaces.empty()) continue;
      const auto& take = options.prefer_surfaces ? surfaces : histories;
      const auto& leave = options.prefer_surfaces ? histories : surfaces;
      std::string taken, left;
      for (const auto& f : take) taken += (taken.empty() ? "" : ", ") + f.filename().string();
      for (const auto& f : leave) {
        dropped.insert(f);
        left += (left.empty() ? "" : ", ") + f.filename().string();
      }
      plan.notes.push_back(folder.string() + ": " + taken + (options.prefer_surfaces ? " (surfaces, as asked)" : " (force history)") +
                           " imported; " + left + " left out: one run read two ways" +
                           (options.prefer_surfaces ? "" : " (--prefer-surfaces takes the surfaces)"));
    }
    for (const auto& [key, twins] : by_stem) {
      if (twins.size() < 2) continue;
      if (std::all_of(twins.begin(), twins.end(), [&](const fs::path& t) { return dropped.count(t) > 0; })) continue;
      const auto rank = [](const fs::path& p) {
        const std::string e = lower(p.extension().string());
        return e == ".vtp" ? 0 : e == ".vtu" ? 1 : 2;
      };
      const fs::path kept = *std::min_element(twins.begin(), twins.end(),
                                              [&](const fs::path& a, const fs::path& b) { return rank(a) < rank(b); });
      std::string others;
      for (const auto& twin : twins)
        if (twin != kept) {
          dropped.insert(twin);
          others += (others.empty() ? "" : ", ") + twin.filename().string();
        }
      plan.notes.push_back(kept.string() + ": imported; its twin " + others + " (same name, same folder) left out");
    }

    std::size_t planned = 0;
    for (const auto& folder : cases) {
      const fs::path relative = folder.lexically_relative(input);
      if (!filtered_in(relative, options)) {
        ++plan.excluded;
        continue;
      }
      plan.inputs.push_back(
          {folder, relative, InputKind::OpenFoamCase, case_layers(folder, relative, input, options, plan.notes)});
      ++planned;
    }
    for (const auto& file : files) {
      if (dropped.count(file)) continue;
      const fs::path relative = file.lexically_relative(input);
      if (!filtered_in(relative, options)) {
        ++plan.excluded;
        continue;
      }
      plan.inputs.push_back({file, relative, InputKind::File, layers_for(file, relative, input, true, options)});
      ++planned;
    }
    if (planned == 0) {
      std::string filters;
      for (const auto& p : options.include) filters += " --include '" + p + "'";
      for (const auto& p : options.exclude) filters += " --exclude '" + p + "'";
      throw InputError(SourceLocation{input.string()},
                       "folder holds nothing to import" + (filters.empty() ? std::string() : " with" + filters) +
                           "; expected case folders or files .csv .txt .tsv .dat .vtp .vtu .vtk .vtm .case .cgns");
    }
  }
  return plan;
}

}  // namespace hydrocoef
