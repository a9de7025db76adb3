// Derivative models of several variables in Python (include/hydrocoef/
// derivatives.hpp): fit_derivative_model, list_derivative_models,
// show_derivative_model (in the SI, prime, bis or MMG form),
// delete_derivative_model and evaluate_derivative_model, with their results
// as objects whose attributes are the C++ fields, plus .text() and .json()
// (what the CLI prints).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;

/// The calls that make the result classes here.
constexpr const char* kDerivativesMadeBy =
    "hydrocoef's derivative-model functions (fit_derivative_model, list_derivative_models, show_derivative_model, "
    "delete_derivative_model, evaluate_derivative_model)";

}  // namespace

void register_derivatives(py::module_& m) {
  using hydrocoef::DerivativeCoefficient;
  using hydrocoef::DerivativeModel;
  py::class_<DerivativeCoefficient>(m, "DerivativeCoefficient", py::is_final(),
                                    made_by_the_module_only(kDerivativesMadeBy),
                                    "One coefficient of a derivative model (the derivative by its term).")
      .def_readonly("term", &DerivativeCoefficient::term)
      .def_readonly("unit", &DerivativeCoefficient::unit)
      .def_readonly("value", &DerivativeCoefficient::value)
      .def_readonly("std_error", &DerivativeCoefficient::std_error)
      .def_readonly("interval_low", &DerivativeCoefficient::interval_low)
      .def_readonly("interval_high", &DerivativeCoefficient::interval_high)
      .def_readonly("vif", &DerivativeCoefficient::vif)
      .def_readonly("normalisation", &DerivativeCoefficient::normalisation);
  py::class_<DerivativeModel> model(m, "DerivativeModel", py::is_final(), made_by_the_module_only(kDerivativesMadeBy),
                                    "A derivative model of several variables, fitted or stored.");
  model.def_readonly("name", &DerivativeModel::name)
      .def_readonly("body", &DerivativeModel::body)
      .def_readonly("output", &DerivativeModel::output)
      .def_readonly("terms", &DerivativeModel::terms)
      .def_readonly("template", &DerivativeModel::model_template)
      .def_readonly("selection", &DerivativeModel::selection)
      .def_readonly("candidates", &DerivativeModel::candidates)
      .def_readonly("where", &DerivativeModel::where)
      .def_readonly("unit", &DerivativeModel::unit)
      .def_readonly("form", &DerivativeModel::form)
      .def_readonly("coefficients", &DerivativeModel::coefficients)
      .def_readonly("covariance", &DerivativeModel::covariance, "m x m row by row ([] when undefined).")
      .def_readonly("condition_number", &DerivativeModel::condition_number)
      .def_readonly("rmse", &DerivativeModel::rmse)
      .def_readonly("r2", &DerivativeModel::r2)
      .def_readonly("n", &DerivativeModel::n)
      .def_readonly("weighting", &DerivativeModel::weighting)
      .def_readonly("chi2_reduced", &DerivativeModel::chi2_reduced)
      .def_readonly("covariance_scale", &DerivativeModel::covariance_scale)
      .def_readonly("interval_factor", &DerivativeModel::interval_factor)
      .def_readonly("runs", &DerivativeModel::runs)
      .def_readonly("warnings", &DerivativeModel::warnings)
      .def_readonly("id", &DerivativeModel::id)
      .def_readonly("stale", &DerivativeModel::stale)
      .def_readonly("created_at", &DerivativeModel::created_at);
  add_text_and_json(model);
  py::class_<hydrocoef::DerivativeModelList> list(m, "DerivativeModelList", py::is_final(),
                                                  made_by_the_module_only(kDerivativesMadeBy));
  list.def_readonly("models", &hydrocoef::DerivativeModelList::models);
  add_text_and_json(list);
  py::class_<hydrocoef::DerivativeDeletion> deletion(m, "DerivativeDeletion", py::is_final(),
                                                     made_by_the_module_only(kDerivativesMadeBy));
  deletion.def_readonly("name", &hydrocoef::DerivativeDeletion::name)
      .def_readonly("id", &hydrocoef::DerivativeDeletion::id);
  add_text_and_json(deletion);
  py::class_<hydrocoef::DerivativeEvaluation> evaluation(m, "DerivativeEvaluation", py::is_final(),
                                                         made_by_the_module_only(kDerivativesMadeBy));
  evaluation.def_readonly("name", &hydrocoef::DerivativeEvaluation::name)
      .def_readonly("output", &hydrocoef::DerivativeEvaluation::output)
      .def_readonly("unit", &hydrocoef::DerivativeEvaluation::unit)
      .def_readonly("at", &hydrocoef::DerivativeEvaluation::at)
      .def_readonly("value", &hydrocoef::DerivativeEvaluation::value)
      .def_readonly("std_error", &hydrocoef::DerivativeEvaluation::std_error)
      .def_readonly("basis", &hydrocoef::DerivativeEvaluation::basis)
      .def_readonly("stale", &hydrocoef::DerivativeEvaluation::stale);
  add_text_and_json(evaluation);

  m.def(
      "fit_derivative_model",
      [](py::handle db, const std::string& body, const std::string& output, const std::string& terms,
         const std::string& model_template, const std::string& select, std::uint64_t seed, const py::object& where,
         const py::object& exclude_runs, const std::string& name, bool replace, bool store, bool weighted,
         double vif_threshold, const py::object& u0) {
        hydrocoef::DerivativeModelOptions options;
        options.body = body;
        options.output = output;
        options.terms = terms;
        options.model_template = model_template;
        options.select = select;
        options.seed = seed;
        options.where = texts(where, "where");
        options.exclude_runs = run_ids(exclude_runs, "exclude_runs");
        options.name = name;
        options.replace = replace;
        options.store = store;
        options.weighted = weighted;
        options.vif_threshold = vif_threshold;
        options.u0 = or_nan(u0);
        auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::fit_derivative_model(database, options);
      },
      "database"_a, py::kw_only(), "body"_a, "output"_a, "terms"_a = "", "template"_a = "", "select"_a = "",
      "seed"_a = 1, "where"_a = py::none(), "exclude_runs"_a = py::none(), "name"_a = "", "replace"_a = false,
      "store"_a = true, "weighted"_a = true, "vif_threshold"_a = 10.0, "u0"_a = py::none(),
      "Fits a derivative model to a body's runs and stores it, as `hydrocoef derivatives fit`.");
  m.def(
      "list_derivative_models",
      [](py::handle db, const std::string& body) {
        const auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::list_derivative_models(database, body);
      },
      "database"_a, "body"_a = "", "The stored derivative models, as `hydrocoef derivatives list`.");
  m.def(
      "show_derivative_model",
      [](py::handle db, const std::string& name, const std::string& form, const py::object& length,
         const py::object& speed, const py::object& density, const py::object& draft, const py::object& mass,
         const py::object& volume, double gravity) {
        hydrocoef::DerivativeShowOptions options;
        options.name = name;
        options.form = form;
        set_reference_values(options, length, speed, density, draft, mass, volume, gravity);
        const auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::show_derivative_model(database, options);
      },
      "database"_a, "name"_a, py::kw_only(), "form"_a = "dimensional", "length"_a = py::none(), "speed"_a = py::none(),
      "density"_a = py::none(), "draft"_a = py::none(), "mass"_a = py::none(), "volume"_a = py::none(),
      "gravity"_a = 9.80665, "A stored derivative model in the form asked for, as `hydrocoef derivatives show`.");
  m.def(
      "delete_derivative_model",
      [](py::handle db, const std::string& name) {
        auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::delete_derivative_model(database, name);
      },
      "database"_a, "name"_a, "Deletes a stored derivative model, as `hydrocoef derivatives delete`.");
  m.def(
      "evaluate_derivative_model",
      [](py::handle db, const std::string& name, const std::map<std::string, double>& at) {
        hydrocoef::DerivativeEvaluationOptions options;
        options.name = name;
        options.at = at;
        const auto& database = database_of(db);
        const py::gil_scoped_release release;
        return hydrocoef::evaluate_derivative_model(database, options);
      },
      "database"_a, "name"_a, "at"_a,
      "A stored derivative model at a point {name: value} with its standard error, as `hydrocoef derivatives "
      "evaluate`.");
  for (const char* name : {"DerivativeCoefficient", "DerivativeModel", "DerivativeModelList", "DerivativeDeletion",
                           "DerivativeEvaluation"})
    m.attr(name).attr("__module__") = "hydrocoef";
}

}  // namespace hydrocoef_python
