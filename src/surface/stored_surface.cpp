#include "src/surface/stored_surface.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/source_file.hpp"
#include "src/surface/stored_gp_surface.hpp"

namespace hydrocoef {
namespace {

using nlohmann::json;

RbfOutOfRange parse_rbf_policy(const std::string& text, const std::string& where) {
  if (text == "error") return RbfOutOfRange::Error;
  if (text == "clamp") return RbfOutOfRange::Clamp;
  if (text == "extrapolate") return RbfOutOfRange::Extrapolate;
  throw InputError(where + ": out-of-range policy '" + text + "'; expected error, clamp or extrapolate");
}

json common_definition(const CoefficientSurface& surface) {
  json definition;
  definition["axes"] = json::array();
  for (std::size_t a = 0; a < surface.axis_count(); ++a) {
    json axis = {{"name", surface.axis_names()[a]},
                 {"unit", surface.axis_units()[a]},
                 {"extrapolation", surface.out_of_range_name(a)}};
    if (const GridTable* grid = surface.grid()) axis["breakpoints"] = grid->axes()[a].breakpoints;
    definition["axes"].push_back(std::move(axis));
  }
  definition["outputs"] = json::array();
  for (std::size_t k = 0; k < surface.output_count(); ++k)
    definition["outputs"].push_back({{"name", surface.output_names()[k]}, {"unit", surface.output_units()[k]}});
  definition["sign"] = "on-body";
  if (const auto& symmetry = surface.symmetry(); !symmetry.empty()) {
    json reflections = json::array();
    for (const auto& g : symmetry.generators())
      reflections.push_back({{"axis_signs", g.axis_signs}, {"output_signs", g.output_signs}});
    definition["symmetry"] = std::move(reflections);
  }
  return definition;
}

// Reads a required member of a JSON object, naming the surface and key when
// it is missing or of the wrong type.
template <typename T>
T member(const json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key))
    throw InputError(where + ": the definition has no '" + key +
                     "'; expected it (the database may be from a "
                     "different hydrocoef or edited by hand)");
  try {
    return object.at(key).get<T>();
  } catch (const json::exception&) {
    throw InputError(where + ": '" + key + "' is " + printable_text(escape::json_text(object.at(key)), 40) +
                     "; expected a value of another type");
  }
}

// The symmetry a definition states (none when it has no "symmetry", as
// every surface stored before symmetries were imposed).
SurfaceSymmetry stored_symmetry(const json& definition, std::size_t axes, std::size_t outputs,
                                const std::string& where) {
  if (!definition.contains("symmetry")) return {};
  const json& list = definition.at("symmetry");
  if (!list.is_array() || list.size() > SurfaceSymmetry::kMaxGenerators)
    throw InputError(where + ": 'symmetry' is not a list of at most " +
                     std::to_string(SurfaceSymmetry::kMaxGenerators) + " reflections");
  std::vector<SurfaceReflection> generators;
  for (const auto& g : list)
    generators.push_back(
        {member<std::vector<double>>(g, "axis_signs", where), member<std::vector<double>>(g, "output_signs", where)});
  return SurfaceSymmetry(axes, outputs, std::move(generators));
}

// The hash an RBF solution is stored with: SHA-256 of the samples' bytes
// (coordinates, then values, float64) and of the options that shape the
// system. A solution whose hash does not match is not used.
std::string samples_hash(std::span<const double> points, std::span<const double> values, const json& options) {
  std::string bytes(reinterpret_cast<const char*>(points.data()), points.size_bytes());
  bytes.append(reinterpret_cast<const char*>(values.data()), values.size_bytes());
  bytes += escape::json_text(options);
  return sha256_hex(bytes);
}

json rbf_options_json(const RbfSurface& rbf) {
  std::vector<double> scales;
  for (std::size_t a = 0; a < rbf.axis_count(); ++a) scales.push_back(rbf.length_scale(a));
  return {{"kernel", rbf_kernel_name(rbf.kernel())},
          {"degree", rbf.polynomial_degree()},
          {"smoothing", rbf.smoothing()},
          {"length_scales", scales},
          {"samples", rbf.sample_count()}};
}

// A count from a definition: a non-negative integer (a float or a negative
// number would be cast, silently, by json::get).
std::size_t count_member(const json& object, const char* key, const std::string& where) {
  const json value = member<json>(object, key, where);
  if (!value.is_number_unsigned())
    throw InputError(where + ": '" + key + "' is " + printable_text(escape::json_text(value), 40) +
                     "; expected a whole number >= 0");
  return value.get<std::size_t>();
}

