// A body's reference data and the runs' non-dimensional coefficients
// (include/hydrocoef/reference.hpp) in Python: set_body_reference,
// body_references and run_coefficients, module functions taking a Database.
// Options are keyword arguments with the C++ defaults; results are objects
// with the C++ fields as attributes (columns as numpy arrays), .text() (what
// the CLI prints) and .json() (what --json prints).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <string>
#include <vector>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;

/// The calls that make the result classes here.
constexpr const char* kReferenceMadeBy = "set_body_reference, body_references and run_coefficients";

py::array_t<double> array(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

template <class T>
std::optional<T> optional_value(const py::object& value) {
  return value.is_none() ? std::nullopt : std::optional<T>(value.cast<T>());
}

constexpr const char* kCoefficientNames[] = {"C_X", "C_Y", "C_Z", "C_K", "C_M", "C_N"};

}  // namespace

void register_reference(py::module_& m) {
  py::class_<hydrocoef::BodyReference>(m, "BodyReference", py::is_final(), made_by_the_module_only(kReferenceMadeBy),
                                       "A body's reference data (SI; nan where not given).")
      .def_readonly("body", &hydrocoef::BodyReference::body)
      .def_readonly("length", &hydrocoef::BodyReference::length, "Reference length L [m].")
      .def_readonly("areas", &hydrocoef::BodyReference::areas, "Reference areas by name [m^2].")
      .def_readonly("default_area", &hydrocoef::BodyReference::default_area)
      .def_readonly("draft", &hydrocoef::BodyReference::draft, "[m]")
      .def_readonly("displaced_volume", &hydrocoef::BodyReference::displaced_volume, "[m^3]")
      .def_readonly("moment_reference_point", &hydrocoef::BodyReference::moment_reference_point,
                    "[m], body axes (nan: each run's own reference point).")
      .def_readonly("updated_at", &hydrocoef::BodyReference::updated_at, "'' when the body has no reference data.")
      .def("text", &hydrocoef::BodyReference::text, "What `hydrocoef body set` prints.")
      .def("json", &hydrocoef::BodyReference::json, "What `hydrocoef body set --json` prints.");

  py::class_<hydrocoef::BodyReferences>(m, "BodyReferences", py::is_final(), made_by_the_module_only(kReferenceMadeBy),
                                        "The reference data of a database's bodies.")
      .def_readonly("database", &hydrocoef::BodyReferences::database)
      .def_readonly("bodies", &hydrocoef::BodyReferences::bodies)
      .def("text", &hydrocoef::BodyReferences::text, "What `hydrocoef body show` prints.")
      .def("json", &hydrocoef::BodyReferences::json, "What `hydrocoef body show --json` prints.");

  py::class_<hydrocoef::RunCoefficients>(m, "RunCoefficients", py::is_final(),
                                         made_by_the_module_only(kReferenceMadeBy),
                                         "The selected runs' coefficients as columns (numpy arrays; nan where "
                                         "not defined, `note` says why).")
      .def_readonly("database", &hydrocoef::RunCoefficients::database)
      .def_readonly("gravity", &hydrocoef::RunCoefficients::gravity, "g of the Froude number [m/s^2].")
      .def_property_readonly(
          "references",
          [](const hydrocoef::RunCoefficients& r) {
            py::list out;
            for (const auto& ref : r.references)
              out.append(py::dict("body"_a = ref.body, "area_name"_a = ref.area_name, "area"_a = ref.area,
                                  "length"_a = ref.length, "moment_reference_point"_a = ref.moment_reference_point));
            return out;
          })
      .def_property_readonly("id",
                             [](const hydrocoef::RunCoefficients& r) {
                               return py::array_t<std::int64_t>(static_cast<py::ssize_t>(r.id.size()), r.id.data());
                             })
      .def_readonly("body", &hydrocoef::RunCoefficients::body)
      .def_property_readonly("velocity",
                             [](const hydrocoef::RunCoefficients& r) {
                               py::dict out;
                               for (std::size_t c = 0; c < 6; ++c) out[kVelocityNames[c]] = array(r.velocity[c]);
                               return out;
                             })
      .def_property_readonly("disturbances",
                             [](const hydrocoef::RunCoefficients& r) {
                               py::dict out;
                               for (const auto& [name, column] : r.disturbances) out[py::str(name)] = array(column);
                               return out;
                             })
      .def_property_readonly("speed", [](const hydrocoef::RunCoefficients& r) { return array(r.speed); })
      .def_property_readonly("density", [](const hydrocoef::RunCoefficients& r) { return array(r.density); })
      .def_property_readonly("kinematic_viscosity",
                             [](const hydrocoef::RunCoefficients& r) { return array(r.kinematic_viscosity); })
      .def_property_readonly("reynolds", [](const hydrocoef::RunCoefficients& r) { return array(r.reynolds); })
      .def_property_readonly("froude", [](const hydrocoef::RunCoefficients& r) { return array(r.froude); })
      .def_property_readonly("coefficients",
                             [](const hydrocoef::RunCoefficients& r) {
                               py::dict out;
                               for (std::size_t c = 0; c < 6; ++c) out[kCoefficientNames[c]] = array(r.coefficient[c]);
                               return out;
                             })
      .def_readonly("note", &hydrocoef::RunCoefficients::note)
      .def("text", &hydrocoef::RunCoefficients::text, "What `hydrocoef runs --coefficients` prints.")
      .def("json", &hydrocoef::RunCoefficients::json, "What `hydrocoef runs --coefficients --json` prints.")
      .def("csv", &hydrocoef::RunCoefficients::csv, "What `hydrocoef runs --coefficients --csv` prints.");

  m.def(
      "set_body_reference",
      [](py::handle self, const std::string& body, const py::object& length, const py::object& areas,
         const py::object& default_area, const py::object& remove_areas, const py::object& draft,
         const py::object& volume, const py::object& moment_point, const py::object& unset) {
        hydrocoef::BodyReferenceOptions options;
        options.body = body;
        options.length = optional_value<double>(length);
        if (!areas.is_none()) options.areas = areas.cast<std::map<std::string, double>>();
        options.default_area = default_area.is_none() ? "" : default_area.cast<std::string>();
        options.remove_areas = texts(remove_areas, "remove_areas");
        options.draft = optional_value<double>(draft);
        options.displaced_volume = optional_value<double>(volume);
        options.moment_reference_point = optional_value<std::array<double, 3>>(moment_point);
        options.unset = texts(unset, "unset");
        auto& database = database_of(self);
        py::gil_scoped_release release;
        return hydrocoef::set_body_reference(database, options);
      },
      "database"_a, "body"_a, py::kw_only(), "length"_a = py::none(), "areas"_a = py::none(),
      "default_area"_a = py::none(), "remove_areas"_a = py::none(), "draft"_a = py::none(), "volume"_a = py::none(),
      "moment_point"_a = py::none(), "unset"_a = py::none(),
      R"doc(Sets a body's reference data, as `hydrocoef body set` does: length L [m], areas {name: A [m^2]}
(added, or replacing one of that name), default_area, remove_areas, draft [m], volume (displaced) [m^3],
moment_point (x, y, z) [m] in body axes, unset ("length", "draft", "volume", "moment-point"). What is not given
stays as it was. Returns the BodyReference stored. Raises InputError as the CLI would.)doc");

  m.def(
      "body_references",
      [](py::handle self, const py::object& body) {
        auto& database = database_of(self);
        const std::string name = body.is_none() ? "" : body.cast<std::string>();
        py::gil_scoped_release release;
        return hydrocoef::body_references(database, name);
      },
      "database"_a, "body"_a = py::none(),
      "The reference data of one body, or of every body, as `hydrocoef body show`. Returns a BodyReferences.");

  m.def(
      "run_coefficients",
      [](py::handle self, const py::object& body, const py::object& where, const py::object& exclude_runs,
         const py::object& area) {
        hydrocoef::CoefficientOptions options;
        options.body = body.is_none() ? "" : body.cast<std::string>();
        options.where = texts(where, "where");
        options.exclude_runs = run_ids(exclude_runs, "exclude_runs");
        options.area = area.is_none() ? "" : area.cast<std::string>();
        auto& database = database_of(self);
        py::gil_scoped_release release;
        return hydrocoef::run_coefficients(database, options);
      },
      "database"_a, py::kw_only(), "body"_a = py::none(), "where"_a = py::none(), "exclude_runs"_a = py::none(),
      "area"_a = py::none(),
      R"doc(The selected runs' non-dimensional coefficients, as `hydrocoef runs --coefficients`:
C_X..C_N = F / (1/2 rho U^2 A), M / (1/2 rho U^2 A L) with the body's reference area (area: its name; default
the body's default) and length, Re = U L / nu, Fn = U / sqrt(g L), g = 9.80665 m/s^2; U = |(u, v, w)|; body
axes, forces on the body. Returns a RunCoefficients (numpy columns, nan where not defined).)doc");

  for (const char* name : {"BodyReference", "BodyReferences", "RunCoefficients"})
    m.attr(name).attr("__module__") = "hydrocoef";
}

}  // namespace hydrocoef_python
