// The run vocabulary: component indices, the canonical disturbance signature
// (sorted, -0 folded, round-trip precision), the human description of a key,
// and the sign-convention names.
#include "src/core/run.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

TEST(ComponentIndex, VelocityNames) {
  const std::vector<std::string> names = {"u", "v", "w", "p", "q", "r"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    ASSERT_TRUE(velocity_index(names[i]).has_value()) << names[i];
    EXPECT_EQ(*velocity_index(names[i]), i) << names[i];
    EXPECT_FALSE(force_index(names[i]).has_value()) << names[i];
  }
  EXPECT_FALSE(velocity_index("U").has_value());
  EXPECT_FALSE(velocity_index("").has_value());
  EXPECT_FALSE(velocity_index("uu").has_value());
  EXPECT_FALSE(velocity_index("x").has_value());
}

TEST(ComponentUnits, SiUnitOfEachComponent) {
  const std::vector<std::string> force = {"N", "N", "N", "N m", "N m", "N m"};
  const std::vector<std::string> velocity = {"m/s", "m/s", "m/s", "rad/s", "rad/s", "rad/s"};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(force_unit(i), force[i]) << kForceNames[i];
    EXPECT_EQ(velocity_unit(i), velocity[i]) << kVelocityNames[i];
  }
}

TEST(ComponentIndex, ForceNames) {
  const std::vector<std::string> names = {"X", "Y", "Z", "K", "M", "N"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    ASSERT_TRUE(force_index(names[i]).has_value()) << names[i];
    EXPECT_EQ(*force_index(names[i]), i) << names[i];
    EXPECT_FALSE(velocity_index(names[i]).has_value()) << names[i];
  }
  EXPECT_FALSE(force_index("x").has_value());
  EXPECT_FALSE(force_index("n").has_value());
  EXPECT_FALSE(force_index("").has_value());
  EXPECT_FALSE(force_index("XY").has_value());
}

TEST(DisturbanceSignature, EmptyWhenNone) { EXPECT_EQ(disturbance_signature({}), ""); }

TEST(DisturbanceSignature, SortedByNameAndSeparated) {
  const std::map<std::string, double> d = {{"current_v", 0.05}, {"alpha", 1.0}, {"beta", -2.5}};
  EXPECT_EQ(disturbance_signature(d), "alpha=1;beta=-2.5;current_v=0.05");
  EXPECT_EQ(disturbance_signature({{"x", 0.5}}), "x=0.5");
}

TEST(DisturbanceSignature, NegativeZeroIsFoldedIntoZero) {
  EXPECT_EQ(disturbance_signature({{"a", -0.0}}), "a=0");
  EXPECT_EQ(disturbance_signature({{"a", -0.0}}), disturbance_signature({{"a", 0.0}}));
  EXPECT_EQ(disturbance_signature({{"a", -0.0}, {"b", 1.0}}), "a=0;b=1");
}