// The quality figures as SurfaceQuality::to_json writes them: an object whose
// members, where present, have the types the readers (surface show, report)
// expect. What is wrong, or nullopt.
std::optional<std::string> quality_problem(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const json quality = json::parse(text, nullptr, false);
  if (quality.is_discarded() || !quality.is_object()) return "its quality figures are not a JSON object";
  using TypeCheck = bool (json::*)() const noexcept;
  const std::pair<const char*, TypeCheck> typed[] = {{"loo_method", &json::is_string},
                                                     {"runs", &json::is_number_unsigned},
                                                     {"loo_defined", &json::is_number_unsigned},
                                                     {"grid_points", &json::is_number_unsigned},
                                                     {"far_threshold", &json::is_number},
                                                     {"far_from_data", &json::is_array},
                                                     {"loo_runs", &json::is_array}};
  for (const auto& [key, is_type] : typed)
    if (quality.contains(key) && !(quality.at(key).*is_type)())
      return std::string("its quality figure '") + key + "' is of the wrong type";
  if (quality.contains("grid_points") && (!quality.contains("far_threshold") || !quality.contains("far_from_data")))
    return "its quality figures name a resampled grid without its far-from-data figures";
  if (quality.contains("outputs")) {
    const json& outputs = quality.at("outputs");
    if (!outputs.is_object()) return "its quality figure 'outputs' is of the wrong type";
    for (const auto& [name, entry] : outputs.items()) {
      if (!entry.is_object())
        return "its quality figures of output '" + printable_text(name, 20) + "' are not an object";
      for (const char* key : {"loo_max", "loo_rms"})
        if (entry.contains(key) && !entry.at(key).is_number() && !entry.at(key).is_null())
          return "its quality figure '" + std::string(key) + "' of output '" + printable_text(name, 20) +
                 "' is not a number";
      if (entry.contains("loo_errors")) {
        const json& errors = entry.at("loo_errors");
        if (!errors.is_array() || !quality.contains("loo_runs") || errors.size() != quality.at("loo_runs").size())
          return "its leave-one-out errors of output '" + printable_text(name, 20) +
                 "' are not one number per run of 'loo_runs'";
        for (const auto& e : errors)
          if (!e.is_number() && !e.is_null())
            return "its leave-one-out errors of output '" + printable_text(name, 20) + "' hold a non-number";
      }
    }
  }
  return std::nullopt;
}

// The uncertainty of a grid or RBF surface, as the definition's
// "uncertainty" (see the header); null when the surface states none.
json uncertainty_json(const CoefficientSurface& surface, std::span<const double> rbf_sigma) {
  if (surface.loo_standard_deviation().empty()) return json();
  json out = {{"formula", "runs-interpolated+loo"}, {"loo_sd", surface.loo_standard_deviation()}};
  if (const GridTable* sigma = surface.run_uncertainty_grid()) out["run_sd"] = sigma->values();
  if (const RbfSurface* sigma = surface.run_uncertainty_rbf()) {
    if (rbf_sigma.size() != sigma->sample_count() * sigma->output_count())
      throw std::invalid_argument("record_from_surface: an RBF surface with an uncertainty needs its runs' sigma");
    const RbfSolution solution = sigma->solution();
    out["run_sd"] = std::vector<double>(rbf_sigma.begin(), rbf_sigma.end());
    out["kernel_weights"] = solution.kernel_weights;
    out["polynomial_weights"] = solution.polynomial_weights;
  }
  return out;
}

// A list of finite numbers >= 0 of the given size from the "uncertainty"
// object, naming the key when it is not.
std::vector<double> sd_list(const json& object, const char* key, std::size_t size, const std::string& where,
                            bool signed_values = false) {
  const auto values = member<std::vector<double>>(object, key, where);
  if (values.size() != size)
    throw InputError(where + ": its uncertainty's '" + key + "' holds " + std::to_string(values.size()) +
                     " numbers; expected " + std::to_string(size));
  for (const double x : values)
    if (!std::isfinite(x) || (!signed_values && x < 0.0))
      throw InputError(where + ": its uncertainty's '" + key + "' holds " + std::to_string(x) +
                       "; expected finite numbers" + (signed_values ? "" : " >= 0"));
  return values;
}

}  // namespace

