// Derivative exports and scaling in Python: export_derivatives (`hydrocoef
// derivatives export`: stored derivative models as CSV, JSON, gz-sim
// parameters or a MATLAB function, include/hydrocoef/exports.hpp) and
// scale_surge_resistance (`hydrocoef scale`: a surge resistance curve or a
// stored surge law between scales, include/hydrocoef/scaling.hpp), with
// their results as objects whose attributes are the C++ fields, plus .text()
// and .json() (what the CLI prints).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>
#include <optional>
#include <string>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;

}  // namespace

void register_derivative_exports(py::module_& m) {
  using hydrocoef::DerivativeExportResult;
  using hydrocoef::ResistanceScalingPoint;
  using hydrocoef::ResistanceScalingResult;
  py::class_<DerivativeExportResult>(m, "DerivativeExportResult", py::is_final(),
                                     made_by_the_module_only("export_derivatives"),
                                     "What `hydrocoef derivatives export` wrote.")
      .def_readonly("database", &DerivativeExportResult::database)
      .def_readonly("format", &DerivativeExportResult::format)
      .def_readonly("form", &DerivativeExportResult::form)
      .def_readonly("file", &DerivativeExportResult::file)
      .def_readonly("body", &DerivativeExportResult::body)
      .def_readonly("models", &DerivativeExportResult::models)
      .def_readonly("outputs", &DerivativeExportResult::outputs)
      .def_readonly("terms", &DerivativeExportResult::terms)
      .def_readonly("stale", &DerivativeExportResult::stale)
      .def_readonly("function_name", &DerivativeExportResult::function_name)
      .def_readonly("inputs", &DerivativeExportResult::inputs)
      .def_readonly("dropped", &DerivativeExportResult::dropped)
      .def_readonly("notes", &DerivativeExportResult::notes)
      .def_readonly("bytes", &DerivativeExportResult::bytes)
      .def_readonly("content", &DerivativeExportResult::content, "The file's text, as written.")
      .def("text", &DerivativeExportResult::text, "What the hydrocoef CLI prints.")
      .def("json", &DerivativeExportResult::json, "What the hydrocoef CLI prints with --json (a JSON text).");
  py::class_<ResistanceScalingPoint>(m, "ResistanceScalingPoint", py::is_final(),
                                     made_by_the_module_only("scale_surge_resistance"),
                                     "One point at both scales (SI).")
      .def_readonly("speed_from", &ResistanceScalingPoint::speed_from)
      .def_readonly("speed_to", &ResistanceScalingPoint::speed_to)
      .def_readonly("force_from", &ResistanceScalingPoint::force_from)
      .def_readonly("force_to", &ResistanceScalingPoint::force_to)
      .def_readonly("resistance_from", &ResistanceScalingPoint::resistance_from)
      .def_readonly("resistance_to", &ResistanceScalingPoint::resistance_to)
      .def_readonly("froude_from", &ResistanceScalingPoint::froude_from)
      .def_readonly("froude_to", &ResistanceScalingPoint::froude_to)
      .def_readonly("reynolds_from", &ResistanceScalingPoint::reynolds_from)
      .def_readonly("reynolds_to", &ResistanceScalingPoint::reynolds_to)
      .def_readonly("friction_from", &ResistanceScalingPoint::friction_from)
      .def_readonly("friction_to", &ResistanceScalingPoint::friction_to)
      .def_readonly("wave", &ResistanceScalingPoint::wave)
      .def_readonly("residual", &ResistanceScalingPoint::residual)
      .def_readonly("total_from", &ResistanceScalingPoint::total_from)
      .def_readonly("total_to", &ResistanceScalingPoint::total_to);
  py::class_<ResistanceScalingResult>(m, "ResistanceScalingResult", py::is_final(),
                                      made_by_the_module_only("scale_surge_resistance"),
                                      "What `hydrocoef scale` computed.")
      .def_readonly("method", &ResistanceScalingResult::method)
      .def_readonly("sign", &ResistanceScalingResult::sign)
      .def_readonly("wave", &ResistanceScalingResult::wave)
      .def_readonly("one_plus_k", &ResistanceScalingResult::one_plus_k)
      .def_readonly("form_factor_method", &ResistanceScalingResult::form_factor_method)
      .def_readonly("prohaska_slope", &ResistanceScalingResult::prohaska_slope)
      .def_readonly("form_factor", &ResistanceScalingResult::form_factor)
      .def_readonly("points", &ResistanceScalingResult::points)
      .def_readonly("assumptions", &ResistanceScalingResult::assumptions)
      .def_readonly("fit", &ResistanceScalingResult::fit)
      .def_readonly("terms", &ResistanceScalingResult::terms)
      .def_readonly("coefficients_from", &ResistanceScalingResult::coefficients_from)
      .def_readonly("coefficients_to", &ResistanceScalingResult::coefficients_to)
      .def_readonly("units", &ResistanceScalingResult::units)
      .def_readonly("max_relative_deviation", &ResistanceScalingResult::max_relative_deviation)
      .def("text", &ResistanceScalingResult::text, "What the hydrocoef CLI prints.")
      .def("json", &ResistanceScalingResult::json, "What the hydrocoef CLI prints with --json (a JSON text).");

  m.def(
      "export_derivatives",
      [](py::handle db, const std::vector<std::string>& names, const std::string& format, const py::object& output,
         const std::string& form, const py::object& length, const py::object& speed, const py::object& density,
         const py::object& draft, const py::object& mass, const py::object& volume, double gravity,
         const py::object& link, const py::object& link_axes, bool drop_unrepresentable, const py::object& added_mass,
         const py::object& added_mass_matrix, const py::object& mass_diagonal, const py::object& mass_matrix) {
        hydrocoef::DerivativeExportOptions options;
        options.names = names;
        options.format = format;
        options.output = py::str(output).cast<std::string>();
        options.form = form;
        set_reference_values(options, length, speed, density, draft, mass, volume, gravity);
        options.link = optional_text(link);
        options.link_axes = optional_text(link_axes);
        options.drop_unrepresentable = drop_unrepresentable;
        options.added_mass = optional_text(added_mass);
        options.added_mass_matrix = optional_text(added_mass_matrix);
        options.mass_diagonal = optional_text(mass_diagonal);
        options.mass_matrix = optional_text(mass_matrix);
        const auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::export_derivatives(database, options);
      },
      "database"_a, "names"_a, py::kw_only(), "format"_a, "output"_a, "form"_a = "dimensional", "length"_a = py::none(),
      "speed"_a = py::none(), "density"_a = py::none(), "draft"_a = py::none(), "mass"_a = py::none(),
      "volume"_a = py::none(), "gravity"_a = 9.80665, "link"_a = py::none(), "link_axes"_a = py::none(),
      "drop_unrepresentable"_a = false, "added_mass"_a = py::none(), "added_mass_matrix"_a = py::none(),
      "mass_diagonal"_a = py::none(), "mass_matrix"_a = py::none(),
      "Writes stored derivative models as csv, json, gazebo or matlab, as `hydrocoef derivatives export`.");
  m.def(
      "scale_surge_resistance",
      [](const py::object& db, double from_length, double from_area, double from_viscosity, double from_density,
         double to_length, double to_area, double to_viscosity, double to_density, const std::string& wave,
         const std::string& form_factor, const py::object& points, const std::string& fit, const py::object& speeds,
         const py::object& target_speeds, const py::object& from_roughness, const py::object& to_roughness,
         const py::object& from_air_area, const py::object& to_air_area, double gravity, const std::string& sign) {
        hydrocoef::ResistanceScalingOptions options;
        options.from_length = from_length;
        options.from_area = from_area;
        options.from_viscosity = from_viscosity;
        options.from_density = from_density;
        options.to_length = to_length;
        options.to_area = to_area;
        options.to_viscosity = to_viscosity;
        options.to_density = to_density;
        options.wave = wave;
        options.form_factor = form_factor;
        if (!points.is_none())
          for (const auto& [speed, force] : points.cast<std::vector<std::pair<double, double>>>()) {
            options.speeds.push_back(speed);
            options.forces.push_back(force);
          }
        options.fit = fit;
        options.sample_speeds = numbers(speeds);
        options.target_speeds = numbers(target_speeds);
        options.from_roughness = or_nan(from_roughness);
        options.to_roughness = or_nan(to_roughness);
        options.from_air_area = or_nan(from_air_area);
        options.to_air_area = or_nan(to_air_area);
        options.gravity = gravity;
        options.sign = sign;
        if (db.is_none()) {
          const py::gil_scoped_release release;
          return hydrocoef::scale_surge_resistance(options);
        }
        const auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::scale_surge_resistance(database, options);
      },
      "database"_a = py::none(), py::kw_only(), "from_length"_a, "from_area"_a, "from_viscosity"_a, "from_density"_a,
      "to_length"_a, "to_area"_a, "to_viscosity"_a, "to_density"_a, "wave"_a, "form_factor"_a = "",
      "points"_a = py::none(), "fit"_a = "", "speeds"_a = py::none(), "target_speeds"_a = py::none(),
      "from_roughness"_a = py::none(), "to_roughness"_a = py::none(), "from_air_area"_a = py::none(),
      "to_air_area"_a = py::none(), "gravity"_a = 9.80665, "sign"_a = "on-body",
      "A surge resistance curve (points [(U, X), ...]) or a stored surge law (fit, speeds; needs the database) from "
      "one scale to another, as `hydrocoef scale`.");
  for (const char* name : {"DerivativeExportResult", "ResistanceScalingPoint", "ResistanceScalingResult"})
    m.attr(name).attr("__module__") = "hydrocoef";
}

}  // namespace hydrocoef_python
