// Surface pressure and wall shear integrated into forces and moments, with
// the geometry checks that say whether the result can be trusted.
//
//   F_p = -∫ (p - p_ref) n dA      F_v = s ∫ τ_w dA       (n: outward normal)
//   M_p = ∫ (x - x_ref) × dF_p     M_v = ∫ (x - x_ref) × dF_v
//
// s = +1 when τ_w is the fluid's shear on the wall (CFX "Wall Shear"), -1 when
// it is the stress on the fluid side (OpenFOAM "wallShearStress").
//
// Quadrature: point data is integrated exactly for fields that are linear
// over a triangle and over the bilinear patch of a quad (2×2 Gauss, so warped
// quads are handled); larger polygons are split into triangles around their
// vertex centroid (value there: the vertex mean). Face (cell) data is
// constant per face, with the finite-volume face geometry that solvers use:
// force p·S_f and τ·|S_f| applied at the face centroid C_f, S_f being the
// face's vector area (exact for any polygon: it depends on the boundary only).
//
// Frames and units: whatever frame the mesh is in (the CFD axes; the loads
// are turned into body axes afterwards by loads_to_body in
// src/loads/frame.hpp); SI (m, Pa) in, N and N m out. Accumulation is
// blockwise (pairwise over blocks of faces) so totals over millions of faces
// keep ~1e-15 relative accuracy.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef {

using Vec3 = std::array<double, 3>;

/// How the wall shear array is signed.
enum class ShearConvention {
  OnWall,   ///< shear the fluid exerts on the wall (CFX): F_v = +∫ τ dA
  OnFluid,  ///< stress on the fluid side (OpenFOAM wallShearStress): F_v = -∫ τ dA
};

/// What to do with face orientation.
enum class NormalPolicy {
  Auto,     ///< make normals outward: closed surfaces by the sign of the enclosed volume,
            ///< open ones by the cone volume about the surface's centre; flip and report
  AsGiven,  ///< trust the file's orientation
  Flip,     ///< the file's normals point into the body
};

struct SurfaceLoadOptions {
  /// Pressure array, in Pa (already static: multiply kinematic pressure by ρ before).
  std::string pressure_field;
  /// Wall shear: one 3-component array, or three scalar arrays x, y, z; empty = no viscous part.
  std::vector<std::string> shear_fields;
  ShearConvention shear_convention = ShearConvention::OnWall;
  /// Subtracted from the pressure [Pa].
  double reference_pressure = 0.0;
  /// Moment reference point [m], in the mesh's frame.
  Vec3 reference_point{};
  NormalPolicy normals = NormalPolicy::Auto;
};

/// What the geometry checks found.
struct SurfaceGeometry {
  std::size_t faces = 0;
  std::size_t triangles = 0, quads = 0, polygons = 0;
  std::size_t degenerate_faces = 0;    ///< zero area (or fewer than 3 distinct points)
  double area = 0.0;                   ///< m^2
  double signed_volume = 0.0;          ///< m^3, (1/3)∮ x·n dA with the normals used; > 0 outward when closed
  std::size_t boundary_edges = 0;      ///< edges used by one face: 0 for a closed surface
  std::size_t nonmanifold_edges = 0;   ///< edges used by more than two faces (counted when the surface
                                       ///< is not closed; a closed surface passes a quick whole-surface test)
  std::size_t inconsistent_edges = 0;  ///< interior edges walked the same way by both faces
  bool closed = false;                 ///< no boundary and no non-manifold edges
  bool normals_flipped = false;        ///< the file's normals were reversed (see NormalPolicy)
  Vec3 integral_n_dA{};                ///< ∫ n dA [m^2] (zero for a closed surface)
  Vec3 integral_x_cross_n_dA{};        ///< ∫ x × n dA about the origin [m^3]
  std::vector<std::string> warnings;   ///< human-readable notes, e.g. "normals flipped"
};

/// Forces and moments with their pressure and viscous parts.
struct SurfaceLoads {
  Vec3 force_pressure{}, force_viscous{};    ///< N, on the body
  Vec3 moment_pressure{}, moment_viscous{};  ///< N m, about reference_point
  Vec3 reference_point{};
  SurfaceGeometry geometry;

  Vec3 force() const;
  Vec3 moment() const;
};

/// Integrates the loads. Throws InputError naming the array when a named
/// array is missing, has the wrong number of components, or holds NaN/Inf
/// where a face uses it (the first bad index of the array is named); when the
/// mesh has no faces, a point index out of range, offsets that go back or
/// coordinates that are not finite; and when the normals are inconsistent
/// (some faces reversed relative to their neighbours) under
/// NormalPolicy::Auto.
///
/// Large meshes are integrated on two threads; surfaces of triangles with
/// point data go through a SIMD kernel (AVX-512 or AVX2 where the processor has it).
SurfaceLoads integrate_surface_loads(const SurfaceMesh& mesh, const SurfaceLoadOptions& options);

/// Geometry checks alone (no fields needed).
SurfaceGeometry check_surface_geometry(const SurfaceMesh& mesh);

/// Recomputes loads for another reference pressure or moment point from the
/// stored integrals, without the mesh: F_p' = F_p + (p_ref' - p_ref)∫n dA, and
/// moments moved to the new point.
SurfaceLoads shift_loads(const SurfaceLoads& loads, double old_reference_pressure, double new_reference_pressure,
                         const Vec3& new_reference_point);

}  // namespace hydrocoef
