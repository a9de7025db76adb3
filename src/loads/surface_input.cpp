#include "src/loads/surface_input.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "src/core/error.hpp"

namespace hydrocoef::loads_detail {
namespace {

std::string available_arrays(const SurfaceMesh& mesh) {
  std::string out;
  for (const auto& field : mesh.fields) {
    if (!out.empty()) out += ", ";
    out += "'" + field.name + "'";
    if (field.components == 3) out += " (vector)";
  }
  return out.empty() ? "none" : out;
}

const FieldArray& find_array(const SurfaceMesh& mesh, const std::string& name, int components, const char* role) {
  const FieldArray* field = mesh.find_field(name);
  if (!field)
    throw InputError(std::string(role) + " array '" + name +
                     "' is not in the file; arrays there: " + available_arrays(mesh));
  if (field->components != components)
    throw InputError(std::string(role) + " array '" + name + "' has " + std::to_string(field->components) +
                     " components, expected " + std::to_string(components));
  const std::size_t expected = field->association == FieldAssociation::Point ? mesh.point_count() : mesh.face_count();
  if (field->size() != expected)
    throw InputError(std::string(role) + " array '" + name + "' has " + std::to_string(field->size()) +
                     " values, expected " + std::to_string(expected) + " (one per " +
                     (field->association == FieldAssociation::Point ? "point" : "face") + ")");
  return *field;
}

}  // namespace

/// The InputError for the first value of `field` that is NaN or Inf.
[[noreturn]] void throw_not_finite(const FieldArray& field, const char* role) {
  std::size_t i = 0;
  while (i < field.values.size() && std::isfinite(field.values[i])) ++i;
  if (i == field.values.size()) throw std::logic_error("throw_not_finite: every value is finite");
  throw InputError(std::string(role) + " array '" + field.name + "' holds " +
                   (std::isnan(field.values[i]) ? "NaN" : "Inf") + " at " +
                   (field.association == FieldAssociation::Point ? "point " : "face ") +
                   std::to_string(i / static_cast<std::size_t>(field.components)) + "; expected finite values");
}

FieldView pressure_view(const SurfaceMesh& mesh, const SurfaceLoadOptions& options) {
  const FieldArray& field = find_array(mesh, options.pressure_field, 1, "pressure");
  FieldView view;
  view.component[0] = field.values.data();
  view.per_point = field.association == FieldAssociation::Point;
  view.arrays[0] = &field;
  view.role = "pressure";
  return view;
}

FieldView shear_view(const SurfaceMesh& mesh, const SurfaceLoadOptions& options) {
  FieldView view;
  view.role = "wall shear";
  if (options.shear_fields.empty()) return view;
  if (options.shear_fields.size() == 1) {
    const FieldArray& field = find_array(mesh, options.shear_fields[0], 3, "wall shear");
    for (int c = 0; c < 3; ++c) view.component[c] = field.values.data() + c;
    view.stride = 3;
    view.per_point = field.association == FieldAssociation::Point;
    view.arrays[0] = &field;
    return view;
  }
  if (options.shear_fields.size() != 3)
    throw InputError("wall shear: expected one vector array or three scalar arrays x,y,z, got " +
                     std::to_string(options.shear_fields.size()) + " names");
  for (int c = 0; c < 3; ++c) {
    const FieldArray& field = find_array(mesh, options.shear_fields[static_cast<std::size_t>(c)], 1, "wall shear");
    view.component[c] = field.values.data();
    view.arrays[c] = &field;
    const bool per_point = field.association == FieldAssociation::Point;
    if (c > 0 && per_point != view.per_point)
      throw InputError("wall shear arrays mix point and face data; expected all three alike");
    view.per_point = per_point;
  }
  return view;
}

/// The checks that cost nothing per face; the rest (offsets that go back,
/// point indices out of range) are made block by block while integrating.
void check_mesh_shape(const SurfaceMesh& mesh) {
  if (mesh.face_count() == 0) throw InputError("the surface has no faces; expected a body surface of polygons");
  if (mesh.points_xyz.size() % 3 != 0) throw InputError("point coordinates are not a multiple of 3");
  if (mesh.face_offsets.front() != 0)
    throw InputError("face offsets start at " + std::to_string(mesh.face_offsets.front()) + "; expected 0");
  if (mesh.face_offsets.back() != mesh.face_indices.size())
    throw InputError("face offsets end at " + std::to_string(mesh.face_offsets.back()) + " but there are " +
                     std::to_string(mesh.face_indices.size()) + " face indices");
  // Edge entries pack a point index and a direction bit into 32 bits.
  if (mesh.point_count() >= (std::size_t{1} << 31))
    throw InputError("the surface has " + std::to_string(mesh.point_count()) + " points; expected fewer than 2^31");
}

/// The InputError for the first face a block could not read.
/// The offsets first (only offsets that never go back keep the index reads
/// inside the array), then the indices.
[[noreturn]] void throw_unreadable_faces(const SurfaceMesh& mesh) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_offsets[f + 1] < mesh.face_offsets[f])
      throw InputError("face offsets go back at face " + std::to_string(f) + " (" +
                       std::to_string(mesh.face_offsets[f + 1]) + " after " + std::to_string(mesh.face_offsets[f]) +
                       "); expected offsets that never decrease");
  const std::size_t points = mesh.point_count();
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (std::size_t i = mesh.face_offsets[f]; i < mesh.face_offsets[f + 1]; ++i)
      if (mesh.face_indices[i] >= points)
        throw InputError("face " + std::to_string(f) + " refers to point " + std::to_string(mesh.face_indices[i]) +
                         " but the surface has " + std::to_string(points) + " points");
  throw std::logic_error("throw_unreadable_faces: every face can be read");
}

/// The InputError for the first point with a coordinate that is NaN or Inf.
[[noreturn]] void throw_not_finite_point(const SurfaceMesh& mesh) {
  for (std::size_t i = 0; i < mesh.points_xyz.size(); ++i)
    if (!std::isfinite(mesh.points_xyz[i]))
      throw InputError("point " + std::to_string(i / 3) + " has " + "xyz"[i % 3] + " = " +
                       (std::isnan(mesh.points_xyz[i]) ? "NaN" : "Inf") + "; expected finite coordinates");
  throw std::logic_error("throw_not_finite_point: every coordinate is finite");
}

}  // namespace hydrocoef::loads_detail
