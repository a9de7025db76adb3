// Exports in Python: Database.export_surface (`hydrocoef export`, a gridded
// surface for another tool), Database.export_forcecoeffs (`hydrocoef export
// --format openfoam-forcecoeffs`, runs as OpenFOAM forceCoeffs files) and
// Database.export_gazebo (`hydrocoef export-gazebo`), the C++ API's calls of
// include/hydrocoef/exports.hpp, and their results (TableExportResult,
// ForceCoeffsExportResult, GazeboExportResult) with text() and json(), what
// the CLI prints.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <optional>
#include <string>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;
using hydrocoef::Database;

/// The calls that make the result classes here.
constexpr const char* kExportsMadeBy =
    "Database.export_surface(...), Database.export_gazebo(...) and Database.export_forcecoeffs(...)";

std::optional<double> optional_number(const py::object& value) {
  if (value.is_none()) return std::nullopt;
  return value.cast<double>();
}

}  // namespace

void bind_exports(py::module_& m, py::class_<Database>& database) {
  py::class_<hydrocoef::TableExportAxis>(m, "TableExportAxis", py::is_final(), made_by_the_module_only(kExportsMadeBy))
      .def_readonly("name", &hydrocoef::TableExportAxis::name)
      .def_readonly("unit", &hydrocoef::TableExportAxis::unit)
      .def_readonly("breakpoints", &hydrocoef::TableExportAxis::breakpoints, "How many.")
      .def_readonly("lower", &hydrocoef::TableExportAxis::lower)
      .def_readonly("upper", &hydrocoef::TableExportAxis::upper)
      .def_readonly("extrapolation", &hydrocoef::TableExportAxis::extrapolation);
  py::class_<hydrocoef::TableExportResult>(m, "TableExportResult", py::is_final(),
                                           made_by_the_module_only(kExportsMadeBy), "What `hydrocoef export` wrote.")
      .def_readonly("surface", &hydrocoef::TableExportResult::surface)
      .def_readonly("body", &hydrocoef::TableExportResult::body)
      .def_readonly("format", &hydrocoef::TableExportResult::format)
      .def_readonly("method", &hydrocoef::TableExportResult::method)
      .def_readonly("content_sha256", &hydrocoef::TableExportResult::content_sha256)
      .def_readonly("runs", &hydrocoef::TableExportResult::runs)
      .def_readonly("stale", &hydrocoef::TableExportResult::stale)
      .def_readonly("nodes", &hydrocoef::TableExportResult::nodes)
      .def_readonly("files", &hydrocoef::TableExportResult::files)
      .def_readonly("surfaces", &hydrocoef::TableExportResult::surfaces)
      .def_readonly("vehicle", &hydrocoef::TableExportResult::vehicle)
      .def_readonly("axes", &hydrocoef::TableExportResult::axes)
      .def_readonly("outputs", &hydrocoef::TableExportResult::outputs)
      .def_readonly("output_units", &hydrocoef::TableExportResult::output_units)
      .def_readonly("notes", &hydrocoef::TableExportResult::notes)
      .def("text", &hydrocoef::TableExportResult::text)
      .def("json", &hydrocoef::TableExportResult::json);
  py::class_<hydrocoef::ForceCoeffsExportRun>(m, "ForceCoeffsExportRun", py::is_final(),
                                              made_by_the_module_only(kExportsMadeBy), "One run's forceCoeffs file.")
      .def_readonly("id", &hydrocoef::ForceCoeffsExportRun::id)
      .def_readonly("body", &hydrocoef::ForceCoeffsExportRun::body)
      .def_readonly("file", &hydrocoef::ForceCoeffsExportRun::file)
      .def_readonly("axes", &hydrocoef::ForceCoeffsExportRun::axes)
      .def_readonly("rows_from", &hydrocoef::ForceCoeffsExportRun::rows_from)
      .def_readonly("rows", &hydrocoef::ForceCoeffsExportRun::rows)
      .def_readonly("rho", &hydrocoef::ForceCoeffsExportRun::rho)
      .def_readonly("mag_u_inf", &hydrocoef::ForceCoeffsExportRun::mag_u_inf)
      .def_readonly("l_ref", &hydrocoef::ForceCoeffsExportRun::l_ref)
      .def_readonly("a_ref", &hydrocoef::ForceCoeffsExportRun::a_ref)
      .def_readonly("area_name", &hydrocoef::ForceCoeffsExportRun::area_name)
      .def_readonly("cofr", &hydrocoef::ForceCoeffsExportRun::cofr)
      .def_readonly("last_coefficients", &hydrocoef::ForceCoeffsExportRun::last_coefficients,
                    "Cd, Cs, Cl, CmRoll, CmPitch, CmYaw of the last row, as written.");
  py::class_<hydrocoef::ForceCoeffsExportResult>(m, "ForceCoeffsExportResult", py::is_final(),
                                                 made_by_the_module_only(kExportsMadeBy),
                                                 "What `hydrocoef export --format openfoam-forcecoeffs` wrote.")
      .def_readonly("database", &hydrocoef::ForceCoeffsExportResult::database)
      .def_readonly("directory", &hydrocoef::ForceCoeffsExportResult::directory)
      .def_readonly("precision", &hydrocoef::ForceCoeffsExportResult::precision)
      .def_readonly("runs", &hydrocoef::ForceCoeffsExportResult::runs)
      .def_readonly("values", &hydrocoef::ForceCoeffsExportResult::values)
      .def_readonly("exact", &hydrocoef::ForceCoeffsExportResult::exact)
      .def_readonly("one_ulp", &hydrocoef::ForceCoeffsExportResult::one_ulp)
      .def_readonly("notes", &hydrocoef::ForceCoeffsExportResult::notes)
      .def("text", &hydrocoef::ForceCoeffsExportResult::text)
      .def("json", &hydrocoef::ForceCoeffsExportResult::json);
  py::class_<hydrocoef::GazeboFitExport>(m, "GazeboFitExport", py::is_final(), made_by_the_module_only(kExportsMadeBy))
      .def_readonly("dof", &hydrocoef::GazeboFitExport::dof)
      .def_readonly("variable", &hydrocoef::GazeboFitExport::variable)
      .def_readonly("name", &hydrocoef::GazeboFitExport::name)
      .def_readonly("id", &hydrocoef::GazeboFitExport::id)
      .def_readonly("terms", &hydrocoef::GazeboFitExport::terms)
      .def_readonly("stored_sign", &hydrocoef::GazeboFitExport::stored_sign)
      .def_readonly("linear", &hydrocoef::GazeboFitExport::linear)
      .def_readonly("quadratic", &hydrocoef::GazeboFitExport::quadratic)
      .def_readonly("linear_unit", &hydrocoef::GazeboFitExport::linear_unit)
      .def_readonly("quadratic_unit", &hydrocoef::GazeboFitExport::quadratic_unit)
      .def_readonly("runs", &hydrocoef::GazeboFitExport::runs)
      .def_readonly("dropped_constant", &hydrocoef::GazeboFitExport::dropped_constant);
  py::class_<hydrocoef::GazeboElementExport>(m, "GazeboElementExport", py::is_final(),
                                             made_by_the_module_only(kExportsMadeBy))
      .def_readonly("name", &hydrocoef::GazeboElementExport::name)
      .def_readonly("values", &hydrocoef::GazeboElementExport::values)
      .def_readonly("unit", &hydrocoef::GazeboElementExport::unit);
  py::class_<hydrocoef::GazeboExportResult>(m, "GazeboExportResult", py::is_final(),
                                            made_by_the_module_only(kExportsMadeBy),
                                            "What `hydrocoef export-gazebo` wrote; matrices 6x6 row-major (36).")
      .def_readonly("body", &hydrocoef::GazeboExportResult::body)
      .def_readonly("flavor", &hydrocoef::GazeboExportResult::flavor)
      .def_readonly("file", &hydrocoef::GazeboExportResult::file)
      .def_readonly("frame", &hydrocoef::GazeboExportResult::frame)
      .def_readonly("link_name", &hydrocoef::GazeboExportResult::link_name)
      .def_readonly("linear_b", &hydrocoef::GazeboExportResult::linear_b)
      .def_readonly("quadratic_b", &hydrocoef::GazeboExportResult::quadratic_b)
      .def_readonly("added_mass_b", &hydrocoef::GazeboExportResult::added_mass_b)
      .def_readonly("added_mass_source", &hydrocoef::GazeboExportResult::added_mass_source)
      .def_readonly("linearized_at", &hydrocoef::GazeboExportResult::linearized_at)
      .def_readonly("fits", &hydrocoef::GazeboExportResult::fits)
      .def_readonly("missing", &hydrocoef::GazeboExportResult::missing)
      .def_readonly("elements", &hydrocoef::GazeboExportResult::elements)
      .def_readonly("notes", &hydrocoef::GazeboExportResult::notes)
      .def("text", &hydrocoef::GazeboExportResult::text)
      .def("json", &hydrocoef::GazeboExportResult::json);

  database
      .def(
          "export_surface",
          [](py::handle self, const std::string& name, const std::string& format, const py::object& output,
             bool single_precision, const std::string& identifier, const std::vector<std::string>& surfaces,
             const py::object& vehicle) {
            hydrocoef::TableExportOptions options;
            options.name = name;
            options.format = format;
            options.output = py::str(output).cast<std::string>();
            options.single_precision = single_precision;
            options.identifier = identifier;
            options.surfaces = surfaces;
            if (!vehicle.is_none()) options.vehicle = py::str(vehicle).cast<std::string>();
            Database& d = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::export_surface(d, options);
          },
          "name"_a, py::kw_only(), "format"_a, "output"_a, "single_precision"_a = false, "identifier"_a = "",
          "surfaces"_a = std::vector<std::string>{}, "vehicle"_a = py::none(),
          R"doc(Writes a stored gridded surface for another tool, as `hydrocoef export`: format csv, csv-wide,
json, c (single_precision, identifier: the C header's), mat, jsbsim, vtk, daveml or runtime (surfaces:
further surfaces of the same body in the runtime file; vehicle: a vehicle file whose whole dynamics model the
runtime file holds too, name then being its body); output the file.
Returns a TableExportResult; InputError (nothing written) for a surface that is not gridded.)doc")
      .def(
          "export_forcecoeffs",
          [](py::handle self, const py::object& output, const std::string& body, const py::object& where,
             const py::object& exclude_runs, const std::string& area, const std::string& axes, int precision,
             bool mean_only) {
            hydrocoef::ForceCoeffsExportOptions options;
            options.output = py::str(output).cast<std::string>();
            options.body = body;
            options.where = texts(where, "where");
            options.exclude_runs = run_ids(exclude_runs, "exclude_runs");
            options.area = area;
            options.axes = axes;
            options.precision = precision;
            options.mean_only = mean_only;
            Database& d = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::export_forcecoeffs(d, options);
          },
          py::kw_only(), "output"_a, "body"_a = "", "where"_a = py::none(), "exclude_runs"_a = py::none(),
          "area"_a = "", "axes"_a = "", "precision"_a = 16, "mean_only"_a = false,
          R"doc(Writes the selected runs as OpenFOAM forceCoeffs files (v1912 coefficient.dat), one per run under
the folder output, as `hydrocoef export --format openfoam-forcecoeffs`: body, where, exclude_runs select the
runs; area the body's area used as Aref; axes the case's axes ("-x,y,-z", CFD to body; default each run's, as
imported); precision digits after the point (16: exact); mean_only one row of the stored forces.
Returns a ForceCoeffsExportResult; InputError (nothing written) for a run without density, speed or one of
X..N, or a body without reference length or area.)doc")
      .def(
          "export_gazebo",
          [](py::handle self, const std::string& body, const std::string& flavor, const py::object& output,
             const py::object& fits, const py::object& added_mass, const py::object& added_mass_matrix,
             const py::object& sphere_radius, const py::object& rho, const py::object& added_mass_rotation,
             const py::object& added_mass_from_database, const py::object& same, const py::object& zero,
             const py::object& added_mass_period, bool drop_constant, bool allow_missing, bool allow_unphysical,
             const py::object& linearize_at, const py::object& link, const py::object& link_axes,
             const py::object& where, const py::object& exclude_runs) {
            hydrocoef::GazeboExportOptions options;
            options.body = body;
            options.flavor = flavor;
            options.output = py::str(output).cast<std::string>();
            options.fits = texts(fits, "fits");
            // Number lists are given as the CLI takes them; a sequence of numbers is joined.
            const auto number_list = [](const py::object& value) -> std::optional<std::string> {
              if (value.is_none()) return std::nullopt;
              if (py::isinstance<py::str>(value)) return value.cast<std::string>();
              std::string text;
              for (const auto& item : value) text += (text.empty() ? "" : ",") + py::repr(item).cast<std::string>();
              return text;
            };
            options.added_mass = number_list(added_mass);
            options.added_mass_matrix = optional_text(added_mass_matrix);
            options.sphere_radius = optional_number(sphere_radius);
            options.rho = optional_number(rho);
            options.added_mass_rotation = number_list(added_mass_rotation);
            options.added_mass_from_database = optional_text(added_mass_from_database);
            options.same = texts(same, "same");
            options.zero = texts(zero, "zero");
            options.added_mass_period = optional_number(added_mass_period);
            options.drop_constant = drop_constant;
            options.allow_missing = allow_missing;
            options.allow_unphysical = allow_unphysical;
            options.linearize_at = optional_number(linearize_at);
            options.link = optional_text(link);
            options.link_axes = optional_text(link_axes);
            options.where = texts(where, "where");
            options.exclude_runs = run_ids(exclude_runs, "exclude_runs");
            Database& d = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::export_gazebo(d, options);
          },
          "body"_a, py::kw_only(), "flavor"_a, "output"_a, "fits"_a = py::none(), "added_mass"_a = py::none(),
          "added_mass_matrix"_a = py::none(), "sphere_radius"_a = py::none(), "rho"_a = py::none(),
          "added_mass_rotation"_a = py::none(), "added_mass_from_database"_a = py::none(), "same"_a = py::none(),
          "zero"_a = py::none(), "added_mass_period"_a = py::none(), "drop_constant"_a = false,
          "allow_missing"_a = false, "allow_unphysical"_a = false, "linearize_at"_a = py::none(), "link"_a = py::none(),
          "link_axes"_a = py::none(), "where"_a = py::none(), "exclude_runs"_a = py::none(),
          R"doc(Writes a body's damping-law fits and an added mass as Gazebo parameters, as `hydrocoef
export-gazebo`: flavor "uuv" or "gz"; fits ["DOF=FITNAME", ...]; exactly one added mass: added_mass
(six numbers, or "d1,...,d6"), added_mass_matrix (a file), sphere_radius with rho (and
added_mass_rotation), or added_mass_from_database (a body; same, zero, added_mass_period).
Returns a GazeboExportResult; InputError, nothing written, when the flavor cannot express a law.)doc");
}

}  // namespace hydrocoef_python
