// The symmetry a surface built with --mirror imposes (src/surface/
// surface_symmetry.hpp), from the body's mirror planes: per plane, the
// surface's axes it reverses (velocity components by the plane's rule,
// disturbances named odd) and the outputs odd in it (the force and moment
// components by the same rule).
//
// A plane is a symmetry of a surface only when every run sits where the
// reflection leaves the quantities that are not axes unchanged: a mirror in
// v over runs at r = 0.1 rad/s would pair them with runs at r = -0.1 that the
// surface does not span. Such a build is refused, naming the run.
#pragma once

#include <string>
#include <vector>

#include "src/core/run.hpp"
#include "src/pipeline/fit_runs.hpp"
#include "src/surface/surface_symmetry.hpp"

namespace hydrocoef {

/// The symmetry of a surface over `axes` with `outputs` (names as in
/// SurfaceSpec) built from `runs` (the measured runs, before their images)
/// with `mirror`; empty without planes. InputError when a run has a
/// quantity the plane reverses, not an axis, away from 0.
SurfaceSymmetry mirror_symmetry(const MirrorSpec& mirror, const std::vector<std::string>& axes,
                                const std::vector<std::string>& outputs, const std::vector<StoredRun>& runs);

}  // namespace hydrocoef
