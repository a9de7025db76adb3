#include "src/loads/surface_loads.hpp"

#include <algorithm>
#include <atomic>
#include <barrier>
#include <cmath>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "src/core/error.hpp"
#include "src/core/vec3.hpp"
#include "src/loads/surface_input.hpp"
#include "src/loads/surface_topology.hpp"

namespace hydrocoef {
namespace {

using namespace loads_detail;

/// Running sums of one block of faces; blocks are then summed, which keeps
/// the rounding error of millions of faces near that of a few thousand.
struct Sums {
  Vec3 force_p{}, force_v{}, moment_p{}, moment_v{};
  Vec3 n_dA{}, y_cross_n_dA{};  // y = x - x_ref
  double area = 0.0, y_dot_n_dA = 0.0;
  std::size_t degenerate = 0;
  /// Σ over directed edges a→b of h(a) g(b) - h(b) g(a), modulo 2^64: exactly
  /// 0 when every edge is walked once each way (closed, consistently
  /// oriented), a random 64-bit number otherwise (see edge_hash).
  std::uint64_t edge_residue = 0;
  std::size_t triangles = 0, quads = 0, polygons = 0;
  bool invalid = false;  ///< the block has an offset that goes back or a point index out of range

  void add(const Sums& o) {
    invalid = invalid || o.invalid;
    edge_residue += o.edge_residue;
    triangles += o.triangles;
    quads += o.quads;
    polygons += o.polygons;
    force_p += o.force_p;
    force_v += o.force_v;
    moment_p += o.moment_p;
    moment_v += o.moment_v;
    n_dA += o.n_dA;
    y_cross_n_dA += o.y_cross_n_dA;
    area += o.area;
    y_dot_n_dA += o.y_dot_n_dA;
    degenerate += o.degenerate;
  }
};

// ---- triangles with point data, eight at a time ---------------------------
//
// Most surfaces are all triangles with point data. Their faces are gathered
// eight at a time into plain arrays, lane by lane, and the arithmetic of
// Integrator::triangle_point_data then runs on whole arrays, which the
// compiler turns into SIMD instructions (AVX-512, or AVX2 and FMA, where
// the processor has them, chosen when the program starts). Each lane keeps its own sums,
// added in lane order at the end of a block, so results do not depend on
// the instruction set beyond rounding, nor on threads at all.

constexpr int kLanes = 8;

struct TriangleLanes {
  double y[3][3][kLanes];        ///< vertex, axis, lane: x - x_ref [m]
  double p[3][kLanes];           ///< vertex, lane: p - p_ref [Pa]
  double tau[3][3][kLanes];      ///< vertex, axis, lane [Pa]
  std::uint64_t ids[3][kLanes];  ///< vertex, lane: point index
};

struct LaneSums {
  double force_p[3][kLanes]{}, force_v[3][kLanes]{}, moment_p[3][kLanes]{}, moment_v[3][kLanes]{};
  double n_dA[3][kLanes]{}, y_cross_n_dA[3][kLanes]{};
  double area[kLanes]{}, y_dot_n_dA[kLanes]{}, degenerate[kLanes]{};
  std::uint64_t edge_residue[kLanes]{};

