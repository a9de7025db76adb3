// Half and quarter models: a body cut by planes of symmetry, as marine CFD
// models it to halve or quarter the mesh, gives the whole body's loads by
// adding the mirror images of the modelled part. For a plane normal to axis
// a through offset d (e.g. y = 0), the mirror R (the identity with -1 at a)
// maps the part's force F to R F and its moment about a point on the plane
// M to -R M (a moment is a pseudo-vector: it flips with the handedness). So
// the whole body has
//
//   F = F_part + R F_part        M = M_part - R M_part   (about a point on the plane)
//
// which doubles the components in the plane and cancels the force along the
// plane's normal and the moments about the other two axes: for y = 0, the
// whole body has no Fy, Mx or Mz. A second plane (z = 0) doubles again.
//
// Frames: the planes and the loads are in the same frame (the CFD axes of
// the case, before the rotation into body axes). The pressure and viscous
// parts and the stored surface integrals (∫n dA, ∫x×n dA) are mirrored the
// same way, so forces can still be recomputed for another reference pressure.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "src/loads/surface_loads.hpp"

namespace hydrocoef {

struct SymmetryPlane {
  int axis = 1;         ///< 0, 1, 2: the plane x = offset, y = offset or z = offset
  double offset = 0.0;  ///< m
};

/// Parses "y=0", "y=0,z=0", "x=0.5": one to three planes on distinct axes.
/// InputError naming the text otherwise.
std::vector<SymmetryPlane> parse_symmetry(std::string_view text);

/// "y=0,z=0".
std::string symmetry_text(const std::vector<SymmetryPlane>& planes);

/// The whole body's loads from the modelled part's (about the same reference
/// point): each plane in turn adds the mirror image of what is there.
/// Geometry counts and area are multiplied by 2 per plane; warnings are kept.
SurfaceLoads mirror_loads(const SurfaceLoads& part, const std::vector<SymmetryPlane>& planes);

/// The same for a force and a moment about `reference_point` (force
/// histories of a half or quarter case).
void mirror_force_moment(Vec3& force, Vec3& moment, const Vec3& reference_point,
                         const std::vector<SymmetryPlane>& planes);

/// The components that vanish on the whole body, by name in the frame of
/// the planes: "Fy, Mx, Mz" for y = 0.
std::string vanishing_components(const std::vector<SymmetryPlane>& planes);

}  // namespace hydrocoef
