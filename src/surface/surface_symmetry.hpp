// Mirror symmetry imposed on a coefficient surface. A body symmetric about
// its xz-plane (a mirror in v) has Y, K, N odd and X, Z, M even under
// v, p, r -> -v, -p, -r; a surface built with --mirror v is made to be so
// exactly, whatever its method, instead of only being fed mirrored copies of
// the runs (a run on the plane keeps its small side force in the copies,
// and a body driven in surge alone would then drift sideways).
//
// A symmetry is a set of commuting reflections (generators), each one sign
// per axis and one per output: g x flips the axes whose sign is -1, and an
// output of sign s satisfies f_k(g x) = s_k f_k(x). The surface evaluated is
// the projection of the interpolant f onto the functions with that symmetry,
//
//     (P f)(x) = 1/|G| sum_{g in G} S_g f(g x),
//
// G the group the generators span (2^p elements), S_g the product of the
// output signs of the generators composing g. P f is symmetric by
// construction: an odd output is exactly 0 on its plane (the two images are
// the same point, evaluated bit for bit the same, and cancel), an even one
// has zero slope across it. Where the interpolant was already symmetric (the
// mirrored runs beside the runs) P changes nothing. The sum is evaluated as
// nested halves, one generator at a time,
//
//     F_j(y) = (F_{j-1}(y) + s_j F_{j-1}(g_j y)) / 2,   F_0 = f,
//
// which is what makes the cancellation exact for any of the planes. The
// gradient follows by the chain rule (a reflection negates the flipped axes'
// slopes). Cost: 2^p evaluations of the interpolant (p <= 3 planes).
//
// A generator that flips no axis of the surface (a mirror in v on a surface
// over u alone) evaluates nothing twice: it zeroes the outputs odd under it
// (a symmetric body in pure surge has no side force) and keeps the others.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace hydrocoef {

struct SurfaceReflection {
  std::vector<double> axis_signs;    ///< per axis: +1 or -1
  std::vector<double> output_signs;  ///< per output: +1 (even) or -1 (odd)
};

class SurfaceSymmetry {
 public:
  /// Planes a symmetry may have at most (2^3 images per evaluation).
  static constexpr std::size_t kMaxGenerators = 3;

  /// No symmetry: the surface is evaluated as it is.
  SurfaceSymmetry() = default;
  /// From its generators over `axes` axes and `outputs` outputs. A generator
  /// that flips nothing (no axis, no output) is dropped. InputError when a
  /// generator has the wrong sizes or a sign other than +1 or -1, two
  /// generators are the same, or there are more than kMaxGenerators.
  SurfaceSymmetry(std::size_t axes, std::size_t outputs, std::vector<SurfaceReflection> generators);

  bool empty() const noexcept { return generators_.empty(); }
  const std::vector<SurfaceReflection>& generators() const noexcept { return generators_; }
  std::size_t axis_count() const noexcept { return axes_; }
  std::size_t output_count() const noexcept { return outputs_; }

  /// The generators that flip at least one axis (those whose images are
  /// evaluated), first; then those that flip outputs only.
  std::size_t moving_count() const noexcept { return moving_; }

  /// image = g_j x for generator j (a coordinate 0 stays +0, so that a point
  /// on the plane is its own image bit for bit).
  void reflect(std::size_t generator, std::span<const double> x, std::span<double> image) const;

  /// "v: Y, K, N odd" per generator, for people; names as the surface's.
  std::string describe(const std::vector<std::string>& axis_names, const std::vector<std::string>& output_names) const;

 private:
  std::size_t axes_ = 0, outputs_ = 0, moving_ = 0;
  std::vector<SurfaceReflection> generators_;
};

}  // namespace hydrocoef
