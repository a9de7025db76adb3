#include "src/loads/surface_topology.hpp"

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include "src/core/huge_pages.hpp"
#include "src/core/parallel.hpp"

namespace hydrocoef::loads_detail {
namespace {

/// The edges whose smaller vertex lies in [first, last). Each edge (a, b) is filed under its smaller vertex with
/// the direction the face walks it; two passes of counting, no sort of the
/// whole edge list, so this stays linear in the number of faces. Working on a
/// vertex range lets two threads share the work; entries are 32 bits (the
/// other vertex and the direction), uninitialised and on huge pages, since
/// filling them is random access over tens of MB.
EdgeCounts count_edges_in(const SurfaceMesh& mesh, std::uint32_t first, std::uint32_t last) {
  EdgeCounts counts;
  if (last <= first) return counts;
  const std::size_t vertices = last - first;
  std::vector<std::uint32_t> start;
  reserve_with_huge_pages(start, vertices + 1);
  start.assign(vertices + 1, 0);
  const std::size_t faces = mesh.face_count();
  const std::uint32_t* offsets = mesh.face_offsets.data();
  const std::uint32_t* indices = mesh.face_indices.data();
  auto for_each_edge = [&](auto&& visit) {
    for (std::size_t f = 0; f < faces; ++f) {
      const std::uint32_t begin = offsets[f], end = offsets[f + 1];
      for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t a = indices[i], b = indices[i + 1 < end ? i + 1 : begin];
        const std::uint32_t low = a < b ? a : b;
        if (a != b && low >= first && low < last) visit(a, b, low - first);
      }
    }
  };
  for_each_edge([&](std::uint32_t, std::uint32_t, std::uint32_t v) { ++start[v + 1]; });
  for (std::size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  const std::size_t total = start[vertices];
  const std::unique_ptr<std::uint32_t[]> entries(new std::uint32_t[total]);
  prefer_huge_pages(entries.get(), total * sizeof(std::uint32_t));
  for_each_edge([&](std::uint32_t a, std::uint32_t b, std::uint32_t v) {
    entries[start[v]++] = ((a < b ? b : a) << 1) | (a < b ? 1u : 0u);
  });
  // start[v] now holds the end of v's entries, start[v - 1] their beginning.
  std::uint32_t begin = 0;
  for (std::size_t v = 0; v < vertices; ++v) {
    const std::uint32_t end = start[v];
    std::uint32_t* list = entries.get() + begin;
    const std::size_t n = end - begin;
    if (n <= 16) {  // lists hold a handful of edges on any sensible mesh
      for (std::size_t i = 1; i < n; ++i)
        for (std::size_t j = i; j > 0 && list[j] < list[j - 1]; --j) std::swap(list[j], list[j - 1]);
    } else {  // a vertex shared by very many faces: O(n log n), whatever the mesh
      std::sort(list, list + n);
    }
    for (std::size_t i = 0; i < n;) {
      std::size_t j = i;
      unsigned walked_forward = 0;
      while (j < n && (list[j] >> 1) == (list[i] >> 1)) walked_forward += list[j++] & 1u;
      const std::size_t uses = j - i;
      if (uses == 1)
        ++counts.boundary;
      else if (uses > 2)
        ++counts.nonmanifold;
      else if (walked_forward != 1)
        ++counts.inconsistent;
      i = j;
    }
    begin = end;
  }
  return counts;
}

}  // namespace

EdgeCounts count_edges(const SurfaceMesh& mesh) {
  const auto points = static_cast<std::uint32_t>(mesh.point_count());
  const auto split = static_cast<std::uint32_t>(0.4 * points);  // lower vertices own more edges
  EdgeCounts halves[2];
  parallel_for(2, 2, [&](std::size_t half) {
    halves[half] = half == 0 ? count_edges_in(mesh, 0, split) : count_edges_in(mesh, split, points);
  });
  return {halves[0].boundary + halves[1].boundary, halves[0].nonmanifold + halves[1].nonmanifold,
          halves[0].inconsistent + halves[1].inconsistent};
}

bool euler_characteristic_two(const SurfaceMesh& mesh) {
  const auto corners = static_cast<std::int64_t>(mesh.face_indices.size());
  const auto points = static_cast<std::int64_t>(mesh.point_count());
  const auto faces = static_cast<std::int64_t>(mesh.face_count());
  return corners % 2 == 0 && points - corners / 2 + faces == 2;
}

void PointsUsed::merge(const PointsUsed& other) {
  for (std::size_t w = 0; w < words_.size(); ++w) words_[w] |= other.words_[w];
}

bool PointsUsed::all() const {
  const std::size_t full = points_ / 64;
  for (std::size_t w = 0; w < full; ++w)
    if (words_[w] != ~std::uint64_t{0}) return false;
  const std::size_t rest = points_ % 64;
  return rest == 0 || words_[full] == (std::uint64_t{1} << rest) - 1;
}

}  // namespace hydrocoef::loads_detail
