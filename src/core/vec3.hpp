// Three-vectors of doubles (Vec3: x, y, z in the frame the caller names) and
// the dot and cross products the importers and the surface loads share.
#pragma once

#include <array>

namespace hydrocoef {

using Vec3 = std::array<double, 3>;

constexpr double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace hydrocoef
