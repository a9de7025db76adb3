// Three-vectors (src/core/vec3.hpp): the dot and cross products of the
// right-handed frames the importers and the surface loads use.
#include "src/core/vec3.hpp"

#include <gtest/gtest.h>

namespace hydrocoef {
namespace {

TEST(Vec3, DotProduct) {
  EXPECT_EQ(dot({1, 2, 3}, {4, -5, 6}), 4.0 - 10.0 + 18.0);
  EXPECT_EQ(dot({1, 0, 0}, {0, 1, 0}), 0.0);
}

TEST(Vec3, CrossProductIsRightHanded) {
  EXPECT_EQ(cross({1, 0, 0}, {0, 1, 0}), (Vec3{0, 0, 1}));
  EXPECT_EQ(cross({0, 1, 0}, {0, 0, 1}), (Vec3{1, 0, 0}));
  EXPECT_EQ(cross({0, 0, 1}, {1, 0, 0}), (Vec3{0, 1, 0}));
  EXPECT_EQ(cross({1, 2, 3}, {4, 5, 6}), (Vec3{2 * 6 - 3 * 5, 3 * 4 - 1 * 6, 1 * 5 - 2 * 4}));
  const Vec3 a{0.3, -1.2, 2.5}, b{-0.7, 0.4, 1.1};
  EXPECT_NEAR(dot(cross(a, b), a), 0.0, 1e-15);
  EXPECT_NEAR(dot(cross(a, b), b), 0.0, 1e-15);
}

}  // namespace
}  // namespace hydrocoef
