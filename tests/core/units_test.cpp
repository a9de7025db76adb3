// Unit parsing: SI scale factors and dimensions of the unit strings CFD tools
// write, the refusal of unknown or malformed units, the angle-aware dimension
// check, and the splitting of CFX "Name [ unit ]" headers. Expected scales are
// worked out by hand from the unit definitions (1 km = 1e3 m, 1 h = 3600 s,
// 1 deg = pi/180 rad, 1 bar = 1e5 Pa, ...).
#include "src/core/units.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

constexpr double kPi = std::numbers::pi;

// The message of the InputError thrown by parse_unit(text); fails the test if
// nothing (or something else) is thrown.
std::string parse_unit_error(const std::string& text) {
  try {
    (void)parse_unit(text);
  } catch (const InputError& error) {
    return error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "parse_unit('" << text << "') threw a non-InputError: " << error.what();
    return {};
  }
  ADD_FAILURE() << "parse_unit('" << text << "') did not throw";
  return {};
}

struct UnitCase {
  std::string text;
  double scale;
  Dimension dimension;
};

class ParseUnitTest : public ::testing::TestWithParam<UnitCase> {};

TEST_P(ParseUnitTest, ScaleAndDimension) {
  const UnitCase& c = GetParam();
  const Unit unit = parse_unit(c.text);
  EXPECT_DOUBLE_EQ(unit.scale, c.scale) << "unit '" << c.text << "'";
  EXPECT_EQ(unit.dimension, c.dimension) << "unit '" << c.text << "' gave " << si_unit_name(unit.dimension)
                                         << ", expected " << si_unit_name(c.dimension);
}

constexpr Dimension kInverseTime{{0, 0, -1, 0}};

INSTANTIATE_TEST_SUITE_P(
    Units, ParseUnitTest,
    ::testing::Values(UnitCase{"m s^-1", 1.0, kVelocity},               //
                      UnitCase{"[ m s^-1 ]", 1.0, kVelocity},           // CFX style, brackets and spaces
                      UnitCase{"[m s^-1]", 1.0, kVelocity},             // monitor style, no inner spaces
                      UnitCase{"  m s^-1  ", 1.0, kVelocity},           //
                      UnitCase{"mm s^-1", 1e-3, kVelocity},             // milli-metre per second
                      UnitCase{"m/s", 1.0, kVelocity},                  //
                      UnitCase{"km h^-1", 1000.0 / 3600.0, kVelocity},  // 1 km/h = 1/3.6 m/s
                      UnitCase{"km/h", 1000.0 / 3600.0, kVelocity},     //
                      UnitCase{"N", 1.0, kForce},                       //
                      UnitCase{"kN", 1e3, kForce},                      //
                      UnitCase{"N m", 1.0, kMoment},                    //
                      UnitCase{"N.m", 1.0, kMoment},                    // '.' as a product
                      UnitCase{"N*m", 1.0, kMoment},                    //
                      UnitCase{"kN m", 1e3, kMoment},                   //
                      UnitCase{"J", 1.0, kMoment},                      // CFX labels torque [J]
                      UnitCase{"Pa", 1.0, kPressure},                   //
                      UnitCase{"kPa", 1e3, kPressure},                  //
                      UnitCase{"hPa", 1e2, kPressure},                  //
                      UnitCase{"bar", 1e5, kPressure},                  //
                      UnitCase{"mbar", 1e2, kPressure},                 //
                      UnitCase{"deg s^-1", kPi / 180.0, kAngularVelocity},
                      UnitCase{"degree s^-1", kPi / 180.0, kAngularVelocity},
                      UnitCase{"rad s^-1", 1.0, kAngularVelocity},     //
                      UnitCase{"radian s^-1", 1.0, kAngularVelocity},  //
                      UnitCase{"rev min^-1", 2.0 * kPi / 60.0, kAngularVelocity},
                      UnitCase{"s^-1", 1.0, kInverseTime},               //
                      UnitCase{"1/s", 1.0, kInverseTime},                //
                      UnitCase{"kg m^-3", 1.0, kDensity},                // k * g = 1e3 * 1e-3
                      UnitCase{"g cm^-3", 1e3, kDensity},                // 1e-3 kg / 1e-6 m^3
                      UnitCase{"kg/m^3", 1.0, kDensity},                 //
                      UnitCase{"m^2 s^-1", 1.0, kKinematicViscosity},    //
                      UnitCase{"m2 s-1", 1.0, kKinematicViscosity},      // exponents without '^'
                      UnitCase{"mm^2 s^-1", 1e-6, kKinematicViscosity},  // (1e-3)^2
                      UnitCase{"km^2", 1e6, Dimension{{0, 2, 0, 0}}},    // prefix is raised with the symbol
                      UnitCase{"min", 60.0, Dimension{{0, 0, 1, 0}}},    // minute, not milli-inch
                      UnitCase{"ms", 1e-3, Dimension{{0, 0, 1, 0}}},     // millisecond
                      UnitCase{"L", 1e-3, Dimension{{0, 3, 0, 0}}},      //
                      UnitCase{"", 1.0, kDimensionless},                 //
                      UnitCase{"1", 1.0, kDimensionless},                //
                      UnitCase{"[ ]", 1.0, kDimensionless}),
    [](const ::testing::TestParamInfo<UnitCase>& param) { return "case" + std::to_string(param.index); });

