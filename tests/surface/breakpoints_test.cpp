// Evenly spaced breakpoints hold the decimal values asked for.
#include "src/surface/breakpoints.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <string>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

std::string shortest(double x) {
  char text[32];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, x);
  return std::string(text, end);
}

TEST(EvenlySpaced, DecimalStepsGiveTheDecimalValues) {
  const auto points = evenly_spaced(-0.1, 0.05, 4);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(shortest(points[0]), "-0.1");
  EXPECT_EQ(shortest(points[1]), "-0.05");
  EXPECT_EQ(points[2], 0.0);
  EXPECT_FALSE(std::signbit(points[2]));
  EXPECT_EQ(shortest(points[3]), "0.05");
  const auto fine = evenly_spaced(0.0, 1.2, 13);
  for (std::size_t i = 0; i < fine.size(); ++i) EXPECT_EQ(fine[i], std::stod(std::to_string(i) + "e-1")) << i;
}

TEST(EvenlySpaced, EveryPointIsTheDoubleNearestItsDecimal) {
  const auto points = evenly_spaced(-0.3, 0.3, 13);  // step 0.05
  for (std::size_t i = 0; i < points.size(); ++i) {
    const long hundredths = -30 + 5 * static_cast<long>(i);
    const double expected = std::stod(std::to_string(hundredths) + "e-2");
    EXPECT_EQ(points[i], expected) << i;
  }
  const auto large = evenly_spaced(100.0, 1000.0, 10);
  for (std::size_t i = 0; i < large.size(); ++i) EXPECT_EQ(large[i], 100.0 * static_cast<double>(i + 1));
}

TEST(EvenlySpaced, NonDecimalStepsFallBackWithExactEndsAndZero) {
  const auto thirds = evenly_spaced(-1.0, 1.0, 4);  // step 2/3
  EXPECT_EQ(thirds.front(), -1.0);
  EXPECT_EQ(thirds.back(), 1.0);
  EXPECT_NEAR(thirds[1], -1.0 / 3.0, 1e-15);
  const auto odd = evenly_spaced(-0.1, 0.1, 3);
  EXPECT_EQ(odd[1], 0.0);
  const auto tiny = evenly_spaced(1e-40, 2e-40, 3);
  EXPECT_EQ(tiny.front(), 1e-40);
  EXPECT_EQ(tiny.back(), 2e-40);
}

TEST(EvenlySpaced, RefusesBadArguments) {
  EXPECT_THROW(evenly_spaced(1.0, 0.0, 3), InputError);
  EXPECT_THROW(evenly_spaced(0.0, 1.0, 1), InputError);
  EXPECT_THROW(evenly_spaced(0.0, INFINITY, 3), InputError);
}

}  // namespace
}  // namespace hydrocoef