  void add_to(Sums& s) const {
    for (int j = 0; j < kLanes; ++j) {
      Sums lane;
      for (int c = 0; c < 3; ++c) {
        lane.force_p[c] = force_p[c][j];
        lane.force_v[c] = force_v[c][j];
        lane.moment_p[c] = moment_p[c][j];
        lane.moment_v[c] = moment_v[c][j];
        lane.n_dA[c] = n_dA[c][j];
        lane.y_cross_n_dA[c] = y_cross_n_dA[c][j];
      }
      lane.area = area[j];
      lane.y_dot_n_dA = y_dot_n_dA[j];
      lane.degenerate = static_cast<std::size_t>(degenerate[j]);
      lane.edge_residue = edge_residue[j];
      s.add(lane);
    }
  }
};

// The formulas of Integrator::triangle_point_data, lane j.
// (__restrict: without it GCC gives up proving the inputs and sums apart.)
template <bool Shear>
[[gnu::always_inline]] inline void triangle_lanes(const TriangleLanes& __restrict in, double shear_sign,
                                                  double degenerate_area, LaneSums& __restrict s) {
  for (int j = 0; j < kLanes; ++j) {
    const double y0x = in.y[0][0][j], y0y = in.y[0][1][j], y0z = in.y[0][2][j];
    const double y1x = in.y[1][0][j], y1y = in.y[1][1][j], y1z = in.y[1][2][j];
    const double y2x = in.y[2][0][j], y2y = in.y[2][1][j], y2z = in.y[2][2][j];
    const double ax = y1x - y0x, ay = y1y - y0y, az = y1z - y0z;
    const double bx = y2x - y0x, by = y2y - y0y, bz = y2z - y0z;
    const double Sx = 0.5 * (ay * bz - az * by), Sy = 0.5 * (az * bx - ax * bz), Sz = 0.5 * (ax * by - ay * bx);
    const double a = std::sqrt(Sx * Sx + Sy * Sy + Sz * Sz);
    const double Yx = y0x + y1x + y2x, Yy = y0y + y1y + y2y, Yz = y0z + y1z + y2z;
    const double p0 = in.p[0][j], p1 = in.p[1][j], p2 = in.p[2][j];
    const double P = p0 + p1 + p2;
    const double mx = (1.0 / 12.0) * (p0 * y0x + p1 * y1x + p2 * y2x + P * Yx);
    const double my = (1.0 / 12.0) * (p0 * y0y + p1 * y1y + p2 * y2y + P * Yy);
    const double mz = (1.0 / 12.0) * (p0 * y0z + p1 * y1z + p2 * y2z + P * Yz);
    const double f = -P / 3.0;
    s.force_p[0][j] += f * Sx;
    s.force_p[1][j] += f * Sy;
    s.force_p[2][j] += f * Sz;
    s.moment_p[0][j] += -(my * Sz - mz * Sy);
    s.moment_p[1][j] += -(mz * Sx - mx * Sz);
    s.moment_p[2][j] += -(mx * Sy - my * Sx);
    const double cx = (1.0 / 3.0) * Yx, cy = (1.0 / 3.0) * Yy, cz = (1.0 / 3.0) * Yz;
    s.area[j] += a;
    s.n_dA[0][j] += Sx;
    s.n_dA[1][j] += Sy;
    s.n_dA[2][j] += Sz;
    s.y_cross_n_dA[0][j] += cy * Sz - cz * Sy;
    s.y_cross_n_dA[1][j] += cz * Sx - cx * Sz;
    s.y_cross_n_dA[2][j] += cx * Sy - cy * Sx;
    s.y_dot_n_dA[j] += cx * Sx + cy * Sy + cz * Sz;
    s.degenerate[j] += a <= degenerate_area ? 1.0 : 0.0;
    // The triangle's share of the edge residue (see edge_residue()).
    const std::uint64_t g0 = in.ids[0][j], g1 = in.ids[1][j], g2 = in.ids[2][j];
    const std::uint64_t h0 = mix64(g0), h1 = mix64(g1), h2 = mix64(g2);
    // (h0 g1 - h1 g0) + (h1 g2 - h2 g1) + (h2 g0 - h0 g2), in three products.
    s.edge_residue[j] += h0 * (g1 - g2) + h1 * (g2 - g0) + h2 * (g0 - g1);
    if constexpr (Shear) {
      const double t0x = in.tau[0][0][j], t0y = in.tau[0][1][j], t0z = in.tau[0][2][j];
      const double t1x = in.tau[1][0][j], t1y = in.tau[1][1][j], t1z = in.tau[1][2][j];
      const double t2x = in.tau[2][0][j], t2y = in.tau[2][1][j], t2z = in.tau[2][2][j];
      const double Tx = t0x + t1x + t2x, Ty = t0y + t1y + t2y, Tz = t0z + t1z + t2z;
      const double fv = shear_sign * a / 3.0;
      s.force_v[0][j] += fv * Tx;
      s.force_v[1][j] += fv * Ty;
      s.force_v[2][j] += fv * Tz;
      const double mv = shear_sign * a / 12.0;
      s.moment_v[0][j] +=
          mv * ((y0y * t0z - y0z * t0y) + (y1y * t1z - y1z * t1y) + (y2y * t2z - y2z * t2y) + (Yy * Tz - Yz * Ty));
      s.moment_v[1][j] +=
          mv * ((y0z * t0x - y0x * t0z) + (y1z * t1x - y1x * t1z) + (y2z * t2x - y2x * t2z) + (Yz * Tx - Yx * Tz));
      s.moment_v[2][j] +=
          mv * ((y0x * t0y - y0y * t0x) + (y1x * t1y - y1y * t1x) + (y2x * t2y - y2y * t2x) + (Yx * Ty - Yy * Tx));
    }
  }
}

/// Where a group's values come from: the point arrays, read through the
/// faces' point indices.
struct TriangleSources {
  const double* xyz;
  const double* pressure;
  const double* tau[3];  ///< null without shear
  std::size_t tau_stride;
  double x_ref[3];
  double p_ref;
};

/// `groups` groups of kLanes triangles from `ids` (3 indices a triangle):
/// gathered lane by lane (inside the clones, so that the gathers are
/// compiled for the same processor as the arithmetic), integrated, and their
/// points marked in `used` when there is one.
template <bool Shear>
[[gnu::always_inline]] inline void triangle_groups(const std::uint32_t* __restrict ids, std::size_t groups,
                                                   const TriangleSources& src, double shear_sign,
                                                   double degenerate_area, LaneSums& __restrict s, PointsUsed* used) {
  for (std::size_t g = 0; g < groups; ++g, ids += 3 * kLanes) {
    TriangleLanes in;
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < kLanes; ++j) {
        const std::size_t i = ids[3 * j + k];
        in.y[k][0][j] = src.xyz[3 * i] - src.x_ref[0];
        in.y[k][1][j] = src.xyz[3 * i + 1] - src.x_ref[1];
        in.y[k][2][j] = src.xyz[3 * i + 2] - src.x_ref[2];
        in.p[k][j] = src.pressure[i] - src.p_ref;
        in.ids[k][j] = i;
        if constexpr (Shear)
          for (int c = 0; c < 3; ++c) in.tau[k][c][j] = src.tau[c][i * src.tau_stride];
      }
    if (used)
      for (int c = 0; c < 3 * kLanes; ++c) used->mark(ids[c]);
    triangle_lanes<Shear>(in, shear_sign, degenerate_area, s);
  }
}

// AVX-512 where the processor has it (eight lanes in one register, and
// 64-bit multiplies for the edge residue), else AVX2 and FMA.
[[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]] void triangle_groups_with_shear(
    const std::uint32_t* ids, std::size_t groups, const TriangleSources& src, double shear_sign, double degenerate_area,
    LaneSums& s, PointsUsed* used) {
  triangle_groups<true>(ids, groups, src, shear_sign, degenerate_area, s, used);
}

[[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]] void triangle_groups_pressure_only(
    const std::uint32_t* ids, std::size_t groups, const TriangleSources& src, double degenerate_area, LaneSums& s,
    PointsUsed* used) {
  triangle_groups<false>(ids, groups, src, 1.0, degenerate_area, s, used);
}

/// Everything a face contributes, computed by one of the rules below.
struct Integrator {
  const SurfaceMesh& mesh;
  const double* xyz;
  Vec3 x_ref;
  FieldView pressure;  // may be absent (geometry only)
  FieldView shear;     // may be absent
  double p_ref = 0.0;
  double shear_sign = 1.0;
  double degenerate_area = 0.0;

