// FMUs as library calls: `hydrocoef export-fmu` writes an FMI 2.0
// Co-Simulation FMU (docs/fmu.md) of a stored gridded surface, or of a
// vehicle (`--vehicle`, stepped with the runtime library's RK4 as `hydrocoef
// simulate` steps it): a zip with
// modelDescription.xml, binaries/linux64/<modelIdentifier>.so (hydrocoef's
// FMU binary, on libhydrocoef_runtime linked in statically: libc and libm
// only) and resources/model.hcr (the runtime file, docs/runtime.md). The FMU
// evaluates the surface as `hydrocoef query` does, bit for bit; a vehicle FMU
// stepped at simulate's output times gives simulate's trajectory bit for bit.
//
// Units and frames: SI; body axes x forward, y starboard, z down (FRD); the
// outputs are forces and moments of the fluid on the body (SNAME "on-body"
// signs: damping is negative). Each variable carries its unit. The FMU is
// written whole or not at all; a refused export writes nothing and never
// touches the database.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/error.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
inline namespace api {

/// What `hydrocoef export-fmu BODY --surface NAME -o FILE.fmu` or
/// `hydrocoef export-fmu BODY --vehicle VEHICLE.json -o FILE.fmu` writes.
struct FmuExportOptions {
  std::string body;     ///< the body whose surface (or vehicle) it is
  std::string surface;  ///< the stored gridded surface (--surface)
  /// A vehicle file, or its JSON text (--vehicle; `hydrocoef simulate
  /// --vehicle`): the vehicle FMU, its damping surfaces of `body` read from
  /// the database. Inputs tau_b X..N [N, N m] (body FRD, on the body), the
  /// current in NED [m/s], the disturbances; outputs position (NED) [m],
  /// q_nb, Euler angles [rad], body velocities, the damping X..N on the
  /// body; parameters the internal RK4 step and the initial state.
  std::string vehicle;
  std::string output;  ///< the .fmu file to write (-o)
  /// InputError, with the CLI's message, for an empty body, neither or both
  /// of --surface and --vehicle, no -o, or an output whose name does not end
  /// in ".fmu".
  HYDROCOEF_EXPORT void validate() const;
};

/// One variable of the FMU (a Real), as modelDescription.xml states it.
struct FmuVariable {
  std::uint32_t value_reference = 0;
  std::string name;
  std::string causality;  ///< input, output or parameter
  std::string unit;
  std::optional<double>
      start;  ///< inputs and parameters: the start value (a surface's: 0 clamped into the axis's range)
  std::string description;
};

/// What an FMU export wrote.
struct FmuExportResult {
  std::string body;
  std::string surface;
  std::string vehicle;                   ///< the vehicle's name (kind "vehicle"; "" otherwise)
  std::string kind;                      ///< the FMU's model kind: "surface" or "vehicle"
  std::string model_identifier;          ///< "hc_" + the surface name, [A-Za-z0-9_] kept, others '_' (64 bytes at most)
  std::string guid;                      ///< "hcrt-xxh64-" + the runtime file's content hash (16 hex digits)
  std::string file;                      ///< the .fmu written
  std::uint64_t runtime_file_bytes = 0;  ///< resources/model.hcr
  std::uint64_t binary_bytes = 0;        ///< binaries/linux64/<modelIdentifier>.so
  std::uint64_t fmu_bytes = 0;           ///< the zip
  std::vector<FmuVariable> variables;    ///< by value reference
  std::vector<std::string> notes;        ///< axes refusing values outside their range, a stale surface

  HYDROCOEF_EXPORT std::string text() const;  ///< what `export-fmu` prints
  HYDROCOEF_EXPORT std::string json() const;  ///< what `export-fmu --json` prints
};

/// Writes the surface FMU of a stored gridded surface, or the vehicle FMU of
/// options.vehicle, as `hydrocoef export-fmu` (options.validate() first).
/// InputError, nothing written, for a surface that is not the body's, not
/// gridded (naming --resample), whose axis and output names collide, a
/// vehicle file `hydrocoef simulate` refuses, a disturbance named as another
/// variable, or a path that cannot be written.
HYDROCOEF_EXPORT FmuExportResult export_fmu(const Database& db, const FmuExportOptions& options);

}  // namespace api
}  // namespace hydrocoef
