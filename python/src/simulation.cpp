// simulate's compiled part (hydrocoef.simulate in python/hydrocoef/__init__.py
// makes the vehicle and scenario texts): the trajectory as numpy columns.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <string>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;

py::dict trajectory_dict(hydrocoef::Trajectory&& trajectory) {
  py::dict out;
  for (std::size_t c = 0; c < trajectory.columns.size(); ++c) {
    py::array_t<double> column(static_cast<py::ssize_t>(trajectory.rows));
    std::copy_n(trajectory.values.data() + c * trajectory.rows, trajectory.rows, column.mutable_data());
    out[py::str(trajectory.columns[c])] = column;
  }
  return out;
}

}  // namespace

void bind_simulation(py::module_& m) {
  m.def(
      "_simulate",
      [](const std::string& vehicle, const std::string& scenario, const std::string& database) {
        hydrocoef::Trajectory trajectory;
        {
          py::gil_scoped_release release;
          trajectory = hydrocoef::simulate(vehicle, scenario, database);
        }
        py::dict units;
        for (std::size_t c = 0; c < trajectory.columns.size(); ++c)
          units[py::str(trajectory.columns[c])] = trajectory.units[c];
        auto notes = trajectory.notes;
        return py::make_tuple(trajectory_dict(std::move(trajectory)), units, notes);
      },
      "vehicle"_a, "scenario"_a, "database"_a,
      "simulate's compiled part: (columns, units, notes). Use hydrocoef.simulate.");
}

}  // namespace hydrocoef_python