  Vec3 point(std::uint32_t i) const {
    const double* p = xyz + 3 * static_cast<std::size_t>(i);
    return {p[0] - x_ref[0], p[1] - x_ref[1], p[2] - x_ref[2]};
  }

  // Triangle with vertex values, exact for linear fields:
  //   ∫ f dA = |S| (f0+f1+f2)/3,  ∫ f y dA = |S|/12 (Σ f_i y_i + F Y).
  [[gnu::always_inline]] void triangle_point_data(const Vec3 (&y)[3], const double (&p)[3], const Vec3* tau,
                                                  Sums& s) const {
    const Vec3 S = 0.5 * cross(y[1] - y[0], y[2] - y[0]);
    const double a = norm(S);
    const Vec3 Y = y[0] + y[1] + y[2];
    const double P = p[0] + p[1] + p[2];
    const Vec3 first_moment = (1.0 / 12.0) * (p[0] * y[0] + p[1] * y[1] + p[2] * y[2] + P * Y);  // ∫p y dA / |S|
    s.force_p += (-P / 3.0) * S;
    s.moment_p += -1.0 * cross(first_moment, S);
    add_geometry(S, a, (1.0 / 3.0) * Y, s);
    if (tau) {
      const Vec3 T = tau[0] + tau[1] + tau[2];
      s.force_v += (shear_sign * a / 3.0) * T;
      s.moment_v +=
          (shear_sign * a / 12.0) * (cross(y[0], tau[0]) + cross(y[1], tau[1]) + cross(y[2], tau[2]) + cross(Y, T));
    }
  }

  [[gnu::always_inline]] void add_geometry(const Vec3& S, double a, const Vec3& centroid, Sums& s) const {
    s.area += a;
    s.n_dA += S;
    s.y_cross_n_dA += cross(centroid, S);
    s.y_dot_n_dA += dot(centroid, S);
    if (a <= degenerate_area) ++s.degenerate;
  }