// Splits "a=1;b=2" back into values, parsing each number with from_chars.
std::vector<double> parse_back(const std::string& signature) {
  std::vector<double> values;
  std::size_t start = 0;
  while (start < signature.size()) {
    auto end = signature.find(';', start);
    if (end == std::string::npos) end = signature.size();
    const auto eq = signature.find('=', start);
    const std::string number = signature.substr(eq + 1, end - eq - 1);
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    EXPECT_EQ(ec, std::errc{}) << number;
    EXPECT_EQ(ptr, number.data() + number.size()) << number;
    values.push_back(value);
    start = end + 1;
  }
  return values;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(DisturbanceSignature, RoundTripPrecision) {
  const std::vector<double> values = {0.1,
                                      0.1 + 0.2,
                                      1.0 / 3.0,
                                      -2.0 / 3.0,
                                      std::nextafter(1.0, 2.0),
                                      123456789.123456789,
                                      1e-300,
                                      std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::min(),
                                      -std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::max(),
                                      2.2250738585072014e-308};
  for (const double value : values) {
    const std::string signature = disturbance_signature({{"d", value}});
    ASSERT_EQ(signature.substr(0, 2), "d=");
    const auto back = parse_back(signature);
    ASSERT_EQ(back.size(), 1u) << signature;
    EXPECT_TRUE(same_bits(back[0], value)) << signature;
  }
  // Several at once, and the order of the values follows the sorted names.
  const std::map<std::string, double> many = {{"z", 0.1 + 0.2}, {"a", 1.0 / 3.0}, {"m", -1e-17}};
  const auto back = parse_back(disturbance_signature(many));
  ASSERT_EQ(back.size(), 3u);
  EXPECT_TRUE(same_bits(back[0], 1.0 / 3.0));
  EXPECT_TRUE(same_bits(back[1], -1e-17));
  EXPECT_TRUE(same_bits(back[2], 0.1 + 0.2));
}

TEST(DisturbanceSignature, NearbyValuesGiveDifferentSignatures) {
  const double a = 0.05;
  const double b = std::nextafter(a, 1.0);
  EXPECT_NE(disturbance_signature({{"v", a}}), disturbance_signature({{"v", b}}));
}

TEST(Describe, ListsNonZeroVelocitiesThenDisturbances) {
  RunKey key;
  key.body = "asr-v";
  key.nu_b = {0.1, 0.0, 0.0, 0.0, 0.0, 0.2};
  key.disturbances = {{"current_v", 0.05}};
  EXPECT_EQ(describe(key), "asr-v u=0.1 r=0.2 current_v=0.05");
}

TEST(Describe, EveryComponentInOrder) {
  RunKey key;
  key.body = "b";
  key.nu_b = {1.0, -2.0, 3.5, 0.25, -0.5, 4.0};
  EXPECT_EQ(describe(key), "b u=1 v=-2 w=3.5 p=0.25 q=-0.5 r=4");
}

TEST(Describe, AtRest) {
  RunKey key;
  key.body = "asr-v";
  EXPECT_EQ(describe(key), "asr-v (at rest)");
  key.nu_b[0] = -0.0;  // -0 is still zero
  EXPECT_EQ(describe(key), "asr-v (at rest)");
}

TEST(Describe, DisturbanceOnlyIsNotAtRest) {
  RunKey key;
  key.body = "hull";
  key.disturbances = {{"current_v", 0.05}, {"alpha", 2.0}};
  EXPECT_EQ(describe(key), "hull alpha=2 current_v=0.05");
}

TEST(Describe, DistinctKeysDescribeDifferently) {
  RunKey a;
  a.body = "b";
  a.nu_b[0] = 0.1;
  RunKey b = a;
  b.nu_b[0] = std::nextafter(0.1, 1.0);
  EXPECT_NE(describe(a), describe(b));
}

TEST(SignConvention, RoundTrip) {
  for (const SignConvention convention : {SignConvention::OnBody, SignConvention::OpposingMotion})
    EXPECT_EQ(parse_sign_convention(to_string(convention)), convention);
  EXPECT_EQ(to_string(SignConvention::OnBody), "on-body");
  EXPECT_EQ(to_string(SignConvention::OpposingMotion), "opposing");
  EXPECT_EQ(parse_sign_convention("on-body"), SignConvention::OnBody);
  EXPECT_EQ(parse_sign_convention("opposing"), SignConvention::OpposingMotion);
}

TEST(SignConvention, UnknownTextIsAnInputErrorNamingIt) {
  for (const std::string text : {"On-Body", "opposing-motion", "", "onbody", " on-body"}) {
    try {
      (void)parse_sign_convention(text);
      ADD_FAILURE() << "'" << text << "' was accepted";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("'" + text + "'"), std::string::npos) << message;
      EXPECT_NE(message.find("on-body"), std::string::npos) << message;
      EXPECT_NE(message.find("opposing"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace hydrocoef