std::string_view rbf_kernel_name(RbfKernel kernel) {
  switch (kernel) {
    case RbfKernel::Cubic: return "cubic";
    case RbfKernel::ThinPlate: return "thin-plate";
    case RbfKernel::Linear: return "linear";
  }
  return "cubic";
}

RbfKernel parse_rbf_kernel(std::string_view text) {
  if (text == "cubic") return RbfKernel::Cubic;
  if (text == "thin-plate") return RbfKernel::ThinPlate;
  if (text == "linear") return RbfKernel::Linear;
  throw InputError("unknown RBF kernel '" + std::string(text) + "'; expected cubic, thin-plate or linear");
}

SurfaceRecord record_from_surface(const CoefficientSurface& surface) {
  if (const GpSurfaces* gp = surface.gp()) {
    SurfaceRecord record;
    record.kind = "gp";
    record.method = std::string(gp_kernel_name(gp->kernel()));
    json definition = common_definition(surface);
    definition["gp"] = gp_definition(*gp);
    record.definition = escape::json_text(definition);
    record.data = gp_data(*gp);
    return record;
  }
  const GridTable* grid = surface.grid();
  if (!grid)
    throw std::invalid_argument("record_from_surface: an RBF surface needs its samples (use the overload with them)");
  SurfaceRecord record;
  record.kind = "grid";
  record.method = surface.method_name();
  json definition = common_definition(surface);
  if (auto uncertainty = uncertainty_json(surface, {}); !uncertainty.is_null())
    definition["uncertainty"] = std::move(uncertainty);
  record.definition = escape::json_text(definition);
  record.data = grid->values();
  return record;
}

SurfaceRecord record_from_surface(const CoefficientSurface& surface, std::span<const double> rbf_points,
                                  std::span<const double> rbf_values, std::span<const double> rbf_sigma) {
  const RbfSurface* rbf = surface.rbf();
  if (!rbf) return record_from_surface(surface);
  if (rbf_points.size() != rbf->sample_count() * rbf->axis_count() ||
      rbf_values.size() != rbf->sample_count() * rbf->output_count())
    throw std::invalid_argument("record_from_surface: the samples given are not the RBF's");
  SurfaceRecord record;
  record.kind = "rbf";
  record.method = std::string(rbf_kernel_name(rbf->kernel()));
  json definition = common_definition(surface);
  json options = rbf_options_json(*rbf);
  // The solved system is stored too: loading is then O(N), not a new solve.
  const RbfSolution solution = rbf->solution();
  definition["rbf"] = options;
  definition["rbf"]["solution"] = {{"samples_sha256", samples_hash(rbf_points, rbf_values, options)},
                                   {"polynomial_terms", solution.polynomial_weights.size() / rbf->output_count()}};
  if (auto uncertainty = uncertainty_json(surface, rbf_sigma); !uncertainty.is_null())
    definition["uncertainty"] = std::move(uncertainty);
  record.definition = escape::json_text(definition);
  record.data.assign(rbf_points.begin(), rbf_points.end());
  record.data.insert(record.data.end(), rbf_values.begin(), rbf_values.end());
  record.data.insert(record.data.end(), solution.kernel_weights.begin(), solution.kernel_weights.end());
  record.data.insert(record.data.end(), solution.polynomial_weights.begin(), solution.polynomial_weights.end());
  record.data.insert(record.data.end(), solution.loo_errors.begin(), solution.loo_errors.end());
  return record;
}

namespace {

// The surface a record describes, without the symmetry its definition may state.
CoefficientSurface unsymmetric_surface(const SurfaceRecord& record, const json& definition, const json& axes_json,
                                       const std::vector<std::string>& axis_names,
                                       const std::vector<std::string>& axis_units,
                                       const std::vector<std::string>& output_names,
                                       const std::vector<std::string>& output_units, const std::string& where);

}  // namespace