  // Quad with vertex values on its bilinear patch, 2×2 Gauss: exact for
  // bilinear fields (the integrands are at most cubic in each direction).
  void quad_point_data(const Vec3 (&y)[4], const double (&p)[4], const Vec3* tau, Sums& s) const {
    static constexpr double g = 0.57735026918962576451;  // 1/sqrt(3)
    static constexpr double xi_of[4] = {-g, g, g, -g};
    static constexpr double eta_of[4] = {-g, -g, g, g};
    Vec3 S_total{}, yS_total{};
    double ydotS = 0.0, area = 0.0;
    for (int q = 0; q < 4; ++q) {
      const double xi = xi_of[q], eta = eta_of[q];
      // Corner order 0:(-1,-1) 1:(1,-1) 2:(1,1) 3:(-1,1); weights of each Gauss point are 1.
      const double N[4] = {0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta), 0.25 * (1 + xi) * (1 + eta),
                           0.25 * (1 - xi) * (1 + eta)};
      const Vec3 d_xi = (0.25 * (1 - eta)) * (y[1] - y[0]) + (0.25 * (1 + eta)) * (y[2] - y[3]);
      const Vec3 d_eta = (0.25 * (1 - xi)) * (y[3] - y[0]) + (0.25 * (1 + xi)) * (y[2] - y[1]);
      const Vec3 J = cross(d_xi, d_eta);
      const Vec3 yq = N[0] * y[0] + N[1] * y[1] + N[2] * y[2] + N[3] * y[3];
      const double pq = N[0] * p[0] + N[1] * p[1] + N[2] * p[2] + N[3] * p[3];
      const double j = norm(J);
      s.force_p += (-pq) * J;
      s.moment_p += (-pq) * cross(yq, J);
      S_total += J;
      yS_total += cross(yq, J);
      ydotS += dot(yq, J);
      area += j;
      if (tau) {
        const Vec3 tq = N[0] * tau[0] + N[1] * tau[1] + N[2] * tau[2] + N[3] * tau[3];
        s.force_v += (shear_sign * j) * tq;
        s.moment_v += (shear_sign * j) * cross(yq, tq);
      }
    }
    s.area += area;
    s.n_dA += S_total;
    s.y_cross_n_dA += yS_total;
    s.y_dot_n_dA += ydotS;
    if (area <= degenerate_area) ++s.degenerate;
  }

  // Finite-volume face: vector area S_f and area-weighted centroid C_f from
  // the triangles around the vertex mean; constant values applied at C_f.
  void face_geometry(std::size_t begin, std::size_t end, Vec3& S, Vec3& C) const {
    const std::size_t k = end - begin;
    Vec3 mean{};
    for (std::size_t i = begin; i < end; ++i) mean += point(mesh.face_indices[i]);
    mean = (1.0 / static_cast<double>(k)) * mean;
    S = {};
    Vec3 weighted{};
    double total = 0.0;
    for (std::size_t i = 0; i < k; ++i) {
      const Vec3 a = point(mesh.face_indices[begin + i]);
      const Vec3 b = point(mesh.face_indices[begin + (i + 1) % k]);
      const Vec3 St = 0.5 * cross(a - mean, b - mean);
      const double w = norm(St);
      S += St;
      weighted += w * ((1.0 / 3.0) * (a + b + mean));
      total += w;
    }
    C = total > 0.0 ? (1.0 / total) * weighted : mean;
  }

  void face_data(std::size_t f, std::size_t begin, std::size_t end, Sums& s) const {
    Vec3 S, C;
    if (end - begin == 3) {
      const Vec3 a = point(mesh.face_indices[begin]), b = point(mesh.face_indices[begin + 1]),
                 c = point(mesh.face_indices[begin + 2]);
      S = 0.5 * cross(b - a, c - a);
      C = (1.0 / 3.0) * (a + b + c);
    } else {
      face_geometry(begin, end, S, C);
    }
    add_geometry(S, norm(S), C, s);
    if (pressure.present()) {
      const double p = pressure_at_face(f, begin, end);
      const Vec3 F = (-p) * S;
      s.force_p += F;
      s.moment_p += cross(C, F);
    }
    if (shear.present()) {
      const Vec3 F = (shear_sign * norm(S)) * shear_at_face(f, begin, end);
      s.force_v += F;
      s.moment_v += cross(C, F);
    }
  }

  double pressure_at_face(std::size_t f, std::size_t begin, std::size_t end) const {
    if (!pressure.per_point) return pressure.scalar(f) - p_ref;
    double sum = 0.0;
    for (std::size_t i = begin; i < end; ++i) sum += pressure.scalar(mesh.face_indices[i]);
    return sum / static_cast<double>(end - begin) - p_ref;
  }
  Vec3 shear_at_face(std::size_t f, std::size_t begin, std::size_t end) const {
    if (!shear.per_point) return shear.vector(f);
    Vec3 sum{};
    for (std::size_t i = begin; i < end; ++i) sum += shear.vector(mesh.face_indices[i]);
    return (1.0 / static_cast<double>(end - begin)) * sum;
  }

