#include "src/pipeline/openfoam_case.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "importers/openfoam_dictionary.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

/// What the dictionary reader read otherwise than written (a stray '}' that
/// ends a file, as OpenFOAM reads it), as notes.
void note_warnings(const FoamDictionary& dictionary, OpenFoamCaseSettings& out) {
  out.notes.insert(out.notes.end(), dictionary.warnings().begin(), dictionary.warnings().end());
}

struct FreeStream {
  std::array<double, 3> value{};
  std::string where;
  std::string patch;
};

bool is_zero(const std::array<double, 3>& v) { return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0; }

/// What one velocity file states: the free stream of its freestream patches
/// and of its inlets (a patch of any name whose fixed or inflow value is not
/// zero), each checked for agreement, and its symmetry patches.
struct VelocityFile {
  std::optional<FreeStream> freestream, inlet;
  std::vector<std::string> symmetry;
  std::vector<std::string> unusable;  ///< patches whose inflow hydrocoef cannot take, in words
  std::vector<std::string> warnings;  ///< what the reader read otherwise than written
};

/// The vector value of `key` in a patch, or nullopt where it is not a
/// uniform vector (nonuniform lists, tables: said in `unusable`).
std::optional<std::array<double, 3>> uniform_vector(const FoamDictionary& d, const std::string& patch, const char* key,
                                                    VelocityFile& out) {
  const FoamValue* value = d.value(key);
  if (!value || value->tokens.empty()) return std::nullopt;
  const auto& t = value->tokens;
  if (t.front() == "uniform" || t.front() == "(") return foam_vector(*value, "patch '" + patch + "' " + key);
  if (t.front() == "constant") {  // uniformFixedValue's Function1 form
    FoamValue rest = *value;
    rest.tokens.erase(rest.tokens.begin());
    return foam_vector(rest, "patch '" + patch + "' " + key);
  }
  out.unusable.push_back("patch '" + patch + "' " + key + " '" + t.front() + " ...' (" + value->where() +
                         "): not a uniform vector");
  return std::nullopt;
}

VelocityFile read_velocity_file(const fs::path& file) {
  VelocityFile out;
  const FoamDictionary u = FoamDictionary::read(file);
  out.warnings = u.warnings();
  const FoamDictionary* boundary = u.dictionary("boundaryField");
  if (!boundary) return out;
  for (const auto& patch : boundary->dictionary_keys()) {
    const FoamDictionary& d = *boundary->dictionary(patch);
    const std::string type = foam_word(d.value("type")).value_or("");
    const auto take = [&](std::optional<FreeStream>& slot, const char* key) {
      const auto vector = uniform_vector(d, patch, key, out);
      if (!vector || is_zero(*vector)) return;  // walls, outlets, still water
      const FoamValue& value = *d.value(key);
      FreeStream stream{*vector, value.where(), patch};
      if (slot && slot->value != stream.value)
        throw InputError(SourceLocation{value.file, value.line, 0},
                         "patches '" + slot->patch + "' (" + slot->where + ") and '" + patch +
                             "' state different free streams; expected one (give the run's flow "
                             "with --flow or a sidecar)");
      if (!slot) slot = stream;
    };
    if (type == "freestreamVelocity" || type == "freestream")
      take(out.freestream, "freestreamValue");
    else if (type == "inletOutlet" || type == "outletInlet")
      take(out.inlet, type == "inletOutlet" ? "inletValue" : "outletValue");
    else if (type == "fixedValue")
      take(out.inlet, "value");
    else if (type == "uniformFixedValue" || type == "uniformInletOutlet")
      take(out.inlet, "uniformValue");
    else if (type == "flowRateInletVelocity" || type == "surfaceNormalFixedValue")
      out.unusable.push_back("patch '" + patch + "' (" + type +
                             ") states an inflow rate normal to the patch, "
                             "whose direction needs the mesh");
    else if (type == "symmetryPlane" || type == "symmetry")
      out.symmetry.push_back(patch);
  }
  return out;
}

/// The velocity files a case may keep its boundary conditions in, in the
/// order they are looked at.
std::vector<fs::path> velocity_files(const fs::path& case_dir) {
  return {case_dir / "0" / "U", case_dir / "0" / "U.orig", case_dir / "0" / "U.0", case_dir / "0.orig" / "U",
          case_dir / "0.orig" / "U.orig"};
}

/// The free stream of forceCoeffs: magUInf along dragDir (OpenFOAM's drag
/// direction is the free stream's), or the speed alone.
struct CoefficientStream {
  std::optional<double> speed;
  std::optional<std::array<double, 3>> direction;
  std::string where;
};

