// hydrocoef.RuntimeModel: a runtime file (docs/runtime.md) loaded through
// libhydrocoef_runtime and its C++ wrapper hydrocoef/runtime.hpp, the same
// numbers a C or C++ simulator gets from the file. A file the runtime cannot
// read, a point it refuses and an input of the wrong size raise
// hydrocoef.InputError with the runtime library's message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "hydrocoef/runtime.hpp"
#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;
using hydrocoef::runtime::Model;

/// The runtime library's and the wrapper's refusals as hydrocoef.InputError.
template <class Call>
auto refusing(Call&& call) {
  try {
    return call();
  } catch (const std::runtime_error& error) {
    throw hydrocoef::InputError(error.what());
  } catch (const std::logic_error& error) {  // invalid_argument, out_of_range: sizes and indices
    throw hydrocoef::InputError(error.what());
  }
}

py::array_t<double> to_array(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

}  // namespace

void register_runtime(py::module_& m) {
  py::class_<Model>(m, "RuntimeModel", py::is_final(),
                    "A runtime file (`hydrocoef export NAME --format runtime`) loaded through libhydrocoef_runtime: "
                    "its numbers are a C or C++ program's (docs/runtime.md).")
      .def(py::init([](const py::object& path) {
             const std::string text = py::str(py::module_::import("os").attr("fspath")(path));
             return refusing([&] { return Model::open(text); });
           }),
           "path"_a)
      .def_property_readonly("surfaces", &Model::surface_names, "The surfaces' names, in the file's order.")
      .def(
          "axes",
          [](const Model& model, const std::string& surface) {
            return refusing([&] { return model.axis_names(model.surface_index(surface)); });
          },
          "surface"_a, "The axes' names of a surface, in the order evaluate takes them.")
      .def(
          "outputs",
          [](const Model& model, const std::string& surface) {
            return refusing([&] { return model.output_names(model.surface_index(surface)); });
          },
          "surface"_a, "The outputs' names of a surface, in the order evaluate gives them.")
      .def_property_readonly("has_vehicle", &Model::has_vehicle, "Whether the file holds a vehicle.")
      .def_property_readonly("disturbances", &Model::disturbance_names,
                             "The disturbance parameters vehicle_step_rk4 takes, in order.")
      .def(
          "evaluate",
          [](const Model& model, const std::string& surface, const py::object& x) {
            const std::vector<double> point = numbers(x);
            return refusing([&] {
              const std::size_t s = model.surface_index(surface);
              const std::size_t n = model.axis_count(s), n_out = model.output_count(s);
              std::vector<double> values(n_out), gradients(n * n_out), sigma(model.has_sigma(s) ? n_out : 0);
              model.evaluate(s, point, values, gradients, sigma);
              const py::array_t<double> gradient_array(
                  std::vector<py::ssize_t>{static_cast<py::ssize_t>(n_out), static_cast<py::ssize_t>(n)},
                  gradients.data());
              py::dict result;
              result["values"] = to_array(values);
              result["gradients"] = gradient_array;
              result["sigma"] = sigma.empty() ? py::object(py::none()) : py::object(to_array(sigma));
              return result;
            });
          },
          "surface"_a, "x"_a,
          R"doc(The surface named `surface` at x (one coordinate per axis, SI): a dict of numpy arrays, "values"
(one per output), "gradients" (outputs x axes) and "sigma" (one per output; None for a surface that states
none).)doc")
      .def(
          "vehicle_step_rk4",
          [](const Model& model, const py::object& x, const py::object& tau, const py::object& current, double dt,
             const py::object& disturbances) {
            std::vector<double> state = numbers(x);
            const std::vector<double> tau_b = numbers(tau), current_n = numbers(current),
                                      inputs = numbers(disturbances);
            refusing([&] {
              model.vehicle_step_rk4(state, tau_b, current_n, inputs, dt);
              return 0;
            });
            return to_array(state);
          },
          "x"_a, "tau"_a, "current"_a, "dt"_a, "disturbances"_a = py::none(),
          R"doc(One RK4 step of the file's vehicle (hc_runtime_vehicle_step_rk4): x the 13-number state (NED
position, quaternion scalar first, body velocities), tau the 6 control forces and moments, current the water's
NED velocity (3, or None), dt [s], disturbances one value per `disturbances` name. Returns the new state.)doc");
  m.attr("RuntimeModel").attr("__module__") = "hydrocoef";
}

}  // namespace hydrocoef_python