  void face(std::size_t f, Sums& s, PointsUsed* used) const {
    const std::size_t begin = mesh.face_offsets[f], end = mesh.face_offsets[f + 1];
    const std::size_t k = end - begin;
    if (used)
      for (std::size_t i = begin; i < end; ++i) used->mark(mesh.face_indices[i]);
    if (k < 3) {
      ++s.degenerate;
      if (k > 0) s.edge_residue += edge_residue(mesh.face_indices.data() + begin, k);
      return;
    }
    s.edge_residue += edge_residue(mesh.face_indices.data() + begin, k);
    if (k == 3)
      ++s.triangles;
    else if (k == 4)
      ++s.quads;
    else
      ++s.polygons;
    const bool point_pressure = pressure.present() && pressure.per_point;
    if (!point_pressure) {
      // Face-constant pressure (or geometry only): finite-volume face rule;
      // shear given per point is averaged over the face's vertices.
      face_data(f, begin, end, s);
      return;
    }
    const bool point_shear = shear.present() && shear.per_point;
    const Vec3 face_tau = shear.present() && !point_shear ? shear.vector(f) : Vec3{};
    if (k == 3) {
      const Vec3 y[3] = {point(mesh.face_indices[begin]), point(mesh.face_indices[begin + 1]),
                         point(mesh.face_indices[begin + 2])};
      const double p[3] = {pressure.scalar(mesh.face_indices[begin]) - p_ref,
                           pressure.scalar(mesh.face_indices[begin + 1]) - p_ref,
                           pressure.scalar(mesh.face_indices[begin + 2]) - p_ref};
      Vec3 tau[3];
      for (int i = 0; i < 3; ++i) tau[i] = point_shear ? shear.vector(mesh.face_indices[begin + i]) : face_tau;
      triangle_point_data(y, p, shear.present() ? tau : nullptr, s);
      return;
    }
    if (k == 4) {
      Vec3 y[4];
      double p[4];
      Vec3 tau[4];
      for (int i = 0; i < 4; ++i) {
        const std::uint32_t v = mesh.face_indices[begin + i];
        y[i] = point(v);
        p[i] = pressure.scalar(v) - p_ref;
        tau[i] = point_shear ? shear.vector(v) : face_tau;
      }
      quad_point_data(y, p, shear.present() ? tau : nullptr, s);
      return;
    }
    // Polygon: triangles around the vertex mean, where the value is the
    // vertex mean (the linear interpolant's value there for a planar polygon).
    Vec3 yc{};
    double pc = 0.0;
    Vec3 tc{};
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint32_t v = mesh.face_indices[i];
      yc += point(v);
      pc += pressure.scalar(v) - p_ref;
      tc += point_shear ? shear.vector(v) : face_tau;
    }
    const double inv = 1.0 / static_cast<double>(k);
    yc = inv * yc;
    pc *= inv;
    tc = inv * tc;
    // Degeneracy is judged on the whole polygon, not on its pieces.
    Sums parts;
    for (std::size_t i = 0; i < k; ++i) {
      const std::uint32_t a = mesh.face_indices[begin + i], b = mesh.face_indices[begin + (i + 1) % k];
      const Vec3 y[3] = {yc, point(a), point(b)};
      const double p[3] = {pc, pressure.scalar(a) - p_ref, pressure.scalar(b) - p_ref};
      const Vec3 tau[3] = {tc, point_shear ? shear.vector(a) : face_tau, point_shear ? shear.vector(b) : face_tau};
      triangle_point_data(y, p, shear.present() ? tau : nullptr, parts);
    }
    parts.degenerate = parts.area <= degenerate_area ? 1 : 0;
    s.add(parts);
  }

  /// Faces [f, f + groups kLanes), all triangles with point pressure (and
  /// point shear when there is shear), through the lane kernel.
  void triangle_groups(std::size_t f, std::size_t groups, LaneSums& lanes, Sums& s, PointsUsed* used) const {
    const std::uint32_t* ids = mesh.face_indices.data() + mesh.face_offsets[f];
    TriangleSources src{xyz,          pressure.component[0],          {nullptr, nullptr, nullptr},
                        shear.stride, {x_ref[0], x_ref[1], x_ref[2]}, p_ref};
    if (shear.present()) {
      for (int c = 0; c < 3; ++c) src.tau[c] = shear.component[c];
      triangle_groups_with_shear(ids, groups, src, shear_sign, degenerate_area, lanes, used);
    } else {
      triangle_groups_pressure_only(ids, groups, src, degenerate_area, lanes, used);
    }
    s.triangles += groups * kLanes;
  }

  static constexpr std::size_t kBlock = 4096;

  /// Checks the block's faces can be read (offsets never go back, point
  /// indices in range) and integrates them. Sums are kept in a local and
  /// stored once: the block results of neighbouring blocks share cache
  /// lines, and updating them in place from two threads made every face
  /// bounce a line between the cores.
  void run_block(std::size_t block, Sums& out, PointsUsed* used) const {
    const std::size_t start = block * kBlock;
    const std::size_t stop = std::min(mesh.face_count(), start + kBlock);
    const std::uint32_t* offsets = mesh.face_offsets.data();
    bool forward = true, triangles_only = true;
    for (std::size_t f = start; f < stop; ++f) {
      forward &= offsets[f + 1] >= offsets[f];
      triangles_only &= offsets[f + 1] - offsets[f] == 3u;
    }
    Sums local;
    if (!forward || offsets[stop] > mesh.face_indices.size()) {
      local.invalid = true;
      out = local;
      return;
    }
    std::uint32_t largest = 0;
    for (std::size_t i = offsets[start]; i < offsets[stop]; ++i) largest = std::max(largest, mesh.face_indices[i]);
    if (offsets[stop] > offsets[start] && largest >= mesh.point_count()) {
      local.invalid = true;
      out = local;
      return;
    }
    std::size_t f = start;
    const bool lanes_apply =
        triangles_only && pressure.present() && pressure.per_point && (!shear.present() || shear.per_point);
    if (lanes_apply) {
      LaneSums lanes;
      const std::size_t groups = (stop - f) / kLanes;
      triangle_groups(f, groups, lanes, local, used);
      f += groups * kLanes;
      lanes.add_to(local);
    }
    for (; f < stop; ++f) face(f, local, used);
    out = local;
  }
};

