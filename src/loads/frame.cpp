#include "src/loads/frame.hpp"

#include "src/core/error.hpp"
#include "src/core/vec3.hpp"

namespace hydrocoef {

Vec3 FrameTransform::vector_to_body(const Vec3& v) const {
  return {dot(rotation[0], v), dot(rotation[1], v), dot(rotation[2], v)};
}

Vec3 FrameTransform::vector_to_cfd(const Vec3& v) const {
  Vec3 out{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t c = 0; c < 3; ++c) out[c] += rotation[i][c] * v[i];
  return out;
}

Vec3 FrameTransform::point_to_body(const Vec3& x) const {
  return vector_to_body({x[0] - origin_cfd[0], x[1] - origin_cfd[1], x[2] - origin_cfd[2]});
}

Vec3 FrameTransform::point_to_cfd(const Vec3& x) const {
  const Vec3 v = vector_to_cfd(x);
  return {v[0] + origin_cfd[0], v[1] + origin_cfd[1], v[2] + origin_cfd[2]};
}

std::string FrameTransform::axes_text() const {
  std::string out;
  for (std::size_t i = 0; i < 3; ++i) {
    if (i) out += ',';
    for (std::size_t c = 0; c < 3; ++c) {
      if (rotation[i][c] == 0.0) continue;
      if (rotation[i][c] < 0.0) out += '-';
      out += static_cast<char>('x' + c);
    }
  }
  return out;
}

FrameTransform parse_axes(std::string_view text) {
  FrameTransform frame;
  std::array<bool, 3> used{};
  std::size_t start = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto comma = text.find(',', start);
    if ((i < 2) == (comma == std::string_view::npos))
      throw InputError("axes '" + std::string(text) + "': expected three comma-separated CFD axes, e.g. -x,y,-z");
    std::string_view item = text.substr(start, comma == std::string_view::npos ? text.npos : comma - start);
    start = comma + 1;
    double sign = 1.0;
    if (!item.empty() && (item.front() == '-' || item.front() == '+')) {
      sign = item.front() == '-' ? -1.0 : 1.0;
      item.remove_prefix(1);
    }
    if (item.size() != 1 || item[0] < 'x' || item[0] > 'z')
      throw InputError("axes '" + std::string(text) + "': '" + std::string(item) + "' is not x, y or z");
    const auto axis = static_cast<std::size_t>(item[0] - 'x');
    if (used[axis]) throw InputError("axes '" + std::string(text) + "': CFD axis " + item[0] + " is used twice");
    used[axis] = true;
    frame.rotation[i] = {};
    frame.rotation[i][axis] = sign;
  }
  if (dot(cross(frame.rotation[0], frame.rotation[1]), frame.rotation[2]) < 0.0)
    throw InputError("axes '" + std::string(text) +
                     "' mirror the CFD frame (left-handed result); expected a rotation, e.g. flip two axes "
                     "rather than one");
  return frame;
}

SurfaceLoads loads_to_body(const SurfaceLoads& in, const FrameTransform& frame) {
  SurfaceLoads out = in;
  out.force_pressure = frame.vector_to_body(in.force_pressure);
  out.force_viscous = frame.vector_to_body(in.force_viscous);
  out.moment_pressure = frame.vector_to_body(in.moment_pressure);
  out.moment_viscous = frame.vector_to_body(in.moment_viscous);
  out.reference_point = frame.point_to_body(in.reference_point);
  out.geometry.integral_n_dA = frame.vector_to_body(in.geometry.integral_n_dA);
  // ∫ x_b × n_b dA = R ∫ (x - o) × n dA = R (∫ x × n dA - o × ∫ n dA).
  const Vec3 about_origin = in.geometry.integral_x_cross_n_dA;
  const Vec3 o_cross_n = cross(frame.origin_cfd, in.geometry.integral_n_dA);
  out.geometry.integral_x_cross_n_dA = frame.vector_to_body(
      {about_origin[0] - o_cross_n[0], about_origin[1] - o_cross_n[1], about_origin[2] - o_cross_n[2]});
  return out;
}

}  // namespace hydrocoef
