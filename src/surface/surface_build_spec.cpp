#include "src/surface/surface_build_spec.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"
#include "src/surface/breakpoints.hpp"
#include "src/surface/grid_table.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef {
namespace {

using json = nlohmann::json;

constexpr std::size_t kMaxResampleCount = 100000;

std::pair<std::string, std::string> split_assignment(const std::string& text, const std::string& option) {
  const auto equals = text.find('=');
  if (equals == std::string::npos || equals == 0) throw InputError(option + " '" + text + "': expected NAME=VALUE");
  return {text.substr(0, equals), text.substr(equals + 1)};
}

double finite_number(const std::string& text, const std::string& option, const std::string& whole) {
  const auto value = parse_finite_number(text);
  if (!value) throw InputError(option + " '" + whole + "': found '" + text + "', expected a finite number");
  return *value;
}

/// Member `key` of a stored specification, checked to be of the expected type.
const json& member(const json& stored, const char* key, bool (json::*is_type)() const noexcept, const char* expected,
                   const std::string& context) {
  if (!stored.contains(key) || !(stored.at(key).*is_type)())
    throw InputError(context + ": its stored build specification has no '" + key + "' " + expected +
                     "; expected what hydrocoef surface build stores (build the surface again)");
  return stored.at(key);
}

std::vector<std::string> strings(const json& array, const char* key, const std::string& context) {
  std::vector<std::string> out;
  for (const auto& item : array) {
    if (!item.is_string())
      throw InputError(context + ": stored build specification '" + key + "' holds a non-text entry; expected text");
    out.push_back(item.get<std::string>());
  }
  return out;
}

}  // namespace

std::vector<std::string> out_of_range_policies(const std::vector<std::string>& axes,
                                               const std::vector<std::string>& entries, const std::string& option) {
  std::map<std::string, std::string> per_axis;
  std::string all;
  for (const auto& text : entries) {
    if (text.find('=') == std::string::npos) {
      all = text;
      continue;
    }
    const auto [axis, policy] = split_assignment(text, option);
    if (std::find(axes.begin(), axes.end(), axis) == axes.end())
      throw InputError(option + " '" + text + "': '" + axis + "' is not one of the surface's axes");
    per_axis[axis] = policy;
  }
  std::vector<std::string> out;
  for (const auto& axis : axes) {
    const auto it = per_axis.find(axis);
    out.push_back(it != per_axis.end() ? it->second : all.empty() ? "error" : all);
  }
  return out;
}

std::pair<std::string, std::vector<double>> parse_resample_entry(const std::string& text, const std::string& option) {
  const auto [axis, spec] = split_assignment(text, option);
  std::vector<double> out;
  if (spec.find(':') != std::string::npos) {
    const auto parts = split(spec, ':');
    if (parts.size() != 3) throw InputError(option + " '" + text + "': expected AXIS=FROM:TO:COUNT or AXIS=X1,X2,...");
    const double from = finite_number(std::string(parts[0]), option, text),
                 to = finite_number(std::string(parts[1]), option, text);
    const double count = finite_number(std::string(parts[2]), option, text);
    if (!(to > from) || count < 2 || count != std::floor(count) || count > static_cast<double>(kMaxResampleCount))
      throw InputError(option + " '" + text + "': expected FROM < TO and a whole COUNT from 2 to 100000");
    out = evenly_spaced(from, to, static_cast<std::size_t>(count));
  } else {
    for (const auto& part : split(spec, ',')) out.push_back(finite_number(std::string(part), option, text));
  }
  return {axis, out};
}

std::vector<std::vector<double>> resample_grid(const std::vector<std::string>& axes,
                                               const std::vector<std::string>& entries, const std::string& option) {
  std::map<std::string, std::vector<double>> by_axis;
  for (const auto& text : entries) by_axis.insert(parse_resample_entry(text, option));
  std::vector<std::vector<double>> grid;
  for (const auto& axis : axes) {
    const auto it = by_axis.find(axis);
    if (it == by_axis.end())
      throw InputError(option + " gives no breakpoints for axis '" + axis + "'; expected one " + option + " per axis");
    grid.push_back(it->second);
  }
  if (by_axis.size() != axes.size())
    throw InputError(option + " names an axis the surface does not have; its axes are given by --axes");
  return grid;
}