/// What one thread finds in its share of the points before integrating:
/// their bounding box, and whether every coordinate is finite.
struct PointScan {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  bool coordinates_finite = true;

  void add(const PointScan& o) {
    for (std::size_t c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], o.lo[c]);
      hi[c] = std::max(hi[c], o.hi[c]);
    }
    coordinates_finite = coordinates_finite && o.coordinates_finite;
  }
};

/// Part `part` of `parts` of the points. (x - x is 0 exactly when x is
/// finite: a test the compiler vectorizes.)
PointScan scan_points(const SurfaceMesh& mesh, std::size_t part, std::size_t parts) {
  PointScan scan;
  const std::size_t n = mesh.point_count();
  const double* x = mesh.points_xyz.data();
  bool finite = true;
  for (std::size_t i = n * part / parts; i < n * (part + 1) / parts; ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const double v = x[3 * i + c];
      finite &= v - v == 0.0;
      scan.lo[c] = std::min(scan.lo[c], v);
      scan.hi[c] = std::max(scan.hi[c], v);
    }
  scan.coordinates_finite = finite;
  return scan;
}

/// Runs the integration on the calling thread and, for large meshes, on a
/// second one. Each first scans its share of the points; they meet, since
/// the degenerate-face threshold needs the whole bounding box;
/// then both take blocks of faces. Block results are summed in block order,
/// so the totals do not depend on which thread ran what. With mark_points,
/// each thread also marks the points its faces use, in a set of its own, and
/// `used` receives their union.
Sums integrate_blocks(Integrator& integrator, PointScan& scanned, bool mark_points, std::optional<PointsUsed>& used) {
  const SurfaceMesh& mesh = integrator.mesh;
  const std::size_t faces = mesh.face_count();
  const std::size_t blocks = (faces + Integrator::kBlock - 1) / Integrator::kBlock;
  const std::size_t threads = faces >= 50000 && std::thread::hardware_concurrency() > 1 ? 2 : 1;
  std::vector<Sums> block_sums(blocks);
  PointScan parts[2];
  auto meet = [&]() noexcept {
    scanned = parts[0];
    if (threads == 2) scanned.add(parts[1]);
    const double diagonal = mesh.point_count() > 0 && scanned.coordinates_finite ? norm(scanned.hi - scanned.lo) : 0.0;
    integrator.degenerate_area = 1e-14 * diagonal * diagonal;
  };
  std::barrier<decltype(meet)> sync(static_cast<std::ptrdiff_t>(threads), meet);
  std::atomic<std::size_t> next{0};
  std::optional<PointsUsed> marked[2];
  auto work = [&](std::size_t thread) {
    if (mark_points) marked[thread].emplace(mesh.point_count());
    PointsUsed* mine = marked[thread] ? &*marked[thread] : nullptr;
    parts[thread] = scan_points(mesh, thread, threads);
    sync.arrive_and_wait();
    for (std::size_t b = next++; b < blocks; b = next++) integrator.run_block(b, block_sums[b], mine);
  };
  if (threads == 2) {
    std::thread helper(work, 1);
    work(0);
    helper.join();
  } else {
    work(0);
  }
  if (mark_points) {
    used = std::move(marked[0]);
    if (threads == 2) used->merge(*marked[1]);
  }
  Sums total;
  for (const auto& block : block_sums) total.add(block);
  return total;
}

