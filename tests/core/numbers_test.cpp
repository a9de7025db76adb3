// The one number formatter (src/core/numbers.hpp): every double reads back
// bit for bit with std::from_chars, with the fewest digits, including
// denormals, the extremes, negative zero and the special values.
#include "src/core/numbers.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

namespace hydrocoef {
namespace {

double read_back(const std::string& text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  EXPECT_EQ(ec, std::errc()) << text;
  EXPECT_EQ(end, text.data() + text.size()) << text;
  return value;
}

void expect_round_trip(double value) {
  const std::string text = shortest_number(value);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(read_back(text)), std::bit_cast<std::uint64_t>(value)) << text;
}

TEST(ShortestNumber, FewestDigitsThatReadBack) {
  EXPECT_EQ(shortest_number(0.1), "0.1");
  EXPECT_EQ(shortest_number(1.0), "1");
  EXPECT_EQ(shortest_number(-2.5), "-2.5");
  EXPECT_EQ(shortest_number(1e21), "1e+21");
  EXPECT_EQ(shortest_number(1e-7), "1e-07");
  EXPECT_EQ(shortest_number(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(shortest_number(123456789012345678.0), "123456789012345680");
}

TEST(ShortestNumber, ExtremesAndDenormalsReadBackExactly) {
  EXPECT_EQ(shortest_number(std::numeric_limits<double>::denorm_min()), "5e-324");
  EXPECT_EQ(shortest_number(-std::numeric_limits<double>::denorm_min()), "-5e-324");
  EXPECT_EQ(shortest_number(std::numeric_limits<double>::max()), "1.7976931348623157e+308");
  EXPECT_EQ(shortest_number(std::numeric_limits<double>::min()), "2.2250738585072014e-308");
  for (double value : {std::numeric_limits<double>::denorm_min(), 3 * std::numeric_limits<double>::denorm_min(),
                       std::numeric_limits<double>::min() / 3, std::numeric_limits<double>::max(),
                       std::numeric_limits<double>::lowest(), std::numeric_limits<double>::epsilon()})
    expect_round_trip(value);
}

TEST(ShortestNumber, RandomBitPatternsReadBackExactly) {
  std::mt19937_64 rng(16);
  for (int i = 0; i < 100000; ++i) {
    const double value = std::bit_cast<double>(rng());
    if (std::isnan(value)) continue;
    expect_round_trip(value);
  }
}

TEST(ShortestNumber, KeepsTheSignOfZeroAndSpellsSpecialValues) {
  EXPECT_EQ(shortest_number(0.0), "0");
  EXPECT_EQ(shortest_number(-0.0), "-0");
  EXPECT_TRUE(std::signbit(read_back(shortest_number(-0.0))));
  EXPECT_EQ(shortest_number(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(shortest_number(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(shortest_number(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(shortest_number(-std::numeric_limits<double>::quiet_NaN()), "-nan");
  EXPECT_TRUE(std::isnan(read_back(shortest_number(std::numeric_limits<double>::quiet_NaN()))));
  EXPECT_EQ(read_back(shortest_number(-std::numeric_limits<double>::infinity())),
            -std::numeric_limits<double>::infinity());
}

TEST(ShortestNumber, AppendWritesTheSameText) {
  std::string line = "x=";
  append_shortest_number(line, 0.1);
  line += ',';
  append_shortest_number(line, -0.0);
  line += ',';
  append_shortest_number(line, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(line, "x=0.1,-0,5e-324");
}

TEST(ShortestFloat, FewestDigitsOfTheFloat) {
  EXPECT_EQ(shortest_float(0.1f), "0.1");
  EXPECT_EQ(shortest_number(static_cast<double>(0.1f)), "0.10000000149011612");
  EXPECT_EQ(shortest_float(std::numeric_limits<float>::max()), "3.4028235e+38");
  EXPECT_EQ(shortest_float(std::numeric_limits<float>::denorm_min()), "1e-45");
  EXPECT_EQ(shortest_float(-0.0f), "-0");
  float value = 0.0f;
  const std::string text = shortest_float(1.0f / 3.0f);
  std::from_chars(text.data(), text.data() + text.size(), value);
  EXPECT_EQ(value, 1.0f / 3.0f);
}

}  // namespace
}  // namespace hydrocoef
