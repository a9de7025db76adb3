#include "src/mesh/duplicate_faces.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "src/core/parallel.hpp"

namespace hydrocoef {
namespace {

/// SplitMix64's finalizer: every input bit changes about half of the output bits.
std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::uint64_t edge_word(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

class Faces {
 public:
  explicit Faces(const SurfaceMesh& mesh)
      : offsets_(mesh.face_offsets.data()), indices_(mesh.face_indices.data()), count_(mesh.face_count()) {}

  std::size_t count() const { return count_; }
  std::uint32_t size(std::size_t f) const { return offsets_[f + 1] - offsets_[f]; }
  const std::uint32_t* corners(std::size_t f) const { return indices_ + offsets_[f]; }

  std::uint32_t lowest_point(std::size_t f) const { return *std::min_element(corners(f), corners(f) + size(f)); }

  /// A word that two copies of a face share: a triangle's two higher points
  /// (its lowest is its bucket), else a hash of the corner count and the
  /// edges, the same for every rotation and orientation. Equal words are
  /// checked by same().
  std::uint64_t key(std::size_t f) const {
    const std::uint32_t n = size(f);
    const std::uint32_t* c = corners(f);
    if (n == 3) {
      const std::uint32_t low = std::min({c[0], c[1], c[2]}), high = std::max({c[0], c[1], c[2]});
      const std::uint32_t middle = c[0] ^ c[1] ^ c[2] ^ low ^ high;
      return (std::uint64_t{middle} << 32) | high;
    }
    std::uint64_t h = mix(n);
    for (std::uint32_t i = 0; i < n; ++i) h += mix(edge_word(c[i], c[i + 1 < n ? i + 1 : 0]));
    return h;
  }

  /// Whether two faces have as many corners and the same edges.
  bool same(std::size_t f, std::size_t g) const {
    const std::uint32_t n = size(f);
    if (size(g) != n) return false;
    std::vector<std::uint64_t> a, b;
    for (std::uint32_t i = 0; i < n; ++i) {
      a.push_back(edge_word(corners(f)[i], corners(f)[i + 1 < n ? i + 1 : 0]));
      b.push_back(edge_word(corners(g)[i], corners(g)[i + 1 < n ? i + 1 : 0]));
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    return a == b;
  }

 private:
  const std::uint32_t* offsets_;
  const std::uint32_t* indices_;
  std::size_t count_;
};

/// Keeps the pair whose later face comes first in the mesh.
void keep_earliest(std::optional<DuplicateFace>& found, std::size_t first, std::size_t second) {
  if (!found || second < found->second || (second == found->second && first < found->first))
    found = DuplicateFace{first, second};
}

/// Each face's lowest point (kNoFace for a face without points) and key,
/// computed once, on two threads (each half of the faces).
constexpr std::uint32_t kNoFace = ~std::uint32_t{0};

struct FaceKeys {
  std::unique_ptr<std::uint32_t[]> lowest;
  std::unique_ptr<std::uint64_t[]> key;
};

FaceKeys face_keys(const Faces& faces) {
  const std::size_t n = faces.count();
  FaceKeys out{std::unique_ptr<std::uint32_t[]>(new std::uint32_t[n]),
               std::unique_ptr<std::uint64_t[]>(new std::uint64_t[n])};
  parallel_for(2, 2, [&](std::size_t half) {
    for (std::size_t f = n * half / 2; f < n * (half + 1) / 2; ++f) {
      const bool empty = faces.size(f) == 0;
      out.lowest[f] = empty ? kNoFace : faces.lowest_point(f);
      out.key[f] = empty ? 0 : faces.key(f);
    }
  });
  return out;
}

/// The earliest repeat among the faces whose lowest point is in [first, last).
/// Faces are bucketed by their lowest point (two copies of a face share it),
/// each with its key, in face order inside a bucket: counted, summed, filled;
/// then a bucket's keys are compared, so that faces are read again only
/// where two keys are equal. (A face outside the range is counted in a spare
/// bucket past the end, which saves a branch the processor cannot predict.)
std::optional<DuplicateFace> find_in(const Faces& faces, const FaceKeys& keyed, std::uint32_t first,
                                     std::uint32_t last) {
  std::optional<DuplicateFace> found;
  if (last <= first) return found;
  const std::size_t points = last - first;
  const std::size_t spare = points + 1;
  std::vector<std::uint32_t> start(points + 2, 0);
  auto bucket = [&](std::size_t f) -> std::size_t {
    const std::uint32_t low = keyed.lowest[f];
    return low >= first && low < last ? low - first : spare - 1;
  };
  for (std::size_t f = 0; f < faces.count(); ++f) ++start[bucket(f) + 1];
  for (std::size_t p = 0; p < points; ++p) start[p + 1] += start[p];
  const std::size_t total = start[points];
  const std::unique_ptr<std::uint64_t[]> keys(new std::uint64_t[total]);
  const std::unique_ptr<std::uint32_t[]> ids(new std::uint32_t[total]);
  for (std::size_t f = 0; f < faces.count(); ++f) {
    const std::uint32_t low = keyed.lowest[f];
    if (low < first || low >= last) continue;
    const std::uint32_t at = start[low - first]++;
    keys[at] = keyed.key[f];
    ids[at] = static_cast<std::uint32_t>(f);
  }
  // start[p] now holds the end of p's bucket, start[p - 1] its beginning.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> sorted;
  std::uint32_t begin = 0;
  for (std::size_t p = 0; p < points; ++p) {
    const std::uint32_t end = start[p];
    const std::size_t n = end - begin;
    const std::uint64_t* key = keys.get() + begin;
    const std::uint32_t* id = ids.get() + begin;
    begin = end;
    if (n < 2) continue;
    if (n <= 16) {  // a handful of faces share a lowest point on any sensible mesh
      for (std::size_t j = 1; j < n; ++j)
        for (std::size_t i = 0; i < j; ++i)
          if (key[i] == key[j] && faces.same(id[i], id[j])) {
            keep_earliest(found, id[i], id[j]);
            break;
          }
      continue;
    }
    // A point shared by very many faces: sorted by key, compared within a key.
    sorted.clear();
    for (std::size_t k = 0; k < n; ++k) sorted.emplace_back(key[k], id[k]);
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t run = 0; run < n;) {
      std::size_t run_end = run + 1;
      while (run_end < n && sorted[run_end].first == sorted[run].first) ++run_end;
      for (std::size_t j = run + 1; j < run_end; ++j)
        for (std::size_t i = run; i < j; ++i)
          if (faces.same(sorted[i].second, sorted[j].second)) {
            keep_earliest(found, sorted[i].second, sorted[j].second);
            break;
          }
      run = run_end;
    }
  }
  return found;
}

}  // namespace

std::optional<DuplicateFace> find_duplicate_face(const SurfaceMesh& mesh) {
  const Faces faces(mesh);
  const auto points = static_cast<std::uint32_t>(mesh.point_count());
  if (faces.count() < 2 || points == 0) return std::nullopt;
  // Two threads, each with the faces whose lowest point is in its half of
  // the points (lower points are the lowest of more faces).
  const auto split = static_cast<std::uint32_t>(0.4 * points);
  const FaceKeys keyed = face_keys(faces);
  std::array<std::optional<DuplicateFace>, 2> halves;
  parallel_for(2, 2, [&](std::size_t half) {
    halves[half] = half == 0 ? find_in(faces, keyed, 0, split) : find_in(faces, keyed, split, points);
  });
  std::optional<DuplicateFace> found = halves[0];
  if (halves[1]) keep_earliest(found, halves[1]->first, halves[1]->second);
  return found;
}

}  // namespace hydrocoef