/// Whether every sum is finite.
bool all_finite(const Sums& s) {
  bool finite = std::isfinite(s.area) && std::isfinite(s.y_dot_n_dA);
  for (const Vec3* v : {&s.force_p, &s.force_v, &s.moment_p, &s.moment_v, &s.n_dA, &s.y_cross_n_dA})
    for (const double x : *v) finite = finite && std::isfinite(x);
  return finite;
}

SurfaceLoads integrate(const SurfaceMesh& mesh, const SurfaceLoadOptions& options, bool with_fields) {
  check_mesh_shape(mesh);
  Integrator integrator{mesh, mesh.points_xyz.data(), options.reference_point, {}, {}, 0.0, 1.0, 0.0};
  if (with_fields) {
    integrator.pressure = pressure_view(mesh, options);
    integrator.shear = shear_view(mesh, options);
  }
  integrator.p_ref = options.reference_pressure;
  integrator.shear_sign = options.shear_convention == ShearConvention::OnWall ? 1.0 : -1.0;

  SurfaceLoads loads;
  PointScan scanned;
  // The points used are marked only where the shortcut below could be taken.
  std::optional<PointsUsed> used;
  const bool euler_two = euler_characteristic_two(mesh);
  const Sums sums = integrate_blocks(integrator, scanned, euler_two, used);
  if (sums.invalid) throw_unreadable_faces(mesh);
  if (!scanned.coordinates_finite) throw_not_finite_point(mesh);
  // A NaN or Inf in a value that a face uses makes its sums NaN or Inf (times
  // a zero area too), so the arrays are searched only when a sum is.
  if (!all_finite(sums)) {
    for (const FieldView* view : {&integrator.pressure, &integrator.shear})
      for (const FieldArray* array : view->arrays)
        if (array != nullptr &&
            !std::all_of(array->values.begin(), array->values.end(), [](double v) { return std::isfinite(v); }))
          throw_not_finite(*array, view->role);
    throw InputError(
        "the integrals overflow (coordinates or values near the largest double); expected a surface "
        "of finite area and forces");
  }
  // Topology. A zero edge residue says that every edge is walked as often one
  // way as the other (only a mesh built to cancel the 64-bit hash sums could
  // fake it); that alone would take every face listed twice (each edge walked
  // twice each way, twice the force) for a closed surface. With every point
  // used, the Euler characteristic V - E + F (E = half the face corners) of a
  // closed, consistently oriented surface of genus 0 is 2, and any set of
  // faces listed twice lowers it (a closed set of faces has more edges than
  // faces). So the shortcut is taken only for residue 0, chi = 2 and no unused
  // point (marked by the kernel as it goes, one bit a point); anything else is
  // counted exactly, edge by edge, on both threads. What the shortcut cannot
  // see: closed pieces that share an edge and add up to chi = 2 (two spheres
  // on one edge: that edge has four faces); telling those apart needs every
  // edge's identity, which is the exact count's cost.
  if (!(sums.edge_residue == 0 && euler_two && used->all())) {
    const EdgeCounts edges = count_edges(mesh);
    loads.geometry.boundary_edges = edges.boundary;
    loads.geometry.nonmanifold_edges = edges.nonmanifold;
    loads.geometry.inconsistent_edges = edges.inconsistent;
  }
  loads.geometry.closed = loads.geometry.boundary_edges == 0 && loads.geometry.nonmanifold_edges == 0;
  loads.reference_point = options.reference_point;
  loads.force_pressure = sums.force_p;
  loads.force_viscous = sums.force_v;
  loads.moment_pressure = sums.moment_p;
  loads.moment_viscous = sums.moment_v;

  SurfaceGeometry& geometry = loads.geometry;
  geometry.faces = mesh.face_count();
  geometry.triangles = sums.triangles;
  geometry.quads = sums.quads;
  geometry.polygons = sums.polygons;
  geometry.degenerate_faces = sums.degenerate;
  geometry.area = sums.area;
  const Vec3& x_ref = options.reference_point;
  geometry.integral_n_dA = sums.n_dA;
  geometry.integral_x_cross_n_dA = sums.y_cross_n_dA + cross(x_ref, sums.n_dA);
  geometry.signed_volume = (sums.y_dot_n_dA + dot(x_ref, sums.n_dA)) / 3.0;

  bool flip = options.normals == NormalPolicy::Flip;
  if (options.normals == NormalPolicy::Auto) {
    if (geometry.inconsistent_edges > 0)
      throw InputError("face orientation is inconsistent: " + std::to_string(geometry.inconsistent_edges) +
                       " interior edges are walked the same way by both of their faces, so some normals point "
                       "in and some out; expected a consistently oriented surface (or give --normals as-given)");
    if (geometry.closed) {
      flip = geometry.signed_volume < 0.0;
    } else {
      // Open surface: the cone volume about the mean of its points.
      Vec3 centre{};
      for (std::size_t i = 0; i < mesh.point_count(); ++i)
        centre += Vec3{mesh.points_xyz[3 * i], mesh.points_xyz[3 * i + 1], mesh.points_xyz[3 * i + 2]};
      centre = (1.0 / static_cast<double>(std::max<std::size_t>(1, mesh.point_count()))) * centre;
      const double cone = sums.y_dot_n_dA - dot(centre - x_ref, sums.n_dA);
      flip = cone < 0.0;
      geometry.warnings.push_back("open surface (" + std::to_string(geometry.boundary_edges) +
                                  " boundary edges): outward normals judged from the cone volume about its centre");
    }
  }
  if (flip) {
    loads.force_pressure = -1.0 * loads.force_pressure;
    loads.moment_pressure = -1.0 * loads.moment_pressure;
    geometry.integral_n_dA = -1.0 * geometry.integral_n_dA;
    geometry.integral_x_cross_n_dA = -1.0 * geometry.integral_x_cross_n_dA;
    geometry.signed_volume = -geometry.signed_volume;
    geometry.normals_flipped = true;
    geometry.warnings.push_back("face normals pointed into the body and were reversed");
  }
  if (geometry.inconsistent_edges > 0 && options.normals != NormalPolicy::Auto)
    geometry.warnings.push_back(std::to_string(geometry.inconsistent_edges) + " edges with inconsistent orientation");
  if (geometry.degenerate_faces > 0)
    geometry.warnings.push_back(std::to_string(geometry.degenerate_faces) + " degenerate faces (zero area)");
  if (geometry.nonmanifold_edges > 0)
    geometry.warnings.push_back(std::to_string(geometry.nonmanifold_edges) +
                                " non-manifold edges (shared by more than two faces): not a closed surface; a face "
                                "listed twice counts twice in the forces");
  return loads;
}

}  // namespace

