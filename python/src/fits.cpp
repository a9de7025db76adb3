// Fits in Python: hydrocoef.Fit (a fitted damping law, with its repr as a
// formula), Database.fit and Database.fits; per-level fits (LevelFits,
// Database.fit_by_level), refits (Refits, Database.refit) and a stored law
// evaluated with its standard error (FitEvaluation, Database.evaluate_fit).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>
#include <string>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;

/// {term: what `value` gives of each coefficient}.
template <class Value>
py::dict by_term(const hydrocoef::FitSummary& fit, Value value) {
  py::dict out;
  for (const auto& c : fit.coefficients) out[py::str(c.term)] = value(c);
  return out;
}

std::string repr_fit(const hydrocoef::FitSummary& fit) {
  std::ostringstream out;
  out.precision(6);
  out << "<hydrocoef.Fit " << fit.name << ": " << fit.output << "(" << fit.variable << ") =";
  for (std::size_t k = 0; k < fit.coefficients.size(); ++k) {
    const auto& c = fit.coefficients[k];
    out << " "
        << (c.value < 0 ? "-"
            : k         ? "+"
                        : "")
        << (c.value < 0 || k ? " " : "") << std::abs(c.value) << (c.term == "1" ? "" : " " + c.term);
  }
  out << ", n=" << fit.n << ", rmse=" << fit.rmse << " "
      << (std::string("XYZ").find(fit.output) != std::string::npos ? "N" : "N m") << ">";
  return out.str();
}

/// A k x k covariance as a numpy array (k from the coefficients); empty (0 x 0) when not recorded.
py::array_t<double> covariance_matrix(const hydrocoef::FitSummary& fit) {
  const std::size_t k = fit.coefficients.size();
  if (fit.covariance.size() != k * k) return py::array_t<double>(std::vector<py::ssize_t>{0, 0});
  py::array_t<double> out(std::vector<py::ssize_t>{static_cast<py::ssize_t>(k), static_cast<py::ssize_t>(k)});
  std::copy(fit.covariance.begin(), fit.covariance.end(), out.mutable_data());
  return out;
}

py::array_t<double> numpy_copy(const std::vector<double>& values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

/// The FitOptions of Database.fit and fit_by_level's keyword arguments.
hydrocoef::FitOptions fit_options(const std::string& body, const std::string& output, const std::string& terms,
                                  const py::object& where, const py::object& exclude_runs, const py::object& mirror,
                                  const py::object& mirror_odd, const std::string& loss, const py::object& name,
                                  bool replace, bool store, bool weighted) {
  hydrocoef::FitOptions options;
  options.body = body;
  options.output = output;
  options.terms = terms;
  options.where = texts(where, "where");
  options.exclude_runs = run_ids(exclude_runs, "exclude_runs");
  options.mirror = texts(mirror, "mirror");
  options.mirror_odd = texts(mirror_odd, "mirror_odd");
  options.loss = loss;
  options.name = name.is_none() ? "" : name.cast<std::string>();
  options.replace = replace;
  options.store = store;
  options.weighted = weighted;
  return options;
}

}  // namespace

