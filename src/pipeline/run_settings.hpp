// The settings that turn a file into runs, and where each came from.
//
// A run's settings come from several places: the command line, a sidecar
// JSON beside the file (FILE.json), a row of a sweep manifest, sidecars of
// the folders above the file (hydrocoef-run.json), the solver's own case
// files (OpenFOAM's 0/U, controlDict, transportProperties; CFX's CCL), and a
// name pattern over the file's path (u{u}_v{v}). Each source becomes one
// SettingsLayer; merge_settings takes, for every setting, the layer of
// highest precedence that states it:
//
//   command line > file sidecar > manifest > folder sidecars (nearest first)
//   > case files > name pattern > defaults
//
// and remembers where the value came from, for the run's provenance and for
// messages. The translation of the body (u, v, w, or the free stream `flow`)
// is taken as a group from the one layer of highest precedence that states
// any of them, so that a velocity is never assembled from two sources.
//
// The frame (axes, origin) and the run key are then resolved once from the
// merged settings (resolve_frame, resolve_key): the free stream is turned
// into the body velocity with the same frame that rotates the forces,
// whatever source each setting came from.
//
// Setting names are the sidecar's keys (SI units):
//   body                         text
//   u v w [m/s], p q r [rad/s]   body velocity, body axes
//   flow [x,y,z] m/s             free stream in CFD axes (the body moves at its negative)
//   disturbances {name: value}   disturbance parameters (stored as "disturbance.NAME")
//   rho [kg m^-3], nu [m^2 s^-1], p_ref [Pa]
//   ref_point [x,y,z] m          moment reference point, body axes
//   cofr [x,y,z] m               the solver's moment centre, CFD coordinates
//   axes "-x,y,-z", origin [x,y,z] m   CFD axes to body axes; body origin in CFD coordinates
//   pressure, shear, pressure_kind, shear_convention, length_unit,
//   pressure_unit, normals, locations    surface exports (see `integrate --help`)
//   window "auto" | "T0:T1" | "last:N"   force histories
//   symmetry "y=0" | "y=0,z=0"           half and quarter models
//   sign "on-body" | "opposing"          force tables and monitors
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "src/core/run.hpp"
#include "src/loads/frame.hpp"

namespace hydrocoef {

enum class SettingSource { CommandLine, FileSidecar, Manifest, FolderSidecar, CaseFiles, NamePattern, Default };

/// "command line", "sidecar", "manifest", "folder sidecar", "case files", "name pattern", "default".
std::string_view setting_source_name(SettingSource source);

struct SettingOrigin {
  SettingSource source = SettingSource::Default;
  std::string where;  ///< "--rho", "a.vtp.json", "sweep.csv:4", "case/0/U:23", "u{u}_v{v}"
};

/// A number (SI), a text, or numbers (a point or a vector, SI), or texts.
using SettingValue = std::variant<double, std::string, std::vector<double>, std::vector<std::string>>;

struct Setting {
  SettingValue value;
  SettingOrigin origin;
};

/// What one source states.
struct SettingsLayer {
  SettingOrigin origin;                   ///< of every value unless the value says otherwise
  std::map<std::string, Setting> values;  ///< by setting name

  void set(const std::string& name, SettingValue value, std::string where = {});
  bool empty() const { return values.empty(); }
};

/// The merged settings of one file.
class RunSettings {
 public:
  std::map<std::string, Setting> values;

  const Setting* find(std::string_view name) const;
  /// Typed reads; InputError naming the setting and its origin when the value
  /// has another type ("a.vtp.json: setting 'rho': expected a number").
  std::optional<double> number(std::string_view name) const;
  std::optional<std::string> text(std::string_view name) const;
  std::optional<Vec3> triple(std::string_view name) const;
  std::optional<std::vector<std::string>> texts(std::string_view name) const;
  /// The disturbances ("disturbance.NAME" settings), by name.
  std::map<std::string, double> disturbances() const;

  /// Every setting with its value, source and place, by name: the record of
  /// how a file became runs (provenance) and, without the places, what
  /// identifies an import (effective_json).
  nlohmann::json provenance_json() const;
  /// The values alone, canonical (sorted keys, shortest round-trip numbers).
  std::string effective_text() const;
};

/// Merges layers given in order of precedence, highest first (see above).
RunSettings merge_settings(const std::vector<SettingsLayer>& layers);

/// The CFD-to-body frame: `axes` and `origin` (identity and 0 by default).
FrameTransform resolve_frame(const RunSettings& settings);

/// The run key: body (or `default_body`), the body velocity from u..r or
/// from the free stream `flow` turned into body axes with `frame` (the body
/// moves at minus the free stream), and the disturbances. InputError when
/// both flow and u, v or w are stated by the same layer.
RunKey resolve_key(const RunSettings& settings, const FrameTransform& frame, const std::string& default_body);

/// A run's velocity is never a default: InputError naming `file` when no
/// setting gives it (flow, u..r, or a flow_speed whose direction
/// check_flow_speed asks for) and the settings do not say the body is at
/// rest (`at_rest`, from --at-rest or a sidecar's "at_rest": true), or when
/// both are said. `looked`: where the input's own files were searched, in
/// words (called only to word the refusal).
void require_velocity(const RunSettings& settings, const std::string& file,
                      const std::function<std::string()>& looked = {});

/// The moment reference point in body axes: `ref_point`, else the solver's
/// `cofr` brought into body axes, else the body origin.
Vec3 resolve_reference_point(const RunSettings& settings, const FrameTransform& frame);

/// Reads a sidecar file (a JSON object whose keys are setting names) into a
/// layer of the given source. Unknown keys, wrong types, non-finite numbers
/// and names that break the name rule are refused naming the file and key.
SettingsLayer read_settings_file(const std::filesystem::path& file, SettingSource source);

/// The JSON object of a sidecar, already parsed (a manifest row, tests).
SettingsLayer settings_from_json(const nlohmann::json& object, SettingOrigin origin);

/// The setting names a sidecar may hold, for messages and the README.
const std::vector<std::string>& sidecar_keys();

}  // namespace hydrocoef
