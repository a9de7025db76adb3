// query_surface (include/hydrocoef/surface.hpp): `hydrocoef query`, a stored
// surface at one point (values, standard deviations, gradients) or at every
// row of a CSV (src/surface/batch_query), with what the command prints.
#include "src/api/internal.hpp"
#include "src/api/surface_report.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "src/core/escape.hpp"
#include "src/core/text.hpp"
#include "src/surface/batch_query.hpp"

namespace hydrocoef {
inline namespace api {
namespace {

using surface_text::significant;

/// The point in the surface's axis order; InputError for an axis given
/// twice, an axis the surface lacks, or one left out.
std::vector<double> point_of(const SurfaceQueryOptions& options, const CoefficientSurface& surface) {
  const std::size_t n_axes = surface.axis_count();
  std::vector<double> point(n_axes, std::nan(""));
  for (const auto& [axis, value] : options.point) {
    const std::size_t a = surface.axis_index(axis);
    if (!std::isnan(point[a])) throw InputError("axis '" + axis + "' is given twice");
    point[a] = value;
  }
  for (std::size_t a = 0; a < n_axes; ++a)
    if (std::isnan(point[a]))
      throw InputError("no value for axis '" + surface.axis_names()[a] + "'; surface '" + options.name +
                       "' needs one value for each of its axes: " + join(surface.axis_names(), ", ") + " (e.g. " +
                       surface.axis_names()[a] + "=0.1)");
  return point;
}

std::string point_json(const SurfaceQueryOptions& options, const SurfaceQueryResult& r) {
  const std::size_t n_axes = r.axes.size();
  nlohmann::json json = {{"surface", options.name}, {"stale", r.stale}};
  for (std::size_t a = 0; a < n_axes; ++a) json["point"][r.axes[a]] = r.point[a];
  for (std::size_t k = 0; k < r.outputs.size(); ++k) {
    const auto& name = r.outputs[k];
    json["values"][name] = r.values[k];
    json["units"][name] = r.units[k];
    if (options.uncertainty) json["standard_deviation"][name] = r.standard_deviation[k];
    if (!r.new_run_standard_deviation.empty())
      json["new_run_standard_deviation"][name] = r.new_run_standard_deviation[k];
    if (options.gradient)
      for (std::size_t a = 0; a < n_axes; ++a) json["gradient"][name][r.axes[a]] = r.gradient[k * n_axes + a];
  }
  return escape::json_text(json, 2) + '\n';
}

std::string point_text(const SurfaceQueryOptions& options, const SurfaceQueryResult& r,
                       const std::vector<std::string>& axis_units) {
  const std::size_t n_axes = r.axes.size();
  std::ostringstream out;
  out << escape::one_line(options.name) << " at";
  for (std::size_t a = 0; a < n_axes; ++a)
    out << " " << escape::one_line(r.axes[a]) << "=" << significant(r.point[a], 8);
  out << " (forces on the body)\n";
  for (std::size_t k = 0; k < r.outputs.size(); ++k) {
    out << "  " << std::left << std::setw(4) << escape::one_line(r.outputs[k]) << std::setw(16)
        << significant(r.values[k], 9) << escape::one_line(r.units[k]);
    if (options.uncertainty)
      out << "  +/- " << significant(r.standard_deviation[k], 3) << " " << escape::one_line(r.units[k]) << " (1 sd"
          << (!r.new_run_standard_deviation.empty()
                  ? "; a new run there: +/- " + significant(r.new_run_standard_deviation[k], 3)
                  : std::string())
          << ")";
    out << '\n';
    if (options.gradient)
      for (std::size_t a = 0; a < n_axes; ++a) {
        const std::string& unit = axis_units[a];
        out << "      d" << escape::one_line(r.outputs[k]) << "/d" << std::setw(10) << escape::one_line(r.axes[a])
            << std::setw(16) << significant(r.gradient[k * n_axes + a], 9) << escape::one_line(r.units[k])
            << (unit.empty() ? "" : " per " + escape::one_line(unit)) << '\n';
      }
  }
  return out.str();
}

}  // namespace

void SurfaceQueryOptions::validate() const {
  if (!input.empty() && !point.empty()) throw InputError("give either a point (AXIS=VALUE ...) or --input, not both");
  if (input.empty() && point.empty())
    throw InputError("no point; expected AXIS=VALUE for each axis of the surface, or --input FILE (- for stdin)");
}

SurfaceQueryResult query_surface(const Database& db, const SurfaceQueryOptions& options) {
  options.validate();
  StoredSurface stored = [&] {
    auto& impl = Database::Access::impl(db);
    const std::lock_guard lock(impl.mutex);
    return load_surface(impl.open_store(), options.name);
  }();
  const CoefficientSurface& surface = stored.surface;
  SurfaceQueryResult r;
  r.surface = options.name;
  r.stale = stored.record.stale;
  if (r.stale) {
    r.warnings.push_back("surface '" + escape::one_line(stored.record.name) +
                         "' is stale: forces of its body changed since it was built (hydrocoef surface rebuild " +
                         escape::one_line(stored.record.name) + ")");
    if (options.warning) options.warning(r.warnings.back());
  }
  r.axes = surface.axis_names();
  r.outputs = surface.output_names();
  r.units = surface.output_units();

  if (!options.input.empty()) {
    r.points = query_csv_batch(
        surface, CsvBatchRequest{options.name, options.input, options.output, options.gradient, options.uncertainty});
    r.output = options.output;
    if (options.output == "-") return r;
    SurfaceQueryResult::Access::set(
        r, "",
        escape::json_text(nlohmann::json{{"surface", options.name}, {"points", r.points}, {"output", options.output}},
                          2) +
            '\n',
        std::to_string(r.points) + " points of surface '" + escape::one_line(options.name) + "' written to " +
            escape::one_line(options.output));
    return r;
  }

  r.point = point_of(options, surface);
  const std::size_t n_axes = surface.axis_count(), n_out = surface.output_count();
  r.values.resize(n_out);
  if (options.gradient) r.gradient.resize(n_out * n_axes);
  if (options.uncertainty) {
    r.standard_deviation.resize(n_out);
    surface.evaluate_with_standard_deviation(r.point, r.values, r.standard_deviation, r.gradient);
    if (surface.gp())
      for (std::size_t k = 0; k < n_out; ++k)
        r.new_run_standard_deviation.push_back(surface.gp()->output(k).run_sd(r.standard_deviation[k]));
  } else if (options.gradient) {
    surface.evaluate_with_gradient(r.point, r.values, r.gradient);
  } else {
    surface.evaluate(r.point, r.values);
  }
  SurfaceQueryResult::Access::set(r, point_text(options, r, surface.axis_units()), point_json(options, r), "");
  return r;
}

std::string SurfaceQueryResult::text() const { return text_; }
std::string SurfaceQueryResult::json() const { return json_; }
std::string SurfaceQueryResult::note() const { return note_; }

}  // namespace api
}  // namespace hydrocoef