TEST(ParseUnit, KeepsTheTrimmedTextWithoutBrackets) {
  EXPECT_EQ(parse_unit("[ m s^-1 ]").text, "m s^-1");
  EXPECT_EQ(parse_unit("  kN  ").text, "kN");
  EXPECT_EQ(parse_unit("").text, "");
}

TEST(ParseUnit, UnknownSymbolNamesIt) {
  const std::string message = parse_unit_error("furlong");
  EXPECT_NE(message.find("furlong"), std::string::npos) << message;
  const std::string in_product = parse_unit_error("N furlong^-1");
  EXPECT_NE(in_product.find("'furlong'"), std::string::npos) << in_product;
}

TEST(ParseUnit, UnknownPrefixIsRefused) {
  // 'P' (peta) and 'h' (hecto) are not in the prefix list; neither is a lower-case 'pa'.
  EXPECT_NE(parse_unit_error("pa").find("pa"), std::string::npos);
  EXPECT_NE(parse_unit_error("xm").find("xm"), std::string::npos);
}

TEST(ParseUnit, BadExponentNamesTheFactor) {
  const std::string message = parse_unit_error("m^x");
  EXPECT_NE(message.find("m^x"), std::string::npos) << message;
  EXPECT_NE(parse_unit_error("s^").find("s^"), std::string::npos);
  EXPECT_NE(parse_unit_error("m^2.5").find("m^2.5"), std::string::npos);
  EXPECT_NE(parse_unit_error("m2x").find("m2x"), std::string::npos);
}

TEST(ParseUnit, HugeExponentsAndScalesAreRefusedNotOverflowed) {
  // Found by fuzzing: the exponent once overflowed an int (undefined
  // behaviour), and mm400 m^-400 once gave a scale of 0, storing every force as 0.
  EXPECT_NE(parse_unit_error("J2000000000").find("exponent 2000000000"), std::string::npos);
  EXPECT_NE(parse_unit_error("N mm400 m^-400").find("exponent 400"), std::string::npos);
  EXPECT_NE(parse_unit_error("m^-13").find("-12 to 12"), std::string::npos);
  EXPECT_NE(parse_unit_error("m12 m12 m12").find("power 36"), std::string::npos);
  EXPECT_DOUBLE_EQ(parse_unit("mm^3").scale, 1e-9);
}

TEST(ParseUnit, TwoSlashesAreRefused) {
  const std::string message = parse_unit_error("kg/m/s");
  EXPECT_NE(message.find("kg/m/s"), std::string::npos) << message;
  EXPECT_NE(message.find('/'), std::string::npos) << message;
}

TEST(DimensionMatches, ExactDimensionsMatch) {
  EXPECT_TRUE(dimension_matches(kVelocity, kVelocity));
  EXPECT_TRUE(dimension_matches(kForce, kForce));
  EXPECT_TRUE(dimension_matches(kMoment, kMoment));
  EXPECT_TRUE(dimension_matches(kAngularVelocity, kAngularVelocity));
}

TEST(DimensionMatches, InverseSecondsAcceptedAsAngularVelocity) {
  EXPECT_TRUE(dimension_matches(parse_unit("rad s^-1").dimension, kAngularVelocity));
  EXPECT_TRUE(dimension_matches(parse_unit("s^-1").dimension, kAngularVelocity));
}

TEST(DimensionMatches, AngleNeverPassesAsLinear) {
  EXPECT_FALSE(dimension_matches(parse_unit("deg s^-1").dimension, kVelocity));
  EXPECT_FALSE(dimension_matches(parse_unit("rad s^-1").dimension, kVelocity));
  EXPECT_FALSE(dimension_matches(parse_unit("s^-1").dimension, kVelocity));
  // A linear velocity is not an angular one either.
  EXPECT_FALSE(dimension_matches(parse_unit("m s^-1").dimension, kAngularVelocity));
  // Only one power of the angle may be implicit.
  EXPECT_FALSE(dimension_matches(parse_unit("rad^2 s^-1").dimension, kAngularVelocity));
}

