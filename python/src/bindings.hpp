// What the files of the compiled Python module (python/src/) share: each
// topic's binder, called once by module.cpp's module init, and the helpers
// several topics use. The files:
//   module.cpp      the module init, calling the binders below in order
//   errors.cpp      hydrocoef.InputError
//   database.cpp    Database: open, close, runs, import_files (ImportedFile, ImportSummary)
//   surfaces.cpp    Surface (its call on numpy arrays), SurfaceInfo, Database's surface methods
//   fits.cpp        Fit, Database.fit and Database.fits
//   exports.cpp     Database.export_surface and export_gazebo, their results
//   simulation.cpp  simulate's and equilibrium's compiled part
//   plots.cpp       plot_fit, plot_curves, plot_surface, plot_history, plot_simulation, plot_steady
//   analysis.cpp    grid_convergence, analyse_pmm, store_pmm, pmm_runs, delete_pmm_runs,
//                   added_mass_matrix, suggest_runs and their results
//   reference.cpp   set_body_reference, body_references, run_coefficients and their results
//   derivatives.cpp fit_derivative_model, list/show/delete/evaluate_derivative_model and their results
//   pmm_derivatives.cpp pmm_derivatives (sway and yaw derivatives from forced oscillation) and its result
//   runtime.cpp     RuntimeModel: a runtime file through libhydrocoef_runtime (hydrocoef/runtime.hpp)
//   common.cpp      the helpers below that are not one topic's
#pragma once

#include <pybind11/pybind11.h>
// In every file: the casters of std::vector, std::map, std::optional ...
// must be the same in every translation unit of the module.
#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hydrocoef/hydrocoef.hpp"

namespace hydrocoef_python {

namespace py = pybind11;

void bind_errors(py::module_& m);
/// The Database class without its methods, which the topics add.
py::class_<hydrocoef::Database> declare_database(py::module_& m);
void bind_surfaces(py::module_& m, py::class_<hydrocoef::Database>& database);
void bind_fits(py::module_& m, py::class_<hydrocoef::Database>& database);
void bind_exports(py::module_& m, py::class_<hydrocoef::Database>& database);
void bind_database(py::module_& m, py::class_<hydrocoef::Database>& database);
void bind_simulation(py::module_& m);
void bind_plots(py::module_& m);
void register_analysis(py::module_& m);
void register_reference(py::module_& m);
void register_derivatives(py::module_& m);
void register_pmm_derivatives(py::module_& m);
void register_derivative_exports(py::module_& m);
void register_fmu(py::module_& m);
void register_runtime(py::module_& m);

/// The Database of a method's self. pybind11 would run a method on an
/// instance whose C++ object was never made on uninitialised memory; this
/// refuses it instead (and a self of another type, given to a method called
/// from the class).
hydrocoef::Database& database_of(py::handle self);

/// The attributes of a class whose objects only the module makes: its
/// __new__ refuses with "hydrocoef.NAME objects come from MADE_BY; they
/// cannot be made directly" (made_by: the calls that make them), and it
/// cannot be subclassed (a subclass's __new__ could reach pybind11's).
py::custom_type_setup made_by_the_module_only(std::string made_by);

/// A list of run ids (None: empty).
std::vector<std::int64_t> run_ids(const py::object& value, const char* what);

/// A number, or NaN for None.
double or_nan(const py::object& value);

/// A one-dimensional sequence of numbers (a list, a tuple, a numpy array) as
/// doubles; None: empty.
std::vector<double> numbers(const py::object& value);

/// A str or a path as text, or nullopt for None.
std::optional<std::string> optional_text(const py::object& value);

/// The reference values `derivatives show` and `derivatives export` take
/// (None: not given, NaN), into options with those fields.
template <class Options>
void set_reference_values(Options& options, const py::object& length, const py::object& speed,
                          const py::object& density, const py::object& draft, const py::object& mass,
                          const py::object& volume, double gravity) {
  options.length = or_nan(length);
  options.speed = or_nan(speed);
  options.density = or_nan(density);
  options.draft = or_nan(draft);
  options.mass = or_nan(mass);
  options.volume = or_nan(volume);
  options.gravity = gravity;
}

/// A str or a list of str (None: empty).
std::vector<std::string> texts(const py::object& value, const char* what);

/// The body velocities' names in the order of the key (u, v, w, p, q, r).
inline constexpr const char* kVelocityNames[] = {"u", "v", "w", "p", "q", "r"};

/// A result class's text() and json(): what the CLI prints, without and with --json.
template <class Result>
void add_text_and_json(py::class_<Result>& type) {
  type.def("text", &Result::text, "What the hydrocoef CLI prints.")
      .def("json", &Result::json, "What the hydrocoef CLI prints with --json (a JSON text).");
}

}  // namespace hydrocoef_python
