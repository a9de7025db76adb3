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
/// of a freestreamVelocity or freestream patch, else the inflow of a patch
/// of any name by its boundary-condition type: fixedValue `value`,
/// inletOutlet `inletValue`, uniformFixedValue `uniformValue`, when it is a
/// uniform vector that is not zero (a zero one is a wall or an outlet); two
/// patches that state different inflows are refused. The velocity file is
/// the first of 0/U, 0/U.orig, 0/U.0, 0.orig/U, 0.orig/U.orig that states a
/// free stream. The forceCoeffs function object's magUInf along dragDir
/// gives it where no file does (magUInf alone: the speed, `flow_speed`), and
/// must agree with a file's (refused naming both otherwise). rho is the forces function object's rhoInf when its rho is
/// rhoInf; cofr its CofR (or origin). Missing files give no setting.
/// InputError (file and line) for a dictionary that cannot be read or a
/// value that is not what its keyword needs.
OpenFoamCaseSettings openfoam_case_settings(const std::filesystem::path& case_dir);

/// Where openfoam_case_settings looked for the free stream and why each place
/// gave none, for the message that refuses a run without a velocity.
std::string openfoam_free_stream_search(const std::filesystem::path& case_dir);

}  // namespace hydrocoef
