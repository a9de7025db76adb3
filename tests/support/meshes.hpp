// Test support: closed and open surfaces with known geometry, built in code
// so that analytic results (volume, centroid, area) are known independently.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "src/mesh/surface_mesh.hpp"

namespace hydrocoef::test {

using P3 = std::array<double, 3>;

inline void add_face(SurfaceMesh& mesh, std::initializer_list<std::uint32_t> indices) {
  for (auto i : indices) mesh.face_indices.push_back(i);
  mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.face_indices.size()));
}

inline std::uint32_t add_point(SurfaceMesh& mesh, const P3& p) {
  mesh.points_xyz.insert(mesh.points_xyz.end(), p.begin(), p.end());
  return static_cast<std::uint32_t>(mesh.point_count() - 1);
}

/// Hexahedron with the 8 given corners (VTK hexahedron order: bottom 0-3
/// counter-clockwise seen from above, top 4-7 above them), as 6 quads with
/// outward normals. With non-coplanar corners the faces are warped
/// (bilinear patches).
inline SurfaceMesh make_hexahedron(const std::array<P3, 8>& corners, bool triangulate = false) {
  SurfaceMesh mesh;
  for (const auto& c : corners) add_point(mesh, c);
  const std::array<std::array<std::uint32_t, 4>, 6> quads = {
      {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
  for (const auto& q : quads) {
    if (triangulate) {
      add_face(mesh, {q[0], q[1], q[2]});
      add_face(mesh, {q[0], q[2], q[3]});
    } else {
      add_face(mesh, {q[0], q[1], q[2], q[3]});
    }
  }
  return mesh;
}

inline std::array<P3, 8> box_corners(double a, double b, double c, P3 origin = {0, 0, 0}) {
  std::array<P3, 8> out{};
  const std::array<P3, 8> unit = {
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  for (std::size_t i = 0; i < 8; ++i)
    out[i] = {origin[0] + a * unit[i][0], origin[1] + b * unit[i][1], origin[2] + c * unit[i][2]};
  return out;
}

/// Volume and centroid of the trilinear hexahedron spanned by the corners,
/// by 3×3×3 Gauss quadrature of det J over the reference cube (exact: the
/// integrands are polynomials of degree ≤ 3 in each direction). Independent
/// of any surface integral.
inline std::pair<double, P3> trilinear_volume_and_centroid(const std::array<P3, 8>& x) {
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const double w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                          {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  double volume = 0.0;
  P3 moment{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const double r[3] = {g[i], g[j], g[k]};
        double J[3][3] = {};
        P3 pos{};
        for (int n = 0; n < 8; ++n) {
          const double N = (1 + s[n][0] * r[0]) * (1 + s[n][1] * r[1]) * (1 + s[n][2] * r[2]) / 8.0;
          const double dN[3] = {s[n][0] * (1 + s[n][1] * r[1]) * (1 + s[n][2] * r[2]) / 8.0,
                                s[n][1] * (1 + s[n][0] * r[0]) * (1 + s[n][2] * r[2]) / 8.0,
                                s[n][2] * (1 + s[n][0] * r[0]) * (1 + s[n][1] * r[1]) / 8.0};
          for (int a = 0; a < 3; ++a) {
            pos[static_cast<std::size_t>(a)] += N * x[static_cast<std::size_t>(n)][static_cast<std::size_t>(a)];
            for (int b = 0; b < 3; ++b) J[a][b] += dN[b] * x[static_cast<std::size_t>(n)][static_cast<std::size_t>(a)];
          }
        }
        const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                           J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                           J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
        const double weight = w[i] * w[j] * w[k] * det;
        volume += weight;
        for (std::size_t a = 0; a < 3; ++a) moment[a] += weight * pos[a];
      }
  return {volume, {moment[0] / volume, moment[1] / volume, moment[2] / volume}};
}

/// Icosphere of radius r: an icosahedron subdivided `levels` times, points
/// projected on the sphere; triangles, outward normals, closed.
inline SurfaceMesh make_icosphere(double radius, int levels, P3 centre = {0, 0, 0}) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<P3> points = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                            {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  auto normalize = [](P3 p) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return P3{p[0] / n, p[1] / n, p[2] / n};
  };
  for (auto& p : points) p = normalize(p);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      points.push_back(normalize(
          {(points[a][0] + points[b][0]) / 2, (points[a][1] + points[b][1]) / 2, (points[a][2] + points[b][2]) / 2}));
      const auto index = static_cast<std::uint32_t>(points.size() - 1);
      midpoints[key] = index;
      return index;
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    for (const auto& f : faces) {
      const auto a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      finer.push_back({f[0], a, c});
      finer.push_back({f[1], b, a});
      finer.push_back({f[2], c, b});
      finer.push_back({a, b, c});
    }
    faces = std::move(finer);
  }
  SurfaceMesh mesh;
  for (const auto& p : points)
    add_point(mesh, {centre[0] + radius * p[0], centre[1] + radius * p[1], centre[2] + radius * p[2]});
  for (const auto& f : faces) add_face(mesh, {f[0], f[1], f[2]});
  return mesh;
}

/// Latitude-longitude sphere: `rings` bands of quads between the poles, with
/// triangles at the poles, `meridians` cells around; outward normals, closed.
/// With `uneven` the latitudes are spaced θ = π (s + 0.2 s (1 - s)), which
/// breaks the mirror symmetry about the equator.
inline SurfaceMesh make_uv_sphere(double radius, int rings, int meridians, bool uneven = false) {
  SurfaceMesh mesh;
  const auto north = add_point(mesh, {0, 0, radius});
  for (int i = 1; i < rings; ++i) {
    const double s = static_cast<double>(i) / rings;
    const double theta = std::numbers::pi * (uneven ? s + 0.2 * s * (1.0 - s) : s);
    for (int j = 0; j < meridians; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / meridians;
      add_point(mesh, {radius * std::sin(theta) * std::cos(phi), radius * std::sin(theta) * std::sin(phi),
                       radius * std::cos(theta)});
    }
  }
  const auto south = add_point(mesh, {0, 0, -radius});
  auto ring_point = [&](int ring, int j) {  // ring 1..rings-1
    return static_cast<std::uint32_t>(1 + (ring - 1) * meridians + (j % meridians));
  };
  for (int j = 0; j < meridians; ++j) add_face(mesh, {north, ring_point(1, j), ring_point(1, j + 1)});
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < meridians; ++j)
      add_face(mesh, {ring_point(i, j), ring_point(i + 1, j), ring_point(i + 1, j + 1), ring_point(i, j + 1)});
  for (int j = 0; j < meridians; ++j) add_face(mesh, {south, ring_point(rings - 1, j + 1), ring_point(rings - 1, j)});
  return mesh;
}

/// Adds a point array computed from each point's coordinates.
template <typename F>
void add_point_scalar(SurfaceMesh& mesh, const std::string& name, F f) {
  FieldArray field{name, FieldAssociation::Point, 1, {}, "Pa"};
  for (std::size_t i = 0; i < mesh.point_count(); ++i)
    field.values.push_back(f(P3{mesh.points_xyz[3 * i], mesh.points_xyz[3 * i + 1], mesh.points_xyz[3 * i + 2]}));
  mesh.fields.push_back(std::move(field));
}

template <typename F>
void add_point_vector(SurfaceMesh& mesh, const std::string& name, F f) {
  FieldArray field{name, FieldAssociation::Point, 3, {}, "Pa"};
  for (std::size_t i = 0; i < mesh.point_count(); ++i) {
    const P3 v = f(P3{mesh.points_xyz[3 * i], mesh.points_xyz[3 * i + 1], mesh.points_xyz[3 * i + 2]});
    field.values.insert(field.values.end(), v.begin(), v.end());
  }
  mesh.fields.push_back(std::move(field));
}

/// Reverses the vertex order of every face (normals point inward).
inline void reverse_faces(SurfaceMesh& mesh) {
  for (std::size_t f = 0; f + 1 < mesh.face_offsets.size(); ++f)
    std::reverse(mesh.face_indices.begin() + mesh.face_offsets[f],
                 mesh.face_indices.begin() + mesh.face_offsets[f + 1]);
}

}  // namespace hydrocoef::test
