// Forces and moments of one surface export, integrated and not stored: what
// `hydrocoef integrate` prints. The file is read with the options of an
// import (ImportOptions: arrays, their kind and units, frames, symmetry
// planes, the run key's settings) and its sidecars.
//
// Frames and units: forces on the body [N] and moments [N m] about the
// reference point, in body axes (x forward, y starboard, z down), after the
// CFD-to-body mapping the options or sidecars give; pressure and viscous parts
// apart; the surface's area [m^2] and enclosed volume [m^3].
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/error.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
inline namespace api {

struct SurfaceIntegration {
  std::string file;
  std::string format;                                                   ///< cfdpost or vtk
  std::array<double, 3> force{}, force_pressure{}, force_viscous{};     ///< X, Y, Z [N]
  std::array<double, 3> moment{}, moment_pressure{}, moment_viscous{};  ///< K, M, N [N m]
  std::array<double, 3> reference_point{};                              ///< [m], body axes
  double area = 0.0;                                                    ///< [m^2]
  double signed_volume = 0.0;                                           ///< [m^3], > 0 for outward normals
  std::size_t faces = 0;
  bool closed = false;
  std::vector<std::string> warnings;

  /// What `hydrocoef integrate` prints; with json(), what `--json` prints.
  HYDROCOEF_EXPORT std::string text() const;
  HYDROCOEF_EXPORT std::string json() const;

  struct Access;  ///< the library's own

 private:
  std::string text_;
  std::string json_;
};

/// Integrates one surface export (a CFD-Post export or a VTK-family file).
/// options.format: auto, cfdpost or vtk. InputError for a file that cannot be
/// read, that is not a surface export, or a bad option.
HYDROCOEF_EXPORT SurfaceIntegration integrate_surface(const std::string& file, const ImportOptions& options = {});

}  // namespace api
}  // namespace hydrocoef
