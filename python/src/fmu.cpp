// The FMU export of include/hydrocoef/fmu.hpp in Python: export_fmu(db, body,
// surface=... or vehicle=..., output=...), as `hydrocoef export-fmu`. The result is an object
// with the C++ fields as attributes, .text() (what the CLI prints) and
// .json() (what --json prints).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;

/// The call that makes the result classes here.
constexpr const char* kFmuMadeBy = "export_fmu";

}  // namespace

void register_fmu(py::module_& m) {
  using hydrocoef::FmuExportResult;
  using hydrocoef::FmuVariable;
  py::class_<FmuVariable>(m, "FmuVariable", py::is_final(), made_by_the_module_only(kFmuMadeBy),
                          "One Real variable of an FMU, as modelDescription.xml states it.")
      .def_readonly("value_reference", &FmuVariable::value_reference)
      .def_readonly("name", &FmuVariable::name)
      .def_readonly("causality", &FmuVariable::causality, "input, output or parameter.")
      .def_readonly("unit", &FmuVariable::unit)
      .def_readonly("start", &FmuVariable::start, "Inputs and parameters: the start value; None for outputs.")
      .def_readonly("description", &FmuVariable::description);
  py::class_<FmuExportResult>(m, "FmuExportResult", py::is_final(), made_by_the_module_only(kFmuMadeBy),
                              "What `hydrocoef export-fmu` wrote.")
      .def_readonly("body", &FmuExportResult::body)
      .def_readonly("surface", &FmuExportResult::surface, "The surface (kind surface; '' otherwise).")
      .def_readonly("vehicle", &FmuExportResult::vehicle, "The vehicle's name (kind vehicle; '' otherwise).")
      .def_readonly("kind", &FmuExportResult::kind, "The FMU's model kind: surface or vehicle.")
      .def_readonly("model_identifier", &FmuExportResult::model_identifier)
      .def_readonly("guid", &FmuExportResult::guid)
      .def_readonly("file", &FmuExportResult::file)
      .def_readonly("runtime_file_bytes", &FmuExportResult::runtime_file_bytes)
      .def_readonly("binary_bytes", &FmuExportResult::binary_bytes)
      .def_readonly("fmu_bytes", &FmuExportResult::fmu_bytes)
      .def_readonly("variables", &FmuExportResult::variables)
      .def_readonly("notes", &FmuExportResult::notes)
      .def("text", &FmuExportResult::text, "What the hydrocoef CLI prints.")
      .def("json", &FmuExportResult::json, "What the hydrocoef CLI prints with --json (a JSON text).");
  m.def(
      "export_fmu",
      [](py::handle db, const std::string& body, const std::string& surface, const std::string& output,
         const std::string& vehicle) {
        hydrocoef::FmuExportOptions options;
        options.body = body;
        options.surface = surface;
        options.vehicle = vehicle;
        options.output = output;
        const auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::export_fmu(database, options);
      },
      "database"_a, "body"_a, py::kw_only(), "surface"_a = "", "output"_a, "vehicle"_a = "",
      R"doc(The stored gridded surface `surface` of `body` as an FMI 2.0 Co-Simulation FMU written to `output`
(NAME.fmu), as `hydrocoef export-fmu BODY --surface NAME -o FILE`; or with `vehicle` (a vehicle file or its JSON
text) the vehicle FMU, as `hydrocoef export-fmu BODY --vehicle FILE -o FILE` (docs/fmu.md). Returns an
FmuExportResult.)doc");
}

}  // namespace hydrocoef_python