TEST(DimensionMatches, ForceIsNotMoment) {
  EXPECT_FALSE(dimension_matches(parse_unit("N").dimension, kMoment));
  EXPECT_FALSE(dimension_matches(parse_unit("N m").dimension, kForce));
  EXPECT_FALSE(dimension_matches(parse_unit("Pa").dimension, kForce));
}

TEST(SplitNameAndUnit, CfxHeaders) {
  struct Case {
    std::string header, name, unit;
  };
  const std::vector<Case> cases = {
      {"X [ m ]", "X", "m"},
      {"Pressure [ Pa ]", "Pressure", "Pa"},
      {"Wall Shear X [ Pa ]", "Wall Shear X", "Pa"},
      {"water.Pressure [ Pa ]", "water.Pressure", "Pa"},
      {"Velocity [ m s^-1 ]", "Velocity", "m s^-1"},
      {"  u [m s^-1]  ", "u", "m s^-1"},
      {"Monitor Point: Fx1 [N]", "Monitor Point: Fx1", "N"},
  };
  for (const auto& c : cases) {
    const NameAndUnit split = split_name_and_unit(c.header);
    EXPECT_EQ(split.name, c.name) << c.header;
    EXPECT_EQ(split.unit, c.unit) << c.header;
    EXPECT_TRUE(split.has_unit) << c.header;
  }
}

TEST(SplitNameAndUnit, WithoutBrackets) {
  for (const std::string header : {"Yplus", "Normal X", "gas.Velocity w", " u "}) {
    const NameAndUnit split = split_name_and_unit(header);
    EXPECT_FALSE(split.has_unit) << header;
    EXPECT_EQ(split.unit, "") << header;
  }
  EXPECT_EQ(split_name_and_unit("Normal X").name, "Normal X");
  EXPECT_EQ(split_name_and_unit(" u ").name, "u");
}

TEST(SplitNameAndUnit, EmptyBracketsAreAnEmptyUnit) {
  const NameAndUnit split = split_name_and_unit("X []");
  EXPECT_EQ(split.name, "X");
  EXPECT_EQ(split.unit, "");
  EXPECT_TRUE(split.has_unit);
}

TEST(SiUnitName, NamesDimensions) {
  EXPECT_EQ(si_unit_name(kDimensionless), "1");
  EXPECT_EQ(si_unit_name(kLength), "m");
  EXPECT_EQ(si_unit_name(kVelocity), "m s^-1");
  EXPECT_EQ(si_unit_name(kForce), "kg m s^-2");
  EXPECT_EQ(si_unit_name(kMoment), "kg m^2 s^-2");
  EXPECT_EQ(si_unit_name(kPressure), "kg m^-1 s^-2");
  EXPECT_EQ(si_unit_name(kDensity), "kg m^-3");
  EXPECT_EQ(si_unit_name(kKinematicViscosity), "m^2 s^-1");
  EXPECT_EQ(si_unit_name(kAngularVelocity), "rad s^-1");
  EXPECT_EQ(si_unit_name(Dimension{{0, 0, -2, 2}}), "rad^2 s^-2");
  EXPECT_EQ(si_unit_name(Dimension{{-1, 0, 0, 0}}), "kg^-1");
}

TEST(SiUnitName, RoundTripsThroughParseUnit) {
  for (const Dimension& d :
       {kLength, kVelocity, kAngularVelocity, kForce, kMoment, kPressure, kDensity, kKinematicViscosity}) {
    const Unit unit = parse_unit(si_unit_name(d));
    EXPECT_EQ(unit.dimension, d) << si_unit_name(d);
    EXPECT_DOUBLE_EQ(unit.scale, 1.0) << si_unit_name(d);
  }
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

TEST(ParseUnit, KelvinIsATemperatureSoCfdPostTemperatureColumnsParse) {
  const Unit kelvin = parse_unit("[ K ]");
  EXPECT_EQ(kelvin.scale, 1.0);
  EXPECT_EQ(kelvin.dimension, (Dimension{{0, 0, 0, 0, 1}}));
  EXPECT_FALSE(dimension_matches(kelvin.dimension, kDimensionless));
  EXPECT_EQ(si_unit_name(parse_unit("W m^-2 K^-1").dimension), "kg K^-1 s^-3");
}

}  // namespace
}  // namespace hydrocoef
