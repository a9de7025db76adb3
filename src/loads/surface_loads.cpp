#include "src/loads/surface_loads.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "src/core/error.hpp"
#include "src/core/huge_pages.hpp"

namespace hydrocoef {
namespace {

// ---- small vector helpers (Vec3 is a plain array so the hot loop stays inline)
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline Vec3& operator+=(Vec3& a, const Vec3& b) {
  a[0] += b[0];
  a[1] += b[1];
  a[2] += b[2];
  return a;
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

/// A scalar or vector array seen through stride and offsets, so that a
/// 3-component array and three scalar arrays are read the same way.
struct FieldView {
  const double* component[3] = {nullptr, nullptr, nullptr};
  std::size_t stride = 1;
  bool per_point = true;
  bool present() const { return component[0] != nullptr; }
  double scalar(std::size_t i) const { return component[0][i * stride]; }
  Vec3 vector(std::size_t i) const {
    return {component[0][i * stride], component[1][i * stride], component[2][i * stride]};
  }
};

std::string available_arrays(const SurfaceMesh& mesh) {
  std::string out;
  for (const auto& field : mesh.fields) {
    if (!out.empty()) out += ", ";
    out += "'" + field.name + "'";
    if (field.components == 3) out += " (vector)";
  }
  return out.empty() ? "none" : out;
}

const FieldArray& find_array(const SurfaceMesh& mesh, const std::string& name, int components, const char* role) {
  const FieldArray* field = mesh.find_field(name);
  if (!field)
    throw InputError(std::string(role) + " array '" + name + "' is not in the file; arrays there: " +
                     available_arrays(mesh));
  if (field->components != components)
    throw InputError(std::string(role) + " array '" + name + "' has " + std::to_string(field->components) +
                     " components, expected " + std::to_string(components));
  const std::size_t expected =
      field->association == FieldAssociation::Point ? mesh.point_count() : mesh.face_count();
  if (field->size() != expected)
    throw InputError(std::string(role) + " array '" + name + "' has " + std::to_string(field->size()) +
                     " values, expected " + std::to_string(expected) + " (one per " +
                     (field->association == FieldAssociation::Point ? "point" : "face") + ")");
  for (std::size_t i = 0; i < field->values.size(); ++i)
    if (!std::isfinite(field->values[i]))
      throw InputError(std::string(role) + " array '" + name + "' holds " +
                       (std::isnan(field->values[i]) ? "NaN" : "Inf") + " at " +
                       (field->association == FieldAssociation::Point ? "point " : "face ") +
                       std::to_string(i / static_cast<std::size_t>(components)) + "; expected finite values");
  return *field;
}

FieldView pressure_view(const SurfaceMesh& mesh, const SurfaceLoadOptions& options) {
  const FieldArray& field = find_array(mesh, options.pressure_field, 1, "pressure");
  FieldView view;
  view.component[0] = field.values.data();
  view.per_point = field.association == FieldAssociation::Point;
  return view;
}

FieldView shear_view(const SurfaceMesh& mesh, const SurfaceLoadOptions& options) {
  FieldView view;
  if (options.shear_fields.empty()) return view;
  if (options.shear_fields.size() == 1) {
    const FieldArray& field = find_array(mesh, options.shear_fields[0], 3, "wall shear");
    for (int c = 0; c < 3; ++c) view.component[c] = field.values.data() + c;
    view.stride = 3;
    view.per_point = field.association == FieldAssociation::Point;
    return view;
  }
  if (options.shear_fields.size() != 3)
    throw InputError("wall shear: expected one vector array or three scalar arrays x,y,z, got " +
                     std::to_string(options.shear_fields.size()) + " names");
  for (int c = 0; c < 3; ++c) {
    const FieldArray& field = find_array(mesh, options.shear_fields[static_cast<std::size_t>(c)], 1, "wall shear");
    view.component[c] = field.values.data();
    const bool per_point = field.association == FieldAssociation::Point;
    if (c > 0 && per_point != view.per_point)
      throw InputError("wall shear arrays mix point and face data; expected all three alike");
    view.per_point = per_point;
  }
  return view;
}

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

  void add(const Sums& o) {
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

/// A 64-bit mix of a vertex index (splitmix64's finalizer).
inline std::uint64_t mix64(std::uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// The face's share of Sums::edge_residue, with h = mix64 and g the index
/// itself: h(a) b - h(b) a is antisymmetric in (a, b), which is all the
/// cancellation needs, at one hash per vertex.
inline std::uint64_t edge_residue(const std::uint32_t* indices, std::size_t k) {
  std::uint64_t residue = 0;
  const std::uint64_t g_first = indices[0], h_first = mix64(g_first);
  std::uint64_t h_prev = h_first, g_prev = g_first;
  for (std::size_t i = 1; i <= k; ++i) {
    const std::uint64_t g = i < k ? indices[i] : g_first;
    const std::uint64_t h = i < k ? mix64(g) : h_first;
    residue += h_prev * g - h * g_prev;
    h_prev = h;
    g_prev = g;
  }
  return residue;
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
  [[gnu::always_inline]] void triangle_point_data(const Vec3 (&y)[3], const double (&p)[3], const Vec3* tau, Sums& s) const {
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
      s.moment_v += (shear_sign * a / 12.0) *
                    (cross(y[0], tau[0]) + cross(y[1], tau[1]) + cross(y[2], tau[2]) + cross(Y, T));
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

  void face(std::size_t f, Sums& s) const {
    const std::size_t begin = mesh.face_offsets[f], end = mesh.face_offsets[f + 1];
    const std::size_t k = end - begin;
    if (k < 3) {
      ++s.degenerate;
      if (k > 0) s.edge_residue += edge_residue(mesh.face_indices.data() + begin, k);
      return;
    }
    s.edge_residue += edge_residue(mesh.face_indices.data() + begin, k);
    if (k == 3) ++s.triangles;
    else if (k == 4) ++s.quads;
    else ++s.polygons;
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

  static constexpr std::size_t kBlock = 4096;

  // Sums in a local and stored once: the block results of neighbouring
  // blocks share cache lines, and updating them in place from two threads
  // made every face bounce a line between the cores.
  void run_block(std::size_t block, Sums& out) const {
    const std::size_t start = block * kBlock;
    const std::size_t stop = std::min(mesh.face_count(), start + kBlock);
    Sums local;
    for (std::size_t f = start; f < stop; ++f) face(f, local);
    out = local;
  }
};

/// Runs the integration blocks on the calling thread and, for large meshes,
/// on a second thread; each thread first does its share of the side work
/// (the edge topology, split by vertex range). Block results are summed in
/// block order, so the totals do not depend on which thread ran what.
template <typename SideWork>
Sums integrate_blocks(const Integrator& integrator, SideWork main_side_work, SideWork helper_side_work) {
  const std::size_t faces = integrator.mesh.face_count();
  const std::size_t blocks = (faces + Integrator::kBlock - 1) / Integrator::kBlock;
  std::vector<Sums> block_sums(blocks);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t b = next++; b < blocks; b = next++) integrator.run_block(b, block_sums[b]);
  };
  if (faces >= 50000 && std::thread::hardware_concurrency() > 1) {
    std::exception_ptr side_error;
    std::thread helper([&] {
      try {
        helper_side_work();
      } catch (...) {
        side_error = std::current_exception();
      }
      worker();
    });
    try {
      main_side_work();
    } catch (...) {
      worker();  // let the helper finish before the error leaves
      helper.join();
      throw;
    }
    worker();
    helper.join();
    if (side_error) std::rethrow_exception(side_error);
  } else {
    main_side_work();
    helper_side_work();
    worker();
  }
  Sums total;
  for (const auto& block : block_sums) total.add(block);
  return total;
}

void check_mesh_indices(const SurfaceMesh& mesh) {
  if (mesh.face_count() == 0) throw InputError("the surface has no faces; expected a body surface of polygons");
  if (mesh.points_xyz.size() % 3 != 0) throw InputError("point coordinates are not a multiple of 3");
  if (mesh.face_offsets.back() != mesh.face_indices.size())
    throw InputError("face offsets end at " + std::to_string(mesh.face_offsets.back()) + " but there are " +
                     std::to_string(mesh.face_indices.size()) + " face indices");
  const std::size_t points = mesh.point_count();
  // Edge entries pack a point index and a direction bit into 32 bits.
  if (points >= (std::size_t{1} << 31))
    throw InputError("the surface has " + std::to_string(points) + " points; expected fewer than 2^31");
  for (std::size_t i = 0; i < mesh.face_indices.size(); ++i)
    if (mesh.face_indices[i] >= points)
      throw InputError("a face refers to point " + std::to_string(mesh.face_indices[i]) + " but the surface has " +
                       std::to_string(points) + " points");
}

/// The diagonal of the points' bounding box, checking on the way that every
/// coordinate is finite (one pass over the points for both).
double bounding_box_diagonal(const SurfaceMesh& mesh) {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  bool finite = true;
  const double* x = mesh.points_xyz.data();
  for (std::size_t i = 0; i < mesh.point_count(); ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const double v = x[3 * i + c];
      finite = finite && std::isfinite(v);
      lo[c] = std::min(lo[c], v);
      hi[c] = std::max(hi[c], v);
    }
  if (!finite) throw InputError("point coordinates hold NaN or Inf; expected finite coordinates");
  return mesh.point_count() ? norm(hi - lo) : 0.0;
}

/// Edge counts of the edges whose smaller vertex lies in [first, last).
struct EdgeCounts {
  std::size_t boundary = 0, nonmanifold = 0, inconsistent = 0;
};

/// Edge topology: each edge (a, b) is filed under its smaller vertex with
/// the direction the face walks it; two passes of counting, no sort of the
/// whole edge list, so this stays linear in the number of faces. Working on a
/// vertex range lets two threads share the work; entries are 32 bits (the
/// other vertex and the direction), uninitialised and on huge pages, since
/// filling them is random access over tens of MB.
EdgeCounts count_edges(const SurfaceMesh& mesh, std::uint32_t first, std::uint32_t last) {
  EdgeCounts counts;
  if (last <= first) return counts;
  const std::size_t vertices = last - first;
  std::vector<std::uint32_t> start;
  reserve_with_huge_pages(start, vertices + 1);
  start.assign(vertices + 1, 0);
  const std::size_t faces = mesh.face_count();
  const std::uint32_t* offsets = mesh.face_offsets.data();
  const std::uint32_t* indices = mesh.face_indices.data();
  auto for_each_edge = [&](auto&& visit) {
    for (std::size_t f = 0; f < faces; ++f) {
      const std::uint32_t begin = offsets[f], end = offsets[f + 1];
      for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t a = indices[i], b = indices[i + 1 < end ? i + 1 : begin];
        const std::uint32_t low = a < b ? a : b;
        if (a != b && low >= first && low < last) visit(a, b, low - first);
      }
    }
  };
  for_each_edge([&](std::uint32_t, std::uint32_t, std::uint32_t v) { ++start[v + 1]; });
  for (std::size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  const std::size_t total = start[vertices];
  const std::unique_ptr<std::uint32_t[]> entries(new std::uint32_t[total]);
  prefer_huge_pages(entries.get(), total * sizeof(std::uint32_t));
  for_each_edge([&](std::uint32_t a, std::uint32_t b, std::uint32_t v) {
    entries[start[v]++] = ((a < b ? b : a) << 1) | (a < b ? 1u : 0u);
  });
  // start[v] now holds the end of v's entries, start[v - 1] their beginning.
  std::uint32_t begin = 0;
  for (std::size_t v = 0; v < vertices; ++v) {
    const std::uint32_t end = start[v];
    std::uint32_t* list = entries.get() + begin;
    const std::size_t n = end - begin;
    for (std::size_t i = 1; i < n; ++i)  // lists hold a handful of edges
      for (std::size_t j = i; j > 0 && list[j] < list[j - 1]; --j) std::swap(list[j], list[j - 1]);
    for (std::size_t i = 0; i < n;) {
      std::size_t j = i;
      unsigned walked_forward = 0;
      while (j < n && (list[j] >> 1) == (list[i] >> 1)) walked_forward += list[j++] & 1u;
      const std::size_t uses = j - i;
      if (uses == 1) ++counts.boundary;
      else if (uses > 2) ++counts.nonmanifold;
      else if (walked_forward != 1) ++counts.inconsistent;
      i = j;
    }
    begin = end;
  }
  return counts;
}

SurfaceLoads integrate(const SurfaceMesh& mesh, const SurfaceLoadOptions& options, bool with_fields) {
  check_mesh_indices(mesh);
  Integrator integrator{mesh, mesh.points_xyz.data(), options.reference_point, {}, {}, 0.0, 1.0, 0.0};
  if (with_fields) {
    integrator.pressure = pressure_view(mesh, options);
    integrator.shear = shear_view(mesh, options);
  }
  integrator.p_ref = options.reference_pressure;
  integrator.shear_sign = options.shear_convention == ShearConvention::OnWall ? 1.0 : -1.0;
  const double diagonal = bounding_box_diagonal(mesh);
  integrator.degenerate_area = 1e-14 * diagonal * diagonal;

  SurfaceLoads loads;
  const std::function<void()> nothing = [] {};
  const Sums sums = integrate_blocks(integrator, nothing, nothing);
  // Topology: a zero edge residue proves every edge is walked once each way
  // (the surface is closed and consistently oriented; only a mesh built to
  // cancel the 64-bit hash sums could fake it). Anything else is counted
  // exactly, edge by edge, on both threads.
  if (sums.edge_residue != 0) {
    const auto points = static_cast<std::uint32_t>(mesh.point_count());
    const auto split = static_cast<std::uint32_t>(0.4 * points);  // lower vertices own more edges
    EdgeCounts low_edges, high_edges;
    std::exception_ptr error;
    std::thread helper([&] {
      try {
        high_edges = count_edges(mesh, split, points);
      } catch (...) {
        error = std::current_exception();
      }
    });
    low_edges = count_edges(mesh, 0, split);
    helper.join();
    if (error) std::rethrow_exception(error);
    loads.geometry.boundary_edges = low_edges.boundary + high_edges.boundary;
    loads.geometry.nonmanifold_edges = low_edges.nonmanifold + high_edges.nonmanifold;
    loads.geometry.inconsistent_edges = low_edges.inconsistent + high_edges.inconsistent;
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
    geometry.warnings.push_back(std::to_string(geometry.nonmanifold_edges) + " non-manifold edges");
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
