// FMUs as library calls: `hydrocoef export-fmu` writes an FMI 2.0
// Co-Simulation FMU (docs/fmu.md) of a stored gridded surface: a zip with
// modelDescription.xml, binaries/linux64/<modelIdentifier>.so (hydrocoef's
// FMU binary, on libhydrocoef_runtime linked in statically: libc and libm
// only) and resources/model.hcr (the runtime file, docs/runtime.md). The FMU
// evaluates the surface as `hydrocoef query` does, bit for bit.
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

/// What `hydrocoef export-fmu BODY --surface NAME -o FILE.fmu` writes.
struct FmuExportOptions {
  std::string body;     ///< the body whose surface it is
  std::string surface;  ///< the stored gridded surface (--surface)
  std::string output;   ///< the .fmu file to write (-o)
  /// InputError, with the CLI's message, for an empty body, no --surface or
  /// no -o, or an output whose name does not end in ".fmu".
  HYDROCOEF_EXPORT void validate() const;
};

/// One variable of the FMU (a Real), as modelDescription.xml states it.
struct FmuVariable {
  std::uint32_t value_reference = 0;
  std::string name;
  std::string causality;  ///< input or output
  std::string unit;
  std::optional<double> start;  ///< inputs: the start value (0 clamped into the axis's range)
  std::string description;
};

/// What an FMU export wrote.
struct FmuExportResult {
  std::string body;
  std::string surface;
  std::string kind;                      ///< the FMU's model kind: "surface"
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

/// Writes the surface FMU of a stored gridded surface, as `hydrocoef
/// export-fmu` (options.validate() first). InputError, nothing written, for a
/// surface that is not the body's, not gridded (naming --resample), whose
/// axis and output names collide, or a path that cannot be written.
HYDROCOEF_EXPORT FmuExportResult export_fmu(const Database& db, const FmuExportOptions& options);

}  // namespace api
}  // namespace hydrocoef