CoefficientSurface surface_from_record(const SurfaceRecord& record) {
  const std::string where =
      (record.database.empty() ? "" : record.database + ": table 'surface', row " + std::to_string(record.id) + ", ") +
      "surface '" + printable_text(record.name, 60) + "'";
  json definition;
  try {
    definition = json::parse(record.definition);
  } catch (const json::exception& error) {
    throw InputError(where + ": its stored definition is not JSON (" + error.what() + ")");
  }
  if (const auto problem = quality_problem(record.quality)) throw InputError(where + ": " + *problem);
  const auto axes_json = member<json>(definition, "axes", where);
  const auto outputs_json = member<json>(definition, "outputs", where);
  if (!axes_json.is_array() || !outputs_json.is_array())
    throw InputError(where + ": 'axes' and 'outputs' must be arrays in its definition");
  if (axes_json.empty() || axes_json.size() > RbfSurface::kMaxAxes || outputs_json.empty() || outputs_json.size() > 6)
    throw InputError(where + ": its definition has " + std::to_string(axes_json.size()) + " axes and " +
                     std::to_string(outputs_json.size()) + " outputs; expected 1 to 6 of each");
  // Names read back from a database follow the same rule as names entering
  // from anywhere else; units are short printable text.
  const auto unit = [&](const json& object) {
    std::string text = member<std::string>(object, "unit", where);
    if (text.size() > 64 || escape::one_line(text) != text)
      throw InputError(where + ": unit '" + printable_text(text, 40) +
                       "'; expected printable text of at most 64 bytes");
    return text;
  };
  std::vector<std::string> axis_names, axis_units, output_names, output_units;
  for (const auto& axis : axes_json) {
    axis_names.push_back(std::string(
        check_name(NameKind::Parameter, member<std::string>(axis, "name", where), {}, where + ", an axis")));
    axis_units.push_back(unit(axis));
  }
  for (const auto& output : outputs_json) {
    output_names.push_back(member<std::string>(output, "name", where));
    if (!force_index(output_names.back()))
      throw InputError(where + ": output '" + printable_text(output_names.back(), 40) +
                       "'; expected a force component X, Y, Z, K, M or N");
    output_units.push_back(unit(output));
  }
  try {
    return unsymmetric_surface(record, definition, axes_json, axis_names, axis_units, output_names, output_units, where)
        .with_symmetry(stored_symmetry(definition, axis_names.size(), output_names.size(), where));
  } catch (const InputError& error) {
    const std::string message = error.what();
    if (message.rfind(where, 0) == 0) throw;
    throw InputError(where + ": " + message);
  }
}

