// Edge topology of a surface: whether it is closed (every edge used by two
// faces) and consistently oriented (the two faces walk it opposite ways), and
// otherwise how many edges are boundary, non-manifold or inconsistent.
//
// The integration kernel adds up a directed-edge residue as it goes (below);
// a zero residue, Euler characteristic 2 and every point used let it skip the
// exact count; anything else is counted edge by edge (count_edges).
#pragma once

#include <cstddef>
#include <cstdint>

#include <vector>

#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef::loads_detail {

/// A 64-bit mix of a vertex index (splitmix64's finalizer).
inline std::uint64_t mix64(std::uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// The face's share of the edge residue Σ over directed edges a→b of
/// h(a) g(b) - h(b) g(a) modulo 2^64, with h = mix64 and g the index itself:
/// exactly 0 when every edge is walked as often one way as the other (the
/// term is antisymmetric in (a, b), which is all the cancellation needs, at
/// one hash per vertex), a random 64-bit number otherwise.
inline std::uint64_t edge_residue(const std::uint32_t* indices, std::size_t k) {
  std::uint64_t residue = 0;
  const std::uint64_t g_first = indices[0], h_first = mix64(g_first);
  std::uint64_t h_prev = h_first, g_prev = g_first;
  for (std::size_t i = 1; i <= k; ++i) {
    const std::uint64_t g = i < k ? indices[i] : g_first;
    const std::uint64_t h = i < k ? mix64(g) : h_first;
    residue += h_prev * g - h * g_prev;
    h_prev = h;
    g_prev = g;
  }
  return residue;
}

/// Edge counts (see SurfaceGeometry).
struct EdgeCounts {
  std::size_t boundary = 0, nonmanifold = 0, inconsistent = 0;
};

/// Every edge counted exactly (linear in the corners, on two threads).
EdgeCounts count_edges(const SurfaceMesh& mesh);

/// True when V - E + F = 2, with V the number of points and E half the sum
/// of the face sizes (the edges, when every edge is used by two faces).
bool euler_characteristic_two(const SurfaceMesh& mesh);

/// Which points the faces use, one bit a point: 80 KiB for a million points,
/// so marking stays in the core's cache. Each thread marks a set of its own;
/// merge() makes their union.
class PointsUsed {
 public:
  explicit PointsUsed(std::size_t points) : words_((points + 63) / 64, 0), points_(points) {}
  /// The point index must be below the number of points.
  void mark(std::uint32_t point) { words_[point >> 6] |= std::uint64_t{1} << (point & 63u); }
  void merge(const PointsUsed& other);
  /// Whether every point is marked.
  bool all() const;

 private:
  std::vector<std::uint64_t> words_;
  std::size_t points_;
};

}  // namespace hydrocoef::loads_detail
