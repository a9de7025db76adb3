#include "src/dynamics/scenario.hpp"

#include <numbers>

#include "src/core/error.hpp"
#include "src/core/run.hpp"
#include "src/dynamics/json_input.hpp"

namespace hydrocoef {
namespace {

namespace ji = json_input;
using ji::Json;

IntegratorSettings read_integrator(const Json& value, const std::string& file) {
  ji::expect_object(value, file, "integrator", {"method", "step", "rtol", "atol", "max_step"});
  IntegratorSettings s;
  const std::string method = ji::string(ji::require(value, file, "integrator", "method"), file, "integrator.method");
  if (method == "rk4") {
    s.method = IntegratorSettings::Method::Rk4;
    for (const char* key : {"rtol", "atol", "max_step"})
      if (ji::find(value, key)) ji::fail(file, ji::join("integrator", key), "belongs to dopri5, not to rk4");
    if (const Json* step = ji::find(value, "step")) s.step_s = ji::positive(*step, file, "integrator.step");
  } else if (method == "dopri5") {
    s.method = IntegratorSettings::Method::DormandPrince45;
    if (ji::find(value, "step")) ji::fail(file, "integrator.step", "belongs to rk4; dopri5 takes rtol, atol, max_step");
    if (const Json* v = ji::find(value, "rtol")) s.relative_tolerance = ji::positive(*v, file, "integrator.rtol");
    if (const Json* v = ji::find(value, "atol")) s.absolute_tolerance = ji::positive(*v, file, "integrator.atol");
    if (const Json* v = ji::find(value, "max_step")) s.max_step_s = ji::positive(*v, file, "integrator.max_step");
  } else {
    ji::fail(file, "integrator.method", "found \"" + method + "\", expected \"rk4\" or \"dopri5\"");
  }
  return s;
}

ScenarioSegment read_segment(const Json& value, const std::string& file, const std::string& path) {
  ji::expect_object(value, file, path, {"start", "tau", "thrusters", "current", "disturbances", "notes"});
  ScenarioSegment s;
  s.start_s = ji::positive(ji::require(value, file, path, "start"), file, ji::join(path, "start"), true);
  if (const Json* tau = ji::find(value, "tau")) {
    const std::string tau_path = ji::join(path, "tau");
    ji::expect_object(*tau, file, tau_path, {"X", "Y", "Z", "K", "M", "N"});
    for (const auto& item : tau->items())
      s.tau_b[static_cast<Eigen::Index>(*force_index(item.key()))] =
          ji::number(item.value(), file, ji::join(tau_path, item.key()));
  }
  if (const Json* thrusters = ji::find(value, "thrusters")) {
    const std::string t_path = ji::join(path, "thrusters");
    if (thrusters->is_array()) {
      s.thrust_N = ji::numbers(*thrusters, file, t_path);
    } else if (thrusters->is_object()) {
      for (const auto& item : thrusters->items())
        s.thrust_by_name_N[item.key()] = ji::number(item.value(), file, ji::join(t_path, item.key()));
    } else {
      ji::fail(
          file, t_path,
          "found " + ji::describe(*thrusters) + ", expected an array of thrusts [N] or an object by thruster name");
    }
  }
  if (const Json* current = ji::find(value, "current"))
    s.current_n = ji::vector3(*current, file, ji::join(path, "current"));
  if (const Json* d = ji::find(value, "disturbances")) {
    const std::string d_path = ji::join(path, "disturbances");
    if (!d->is_object()) ji::fail(file, d_path, "found " + ji::describe(*d) + ", expected an object {name: value}");
    for (const auto& item : d->items())
      s.disturbances[item.key()] = ji::number(item.value(), file, ji::join(d_path, item.key()));
  }
  return s;
}

}  // namespace

Scenario parse_scenario(std::string_view json_text, const std::string& file) {
  const Json doc = ji::parse(json_text, file);
  ji::expect_object(doc, file, "", {"name", "notes", "duration", "output_rate", "integrator", "initial", "segments"});
  Scenario s;
  s.file = file;
  if (const Json* name = ji::find(doc, "name")) s.name = ji::string(*name, file, "name");
  if (const Json* notes = ji::find(doc, "notes")) s.notes = ji::string(*notes, file, "notes");
  s.duration_s = ji::positive(ji::require(doc, file, "", "duration"), file, "duration");
  if (const Json* rate = ji::find(doc, "output_rate")) s.output_rate_Hz = ji::positive(*rate, file, "output_rate");
  if (const Json* integrator = ji::find(doc, "integrator")) s.integrator = read_integrator(*integrator, file);

  if (const Json* initial = ji::find(doc, "initial")) {
    ji::expect_object(*initial, file, "initial", {"position", "euler_deg", "euler_rad", "velocity"});
    if (const Json* p = ji::find(*initial, "position"))
      s.initial_position_n = ji::vector3(*p, file, "initial.position");
    const Json* deg = ji::find(*initial, "euler_deg");
    const Json* rad = ji::find(*initial, "euler_rad");
    if (deg && rad) ji::fail(file, "initial.euler_deg", "expected one of euler_deg and euler_rad, not both");
    if (deg) s.initial_euler_rad = ji::vector3(*deg, file, "initial.euler_deg") * (std::numbers::pi / 180.0);
    if (rad) s.initial_euler_rad = ji::vector3(*rad, file, "initial.euler_rad");
    if (const Json* v = ji::find(*initial, "velocity")) {
      const auto nu = ji::numbers(*v, file, "initial.velocity", 6);
      for (std::size_t i = 0; i < 6; ++i) s.initial_nu_b[static_cast<Eigen::Index>(i)] = nu[i];
    }
  }

  const Json& segments = ji::require(doc, file, "", "segments");
  if (!segments.is_array() || segments.empty())
    ji::fail(file, "segments", "found " + ji::describe(segments) + ", expected a non-empty array of segments");
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string path = "segments[" + std::to_string(i) + "]";
    s.segments.push_back(read_segment(segments[i], file, path));
    const double start = s.segments.back().start_s;
    if (i == 0 && start != 0.0)
      ji::fail(file, path + ".start", "found " + std::to_string(start) + ", expected the first segment to start at 0");
    if (i > 0 && !(start > s.segments[i - 1].start_s))
      ji::fail(file, path + ".start",
               "found " + std::to_string(start) + ", expected a start after the previous segment's");
    if (start >= s.duration_s && i > 0)
      ji::fail(file, path + ".start",
               "found " + std::to_string(start) + ", expected a start before the duration " +
                   std::to_string(s.duration_s) + " s");
  }
  return s;
}

Scenario load_scenario(const std::filesystem::path& path) {
  return parse_scenario(json_input::read_file(path.string()), path.string());
}

}  // namespace hydrocoef