json build_spec_json(const SurfaceBuildSpec& spec) {
  const SurfaceSpec& s = spec.surface;
  json out = {{"version", kBuildSpecVersion},
              {"axes", s.axes},
              {"outputs", s.outputs},
              {"method", s.method},
              {"out_of_range", s.out_of_range},
              {"where", spec.where},
              {"exclude_runs", spec.exclude_runs},
              {"mirror", {{"planes", spec.mirror_planes}, {"odd", spec.mirror_odd}}},
              {"rbf",
               {{"kernel", std::string(rbf_kernel_name(s.rbf.kernel))},
                {"degree", s.rbf.polynomial_degree},
                {"smoothing", s.rbf.smoothing}}},
              {"resample", s.resample ? json(*s.resample) : json()},
              {"resample_method", s.resample_method},
              {"far_threshold", s.far_threshold}};
  if (s.method == "gp")
    out["gp"] = {{"kernel", std::string(gp_kernel_name(s.gp.kernel))},
                 {"degree", s.gp.mean_degree},
                 {"starts", s.gp.starts},
                 {"seed", s.gp.seed}};
  return out;
}

SurfaceBuildSpec parse_build_spec(const json& stored, const std::string& context) {
  if (!stored.is_object())
    throw InputError(context +
                     ": its stored build specification is not a JSON object; expected what hydrocoef "
                     "surface build stores");
  const auto& version = member(stored, "version", &json::is_number_integer, "whole number", context);
  if (version.get<std::int64_t>() != kBuildSpecVersion)
    throw InputError(context + ": stored build specification version " + version.dump() + "; expected " +
                     std::to_string(kBuildSpecVersion) + " (made by another hydrocoef version)");
  SurfaceBuildSpec spec;
  SurfaceSpec& s = spec.surface;
  s.axes = strings(member(stored, "axes", &json::is_array, "list", context), "axes", context);
  s.outputs = strings(member(stored, "outputs", &json::is_array, "list", context), "outputs", context);
  s.method = member(stored, "method", &json::is_string, "text", context).get<std::string>();
  s.out_of_range = strings(member(stored, "out_of_range", &json::is_array, "list", context), "out_of_range", context);
  if (s.out_of_range.size() != s.axes.size())
    throw InputError(context + ": stored build specification has " + std::to_string(s.out_of_range.size()) +
                     " out-of-range policies for " + std::to_string(s.axes.size()) + " axes; expected one per axis");
  spec.where = strings(member(stored, "where", &json::is_array, "list", context), "where", context);
  for (const auto& id : member(stored, "exclude_runs", &json::is_array, "list", context)) {
    if (!id.is_number_integer())
      throw InputError(context + ": stored build specification 'exclude_runs' holds " + id.dump(-1).substr(0, 40) +
                       "; expected run ids");
    spec.exclude_runs.push_back(id.get<std::int64_t>());
  }
  const auto& mirror = member(stored, "mirror", &json::is_object, "object", context);
  spec.mirror_planes = strings(member(mirror, "planes", &json::is_array, "list", context), "mirror.planes", context);
  spec.mirror_odd = strings(member(mirror, "odd", &json::is_array, "list", context), "mirror.odd", context);
  const auto& rbf = member(stored, "rbf", &json::is_object, "object", context);
  s.rbf.kernel = parse_rbf_kernel(member(rbf, "kernel", &json::is_string, "text", context).get<std::string>());
  const auto& degree = member(rbf, "degree", &json::is_number_integer, "whole number", context);
  if (degree.get<std::int64_t>() < 0 || degree.get<std::int64_t>() > 2)
    throw InputError(context + ": stored RBF degree " + degree.dump() + "; expected 0, 1 or 2");
  s.rbf.polynomial_degree = degree.get<int>();
  s.rbf.smoothing = member(rbf, "smoothing", &json::is_number, "number", context).get<double>();
  if (!(s.rbf.smoothing >= 0.0) || !std::isfinite(s.rbf.smoothing))
    throw InputError(context + ": stored RBF smoothing is not a finite number >= 0");
  if (!stored.contains("resample"))
    throw InputError(context + ": its stored build specification has no 'resample'; expected null or breakpoints");
  const auto& resample = stored.at("resample");
  if (!resample.is_null()) {
    if (!resample.is_array() || resample.size() != s.axes.size())
      throw InputError(context + ": stored resampling breakpoints are not one list per axis");
    std::vector<std::vector<double>> grid;
    for (const auto& axis : resample) {
      if (!axis.is_array() || axis.size() < 2 || axis.size() > kMaxResampleCount)
        throw InputError(context + ": stored resampling breakpoints of an axis are not a list of 2 to 100000 numbers");
      std::vector<double> values;
      for (const auto& value : axis) {
        if (!value.is_number() || !std::isfinite(value.get<double>()))
          throw InputError(context + ": stored resampling breakpoint " + value.dump(-1).substr(0, 40) +
                           "; expected a finite number");
        values.push_back(value.get<double>());
      }
      grid.push_back(std::move(values));
    }
    s.resample = std::move(grid);
  }
  s.resample_method = member(stored, "resample_method", &json::is_string, "text", context).get<std::string>();
  (void)parse_interpolation(s.resample_method);
  s.far_threshold = member(stored, "far_threshold", &json::is_number, "number", context).get<double>();
  if (!(s.far_threshold > 0.0) || !std::isfinite(s.far_threshold))
    throw InputError(context + ": stored far-from-data threshold is not a finite number > 0");
  if (s.method == "gp") {
    const auto& gp = member(stored, "gp", &json::is_object, "object", context);
    s.gp.kernel = parse_gp_kernel(member(gp, "kernel", &json::is_string, "text", context).get<std::string>());
    const auto whole = [&](const char* key, std::int64_t lowest, std::int64_t highest) {
      const auto& value = member(gp, key, &json::is_number_integer, "whole number", context);
      if (value.get<std::int64_t>() < lowest || value.get<std::int64_t>() > highest)
        throw InputError(context + ": stored GP " + key + " " + value.dump() + "; expected " + std::to_string(lowest) +
                         " to " + std::to_string(highest));
      return value.get<std::int64_t>();
    };
    s.gp.mean_degree = static_cast<int>(whole("degree", 0, 2));
    s.gp.starts = static_cast<int>(whole("starts", 1, 100));
    s.gp.seed = static_cast<unsigned>(whole("seed", 0, 4294967295));
  }
  return spec;
}

