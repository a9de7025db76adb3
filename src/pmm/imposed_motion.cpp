#include "src/pmm/imposed_motion.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {

namespace {
constexpr std::array<std::string_view, 6> kDofNames = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
constexpr std::array<std::string_view, 6> kVelocityLetters = {"u", "v", "w", "p", "q", "r"};
}  // namespace

std::string_view dof_name(std::size_t dof) { return dof < 6 ? kDofNames[dof] : "?"; }

std::optional<std::size_t> dof_named(std::string_view name) {
  for (std::size_t i = 0; i < 6; ++i)
    if (name == kDofNames[i] || name == kVelocityLetters[i]) return i;
  return std::nullopt;
}

HarmonicMotion motion_from_options(std::string_view dof, double amplitude, double period, double phase) {
  const auto index = dof_named(dof);
  if (!index)
    throw InputError("--motion '" + printable_text(dof, 40) +
                     "': expected surge, sway, heave, roll, pitch or yaw (or u, v, w, p, q, r)");
  if (!(std::isfinite(amplitude) && amplitude > 0.0))
    throw InputError("--amplitude " + shortest_number(amplitude) + ": expected a number > 0 (m, or rad for rotations)");
  if (!(std::isfinite(period) && period > 0.0))
    throw InputError("--period " + shortest_number(period) + ": expected a number > 0 (s)");
  if (!std::isfinite(phase)) throw InputError("--phase: expected a finite number (rad)");
  HarmonicMotion motion;
  motion.dof = *index;
  motion.amplitude = amplitude;
  motion.omega = 2.0 * std::numbers::pi / period;
  motion.phase = phase;
  return motion;
}

HarmonicMotion body_motion(const CaseOscillation& oscillation, const FrameTransform& frame) {
  const Vec3 body = frame.vector_to_body(oscillation.amplitude);
  std::size_t axis = 3;
  for (std::size_t i = 0; i < 3; ++i) {
    if (body[i] == 0.0) continue;
    if (axis != 3)
      throw InputError(SourceLocation{oscillation.where}, "the motion moves along several body axes (" +
                                                              oscillation.description +
                                                              "); expected one degree of freedom per run");
    axis = i;
  }
  if (axis == 3) throw InputError(SourceLocation{oscillation.where}, "the motion's amplitude is zero; expected > 0");
  if (oscillation.rotation) {
    const Vec3 origin_b = frame.point_to_body(oscillation.origin);
    if (std::hypot(origin_b[0], origin_b[1], origin_b[2]) > 1e-9)
      throw InputError(SourceLocation{oscillation.where},
                       "the rotation's origin is at (" + shortest_number(origin_b[0]) + ", " +
                           shortest_number(origin_b[1]) + ", " + shortest_number(origin_b[2]) +
                           ") m in body axes; expected the body origin (set --origin to the case's rotation origin)");
  }
  HarmonicMotion motion;
  motion.dof = axis + (oscillation.rotation ? 3 : 0);
  motion.amplitude = std::abs(body[axis]);
  motion.omega = oscillation.omega;
  motion.phase = oscillation.phase + (body[axis] < 0.0 ? std::numbers::pi : 0.0);
  return motion;
}

}  // namespace hydrocoef
