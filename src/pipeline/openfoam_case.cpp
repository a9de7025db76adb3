#include "src/pipeline/openfoam_case.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

#include "importers/openfoam_dictionary.hpp"
#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

std::string where_of(const FoamValue& value) { return value.file + ":" + std::to_string(value.line); }

/// What the dictionary reader read otherwise than written (a stray '}' that
/// ends a file, as OpenFOAM reads it), as notes.
void note_warnings(const FoamDictionary& dictionary, OpenFoamCaseSettings& out) {
  out.notes.insert(out.notes.end(), dictionary.warnings().begin(), dictionary.warnings().end());
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

struct FreeStream {
  std::array<double, 3> value{};
  std::string where;
  std::string patch;
};

void read_velocity(const fs::path& file, OpenFoamCaseSettings& out) {
  const FoamDictionary u = FoamDictionary::read(file);
  note_warnings(u, out);
  const FoamDictionary* boundary = u.dictionary("boundaryField");
  if (!boundary) return;
  std::optional<FreeStream> freestream, inlet;
  std::vector<std::string> symmetry;
  for (const auto& patch : boundary->dictionary_keys()) {
    const FoamDictionary& d = *boundary->dictionary(patch);
    const std::string type = foam_word(d.value("type")).value_or("");
    const auto take = [&](std::optional<FreeStream>& slot, const char* key) {
      const FoamValue* value = d.value(key);
      if (!value) return;
      FreeStream stream{foam_vector(*value, "patch '" + patch + "' " + key), where_of(*value), patch};
      if (slot && slot->value != stream.value)
        throw InputError(SourceLocation{value->file, value->line, 0},
                         "patches '" + slot->patch + "' and '" + patch +
                             "' state different free streams; expected one (give the run's flow in a sidecar)");
      if (!slot) slot = stream;
    };
    if (type == "freestreamVelocity" || type == "freestream")
      take(freestream, "freestreamValue");
    else if (type == "inletOutlet" && lower(patch).find("inlet") != std::string::npos)
      take(inlet, "inletValue");
    else if (type == "fixedValue" && lower(patch).find("inlet") != std::string::npos)
      take(inlet, "value");
    else if (type == "symmetryPlane" || type == "symmetry")
      symmetry.push_back(patch);
  }
  const auto& stream = freestream ? freestream : inlet;
  if (stream) out.layer.set("flow", std::vector<double>(stream->value.begin(), stream->value.end()), stream->where);
  if (!symmetry.empty()) {
    std::string names;
    for (const auto& name : symmetry) names += (names.empty() ? "" : ", ") + name;
    out.notes.push_back("symmetry patches (" + names + ") in " + file.string() +
                        ": the forces are the modelled part's; give --symmetry PLANE for the whole body's");
  }
}

void read_forces_function(const fs::path& file, OpenFoamCaseSettings& out) {
  const FoamDictionary control = FoamDictionary::read(file);
  note_warnings(control, out);
  const FoamDictionary* functions = control.dictionary("functions");
  bool found = false;
  if (functions) {
    for (const auto& name : functions->dictionary_keys()) {
      const FoamDictionary& f = *functions->dictionary(name);
      const std::string type = foam_word(f.value("type")).value_or("");
      if (type != "forces" && type != "forceCoeffs") continue;
      found = true;
      const auto rho = foam_word(f.value("rho"));
      if (const FoamValue* rho_inf = f.value("rhoInf"); rho_inf && (!rho || *rho == "rhoInf"))
        out.layer.set("rho", foam_scalar(*rho_inf, "rhoInf"), where_of(*rho_inf));
      const FoamValue* centre = f.value("CofR");
      if (!centre) centre = f.value("origin");
      if (centre) {
        const auto x = foam_vector(*centre, "CofR");
        out.layer.set("cofr", std::vector<double>(x.begin(), x.end()), where_of(*centre));
      }
      break;
    }
    if (!found && !functions->unread_includes().empty())
      out.notes.push_back(file.string() + " names function objects in files of the OpenFOAM installation (" +
                          functions->unread_includes().front() +
                          "), which hydrocoef does not read: give rho and the moment centre in a sidecar if they "
                          "matter");
  }
}

void read_viscosity(const fs::path& case_dir, OpenFoamCaseSettings& out) {
  for (const char* name : {"transportProperties", "physicalProperties"}) {
    const fs::path file = case_dir / "constant" / name;
    if (!fs::is_regular_file(file)) continue;
    const FoamDictionary d = FoamDictionary::read(file);
    note_warnings(d, out);
    if (const FoamValue* nu = d.value("nu")) {
      out.layer.set("nu", foam_scalar(*nu, "nu"), where_of(*nu));
      return;
    }
  }
}

}  // namespace

OpenFoamCaseSettings openfoam_case_settings(const fs::path& case_dir) {
  OpenFoamCaseSettings out;
  out.layer.origin = {SettingSource::CaseFiles, case_dir.string()};
  std::error_code ec;
  if (fs::is_regular_file(case_dir / "0" / "U", ec))
    read_velocity(case_dir / "0" / "U", out);
  else if (fs::is_regular_file(case_dir / "0.orig" / "U", ec))
    read_velocity(case_dir / "0.orig" / "U", out);
  if (fs::is_regular_file(case_dir / "system" / "controlDict", ec))
    read_forces_function(case_dir / "system" / "controlDict", out);
  read_viscosity(case_dir, out);
  return out;
}

}  // namespace hydrocoef