json build_spec_from_legacy_options(const json& legacy, const std::string& context) {
  try {
    SurfaceBuildSpec spec;
    SurfaceSpec& s = spec.surface;
    s.axes = legacy.at("axes").get<std::vector<std::string>>();
    s.outputs = legacy.at("outputs").get<std::vector<std::string>>();
    s.method = legacy.at("method").get<std::string>();
    s.out_of_range =
        out_of_range_policies(s.axes, legacy.at("extrapolate").get<std::vector<std::string>>(), "--extrapolate");
    spec.where = legacy.at("where").get<std::vector<std::string>>();
    if (legacy.contains("exclude_runs")) spec.exclude_runs = legacy.at("exclude_runs").get<std::vector<std::int64_t>>();
    if (legacy.contains("mirror")) spec.mirror_planes = legacy.at("mirror").get<std::vector<std::string>>();
    if (legacy.contains("mirror_odd")) spec.mirror_odd = legacy.at("mirror_odd").get<std::vector<std::string>>();
    s.rbf.kernel = parse_rbf_kernel(legacy.at("kernel").get<std::string>());
    s.rbf.polynomial_degree = legacy.at("degree").get<int>();
    s.rbf.smoothing = legacy.at("smoothing").get<double>();
    const auto resample = legacy.at("resample").get<std::vector<std::string>>();
    if (!resample.empty()) s.resample = resample_grid(s.axes, resample, "--resample");
    s.resample_method = legacy.at("resample_method").get<std::string>();
    s.far_threshold = legacy.at("far_threshold").get<double>();
    return build_spec_json(spec);
  } catch (const json::exception& error) {
    throw InputError(context + ": its stored build options are incomplete (" + std::string(error.what()) +
                     "); expected what hydrocoef surface build stored");
  }
}

}  // namespace hydrocoef
