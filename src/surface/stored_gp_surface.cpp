#include "src/surface/stored_gp_surface.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

using nlohmann::json;

const json& required(const json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key))
    throw InputError(where + ": its GP definition has no '" + key + "'; expected what hydrocoef surface build stores");
  return object.at(key);
}

double number(const json& object, const char* key, const std::string& where) {
  const json& value = required(object, key, where);
  if (!value.is_number() || !std::isfinite(value.get<double>()))
    throw InputError(where + ": its GP definition's '" + key + "' is not a finite number");
  return value.get<double>();
}

std::size_t count(const json& object, const char* key, std::size_t most, const std::string& where) {
  const json& value = required(object, key, where);
  if (!value.is_number_unsigned() || value.get<std::size_t>() > most)
    throw InputError(where + ": its GP definition's '" + key + "' is not a whole number from 0 to " +
                     std::to_string(most));
  return value.get<std::size_t>();
}

std::vector<double> numbers(const json& object, const char* key, std::size_t size, const std::string& where) {
  const json& value = required(object, key, where);
  if (!value.is_array() || value.size() != size)
    throw InputError(where + ": its GP definition's '" + key + "' is not a list of " + std::to_string(size) +
                     " numbers");
  std::vector<double> out;
  for (const auto& x : value) {
    if (!x.is_number() || !std::isfinite(x.get<double>()))
      throw InputError(where + ": its GP definition's '" + key + "' holds a value that is not a finite number");
    out.push_back(x.get<double>());
  }
  return out;
}

}  // namespace

json gp_definition(const GpSurfaces& gp) {
  json out = {{"kernel", std::string(gp_kernel_name(gp.kernel()))},
              {"degree", gp.mean_degree()},
              {"samples", gp.sample_count()}};
  std::vector<double> lower, upper;
  for (std::size_t a = 0; a < gp.axis_count(); ++a) lower.push_back(gp.lower(a)), upper.push_back(gp.upper(a));
  out["lower"] = lower;
  out["upper"] = upper;
  out["outputs"] = json::array();
  for (std::size_t k = 0; k < gp.output_count(); ++k) {
    const GpState& s = gp.output(k).state();
    out["outputs"].push_back({{"sigma", s.sigma},
                              {"value_centre", s.value_centre},
                              {"value_scale", s.value_scale},
                              {"log_likelihood", s.log_likelihood},
                              {"axis_centre", s.axis_centre},
                              {"axis_scale", s.axis_scale},
                              {"length_scales", s.length_scales},
                              {"beta", s.beta},
                              {"nugget", s.nugget},
                              {"sd_factor", s.sd_factor},
                              {"loo_rms_z", s.loo_rms_z},
                              {"loo_max_z", s.loo_max_z}});
  }
  return out;
}

std::vector<double> gp_data(const GpSurfaces& gp) {
  std::vector<double> data;
  for (std::size_t k = 0; k < gp.output_count(); ++k) {
    const GpState& s = gp.output(k).state();
    for (const auto* part : {&s.points, &s.alpha, &s.cholesky, &s.basis_solve, &s.mean_cholesky})
      data.insert(data.end(), part->begin(), part->end());
  }
  return data;
}

GpSurfaces gp_from_stored(const json& gp_json, std::span<const double> data, std::vector<std::string> axis_names,
                          std::vector<RbfOutOfRange> policies, std::size_t outputs, const std::string& where) {
  const std::size_t d = axis_names.size();
  const GpKernel kernel = [&] {
    const json& text = required(gp_json, "kernel", where);
    if (!text.is_string()) throw InputError(where + ": its GP kernel is not text");
    return parse_gp_kernel(text.get<std::string>());
  }();
  const int degree = static_cast<int>(count(gp_json, "degree", 2, where));
  const std::size_t n = count(gp_json, "samples", GpSurfaces::kMaxSamples, where);
  const std::size_t m = gp_mean_terms(degree, d);
  if (n < m + 1)
    throw InputError(where + ": its GP definition has " + std::to_string(n) + " samples; a mean of degree " +
                     std::to_string(degree) + " needs at least " + std::to_string(m + 1));
  const json& per_output = required(gp_json, "outputs", where);
  if (!per_output.is_array() || per_output.size() != outputs)
    throw InputError(where + ": its GP definition does not hold one entry per output (" + std::to_string(outputs) +
                     ")");
  // Sizes are bounded above (n <= 5000, d <= 6, outputs <= 6), so these products cannot overflow.
  const std::size_t per = d * n + n + n * (n + 1) / 2 + m * n + m * (m + 1) / 2;
  if (data.size() != per * outputs)
    throw InputError(where + ": its data holds " + std::to_string(data.size()) + " numbers; expected " +
                     std::to_string(per * outputs) + " for a GP of " + std::to_string(n) + " samples, " +
                     std::to_string(d) + " axes and " + std::to_string(outputs) + " outputs");
  std::vector<GpSurface> surfaces;
  std::size_t at = 0;
  const auto take = [&](std::size_t size) {
    std::vector<double> part(data.begin() + static_cast<std::ptrdiff_t>(at),
                             data.begin() + static_cast<std::ptrdiff_t>(at + size));
    at += size;
    return part;
  };
  for (const json& entry : per_output) {
    GpState s;
    s.kernel = kernel;
    s.mean_degree = degree;
    s.dims = d;
    s.samples = n;
    s.sigma = number(entry, "sigma", where);
    s.value_centre = number(entry, "value_centre", where);
    s.value_scale = number(entry, "value_scale", where);
    s.log_likelihood = number(entry, "log_likelihood", where);
    s.axis_centre = numbers(entry, "axis_centre", d, where);
    s.axis_scale = numbers(entry, "axis_scale", d, where);
    s.length_scales = numbers(entry, "length_scales", d, where);
    s.beta = numbers(entry, "beta", m, where);
    // Surfaces stored before the nugget and the calibration were kept have
    // neither: tau 0, factor 1, calibration unknown (NaN).
    if (entry.contains("nugget")) s.nugget = number(entry, "nugget", where);
    if (entry.contains("sd_factor")) s.sd_factor = number(entry, "sd_factor", where);
    if (entry.contains("loo_rms_z") && !entry["loo_rms_z"].is_null()) {
      s.loo_rms_z = number(entry, "loo_rms_z", where);
      s.loo_max_z = number(entry, "loo_max_z", where);
    }
    s.points = take(d * n);
    s.alpha = take(n);
    s.cholesky = take(n * (n + 1) / 2);
    s.basis_solve = take(m * n);
    s.mean_cholesky = take(m * (m + 1) / 2);
    surfaces.push_back(GpSurface::from_state(std::move(s)));
  }
  return GpSurfaces(std::move(surfaces), numbers(gp_json, "lower", d, where), numbers(gp_json, "upper", d, where),
                    std::move(axis_names), std::move(policies));
}

}  // namespace hydrocoef
