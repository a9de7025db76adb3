// A surface export turned into one run: read the mesh (CFD-Post export or
// any VTK-family file), bring its arrays to Pa, integrate pressure and wall
// shear, rotate into body axes and attach the run key and provenance. This is
// the one place that composes importers/ and src/loads; each stays ignorant
// of the other.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "src/core/run.hpp"
#include "src/loads/frame.hpp"
#include "src/loads/surface_loads.hpp"
#include "src/loads/symmetry.hpp"

namespace hydrocoef {

enum class PressureKind {
  Static,    ///< Pa
  Kinematic  ///< p/ρ in m^2 s^-2, as OpenFOAM writes incompressible results
};

struct SurfaceRunOptions {
  std::string format = "auto";          ///< auto, cfdpost, vtk (.vtk .vtp .vtu .vtm .case .cgns)
  std::vector<std::string> locations;   ///< patches/blocks/[Name]s to integrate; empty = all
  std::optional<std::string> pressure;  ///< array name; default by what the file holds
  /// One vector array or three scalar arrays; {"none"} for no viscous part;
  /// empty = default by what the file holds.
  std::vector<std::string> shear;
  std::optional<PressureKind> pressure_kind;        ///< default: kinematic for OpenFOAM's p, else static
  std::optional<ShearConvention> shear_convention;  ///< default: on-fluid for wallShearStress, else on-wall
  std::optional<double> density;                    ///< kg m^-3, needed for kinematic arrays
  std::optional<double> kinematic_viscosity;        ///< m^2 s^-1, recorded with the run
  double reference_pressure = 0.0;                  ///< Pa, subtracted from the pressure
  Vec3 reference_point_b{};                         ///< m, body axes
  FrameTransform frame;                             ///< CFD axes to body axes
  std::optional<std::string> length_unit;           ///< for files that do not say (VTK); default m
  std::optional<std::string> pressure_unit;         ///< for files that do not say; default Pa or m^2 s^-2
  NormalPolicy normals = NormalPolicy::Auto;
  /// Planes of symmetry of a half or quarter model, in CFD coordinates: the
  /// loads become the whole body's (src/loads/symmetry.hpp).
  std::vector<SymmetryPlane> symmetry;
  RunKey key;  ///< body, velocity (body axes) and disturbances
};

struct SurfaceRun {
  ImportBatch batch;     ///< one run, forces on the body in body axes
  SurfaceLoads loads_b;  ///< the same, with geometry, in body axes
  std::string format;    ///< "cfdpost" or "vtk"
  std::string pressure_array;
  std::string shear_array;  ///< "" when none
  PressureKind pressure_kind = PressureKind::Static;
  ShearConvention shear_convention = ShearConvention::OnWall;
  std::vector<std::string> warnings;
};

inline constexpr std::string_view kSurfaceImporterVersion = "1";

/// "cfdpost", "vtk", "monitor" or "table" for a file, from its extension and
/// its first bytes; `requested` other than "auto" is checked and returned.
std::string detect_format(const std::filesystem::path& file, const std::string& requested = "auto");

/// Reads, integrates and keys one surface export. Throws InputError naming
/// the file for anything wrong with it or with the options.
SurfaceRun import_surface_run(const std::filesystem::path& file, const SurfaceRunOptions& options);

}  // namespace hydrocoef
