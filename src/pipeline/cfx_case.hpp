// What an ANSYS CFX case states about its run, as a settings layer of source
// "case files" (src/pipeline/run_settings.hpp), read from the case's CCL: a
// .ccl file written by CFX-Pre, or the CCL that the CFX solver echoes at the
// top of its output file (.out). The free stream from the inlet boundary, the
// density and kinematic viscosity of the domain's material, and the domain's
// reference pressure, each with the file and line it came from; what the case
// states that hydrocoef cannot use is said in notes. The OpenFOAM counterpart
// is src/pipeline/openfoam_case.hpp.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "importers/cfx_ccl.hpp"
#include "src/pipeline/run_settings.hpp"

namespace hydrocoef {

struct CfxCaseSettings {
  /// Source CaseFiles, `where` the file; each value's `where` is "file:line":
  ///   flow [x,y,z] m/s   free stream in CFD axes, from the inlets' Cartesian
  ///                      velocity components
  ///   flow_speed m/s     instead of flow when the inlets give a Normal Speed:
  ///                      the direction is the inlet's normal, which the CCL
  ///                      does not state (a note says so; the caller decides)
  ///   flow_unstated      instead of flow when no inlet states a velocity and
  ///                      a pressure opening drives the flow: why, at the
  ///                      opening's line. The free stream must come from a
  ///                      source of higher precedence (command line, sidecar,
  ///                      manifest) or the name pattern; the import refuses
  ///                      the run at that line when none gives it.
  ///   rho kg m^-3, nu m^2 s^-1 (dynamic viscosity / density), p_ref Pa
  SettingsLayer layer;
  std::vector<std::string> notes;  ///< symmetry and wall boundaries, settings not read and why
};

/// Reads a .ccl file, or the CCL section of a CFX solver output file (a file
/// ending in .out, or any file holding the "CFX Command Language for Run"
/// banner); line numbers in settings and messages are the file's own.
///
/// The free stream: every INLET of every fluid DOMAIN of the FLOW, from
/// BOUNDARY CONDITIONS: MASS AND MOMENTUM: with Option = Cartesian Velocity
/// Components (U, V, W) or Option = Normal Speed (Normal Speed). Inlets that
/// state different velocities, an inlet velocity that is not a constant (a
/// profile, a function of x or t) are refused with the file and line. Other inlet options (mass flow rate,
/// total pressure, per-fluid velocities) and a moving domain (DOMAIN MOTION
/// other than Stationary, a frame velocity given as Cartesian components) give
/// notes only. A pressure opening with no inlet that states a velocity gives
/// flow_unstated (above), which the import checks once the settings are
/// merged.
///
/// The fluid: the domain's FLUID DEFINITION's Material, looked up in the
/// file's LIBRARY: MATERIAL: (its PROPERTIES: or MATERIAL PROPERTIES:);
/// rho from EQUATION OF STATE with Option = Value, nu from DYNAMIC VISCOSITY
/// with Option = Value divided by rho. p_ref from DOMAIN MODELS: REFERENCE
/// PRESSURE. A property that is missing gives no setting; one that is not
/// constant (Option = Ideal Gas, an expression of temperature), several
/// fluids in a domain or domains that disagree give a note and no setting.
///
/// InputError with file and line for a file that cannot be read or parsed
/// (importers/cfx_ccl.hpp), a .out without the CCL banner, values of the
/// wrong dimension (a velocity in Pa) and the refusals above.
CfxCaseSettings cfx_case_settings(const std::filesystem::path& file);

/// The same from a parsed document (its `file` names it in settings and notes).
CfxCaseSettings cfx_case_settings(const CclDocument& ccl);

/// True for a .ccl file (any case of the extension), and for a .out file one
/// of whose first 200 lines is the "CFX Command Language for Run" banner.
/// Never throws; a file that cannot be read is not a case file.
bool is_cfx_case_file(const std::filesystem::path& file);

}  // namespace hydrocoef
