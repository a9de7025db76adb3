// A body's planes of symmetry, used to let each run also stand for its
// mirror image (fit --mirror, surface build --mirror). The runs themselves
// are never changed or stored twice: mirror images are made when a fit or a
// surface gathers its samples, and marked as such.
//
// A reflection R (the identity with -1 on the plane's normal axis) maps the
// linear velocity and the force as vectors and the angular velocity and the
// moment as pseudo-vectors (-R):
//
//   --mirror v  port-starboard (the x-z plane):  (u, v, w, p, q, r) -> (u, -v, w, -p, q, -r)
//                                                (X, Y, Z, K, M, N) -> (X, -Y, Z, -K, M, -N)
//   --mirror w  top-bottom (the x-y plane):      (u, v, -w, -p, -q, r), (X, Y, -Z, -K, -M, N)
//   --mirror u  fore-aft (the y-z plane):        (-u, v, w, p, -q, -r), (-X, Y, Z, K, -M, -N)
//
// Disturbance parameters keep their value unless named odd (a lateral
// current under --mirror v changes sign). A run on the plane (v = p = r = 0
// and odd disturbances 0, for --mirror v) is its own image and is not
// repeated.
#pragma once

#include <array>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/run.hpp"

namespace hydrocoef {

struct BodyMirror {
  std::size_t axis = 1;                    ///< 0, 1, 2: the plane's normal (u/x, v/y, w/z)
  std::set<std::string> odd_disturbances;  ///< parameters that change sign in the mirror

  /// +1 or -1 for each of u..r (and of X..N: the same pattern).
  std::array<double, 6> signs() const;
  /// The mirror image of a key.
  RunKey key(const RunKey& key) const;
  /// True when the key is its own image.
  bool on_plane(const RunKey& key) const;
  /// "v" and the rule in words for messages and provenance.
  std::string text() const;
};

/// Parses "u", "v" or "w" (the velocity component the mirror reverses) and
/// the odd disturbance names. InputError naming the option otherwise.
BodyMirror parse_body_mirror(std::string_view component, const std::vector<std::string>& odd_disturbances = {});

}  // namespace hydrocoef