void bind_fits(py::module_& m, py::class_<hydrocoef::Database>& database) {
  py::class_<hydrocoef::FitSummary>(m, "Fit", py::is_final(),
                                    made_by_the_module_only("Database.fit(...) and Database.fits()"),
                                    "A fitted damping law F_output(x) = sum_k c_k term_k(x).")
      .def_readonly("name", &hydrocoef::FitSummary::name)
      .def_readonly("body", &hydrocoef::FitSummary::body)
      .def_readonly("output", &hydrocoef::FitSummary::output, "Force component X..N.")
      .def_readonly("variable", &hydrocoef::FitSummary::variable, "Velocity component u..r.")
      .def_readonly("terms", &hydrocoef::FitSummary::terms, "Canonical terms, e.g. '1,u,u|u|'.")
      .def_readonly("loss", &hydrocoef::FitSummary::loss)
      .def_readonly("where", &hydrocoef::FitSummary::where, "The run selection ('' all runs).")
      .def_readonly("mirror", &hydrocoef::FitSummary::mirror)
      .def_readonly("sign_convention", &hydrocoef::FitSummary::sign_convention,
                    "'on-body' (force on the body) or 'opposing' (damping magnitude, positive opposes motion).")
      .def_property_readonly(
          "coefficients",
          [](const hydrocoef::FitSummary& f) { return by_term(f, [](const auto& c) { return c.value; }); },
          "{term: coefficient}, in the units of `units`.")
      .def_property_readonly(
          "std_errors",
          [](const hydrocoef::FitSummary& f) { return by_term(f, [](const auto& c) { return c.std_error; }); },
          "{term: one-sigma standard error} (nan when undefined).")
      .def_property_readonly(
          "units", [](const hydrocoef::FitSummary& f) { return by_term(f, [](const auto& c) { return c.unit; }); },
          "{term: unit}, e.g. {'u|u|': 'N/(m/s)^2'}.")
      .def_readonly("rmse", &hydrocoef::FitSummary::rmse, "Root-mean-square residual [N or N m].")
      .def_readonly("r2", &hydrocoef::FitSummary::r2, "R^2 (nan when the force does not vary).")
      .def_readonly("n", &hydrocoef::FitSummary::n, "Samples fitted.")
      .def_readonly("runs", &hydrocoef::FitSummary::runs, "Ids of the runs it was made from.")
      .def_readonly("warnings", &hydrocoef::FitSummary::warnings,
                    "Physical checks and unconverged runs ('kind: message').")
      .def_readonly("id", &hydrocoef::FitSummary::id, "Id in the database (0 when not stored).")
      .def_readonly("stale", &hydrocoef::FitSummary::stale)
      .def_readonly("created_at", &hydrocoef::FitSummary::created_at)
      .def_readonly("weighting", &hydrocoef::FitSummary::weighting,
                    "'uncertainty' (each run weighted by 1/s^2 of its standard uncertainty) or 'none'.")
      .def_readonly("chi2_reduced", &hydrocoef::FitSummary::chi2_reduced,
                    "Weighted fits: chi^2/(n-k) (nan for unweighted fits or n <= k).")
      .def_readonly("covariance_scale", &hydrocoef::FitSummary::covariance_scale)
      .def_property_readonly("covariance", &covariance_matrix,
                             "The coefficients' covariance, a k x k numpy array in the order of `coefficients` "
                             "(0 x 0 when not recorded).")
      .def_readonly("mirror_images", &hydrocoef::FitSummary::mirror_images)
      .def_readonly("varying_conditions", &hydrocoef::FitSummary::varying_conditions)
      .def("text", &hydrocoef::FitSummary::text, "What `hydrocoef fit` (or `fits`, for a stored fit) prints.")
      .def("json", &hydrocoef::FitSummary::json, "What `hydrocoef fit --json` (or `fits --json`) prints.")
      .def("__repr__", &repr_fit);

  py::class_<hydrocoef::LevelFitSummary>(m, "LevelFit", py::is_final(),
                                         made_by_the_module_only("Database.fit_by_level(...)"),
                                         "The law fitted at one level of a per-level fit.")
      .def_readonly("level", &hydrocoef::LevelFitSummary::level)
      .def_readonly("name", &hydrocoef::LevelFitSummary::name)
      .def_readonly("n", &hydrocoef::LevelFitSummary::n)
      .def_readonly("rmse", &hydrocoef::LevelFitSummary::rmse)
      .def_readonly("r2", &hydrocoef::LevelFitSummary::r2)
      .def_property_readonly("coefficients",
                             [](const hydrocoef::LevelFitSummary& f) {
                               py::dict out;
                               for (const auto& c : f.coefficients) out[py::str(c.term)] = c.value;
                               return out;
                             })
      .def_property_readonly("std_errors",
                             [](const hydrocoef::LevelFitSummary& f) {
                               py::dict out;
                               for (const auto& c : f.coefficients) out[py::str(c.term)] = c.std_error;
                               return out;
                             })
      .def_readonly("id", &hydrocoef::LevelFitSummary::id);

  py::class_<hydrocoef::LevelFits>(m, "LevelFits", py::is_final(),
                                   made_by_the_module_only("Database.fit_by_level(...)"),
                                   "What `hydrocoef fit --by` makes: the law at each level, each coefficient as a "
                                   "curve of the level.")
      .def_readonly("name", &hydrocoef::LevelFits::name)
      .def_readonly("by", &hydrocoef::LevelFits::by)
      .def_readonly("curve", &hydrocoef::LevelFits::curve)
      .def_readonly("sign_convention", &hydrocoef::LevelFits::sign_convention)
      .def_readonly("levels", &hydrocoef::LevelFits::levels)
      .def_property_readonly("skipped",
                             [](const hydrocoef::LevelFits& f) {
                               py::list out;
                               for (const auto& s : f.skipped)
                                 out.append(py::dict("level"_a = s.level, "runs"_a = s.runs, "reason"_a = s.reason));
                               return out;
                             })
      .def_property_readonly(
          "curves",
          [](const hydrocoef::LevelFits& f) {
            py::dict out;
            for (const auto& c : f.curves)
              out[py::str(c.term)] =
                  py::dict("kind"_a = c.kind, "degree"_a = c.degree, "polynomial"_a = c.polynomial,
                           "levels"_a = c.levels, "values"_a = c.values, "rmse"_a = c.rmse, "unit"_a = c.unit);
            return out;
          },
          "{term: {kind, degree, polynomial (a_0, a_1, ...), levels, values, rmse, unit}}.")
      .def_readonly("warnings", &hydrocoef::LevelFits::warnings)
      .def("text", &hydrocoef::LevelFits::text)
      .def("json", &hydrocoef::LevelFits::json);

  py::class_<hydrocoef::Refits>(m, "Refits", py::is_final(), made_by_the_module_only("Database.refit(...)"),
                                "Stored fits made again: each as it was (previous) and as made (made).")
      .def_readonly("previous", &hydrocoef::Refits::previous)
      .def_readonly("made", &hydrocoef::Refits::made)
      .def("text", &hydrocoef::Refits::text)
      .def("json", &hydrocoef::Refits::json);

  py::class_<hydrocoef::FitEvaluation>(m, "FitEvaluation", py::is_final(),
                                       made_by_the_module_only("Database.evaluate_fit(...)"),
                                       "A stored law at given velocities with the standard error of each value.")
      .def_readonly("name", &hydrocoef::FitEvaluation::name)
      .def_readonly("output", &hydrocoef::FitEvaluation::output)
      .def_readonly("variable", &hydrocoef::FitEvaluation::variable)
      .def_readonly("sign_convention", &hydrocoef::FitEvaluation::sign_convention)
      .def_readonly("unit", &hydrocoef::FitEvaluation::unit)
      .def_readonly("variable_unit", &hydrocoef::FitEvaluation::variable_unit)
      .def_property_readonly("at", [](const hydrocoef::FitEvaluation& e) { return numpy_copy(e.at); })
      .def_property_readonly(
          "value", [](const hydrocoef::FitEvaluation& e) { return numpy_copy(e.value); },
          "The law at each velocity [N or N m].")
      .def_property_readonly(
          "std_error", [](const hydrocoef::FitEvaluation& e) { return numpy_copy(e.std_error); },
          "One sigma of each value from the coefficients' covariance (nan when not recorded).")
      .def_property_readonly(
          "fitted_range", [](const hydrocoef::FitEvaluation& e) { return py::make_tuple(e.fitted_min, e.fitted_max); })
      .def_readonly("stale", &hydrocoef::FitEvaluation::stale)
      .def("text", &hydrocoef::FitEvaluation::text)
      .def("json", &hydrocoef::FitEvaluation::json);

  database
      .def(
          "fit",
          [](py::handle self, const std::string& body, const std::string& output, const std::string& terms,
             const py::object& where, const py::object& exclude_runs, const py::object& mirror,
             const py::object& mirror_odd, const std::string& loss, const py::object& name, bool replace, bool store,
             bool weighted) {
            const auto options = fit_options(body, output, terms, where, exclude_runs, mirror, mirror_odd, loss, name,
                                             replace, store, weighted);
            auto& db = database_of(self);
            py::gil_scoped_release release;
            return db.fit(options);
          },
          py::kw_only(), "body"_a, "output"_a, "terms"_a, "where"_a = py::none(), "exclude_runs"_a = py::none(),
          "mirror"_a = py::none(), "mirror_odd"_a = py::none(), "loss"_a = "squared", "name"_a = py::none(),
          "replace"_a = false, "store"_a = true, "weighted"_a = true,
          R"doc(Fits a damping law F_output(x) = sum_k c_k term_k(x) to the selected runs and stores it, as `hydrocoef fit`.

output: X Y Z K M N; terms: e.g. "1,u,u|u|" (1, x, x|x|, x^2, x^3, |x| of one velocity component);
where / exclude_runs: the run selection; mirror: planes of symmetry ("v"), mirror_odd: disturbances
that change sign; loss: squared, huber:S, cauchy:S, soft-l1:S; name: default body:X(terms);
replace: replace a stored fit of that name; store=False: fit only; weighted=False: ordinary least
squares even when every run states an uncertainty (the CLI's --unweighted). Returns a Fit.)doc")
      .def(
          "fit_by_level",
          [](py::handle self, const std::string& body, const std::string& output, const std::string& terms,
             const std::string& by, const std::string& curve, bool strict, const py::object& where,
             const py::object& exclude_runs, const py::object& mirror, const py::object& mirror_odd,
             const std::string& loss, const py::object& name, bool replace, bool store, bool weighted) {
            auto options = fit_options(body, output, terms, where, exclude_runs, mirror, mirror_odd, loss, name,
                                       replace, store, weighted);
            options.by = by;
            options.curve = curve;
            options.strict = strict;
            auto& db = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::fit_by_level(db, options);
          },
          py::kw_only(), "body"_a, "output"_a, "terms"_a, "by"_a, "curve"_a = "polynomial:2", "strict"_a = false,
          "where"_a = py::none(), "exclude_runs"_a = py::none(), "mirror"_a = py::none(), "mirror_odd"_a = py::none(),
          "loss"_a = "squared", "name"_a = py::none(), "replace"_a = false, "store"_a = true, "weighted"_a = true,
          R"doc(Fits the law at each level of `by` (a velocity component or disturbance), then each coefficient
as a curve of the level (curve: "polynomial:D" or "pchip"), as `hydrocoef fit --by`. strict: refuse a
level with too few runs (else it is skipped with a note). Other arguments as fit(). Returns LevelFits.)doc")
      .def(
          "refit",
          [](py::handle self, const py::object& name, const py::object& body) {
            hydrocoef::FitOptions options;
            options.name = name.is_none() ? "" : name.cast<std::string>();
            options.body = body.is_none() ? "" : body.cast<std::string>();
            auto& db = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::refit_fits(db, options);
          },
          "name"_a = py::none(), "body"_a = py::none(),
          "Makes stored fits again from the runs their selections pick now (`hydrocoef fit --refit`): the one "
          "named, else every stale one (of body). Returns Refits.")
      .def(
          "evaluate_fit",
          [](py::handle self, const std::string& name, const py::object& at) {
            hydrocoef::FitEvaluationOptions options;
            options.name = name;
            const auto values = py::module_::import("numpy").attr("asarray")(at, "dtype"_a = "float64");
            options.at = values.attr("ravel")().cast<std::vector<double>>();
            const auto& db = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::evaluate_fit(db, options);
          },
          "name"_a, "at"_a,
          R"doc(A stored fit's law at velocities `at` (a number or an array, m/s or rad/s), with the standard
error of each value from the coefficients' covariance, as `hydrocoef fits evaluate NAME --at ...`.
Returns a FitEvaluation: .value, .std_error (numpy arrays), .fitted_range.)doc")
      .def(
          "fits",
          [](py::handle self, const py::object& body) {
            return database_of(self).fits(body.is_none() ? "" : body.cast<std::string>());
          },
          "body"_a = py::none(), "The stored fits (of one body), by name: a list of Fit.");
}

}  // namespace hydrocoef_python
