// A body surface as importers deliver it: points, polygonal faces and named
// field arrays, in SI units and in the coordinates of the source file (the
// caller decides how CFD axes map to body axes). Plain data: importers fill
// it, src/loads reads it; nothing here knows file formats.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hydrocoef {

/// Whether an array holds one value per point (node) or one per face (cell).
enum class FieldAssociation { Point, Face };

/// A named array with 1 (scalar) or 3 (vector) components per entry, stored
/// entry-major: values[i * components + c]. Values are SI after import.
struct FieldArray {
  std::string name;
  FieldAssociation association = FieldAssociation::Point;
  int components = 1;
  std::vector<double> values;
  std::string unit;  ///< SI unit after conversion, e.g. "Pa"; "" when the source did not say

  std::size_t size() const { return components > 0 ? values.size() / static_cast<std::size_t>(components) : 0; }
};

/// Polygonal surface in compressed-row form: the indices of face f are
/// face_indices[face_offsets[f] .. face_offsets[f + 1]).
struct SurfaceMesh {
  std::vector<double> points_xyz;              ///< 3 per point [m]
  std::vector<std::uint32_t> face_offsets{0};  ///< faces + 1 entries, starts with 0
  std::vector<std::uint32_t> face_indices;     ///< 0-based point indices
  std::vector<std::string> location_names;     ///< patches, zones or blocks the faces came from
  std::vector<std::uint32_t> face_location;    ///< per face, index into location_names
  std::vector<FieldArray> fields;

  std::size_t point_count() const { return points_xyz.size() / 3; }
  std::size_t face_count() const { return face_offsets.empty() ? 0 : face_offsets.size() - 1; }
  /// The array with this name, or nullptr.
  const FieldArray* find_field(const std::string& name) const {
    for (const auto& field : fields)
      if (field.name == name) return &field;
    return nullptr;
  }
};

}  // namespace hydrocoef