namespace {

CoefficientSurface unsymmetric_surface(const SurfaceRecord& record, const json& definition, const json& axes_json,
                                       const std::vector<std::string>& axis_names,
                                       const std::vector<std::string>& axis_units,
                                       const std::vector<std::string>& output_names,
                                       const std::vector<std::string>& output_units, const std::string& where) {
  {
    if (record.kind == "grid") {
      std::vector<GridAxis> axes;
      for (const auto& axis : axes_json)
        axes.push_back({member<std::string>(axis, "name", where),
                        member<std::vector<double>>(axis, "breakpoints", where),
                        parse_extrapolation(member<std::string>(axis, "extrapolation", where))});
      CoefficientSurface surface(
          GridTable(std::move(axes), output_names, record.data, parse_interpolation(record.method)), axis_units,
          output_units);
      // Stored before surfaces had an uncertainty: none is stated.
      if (!definition.contains("uncertainty")) return surface;
      const auto uncertainty = member<json>(definition, "uncertainty", where);
      return surface.with_run_uncertainty(sd_list(uncertainty, "run_sd", record.data.size(), where),
                                          sd_list(uncertainty, "loo_sd", output_names.size(), where));
    }
    if (record.kind == "rbf") {
      const auto rbf_json = member<json>(definition, "rbf", where);
      RbfOptions options;
      options.kernel = parse_rbf_kernel(member<std::string>(rbf_json, "kernel", where));
      options.polynomial_degree = static_cast<int>(std::min<std::size_t>(count_member(rbf_json, "degree", where), 99));
      options.smoothing = member<double>(rbf_json, "smoothing", where);
      options.length_scales = member<std::vector<double>>(rbf_json, "length_scales", where);
      options.axis_names = axis_names;
      for (const auto& axis : axes_json)
        options.out_of_range.push_back(parse_rbf_policy(member<std::string>(axis, "extrapolation", where), where));
      // Sizes from the file are checked before they are multiplied or used.
      const auto samples = count_member(rbf_json, "samples", where);
      if (samples > RbfSurface::kMaxSamples)
        throw InputError(where + ": " + std::to_string(samples) +
                         " samples; this hydrocoef loads RBF surfaces of at "
                         "most " +
                         std::to_string(RbfSurface::kMaxSamples) + " samples");
      const std::size_t d = axis_names.size(), k = output_names.size();
      const std::size_t n_points = samples * d;
      const std::size_t n_values = samples * k;
      const std::span<const double> data(record.data);
      std::optional<RbfSolution> solution;
      std::size_t expected = n_points + n_values;
      if (rbf_json.contains("solution")) {
        const auto stored = member<json>(rbf_json, "solution", where);
        const auto terms = count_member(stored, "polynomial_terms", where);
        if (terms > 28)
          throw InputError(where + ": " + std::to_string(terms) + " polynomial terms; expected at most 28");
        expected += (2 * samples + terms) * k;
        if (record.data.size() == expected) {
          json options_json = rbf_json;
          options_json.erase("solution");
          if (member<std::string>(stored, "samples_sha256", where) !=
              samples_hash(data.first(n_points), data.subspan(n_points, n_values), options_json))
            throw InputError(where +
                             ": its stored solution is not of its stored samples (the database was changed "
                             "after the surface was built); expected them to match: rebuild it with hydrocoef surface "
                             "rebuild");
          std::size_t at = n_points + n_values;
          const auto take = [&](std::size_t count) {
            const auto part = data.subspan(at, count);
            at += count;
            return std::vector<double>(part.begin(), part.end());
          };
          RbfSolution parts;
          parts.kernel_weights = take(samples * k);
          parts.polynomial_weights = take(terms * k);
          parts.loo_errors = take(samples * k);
          solution = std::move(parts);
        }
      }
      if (record.data.size() != expected)
        throw InputError(where + ": its data holds " + std::to_string(record.data.size()) + " numbers; expected " +
                         std::to_string(expected) + " for " + std::to_string(samples) + " samples");
      RbfSurface rbf =
          solution ? RbfSurface(d, data.first(n_points), k, data.subspan(n_points, n_values), options, *solution)
                   : RbfSurface(d, data.first(n_points), k, data.subspan(n_points, n_values), options);
      CoefficientSurface surface(std::move(rbf), axis_names, output_names, axis_units, output_units);
      // Stored before surfaces had an uncertainty: none is stated.
      if (!definition.contains("uncertainty")) return surface;
      const auto uncertainty = member<json>(definition, "uncertainty", where);
      // The RBF of the runs' uncertainties: the same samples and options,
      // clamped outside the range, with its stored weights (no solve).
      const std::vector<double> sigma = sd_list(uncertainty, "run_sd", n_values, where);
      RbfSolution sigma_solution;
      sigma_solution.kernel_weights = sd_list(uncertainty, "kernel_weights", n_values, where, true);
      sigma_solution.polynomial_weights =
          sd_list(uncertainty, "polynomial_weights", surface.rbf()->solution().polynomial_weights.size(), where, true);
      sigma_solution.loo_errors.assign(n_values, std::numeric_limits<double>::quiet_NaN());
      options.out_of_range.assign(d, RbfOutOfRange::Clamp);
      return surface.with_run_uncertainty(RbfSurface(d, data.first(n_points), k, sigma, options, sigma_solution),
                                          sd_list(uncertainty, "loo_sd", k, where));
    }
    if (record.kind == "gp") {
      std::vector<RbfOutOfRange> policies;
      for (const auto& axis : axes_json)
        policies.push_back(parse_rbf_policy(member<std::string>(axis, "extrapolation", where), where));
      GpSurfaces gp = gp_from_stored(member<json>(definition, "gp", where), record.data, axis_names,
                                     std::move(policies), output_names.size(), where);
      if (std::string(gp_kernel_name(gp.kernel())) != record.method)
        throw InputError(where + ": its method '" + printable_text(record.method, 40) + "' is not its GP kernel '" +
                         std::string(gp_kernel_name(gp.kernel())) + "'");
      return CoefficientSurface(std::move(gp), axis_names, output_names, axis_units, output_units);
    }
  }
  throw InputError(where + ": kind '" + printable_text(record.kind, 20) + "'; expected grid, rbf or gp");
}

}  // namespace

StoredSurface load_surface(RunDatabase& database, const std::string& name) {
  SurfaceRecord record = database.surface(name);
  CoefficientSurface surface = surface_from_record(record);
  return {std::move(record), std::move(surface)};
}

}  // namespace hydrocoef
