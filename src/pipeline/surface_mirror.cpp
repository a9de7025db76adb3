#include "src/pipeline/surface_mirror.hpp"

#include <algorithm>

#include "src/core/body_symmetry.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {

SurfaceSymmetry mirror_symmetry(const MirrorSpec& mirror, const std::vector<std::string>& axes,
                                const std::vector<std::string>& outputs, const std::vector<StoredRun>& runs) {
  std::vector<SurfaceReflection> generators;
  for (const auto& plane : mirror.planes) {
    const BodyMirror reflection = parse_body_mirror(plane, mirror.odd);
    const auto signs = reflection.signs();
    SurfaceReflection g;
    for (const auto& axis : axes) {
      if (const auto v = velocity_index(axis))
        g.axis_signs.push_back(signs[*v]);
      else
        g.axis_signs.push_back(reflection.odd_disturbances.count(axis) ? -1.0 : 1.0);
    }
    for (const auto& output : outputs) {
      const auto f = force_index(output);
      g.output_signs.push_back(f ? signs[*f] : 1.0);
    }
    // What the plane reverses but the surface does not span must be 0 in every run.
    const auto is_axis = [&](const std::string& name) {
      return std::find(axes.begin(), axes.end(), name) != axes.end();
    };
    for (const auto& run : runs) {
      for (std::size_t c = 0; c < 6; ++c)
        if (signs[c] < 0.0 && !is_axis(std::string(kVelocityNames[c])) && run.key.nu_b[c] != 0.0)
          throw InputError("--mirror " + plane + " reverses " + std::string(kVelocityNames[c]) + ", which is not an " +
                           "axis of the surface and is " + shortest_number(run.key.nu_b[c]) + " in run " +
                           std::to_string(run.id) + ": its image does not lie on this surface; expected " +
                           std::string(kVelocityNames[c]) + " = 0 in every run (select them with --where), or " +
                           std::string(kVelocityNames[c]) + " as an axis");
      for (const auto& [name, value] : run.key.disturbances)
        if (reflection.odd_disturbances.count(name) && !is_axis(name) && value != 0.0)
          throw InputError("--mirror " + plane + " reverses the disturbance " + name + " (--mirror-odd), which is " +
                           "not an axis of the surface and is " + shortest_number(value) + " in run " +
                           std::to_string(run.id) + ": its image does not lie on this surface; expected " + name +
                           " = 0 in every run (select them with --where), or " + name + " as an axis");
    }
    generators.push_back(std::move(g));
  }
  return SurfaceSymmetry(axes.size(), outputs.size(), std::move(generators));
}

}  // namespace hydrocoef
