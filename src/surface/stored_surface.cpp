#include "src/surface/stored_surface.hpp"

#include <nlohmann/json.hpp>

#include "src/core/error.hpp"

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
  return definition;
}

// Reads a required member of a JSON object, naming the surface and key when
// it is missing or of the wrong type.
template <typename T>
T member(const json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key))
    throw InputError(where + ": the definition has no '" + key + "'; expected it (the database may be from a "
                     "different hydrocoef or edited by hand)");
  try {
    return object.at(key).get<T>();
  } catch (const json::exception&) {
    throw InputError(where + ": '" + key + "' is " + object.at(key).dump() + "; expected a value of another type");
  }
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
  const GridTable* grid = surface.grid();
  if (!grid)
    throw std::invalid_argument("record_from_surface: an RBF surface needs its samples (use the overload with them)");
  SurfaceRecord record;
  record.kind = "grid";
  record.method = surface.method_name();
  record.definition = common_definition(surface).dump();
  record.data = grid->values();
  return record;
}

SurfaceRecord record_from_surface(const CoefficientSurface& surface, std::span<const double> rbf_points,
                                  std::span<const double> rbf_values) {
  const RbfSurface* rbf = surface.rbf();
  if (!rbf) return record_from_surface(surface);
  if (rbf_points.size() != rbf->sample_count() * rbf->axis_count() ||
      rbf_values.size() != rbf->sample_count() * rbf->output_count())
    throw std::invalid_argument("record_from_surface: the samples given are not the RBF's");
  SurfaceRecord record;
  record.kind = "rbf";
  record.method = std::string(rbf_kernel_name(rbf->kernel()));
  json definition = common_definition(surface);
  std::vector<double> scales;
  for (std::size_t a = 0; a < rbf->axis_count(); ++a) scales.push_back(rbf->length_scale(a));
  definition["rbf"] = {{"kernel", rbf_kernel_name(rbf->kernel())},
                       {"degree", rbf->polynomial_degree()},
                       {"smoothing", rbf->smoothing()},
                       {"length_scales", scales},
                       {"samples", rbf->sample_count()}};
  record.definition = definition.dump();
  record.data.assign(rbf_points.begin(), rbf_points.end());
  record.data.insert(record.data.end(), rbf_values.begin(), rbf_values.end());
  return record;
}

CoefficientSurface surface_from_record(const SurfaceRecord& record) {
  const std::string where = "surface '" + record.name + "'";
  json definition;
  try {
    definition = json::parse(record.definition);
  } catch (const json::exception& error) {
    throw InputError(where + ": its stored definition is not JSON (" + error.what() + ")");
  }
  const auto axes_json = member<json>(definition, "axes", where);
  const auto outputs_json = member<json>(definition, "outputs", where);
  if (!axes_json.is_array() || !outputs_json.is_array())
    throw InputError(where + ": 'axes' and 'outputs' must be arrays in its definition");
  std::vector<std::string> axis_names, axis_units, output_names, output_units;
  for (const auto& axis : axes_json) {
    axis_names.push_back(member<std::string>(axis, "name", where));
    axis_units.push_back(member<std::string>(axis, "unit", where));
  }
  for (const auto& output : outputs_json) {
    output_names.push_back(member<std::string>(output, "name", where));
    output_units.push_back(member<std::string>(output, "unit", where));
  }
  try {
    if (record.kind == "grid") {
      std::vector<GridAxis> axes;
      for (const auto& axis : axes_json)
        axes.push_back({member<std::string>(axis, "name", where), member<std::vector<double>>(axis, "breakpoints", where),
                        parse_extrapolation(member<std::string>(axis, "extrapolation", where))});
      return CoefficientSurface(GridTable(std::move(axes), output_names, record.data, parse_interpolation(record.method)),
                                axis_units, output_units);
    }
    if (record.kind == "rbf") {
      const auto rbf_json = member<json>(definition, "rbf", where);
      RbfOptions options;
      options.kernel = parse_rbf_kernel(member<std::string>(rbf_json, "kernel", where));
      options.polynomial_degree = member<int>(rbf_json, "degree", where);
      options.smoothing = member<double>(rbf_json, "smoothing", where);
      options.length_scales = member<std::vector<double>>(rbf_json, "length_scales", where);
      options.axis_names = axis_names;
      for (const auto& axis : axes_json)
        options.out_of_range.push_back(parse_rbf_policy(member<std::string>(axis, "extrapolation", where), where));
      const auto samples = member<std::size_t>(rbf_json, "samples", where);
      const std::size_t n_points = samples * axis_names.size();
      if (record.data.size() != n_points + samples * output_names.size())
        throw InputError(where + ": its data holds " + std::to_string(record.data.size()) + " numbers; expected " +
                         std::to_string(n_points + samples * output_names.size()) + " for " +
                         std::to_string(samples) + " samples");
      const std::span<const double> data(record.data);
      RbfSurface rbf(axis_names.size(), data.first(n_points), output_names.size(), data.subspan(n_points), options);
      return CoefficientSurface(std::move(rbf), axis_names, output_names, axis_units, output_units);
    }
  } catch (const InputError& error) {
    const std::string message = error.what();
    if (message.rfind(where, 0) == 0) throw;
    throw InputError(where + ": " + message);
  }
  throw InputError(where + ": kind '" + record.kind + "'; expected grid or rbf");
}

StoredSurface load_surface(Database& database, const std::string& name) {
  SurfaceRecord record = database.surface(name);
  CoefficientSurface surface = surface_from_record(record);
  return {std::move(record), std::move(surface)};
}

}  // namespace hydrocoef
