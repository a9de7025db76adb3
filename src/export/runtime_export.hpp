// The runtime file (`hydrocoef export NAME --format runtime`): one body's
// gridded surfaces as hydrocoef evaluates them, for libhydrocoef_runtime
// (runtime/include/hydrocoef/runtime.h) to load without hydrocoef. The
// format, section by section, is docs/runtime.md; the reader is
// runtime/src/runtime_file.c. The file holds exactly the doubles GridTable
// evaluates with (for the cubic methods its hermite_data(): every node's
// value and mixed derivatives), so the runtime's numbers are the library's
// bit for bit. With a vehicle (format version 2) the file also holds the
// whole dynamics model, VehicleModel's exact doubles and its damping as
// DampingModel evaluates it, the surfaces it reads among the file's.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "src/surface/coefficient_surface.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef {

/// Texts by key, in the file's order.
using RuntimeTexts = std::vector<std::pair<std::string, std::string>>;

/// One surface of a runtime file.
struct RuntimeSurface {
  std::string name;
  const GridTable* table = nullptr;       ///< the evaluated table (not owned)
  std::vector<std::string> axis_units;    ///< one per axis
  std::vector<std::string> output_units;  ///< one per output
  /// The surface's standard deviation (CoefficientSurface::has_standard_deviation):
  /// the runs' sigma table (same axes and method, clamped outside) and the
  /// leave-one-out part per output; nullptr / empty when it states none.
  const GridTable* sigma_table = nullptr;
  std::vector<double> loo;
  RuntimeTexts metadata;  ///< provenance: content_sha256, runs, created_at, stale, source
};

/// A stored surface as a runtime surface (pointing into `surface`, which
/// must outlive it). InputError, one line, for an RBF or GP surface (saying
/// how to tabulate it: --resample), or a surface with a mirror symmetry
/// imposed (its values are the projection, not the table).
RuntimeSurface runtime_surface(const std::string& name, const CoefficientSurface& surface, RuntimeTexts metadata);

class VehicleModel;

/// A vehicle of a runtime file: the model (not owned; its damping's
/// surfaces must be among the file's, by name) and its texts (name, file).
struct RuntimeVehicle {
  const VehicleModel* model = nullptr;
  RuntimeTexts metadata;
};

/// The bytes of a runtime file: the model's texts (database, body,
/// created_at, hydrocoef_version, frame, units, sign_convention, surfaces),
/// the surfaces, and the vehicle when there is one (format version 2;
/// version 1 otherwise). InputError when the surfaces' names are not unique,
/// units do not match a table, a number is not finite, there are more than
/// 4096 surfaces, or the vehicle reads a surface that is not in the file
/// or one the runtime cannot evaluate as the library does (more than 6 axes
/// or 32 outputs).
std::string runtime_file_bytes(const RuntimeTexts& model, const std::vector<RuntimeSurface>& surfaces,
                               const RuntimeVehicle* vehicle = nullptr);

/// The texts every runtime file states: frame, units, sign convention,
/// hydrocoef version, format (version 2 with a vehicle; merged after `given`).
RuntimeTexts runtime_model_texts(RuntimeTexts given, bool vehicle = false);

}  // namespace hydrocoef
