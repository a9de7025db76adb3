#include "src/pipeline/import_plan.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include "importers/cfx_monitor.hpp"
#include "importers/cfx_out.hpp"
#include "src/core/error.hpp"
#include "src/core/text.hpp"
#include "src/pipeline/cfx_case.hpp"
#include "src/pipeline/openfoam_case.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

bool is_data_extension(const std::string& extension) {
  static const std::set<std::string> known = {".csv", ".txt", ".tsv",  ".dat",   ".vtp", ".vtu",
                                              ".vtk", ".vtm", ".case", ".encas", ".cgns"};
  return known.count(extension) > 0;
}

bool is_surface_extension(const std::string& extension) {
  static const std::set<std::string> known = {".vtp", ".vtu", ".vtk", ".vtm", ".case", ".encas", ".cgns"};
  return known.count(extension) > 0;
}

constexpr const char* kFolderSidecar = "hydrocoef-run.json";

/// The path a name pattern reads for an input named on the command line: the
/// path as given, without its root.
fs::path pattern_path(const fs::path& given) { return given.lexically_normal().relative_path(); }

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
/// cfx5mondata CSV beside it whose name starts with the case's stem; empty
/// when there is none.
std::optional<fs::path> cfx_monitor_of(const fs::path& case_file) {
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
  if (found.empty()) return std::nullopt;
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

/// Settings files of a folder walk: sidecars and the manifest, used, not data.
bool is_settings_file(const fs::path& file, const ImportPlanOptions& options) {
  const std::string name = file.filename().string();
  if (name == kFolderSidecar) return true;
  std::error_code ec;
  if (lower(file.extension().string()) == ".json" && fs::exists(file.parent_path() / file.stem(), ec)) return true;
  return options.manifest && fs::equivalent(file, options.manifest->file(), ec);
}

std::string skipped_note(const std::vector<fs::path>& skipped) {
  std::string names;
  const std::size_t shown = std::min<std::size_t>(skipped.size(), 5);
  for (std::size_t i = 0; i < shown; ++i) names += (i ? ", " : "") + skipped[i].generic_string();
  if (skipped.size() > shown) names += ", ... (" + std::to_string(skipped.size() - shown) + " more)";
  return std::to_string(skipped.size()) + (skipped.size() == 1 ? " file" : " files") +
         " skipped as not CFD data (documentation, logs, solver outputs other than forces, other formats): " + names;
}

/// The time of a foamToVTK name, NAME_TIME(.vtm): the number after the last '_'.
std::optional<double> vtk_time(const fs::path& file) {
  const std::string stem = file.stem().string();
  const auto underscore = stem.rfind('_');
  if (underscore == std::string::npos) return std::nullopt;
  const std::string text = stem.substr(underscore + 1);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

bool is_not_cfd_data(const fs::path& file) {
  const std::string name = lower(file.filename().string());
  if (name.rfind("log.", 0) == 0 || name.ends_with(".log")) return true;
  std::string stem = lower(file.stem().string());
  for (const char* documentation : {"readme", "source", "sources", "notes", "note", "license", "licence", "provenance",
                                    "changelog", "citation", "authors", "todo", "description"})
    if (stem == documentation) return true;
  if (stem.rfind("readme", 0) == 0) return true;
  // OpenFOAM function objects other than forces, with or without a restart time.
  if (const auto underscore = stem.rfind('_'); underscore != std::string::npos) {
    const std::string time = stem.substr(underscore + 1);
    if (!time.empty() && time.find_first_not_of("0123456789.e+-") == std::string::npos) stem.resize(underscore);
  }
  for (const char* output :
       {"solverinfo", "yplus", "wallshearstress", "residuals", "fieldminmax", "surfacefieldvalue", "volfieldvalue",
        "fieldaverage", "courantno", "wallheatflux", "continuityerror", "cellzoneflux"})
    if (stem == output) return true;
  return false;
}

std::optional<fs::path> case_surface_export(const fs::path& case_folder, std::string& why) {
  const fs::path vtk = case_folder / "VTK";
  std::error_code ec;
  if (!fs::is_directory(vtk, ec)) {
    why = "no VTK/ folder";
    return std::nullopt;
  }
  std::vector<std::pair<double, fs::path>> multiblocks;
  std::vector<fs::path> untimed;
  for (const auto& entry : fs::directory_iterator(vtk, ec)) {
    if (!entry.is_regular_file(ec) || lower(entry.path().extension().string()) != ".vtm") continue;
    if (const auto time = vtk_time(entry.path()))
      multiblocks.emplace_back(*time, entry.path());
    else
      untimed.push_back(entry.path());
  }
  fs::path chosen;
  if (!multiblocks.empty()) {
    std::sort(multiblocks.begin(), multiblocks.end());
    chosen = multiblocks.back().second;
  } else if (untimed.size() == 1) {
    chosen = untimed.front();
  } else {
    why = untimed.empty() ? "no .vtm under VTK/" : "several .vtm under VTK/ without a time in their names";
    return std::nullopt;
  }
  // foamToVTK's layout: NAME_TIME.vtm beside NAME_TIME/ holding the blocks.
  const fs::path blocks = chosen.parent_path() / chosen.stem();
  std::vector<fs::path> surfaces;
  if (fs::is_directory(blocks, ec))
    for (const auto& entry : fs::recursive_directory_iterator(blocks, ec))
      if (entry.is_regular_file(ec) && is_surface_extension(lower(entry.path().extension().string())))
        surfaces.push_back(entry.path());
  return surfaces.size() == 1 ? surfaces.front() : chosen;
}

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

namespace {

/// An OpenFOAM case as one input: its force history, or with
/// --prefer-surfaces the surface export under its VTK/ folder.
PlannedInput case_input(const fs::path& folder, const fs::path& relative, const fs::path& pattern, const fs::path& root,
                        const ImportPlanOptions& options, std::vector<std::string>& notes) {
  PlannedInput input{folder, relative, InputKind::OpenFoamCase, case_layers(folder, pattern, root, options, notes)};
  if (!options.prefer_surfaces) return input;
  std::string why;
  const auto surface = case_surface_export(folder, why);
  if (!surface) {
    notes.push_back(folder.string() + ": no surface export to prefer (" + why + "); its force history imported");
    return input;
  }
  notes.push_back(folder.string() + ": " + surface->lexically_relative(folder).generic_string() +
                  " (surfaces, as asked) imported; postProcessing's forces left out: one run read two ways");
  input.path = *surface;
  input.kind = InputKind::File;
  if (!relative.empty()) input.relative = relative / surface->lexically_relative(folder);
  return input;
}

}  // namespace

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
      // A CFX case file named directly stands for its run: its monitors, with
      // its settings, or the wall force summary of its .out.
      fs::path file = input;
      if (is_cfx_case_extension(input) && is_cfx_case_file(input)) {
        if (const auto monitors = cfx_monitor_of(input)) {
          file = *monitors;
          plan.notes.push_back(input.string() + ": a CFX run; its monitors read from " + file.filename().string());
        } else if (lower(input.extension().string()) == ".out" && file_has_cfx_wall_forces(input)) {
          plan.notes.push_back(input.string() +
                               ": a CFX run without monitor files beside it; its forces read from the solver's wall "
                               "force and moment summary");
        } else {
          const std::string stem = input.stem().string();
          throw InputError(SourceLocation{input.string()},
                           "a CFX case file, but no monitor file beside it (" + stem +
                               "*.csv with an 'Accumulated Timestep' header)" +
                               (lower(input.extension().string()) == ".out" ? " and no wall force summary in it" : "") +
                               "; expected the monitors exported with cfx5mondata -res " + stem + ".res -out " + stem +
                               ".csv, or the .out of the finished run");
        }
      }
      auto layers = layers_for(file, pattern_path(input), {}, true, options);
      if (const auto case_file = cfx_cases.of(file)) add_cfx_case_layer(file, *case_file, layers, plan.notes);
      plan.inputs.push_back({file, {}, InputKind::File, std::move(layers)});
      continue;
    }
    if (is_openfoam_case(input)) {
      plan.inputs.push_back(case_input(input, {}, pattern_path(input), input, options, plan.notes));
      continue;
    }
    // A walk that does not enter case folders and keeps the order stable.
    std::vector<fs::path> files, cases, cfx_outs;
    std::vector<fs::path> skipped;
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
      if (!it->is_regular_file(ec) || is_settings_file(path, options)) continue;
      const std::string extension = lower(path.extension().string());
      if (is_cfx_case_extension(path) && is_cfx_case_file(path)) {
        if (extension == ".out") cfx_outs.push_back(path);  // settings, or a run of its own (below)
        continue;
      }
      if (!is_data_extension(extension) || is_not_cfd_data(path)) {
        skipped.push_back(path);
        continue;
      }
      // The filters come first: twins and partners are paired among the files kept.
      if (!filtered_in(path.lexically_relative(input), options)) {
        ++plan.excluded;
        continue;
      }
      files.push_back(path);
    }
    // A CFX .out that no data file of its run takes settings from is a run
    // of its own when it holds the solver's wall force summary.
    std::set<fs::path> settings_of_data;
    for (const auto& file : files)
      if (const auto case_file = cfx_cases.of(file)) settings_of_data.insert(*case_file);
    for (const auto& out : cfx_outs) {
      if (settings_of_data.count(out)) continue;
      if (!file_has_cfx_wall_forces(out)) {
        skipped.push_back(out);
      } else if (!filtered_in(out.lexically_relative(input), options)) {
        ++plan.excluded;
      } else {
        files.push_back(out);
        plan.notes.push_back(out.string() +
                             ": a CFX run without data files beside it; its forces read from the solver's wall force "
                             "and moment summary");
      }
    }
    std::sort(files.begin(), files.end());
    std::sort(cases.begin(), cases.end());
    std::vector<fs::path> skipped_here;
    for (const auto& file : skipped) skipped_here.push_back(file.lexically_relative(input));
    std::sort(skipped_here.begin(), skipped_here.end());
    plan.skipped.insert(plan.skipped.end(), skipped_here.begin(), skipped_here.end());

    // Twins and partners, decided per folder.
    std::set<fs::path> dropped;
    std::map<std::pair<fs::path, std::string>, std::vector<fs::path>> by_stem;
    for (const auto& file : files) {
      const std::string extension = lower(file.extension().string());
      if (extension == ".vtp" || extension == ".vtu" || extension == ".vtk")
        by_stem[{file.parent_path(), file.stem().string()}].push_back(file);
      // (when the filters left some of its blocks)
      const fs::path blocks = file.parent_path() / file.stem();
      if (extension == ".vtm" && std::any_of(files.begin(), files.end(), [&](const fs::path& other) {
            const auto rest = other.lexically_relative(blocks);
            return !rest.empty() && *rest.begin() != "..";
          })) {
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
      else if (is_surface_extension(extension))
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
      plan.inputs.push_back(case_input(folder, relative, relative, input, options, plan.notes));
      ++planned;
    }
    for (const auto& file : files) {
      if (dropped.count(file)) continue;
      const fs::path relative = file.lexically_relative(input);
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
                           (skipped_here.empty() ? std::string() : " (" + skipped_note(skipped_here) + ")") +
                           "; expected case folders or files .csv .txt .tsv .dat .vtp .vtu .vtk .vtm .case .cgns, "
                           "or CFX .out files with their wall force summary");
    }
  }
  if (!plan.skipped.empty()) plan.notes.push_back(skipped_note(plan.skipped));
  return plan;
}

}  // namespace hydrocoef
