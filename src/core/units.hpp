// Unit strings as CFD tools write them ("m s^-1", "[ N m ]", "kPa", "deg s^-1",
// "mm", "kg m^-3") turned into an SI scale factor and a dimension, so that
// importers convert once at the edge and refuse a column whose unit is not of
// the expected kind. Angles are a dimension of their own here (rad), so that
// "deg s^-1" is never mistaken for a linear velocity.
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace hydrocoef {

/// Exponents of mass, length, time, plane angle and temperature.
struct Dimension {
  std::array<int, 5> exponents{};  ///< kg, m, s, rad, K
  bool operator==(const Dimension&) const = default;
};

inline constexpr Dimension kDimensionless{};
inline constexpr Dimension kLength{{0, 1, 0, 0}};
inline constexpr Dimension kVelocity{{0, 1, -1, 0}};
inline constexpr Dimension kAngularVelocity{{0, 0, -1, 1}};
inline constexpr Dimension kForce{{1, 1, -2, 0}};
inline constexpr Dimension kMoment{{1, 2, -2, 0}};
inline constexpr Dimension kPressure{{1, -1, -2, 0}};
inline constexpr Dimension kDensity{{1, -3, 0, 0}};
inline constexpr Dimension kKinematicViscosity{{0, 2, -1, 0}};

/// "kg m s^-2"-style SI spelling of a dimension ("1" when dimensionless).
std::string si_unit_name(const Dimension& dimension);

/// A parsed unit: value_si = value * scale + offset.
struct Unit {
  std::string text;  ///< as written, trimmed
  double scale = 1.0;
  Dimension dimension;
};

/// Parses a unit expression: factors separated by spaces, '*' or '.', each a
/// symbol with an optional SI prefix and an optional exponent ("s^-1", "m^2",
/// "m2"); one '/' divides by everything after it. Symbols: m, g, s, min, h, N,
/// Pa, bar, J, W, rad, radian, deg, degree, rev, L, K (kelvin; temperature
/// differences and absolute temperatures alike, no offset units). Surrounding brackets and
/// spaces are ignored; "" and "1" are dimensionless. Throws InputError naming
/// the unknown part.
Unit parse_unit(std::string_view text);

/// True when a unit of dimension `found` may be read as `expected`. Plane angle
/// is dimensionless in SI, so an angular velocity may be written "s^-1"; the
/// reverse (a linear quantity carrying an angle) is refused.
bool dimension_matches(const Dimension& found, const Dimension& expected);

/// Splits a CFX-style header "Name [ unit ]" into its name and unit text (no
/// brackets). A header without brackets has an empty unit.
struct NameAndUnit {
  std::string name;
  std::string unit;
  bool has_unit = false;
};
NameAndUnit split_name_and_unit(std::string_view header);

}  // namespace hydrocoef
