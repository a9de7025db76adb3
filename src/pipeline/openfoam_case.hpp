// What an OpenFOAM case folder says about its run, as a settings layer of
// source "case files" (src/pipeline/run_settings.hpp): the free stream from
// 0/U, the density and moment centre from the forces function object in
// system/controlDict, the kinematic viscosity from
// constant/transportProperties (or physicalProperties). With these a case
// folder imports with sweep-wide flags only (--body, --axes), no per-case
// file. What a case states that hydrocoef cannot use is said in notes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "src/pipeline/run_settings.hpp"

namespace hydrocoef {

struct OpenFoamCaseSettings {
  SettingsLayer layer;             ///< flow, rho, cofr, nu, each with its file and line
  std::vector<std::string> notes;  ///< e.g. symmetry patches, settings in files not read
};

/// Reads the case's dictionaries. The free stream is the `freestreamValue`
/// of a freestreamVelocity or freestream patch of 0/U, else the value of an
/// inlet patch (fixedValue `value`, inletOutlet `inletValue`, a patch whose
/// name contains "inlet"); two patches that state different free streams are
/// refused. rho is the forces function object's rhoInf when its rho is
/// rhoInf; cofr its CofR (or origin). Missing files give no setting.
/// InputError (file and line) for a dictionary that cannot be read or a
/// value that is not what its keyword needs.
OpenFoamCaseSettings openfoam_case_settings(const std::filesystem::path& case_dir);

}  // namespace hydrocoef