std::optional<CoefficientStream> coefficient_stream(const fs::path& control_dict) {
  std::error_code ec;
  if (!fs::is_regular_file(control_dict, ec)) return std::nullopt;
  const FoamDictionary control = FoamDictionary::read(control_dict);
  const FoamDictionary* functions = control.dictionary("functions");
  if (!functions) return std::nullopt;
  for (const auto& name : functions->dictionary_keys()) {
    const FoamDictionary& f = *functions->dictionary(name);
    if (foam_word(f.value("type")).value_or("") != "forceCoeffs") continue;
    const FoamValue* speed = f.value("magUInf");
    if (!speed) continue;
    CoefficientStream out;
    out.speed = foam_scalar(*speed, "magUInf");
    out.where = speed->where();
    if (!(*out.speed >= 0.0))
      throw InputError(SourceLocation{speed->file, speed->line, 0},
                       "magUInf " + shortest_number(*out.speed) + ": expected a speed >= 0");
    if (const FoamValue* drag = f.value("dragDir")) {
      auto d = foam_vector(*drag, "dragDir");
      const double norm = std::hypot(d[0], d[1], d[2]);
      if (!(norm > 0.0))
        throw InputError(SourceLocation{drag->file, drag->line, 0}, "dragDir (0 0 0): expected a direction");
      for (auto& x : d) x /= norm;
      out.direction = d;
      out.where += " and " + drag->where();
    }
    return out;
  }
  return std::nullopt;
}

void read_velocity(const fs::path& case_dir, OpenFoamCaseSettings& out) {
  std::error_code ec;
  std::optional<FreeStream> stream;
  for (const auto& file : velocity_files(case_dir)) {
    if (!fs::is_regular_file(file, ec)) continue;
    const VelocityFile read = read_velocity_file(file);
    out.notes.insert(out.notes.end(), read.warnings.begin(), read.warnings.end());
    if (!read.symmetry.empty()) {
      std::string names;
      for (const auto& name : read.symmetry) names += (names.empty() ? "" : ", ") + name;
      out.notes.push_back("symmetry patches (" + names + ") in " + file.string() +
                          ": the forces are the modelled part's; give --symmetry PLANE for the whole body's");
    }
    stream = read.freestream ? read.freestream : read.inlet;
    if (stream) break;
  }
  const auto coefficients = coefficient_stream(case_dir / "system" / "controlDict");
  if (stream && coefficients) {
    // The two must agree: the speed, and the direction where dragDir is given.
    const auto& v = stream->value;
    const double speed = std::hypot(v[0], v[1], v[2]);
    const double tolerance = 1e-6 * std::max(speed, *coefficients->speed);
    bool agree = std::abs(speed - *coefficients->speed) <= tolerance;
    if (agree && coefficients->direction)
      for (std::size_t i = 0; i < 3; ++i)
        agree = agree && std::abs(v[i] - *coefficients->speed * (*coefficients->direction)[i]) <= 1e-6 * speed;
    if (!agree)
      throw InputError(SourceLocation{case_dir.string()},
                       "the free stream (" + shortest_number(v[0]) + " " + shortest_number(v[1]) + " " +
                           shortest_number(v[2]) + ") m/s of patch '" + stream->patch + "' (" + stream->where +
                           ") contradicts forceCoeffs' magUInf " + shortest_number(*coefficients->speed) + " m/s" +
                           (coefficients->direction ? " along dragDir" : "") + " (" + coefficients->where +
                           "); expected one free stream (give the run's flow with --flow or a sidecar)");
  }
  if (stream) {
    out.layer.set("flow", std::vector<double>(stream->value.begin(), stream->value.end()), stream->where);
  } else if (coefficients && coefficients->direction) {
    std::vector<double> flow(3);
    for (std::size_t i = 0; i < 3; ++i) flow[i] = *coefficients->speed * (*coefficients->direction)[i];
    out.layer.set("flow", std::move(flow), coefficients->where);
  } else if (coefficients) {
    out.layer.set("flow_speed", *coefficients->speed, coefficients->where);
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
        out.layer.set("rho", foam_scalar(*rho_inf, "rhoInf"), rho_inf->where());
      const FoamValue* centre = f.value("CofR");
      if (!centre) centre = f.value("origin");
      if (centre) {
        const auto x = foam_vector(*centre, "CofR");
        out.layer.set("cofr", std::vector<double>(x.begin(), x.end()), centre->where());
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
      out.layer.set("nu", foam_scalar(*nu, "nu"), nu->where());
      return;
    }
  }
}

}  // namespace

std::string openfoam_free_stream_search(const fs::path& case_dir) {
  std::error_code ec;
  std::string looked;
  for (const auto& file : velocity_files(case_dir)) {
    if (!fs::is_regular_file(file, ec)) continue;
    const VelocityFile read = read_velocity_file(file);
    looked += (looked.empty() ? "" : "; ") + file.string() + ": no patch with a free stream";
    for (const auto& why : read.unusable) looked += ", " + why;
  }
  if (looked.empty()) looked = "no velocity file (" + (case_dir / "0" / "U").string() + ", U.orig, U.0, 0.orig/U)";
  looked += "; " + (case_dir / "system" / "controlDict").string() + ": no forceCoeffs with magUInf";
  return looked;
}

OpenFoamCaseSettings openfoam_case_settings(const fs::path& case_dir) {
  OpenFoamCaseSettings out;
  out.layer.origin = {SettingSource::CaseFiles, case_dir.string()};
  std::error_code ec;
  read_velocity(case_dir, out);
  if (fs::is_regular_file(case_dir / "system" / "controlDict", ec))
    read_forces_function(case_dir / "system" / "controlDict", out);
  read_viscosity(case_dir, out);
  return out;
}

}  // namespace hydrocoef
