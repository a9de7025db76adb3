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
//   common.cpp      the helpers below that are not one topic's
#pragma once

#include <pybind11/pybind11.h>
// In every file: the casters of std::vector, std::map, std::optional ...
// must be the same in every translation unit of the module.
#include <pybind11/stl.h>

#include <cstdint>
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

/// A str or a list of str (None: empty).
std::vector<std::string> texts(const py::object& value, const char* what);

}  // namespace hydrocoef_python
