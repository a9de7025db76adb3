// What the surface integration reads from a mesh, and what it refuses: the
// pressure and wall-shear arrays, seen alike whether a vector array or three
// scalar ones, and the one-line InputErrors for arrays, faces and points that
// cannot be integrated (src/loads/surface_loads.cpp calls these; the rest of
// the library goes through integrate_surface_loads).
#pragma once

#include <cstddef>

#include "src/loads/surface_loads.hpp"

namespace hydrocoef::loads_detail {

/// A scalar or vector array seen through stride and offsets, so that a
/// 3-component array and three scalar arrays are read the same way.
struct FieldView {
  const double* component[3] = {nullptr, nullptr, nullptr};
  std::size_t stride = 1;
  bool per_point = true;
  const FieldArray* arrays[3] = {nullptr, nullptr, nullptr};  ///< the distinct arrays behind it
  const char* role = "";
  bool present() const { return component[0] != nullptr; }
  double scalar(std::size_t i) const { return component[0][i * stride]; }
  Vec3 vector(std::size_t i) const {
    return {component[0][i * stride], component[1][i * stride], component[2][i * stride]};
  }
};

/// The pressure array named by the options (scalar, one value per point or face).
FieldView pressure_view(const SurfaceMesh& mesh, const SurfaceLoadOptions& options);

/// The wall shear arrays named by the options; absent when none is named.
FieldView shear_view(const SurfaceMesh& mesh, const SurfaceLoadOptions& options);

/// The InputError for the first value of `field` that is NaN or Inf.
[[noreturn]] void throw_not_finite(const FieldArray& field, const char* role);

/// The checks that cost nothing per face; the rest (offsets that go back,
/// point indices out of range) are made block by block while integrating.
void check_mesh_shape(const SurfaceMesh& mesh);

/// The InputError for the first face a block could not read.
[[noreturn]] void throw_unreadable_faces(const SurfaceMesh& mesh);

/// The InputError for the first point with a coordinate that is NaN or Inf.
[[noreturn]] void throw_not_finite_point(const SurfaceMesh& mesh);

}  // namespace hydrocoef::loads_detail
