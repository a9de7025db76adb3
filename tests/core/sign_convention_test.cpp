// The one sign conversion (src/core/sign_convention.hpp): the same number
// when the conventions agree, its negative when they differ, both ways, for
// forces and law coefficients alike; and the names read and written.
#include "src/core/sign_convention.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

constexpr auto kOnBody = SignConvention::OnBody;
constexpr auto kOpposing = SignConvention::OpposingMotion;

TEST(SignConvention, DampingIsNegativeOnTheBodyAndPositiveOpposing) {
  // The ASR-V surge damping at u = 0.2 m/s, as its paper tabulates it (opposing) and on the body.
  const double opposing = 0.0155 * 0.2 + 11.0365 * 0.2 * 0.2;
  EXPECT_EQ(to_on_body(opposing, kOpposing), -opposing);
  EXPECT_EQ(to_on_body(-opposing, kOnBody), -opposing);
  EXPECT_EQ(to_convention(-opposing, kOnBody, kOpposing), opposing);
  EXPECT_EQ(to_convention(opposing, kOpposing, kOpposing), opposing);
}

TEST(SignConvention, ConvertingThereAndBackIsTheIdentity) {
  for (const double value : {0.0, -0.0, 1.5, -2.25e-300, 1e308}) {
    for (const auto from : {kOnBody, kOpposing}) {
      for (const auto to : {kOnBody, kOpposing}) {
        const double there = to_convention(value, from, to);
        EXPECT_EQ(std::abs(there), std::abs(value));
        EXPECT_EQ(std::signbit(there), std::signbit(value) != (from != to)) << value;
        EXPECT_EQ(to_convention(there, to, from), value);
        EXPECT_EQ(there, sign_factor(from, to) * value);
      }
    }
  }
  EXPECT_EQ(sign_factor(kOnBody, kOnBody), 1.0);
  EXPECT_EQ(sign_factor(kOpposing, kOpposing), 1.0);
  EXPECT_EQ(sign_factor(kOnBody, kOpposing), -1.0);
  EXPECT_EQ(sign_factor(kOpposing, kOnBody), -1.0);
  static_assert(to_on_body(2.0, SignConvention::OpposingMotion) == -2.0);
}

TEST(SignConvention, NamesReadBackAndUnknownNamesAreRefused) {
  for (const auto convention : {kOnBody, kOpposing}) {
    EXPECT_EQ(parse_sign_convention(to_string(convention)), convention);
    EXPECT_EQ(sign_convention_named(to_string(convention)), convention);
  }
  EXPECT_EQ(to_string(kOnBody), "on-body");
  EXPECT_EQ(to_string(kOpposing), "opposing");
  EXPECT_EQ(sign_convention_named("On-Body"), std::nullopt);
  EXPECT_THROW(parse_sign_convention("reaction"), InputError);
}

}  // namespace
}  // namespace hydrocoef
