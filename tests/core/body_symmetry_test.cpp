// Mirror images of runs: the sign patterns of the three planes (vectors and
// pseudo-vectors), odd disturbances, runs on the plane, and the check that a
// mirrored force field is the one the reflected body feels.
#include "src/core/body_symmetry.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

TEST(BodyMirror, SignPatternsOfTheThreePlanes) {
  EXPECT_EQ(parse_body_mirror("v").signs(), (std::array<double, 6>{1, -1, 1, -1, 1, -1}));
  EXPECT_EQ(parse_body_mirror("w").signs(), (std::array<double, 6>{1, 1, -1, -1, -1, 1}));
  EXPECT_EQ(parse_body_mirror("u").signs(), (std::array<double, 6>{-1, 1, 1, 1, -1, -1}));
}

TEST(BodyMirror, PseudoVectorsFollowFromTheCrossProduct) {
  // The moment of a force F at a point x, M = x × F, must map like the
  // pattern says when x and F map as vectors.
  for (const char* component : {"u", "v", "w"}) {
    const auto s = parse_body_mirror(component).signs();
    const std::array<double, 3> x{0.3, -0.7, 1.1}, F{2.0, 0.5, -1.5};
    const auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    std::array<double, 3> xr{}, Fr{};
    for (std::size_t i = 0; i < 3; ++i) xr[i] = s[i] * x[i], Fr[i] = s[i] * F[i];
    const auto M = cross(x, F), Mr = cross(xr, Fr);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(Mr[i], s[3 + i] * M[i]) << component << " " << i;
  }
}

TEST(BodyMirror, KeysOddDisturbancesAndRunsOnThePlane) {
  const auto mirror = parse_body_mirror("v", {"current_v"});
  RunKey key{"hull", {0.2, 0.05, 0, 0.1, 0, 0.3}, {{"current_v", 0.02}, {"depth", 3.0}}};
  const RunKey image = mirror.key(key);
  EXPECT_EQ(image.nu_b, (std::array<double, 6>{0.2, -0.05, 0, -0.1, 0, -0.3}));
  EXPECT_EQ(image.disturbances.at("current_v"), -0.02);
  EXPECT_EQ(image.disturbances.at("depth"), 3.0);
  EXPECT_FALSE(mirror.on_plane(key));
  EXPECT_TRUE(mirror.on_plane(RunKey{"hull", {0.2, 0, 0.1, 0, 0.3, 0}, {{"depth", 3.0}}}));
  EXPECT_FALSE(mirror.on_plane(RunKey{"hull", {0.2, 0, 0, 0, 0, 0}, {{"current_v", 0.01}}}));
  // No negative zero in an image.
  EXPECT_FALSE(std::signbit(mirror.key(RunKey{"hull", {0.2, 0, 0, 0, 0, 0}, {}}).nu_b[1]));
}

TEST(BodyMirror, RefusesWhatIsNotAPlane) {
  EXPECT_THROW(parse_body_mirror("r"), InputError);
  EXPECT_THROW(parse_body_mirror("y"), InputError);
  EXPECT_THROW(parse_body_mirror("v", {"a;b"}), InputError);
  EXPECT_NE(parse_body_mirror("v").text().find("(X,-Y,Z,-K,M,-N)"), std::string::npos);
}

}  // namespace
}  // namespace hydrocoef