Vec3 SurfaceLoads::force() const { return force_pressure + force_viscous; }
Vec3 SurfaceLoads::moment() const { return moment_pressure + moment_viscous; }

SurfaceLoads integrate_surface_loads(const SurfaceMesh& mesh, const SurfaceLoadOptions& options) {
  if (options.pressure_field.empty()) throw InputError("no pressure array named; expected e.g. --pressure Pressure");
  return integrate(mesh, options, true);
}

SurfaceGeometry check_surface_geometry(const SurfaceMesh& mesh) {
  SurfaceLoadOptions options;
  options.normals = NormalPolicy::AsGiven;
  return integrate(mesh, options, false).geometry;
}

SurfaceLoads shift_loads(const SurfaceLoads& loads, double old_reference_pressure, double new_reference_pressure,
                         const Vec3& new_reference_point) {
  SurfaceLoads out = loads;
  const double delta = new_reference_pressure - old_reference_pressure;
  const Vec3& n_dA = loads.geometry.integral_n_dA;
  // ∫ (x - x_ref) × n dA about the old point.
  const Vec3 y_cross_n = loads.geometry.integral_x_cross_n_dA - cross(loads.reference_point, n_dA);
  out.force_pressure = loads.force_pressure + delta * n_dA;
  const Vec3 moment_pressure_old_point = loads.moment_pressure + delta * y_cross_n;
  // M about x' = M about x - (x' - x) × F.
  const Vec3 shift = new_reference_point - loads.reference_point;
  out.moment_pressure = moment_pressure_old_point - cross(shift, out.force_pressure);
  out.moment_viscous = loads.moment_viscous - cross(shift, loads.force_viscous);
  out.reference_point = new_reference_point;
  return out;
}

}  // namespace hydrocoef
