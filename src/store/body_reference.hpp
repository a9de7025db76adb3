// A body's reference data as the database stores it (tables body_reference
// and body_reference_area, schema/0017_body_reference.sql): plain data,
// written by `hydrocoef body set` (src/api/body_reference.cpp) and read by
// the coefficients of its runs (`runs --coefficients`).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hydrocoef {

struct BodyReferenceRecord {
  std::string body;
  std::optional<double> length;            ///< reference length L [m], > 0
  std::map<std::string, double> areas;     ///< named reference areas [m^2], each > 0
  std::string default_area;                ///< one of `areas`, or "" when none is chosen
  std::optional<double> draft;             ///< [m], > 0
  std::optional<double> displaced_volume;  ///< [m^3], > 0
  /// The point moment coefficients are taken about [m], body axes (x
  /// forward, y starboard, z down); empty: each run's own reference point.
  std::optional<std::array<double, 3>> moment_point_b;
  std::string updated_at;  ///< UTC, ISO 8601 ("" before it is stored)

  /// The same reference data (updated_at aside).
  bool same_data(const BodyReferenceRecord& other) const;
  /// What is wrong with the record ("area 'x' is not positive", "the default
  /// area 'y' is not one of the body's areas"), or "" when nothing is.
  std::string problem() const;
};

}  // namespace hydrocoef
