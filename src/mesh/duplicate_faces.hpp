// Faces listed twice. A surface export that lists one face twice (the same
// points, in any rotation or in either orientation) is broken: the face would
// count twice in the forces, and no exporter writes one on purpose. Importers
// look for such a pair once, when a mesh is loaded, and refuse the file with
// both faces' places; the integration loop never looks.
#pragma once

#include <cstddef>
#include <optional>

#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef {

/// Two faces of one mesh that list the same points: `first` < `second`, and
/// `first` is the earliest face that `second` repeats.
struct DuplicateFace {
  std::size_t first = 0;
  std::size_t second = 0;
};

/// The first face (in mesh order) that repeats an earlier one, with that
/// earlier face; nullopt when every face is listed once. Two faces are the
/// same when they have as many corners and the same edges {a, b} (point
/// indices, each edge as often): for a polygon without repeated points, the
/// same points in a rotation or the reverse order. Faces are bucketed by
/// their lowest point index, each with a 64-bit key (a triangle's other two
/// points, a polygon's hash of its edges), and only faces of one bucket with
/// equal keys are compared (a large bucket is sorted by key), so the time is
/// linear in the face corners and O(n log n) at worst, on two threads (each
/// half of the points' buckets), with 24 bytes per face and 4 per point of
/// scratch. The point indices must be below mesh.point_count().
std::optional<DuplicateFace> find_duplicate_face(const SurfaceMesh& mesh);

}  // namespace hydrocoef
