#include "src/pipeline/import_plan.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include "importers/cfx_monitor.hpp"
#include "src/core/error.hpp"
#include "src/pipeline/cfx_case.hpp"
#include "src/pipeline/openfoam_case.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool is_data_extension(const std::string& extension) {
  static const std::set<std::string> known = {".csv", ".txt", ".tsv",  ".dat",   ".vtp", ".vtu",
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

// --- CFX runs ----------------------------------------------------------------
// A CFX run leaves its settings in a case file (the CCL written by CFX-Pre,
// STEM.ccl, or echoed by the solver at the top of STEM.out) and its forces in
// files exported beside it: cfx5mondata's monitor CSV or a CFD-Post export,
// named after the run (STEM.csv, STEM_monitors.csv, ...). A data file whose
// name starts with a case file's stem, in the same folder, takes that case
// file's settings as its case-files layer; of STEM.out and STEM.ccl the
// solver's .out is taken (it is what ran).

bool is_cfx_case_extension(const fs::path& file) {
  const std::string extension = lower(file.extension().string());
  return extension == ".ccl" || extension == ".out";
}

/// The case files of a folder, longest stem first (read once per folder).
class CfxCaseFiles {
 public:
  const std::vector<fs::path>& in(const fs::path& folder) {
    auto [it, inserted] = cache_.try_emplace(folder);
    if (!inserted) return it->second;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder.empty() ? fs::path(".") : folder, ec)) {
      if (!entry.is_regular_file(ec) || !is_cfx_case_extension(entry.path())) continue;
      if (is_cfx_case_file(entry.path())) it->second.push_back(entry.path());
    }
    std::sort(it->second.begin(), it->second.end(), [](const fs::path& a, const fs::path& b) {
      const auto la = a.stem().string().size(), lb = b.stem().string().size();
      if (la != lb) return la > lb;
      return lower(a.extension().string()) > lower(b.extension().string());  // .out before .ccl
    });
    return it->second;
  }

  /// The case file of a data file: the one with the longest stem its name starts with.
  std::optional<fs::path> of(const fs::path& data_file) {
    const std::string stem = data_file.stem().string();
    for (const auto& candidate : in(data_file.parent_path()))
      if (stem.rfind(candidate.stem().string(), 0) == 0) return candidate;
    return std::nullopt;
  }

 private:
  std::map<fs::path, std::vector<fs::path>> cache_;
};

/// A data file's layers with its CFX case file's settings ranked as case
/// files (below sidecars and the manifest, above the name pattern).
void add_cfx_case_layer(const fs::path& file, const fs::path& case_file, std::vector<SettingsLayer>& layers,
                        std::vector<std::string>& notes) {
  CfxCaseSettings settings = cfx_case_settings(case_file);
  notes.push_back(file.string() + ": settings from the CFX case " + case_file.filename().string() + " beside it");
  for (const auto& note : settings.notes) notes.push_back(case_file.string() + ": " + note);
  if (settings.layer.empty()) return;
  const auto pattern = std::find_if(layers.begin(), layers.end(), [](const SettingsLayer& layer) {
    return layer.origin.source == SettingSource::NamePattern;
  });
  layers.insert(pattern, std::move(settings.layer));
}

/// The monitor file of a CFX case file named on the command line: the one
/// cfx5mondata CSV beside it whose name starts with the case's stem.
fs::path cfx_monitor_of(const fs::path& case_file) {
  std::vector<fs::path> found;
  std::error_code ec;
  const fs::path folder = case_file.parent_path().empty() ? fs::path(".") : case_file.parent_path();
  const std::string stem = case_file.stem().string();
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const fs::path& path = entry.path();
    if (!entry.is_regular_file(ec) || lower(path.extension().string()) != ".csv" ||
        path.stem().string().rfind(stem, 0) != 0)
      continue;
    std::string head(4096, '\0');
    {
      std::FILE* in = std::fopen(path.c_str(), "rb");
      if (!in) continue;
      head.resize(std::fread(head.data(), 1, head.size(), in));
      std::fclose(in);
    }
    if (looks_like_cfx_monitor(head)) found.push_back(folder / path.filename());
  }
  std::sort(found.begin(), found.end());
  if (found.size() == 1) return found.front();
  if (found.empty())
    throw InputError(SourceLocation{case_file.string()},
                     "a CFX case file, but no monitor file beside it (" + stem +
                         "*.csv with an 'Accumulated Timestep' header); expected the monitors exported with "
                         "cfx5mondata -res " +
                         stem + ".res -out " + stem + ".csv");
  std::string names;
  for (const auto& f : found) names += (names.empty() ? "" : ", ") + f.filename().string();
  throw InputError(SourceLocation{case_file.string()}, "a CFX case file with " + std::to_string(found.size()) +
                                                           " monitor files beside it (" + names +
                                                           "); expected one: name the monitor file to import instead");
}

bool filtered_in(const fs::path& relative, const ImportPlanOptions& options) {
  if (!options.include.empty() && std::none_of(options.include.begin(), options.include.end(),
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
  const std::string text =
      pattern.find('/') == std::string::npos ? relative.filename().string() : relative.generic_string();
  return fnmatch(pattern.c_str(), text.c_str(), 0) == 0;
}

ImportPlan plan_import(const std::vector<fs::path>& inputs, const ImportPlanOptions& options) {
  ImportPlan plan;
  CfxCaseFiles cfx_cases;
  for (const auto& input : inputs) {
    std::error_code ec;
    if (!fs::exists(input, ec))
      throw InputError(SourceLocation{input.string()},
                       "no such file or folder; expected a CFD result file, a folder of "
                       "them or a case folder");
    if (!fs::is_directory(input, ec)) {
      // A CFX case file named directly stands for its run: its monitors, with its settings.
      fs::path file = input;
      if (is_cfx_case_extension(input) && is_cfx_case_file(input)) {
        file = cfx_monitor_of(input);
        plan.notes.push_back(input.string() + ": a CFX run; its monitors read from " + file.filename().string());
      }
      auto layers = layers_for(file, {}, {}, true, options);
      if (const auto case_file = cfx_cases.of(file)) add_cfx_case_layer(file, *case_file, layers, plan.notes);
      plan.inputs.push_back({file, {}, InputKind::File, std::move(layers)});
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
      if (is_force_history_name(file))
        kinds[file.parent_path()].first.push_back(file);
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
      plan.notes.push_back(folder.string() + ": " + taken +
                           (options.prefer_surfaces ? " (surfaces, as asked)" : " (force history)") + " imported; " +
                           left + " left out: one run read two ways" +
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
      auto layers = layers_for(file, relative, input, true, options);
      if (const auto case_file = cfx_cases.of(file)) add_cfx_case_layer(file, *case_file, layers, plan.notes);
      plan.inputs.push_back({file, relative, InputKind::File, std::move(layers)});
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
