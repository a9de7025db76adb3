// From the axes a CFD case was set up in to the body axes of hydrocoef
// (x forward, y starboard, z down). A mapping is a signed permutation of the
// CFD axes, written as the CFD axis that each body axis points along:
// "-x,y,-z" says body x = -CFD x, body y = CFD y, body z = -CFD z (a z-up case
// whose stream flows along +x, seen from a body moving into it). Only proper
// rotations are accepted, so no handedness is ever lost. Forces are
// integrated in the file's axes and then rotated, which keeps the
// integration free of per-point transforms.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "src/loads/surface_loads.hpp"

namespace hydrocoef {

struct FrameTransform {
  /// rotation[i] is body axis i written in CFD axes: v_b[i] = rotation[i] · v_cfd.
  std::array<Vec3, 3> rotation{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  /// The body origin in CFD coordinates [m]: x_b = R (x_cfd - origin_cfd).
  Vec3 origin_cfd{};

  Vec3 vector_to_body(const Vec3& v_cfd) const;
  Vec3 vector_to_cfd(const Vec3& v_b) const;
  Vec3 point_to_body(const Vec3& x_cfd) const;
  Vec3 point_to_cfd(const Vec3& x_b) const;
  /// The mapping in the "-x,y,-z" form (identity: "x,y,z").
  std::string axes_text() const;
};

/// Parses "x,y,z", "-x,y,-z", "y,-x,z" ...; InputError unless each CFD axis
/// appears once and the result is a proper rotation (det = +1).
FrameTransform parse_axes(std::string_view text);

/// Loads integrated in CFD axes (about the CFD point that is the body
/// reference point) expressed in body axes.
SurfaceLoads loads_to_body(const SurfaceLoads& loads_cfd, const FrameTransform& frame);

}  // namespace hydrocoef
