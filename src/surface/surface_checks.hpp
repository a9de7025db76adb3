// Physical checks of a coefficient surface before it drives a simulation, as
// src/fit/physical_checks.hpp does for damping laws: a damping force takes
// energy out of the motion it opposes. For each output that is the force (or
// moment) of a velocity axis the surface spans (X of u, Y of v, Z of w, K of
// p, M of q, N of r), the power F x along that axis must not be positive:
// surfaces hold forces on the body, so F x > 0 means the surface pushes the
// body along its motion there (a Y(u, v) with dY/dv > 0 ran away in sway).
// The surface is evaluated on a lattice over its whole range (up to 41
// points per axis, at most 20,000 points, the axis' ends included); a power
// above 1e-9 of the largest |F| |x| on the lattice counts as positive, and
// the largest is reported with where it is.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "src/surface/coefficient_surface.hpp"

namespace hydrocoef {

struct SurfaceProblem {
  std::string output;   ///< e.g. "Y"
  std::string axis;     ///< e.g. "v"
  std::string message;  ///< one line: what, where, the power
};

/// One problem per output that feeds energy into its own motion somewhere in
/// the range (empty when the surface is dissipative along every axis it
/// spans).
/// `on_body`: +1 when the surface's values are forces on the body (what
/// hydrocoef builds), -1 when positive values oppose the motion.
std::vector<SurfaceProblem> dissipativity_problems(const CoefficientSurface& surface, double on_body = 1.0);

/// The check of one output along one axis (the output being the force of
/// the motion that axis is bound to), or nothing when it is dissipative.
std::optional<SurfaceProblem> dissipativity_problem(const CoefficientSurface& surface, std::size_t output,
                                                    std::size_t axis, double on_body = 1.0);

}  // namespace hydrocoef
