// The compiled part of the Python module `hydrocoef` (hydrocoef._hydrocoef):
// the public C++ API (include/hydrocoef/) with numpy arrays in and out. It
// holds no pipeline logic of its own: every call is one call of the C++ API,
// which is what the command-line tool calls too. python/hydrocoef/__init__.py
// adds the pure-Python conveniences (Table.to_pandas, dict vehicles).
//
// One file a topic, as python/src/bindings.hpp lists them; this one is the
// module init, which calls each topic's binder.
#include <pybind11/pybind11.h>

#include "python/src/bindings.hpp"

PYBIND11_MODULE(_hydrocoef, m) {
  m.doc() = "hydrocoef's compiled core: the public C++ API with numpy arrays (import hydrocoef, not this).";
  m.attr("__version__") = hydrocoef::kVersion;

  hydrocoef_python::bind_errors(m);
  // The Database class first: surfaces and fits add methods to it after
  // their own classes, which those methods return.
  auto database = hydrocoef_python::declare_database(m);
  hydrocoef_python::bind_surfaces(m, database);
  hydrocoef_python::bind_fits(m, database);
  hydrocoef_python::bind_exports(m, database);
  hydrocoef_python::bind_database(m, database);

  // The public classes say they are hydrocoef's (help(), repr of the type), not the extension's
  // (Database is: hydrocoef.Database is its Python subclass in __init__.py).
  for (const char* name : {"Surface", "Fit", "SurfaceInfo", "ImportedFile", "ImportSummary", "InputError"})
    m.attr(name).attr("__module__") = "hydrocoef";
  for (const char* name : {"SurfaceReport",      "SurfaceAxisReport",  "SurfaceOutputReport",
                           "SurfaceList",        "SurfaceBuildReport", "SurfaceRebuildReport",
                           "SurfaceQueryResult", "TableExportResult",  "TableExportAxis",
                           "GazeboExportResult", "GazeboFitExport",    "GazeboElementExport",
                           "LevelFit",           "LevelFits",          "Refits",
                           "FitEvaluation",      "RunDetails",         "DeleteSummary",
                           "MergeSummary",       "CopySummary",        "MigrationSummary",
                           "ReportSummary",      "SurfaceIntegration"})
    m.attr(name).attr("__module__") = "hydrocoef";

  hydrocoef_python::bind_simulation(m);
  hydrocoef_python::bind_plots(m);
  m.attr("PlotFiles").attr("__module__") = "hydrocoef";
  hydrocoef_python::register_analysis(m);
  hydrocoef_python::register_reference(m);
  hydrocoef_python::register_derivatives(m);
  hydrocoef_python::register_pmm_derivatives(m);
  hydrocoef_python::register_derivative_exports(m);
  hydrocoef_python::register_fmu(m);
  hydrocoef_python::register_runtime(m);
}
