#include "src/loads/symmetry.hpp"

#include <charconv>
#include <cmath>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/vec3.hpp"

namespace hydrocoef {
namespace {

Vec3 reflect(Vec3 v, int axis) {
  v[static_cast<std::size_t>(axis)] = -v[static_cast<std::size_t>(axis)];
  return v;
}

/// A force F and a moment M about `point`, and their mirror image added:
/// moments are taken to the plane's foot of `point`, mirrored there and
/// taken back.
void mirror_pair(Vec3& force, Vec3& moment, const Vec3& point, const SymmetryPlane& plane) {
  Vec3 foot = point;
  foot[static_cast<std::size_t>(plane.axis)] = plane.offset;
  const Vec3 moment_foot = moment + cross(point - foot, force);
  const Vec3 whole_force = force + reflect(force, plane.axis);
  const Vec3 whole_moment_foot = moment_foot - reflect(moment_foot, plane.axis);
  force = whole_force;
  moment = whole_moment_foot + cross(foot - point, whole_force);
}

}  // namespace

std::vector<SymmetryPlane> parse_symmetry(std::string_view text) {
  const auto refuse = [&](const std::string& what) {
    throw InputError("--symmetry '" + printable_text(text, 60) + "': " + what +
                     "; expected planes such as y=0 or y=0,z=0");
  };
  std::vector<SymmetryPlane> planes;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = text.find(',', start);
    std::string_view part =
        text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    if (part.size() < 3 || part[1] != '=' || (part[0] != 'x' && part[0] != 'y' && part[0] != 'z'))
      refuse("'" + std::string(part) + "' is not AXIS=OFFSET");
    SymmetryPlane plane;
    plane.axis = part[0] - 'x';
    std::string_view number = part.substr(2);
    if (!number.empty() && number.front() == '+') number.remove_prefix(1);
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), plane.offset);
    if (number.empty() || ec != std::errc() || end != number.data() + number.size() || !std::isfinite(plane.offset))
      refuse("'" + std::string(part.substr(2)) + "' is not a finite offset [m]");
    for (const auto& p : planes)
      if (p.axis == plane.axis) refuse("two planes normal to " + std::string(1, part[0]));
    planes.push_back(plane);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return planes;
}

std::string symmetry_text(const std::vector<SymmetryPlane>& planes) {
  std::string out;
  for (const auto& p : planes) {
    out += (out.empty() ? "" : ",") + std::string(1, static_cast<char>('x' + p.axis)) + "=" +
           shortest_number(p.offset == 0.0 ? 0.0 : p.offset);
  }
  return out;
}

void mirror_force_moment(Vec3& force, Vec3& moment, const Vec3& reference_point,
                         const std::vector<SymmetryPlane>& planes) {
  for (const auto& plane : planes) mirror_pair(force, moment, reference_point, plane);
}

SurfaceLoads mirror_loads(const SurfaceLoads& part, const std::vector<SymmetryPlane>& planes) {
  SurfaceLoads whole = part;
  auto& g = whole.geometry;
  for (const auto& plane : planes) {
    mirror_pair(whole.force_pressure, whole.moment_pressure, whole.reference_point, plane);
    mirror_pair(whole.force_viscous, whole.moment_viscous, whole.reference_point, plane);
    // ∫x×n dA about the origin: the image point is R x + t (t = 2 d e_a) and
    // its normal R n, so its integral is -R ∫x×n dA + t × R ∫n dA.
    Vec3 t{};
    t[static_cast<std::size_t>(plane.axis)] = 2.0 * plane.offset;
    const Vec3 n_image = reflect(g.integral_n_dA, plane.axis);
    const Vec3 xn_image = cross(t, n_image) - reflect(g.integral_x_cross_n_dA, plane.axis);
    g.integral_n_dA += n_image;
    g.integral_x_cross_n_dA += xn_image;
    g.faces *= 2, g.triangles *= 2, g.quads *= 2, g.polygons *= 2, g.degenerate_faces *= 2;
    g.area *= 2.0;
    // The volume (1/3)∮x·n dA of the image equals the part's for a plane
    // through the origin; for an offset plane the open part's volume has no
    // meaning of its own, and the doubled value is what the whole encloses
    // when the part's open boundary lies on the planes.
    g.signed_volume *= 2.0;
  }
  return whole;
}

std::string vanishing_components(const std::vector<SymmetryPlane>& planes) {
  bool force_zero[3] = {false, false, false}, moment_zero[3] = {false, false, false};
  for (const auto& p : planes) {
    force_zero[p.axis] = true;
    for (int a = 0; a < 3; ++a)
      if (a != p.axis) moment_zero[a] = true;
  }
  std::string out;
  for (int a = 0; a < 3; ++a)
    if (force_zero[a]) out += (out.empty() ? "F" : ", F") + std::string(1, static_cast<char>('x' + a));
  for (int a = 0; a < 3; ++a)
    if (moment_zero[a]) out += (out.empty() ? "M" : ", M") + std::string(1, static_cast<char>('x' + a));
  return out;
}

}  // namespace hydrocoef
