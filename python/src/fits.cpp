// Fits in Python: hydrocoef.Fit (a fitted damping law, with its repr as a
// formula), Database.fit and Database.fits.
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

}  // namespace

void bind_fits(py::module_& m, py::class_<hydrocoef::Database>& database) {
  py::class_<hydrocoef::FitSummary>(m, "Fit", py::is_final(), made_by_the_module_only(),
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
      .def("__repr__", &repr_fit);

  database
      .def(
          "fit",
          [](py::handle self, const std::string& body, const std::string& output, const std::string& terms,
             const py::object& where, const py::object& exclude_runs, const py::object& mirror,
             const py::object& mirror_odd, const std::string& loss, const py::object& name, bool replace, bool store) {
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
            return database_of(self).fit(options);
          },
          py::kw_only(), "body"_a, "output"_a, "terms"_a, "where"_a = py::none(), "exclude_runs"_a = py::none(),
          "mirror"_a = py::none(), "mirror_odd"_a = py::none(), "loss"_a = "squared", "name"_a = py::none(),
          "replace"_a = false, "store"_a = true,
          R"doc(Fits a damping law F_output(x) = sum_k c_k term_k(x) to the selected runs and stores it, as `hydrocoef fit`.

output: X Y Z K M N; terms: e.g. "1,u,u|u|" (1, x, x|x|, x^2, x^3, |x| of one velocity component);
where / exclude_runs: the run selection; mirror: planes of symmetry ("v"), mirror_odd: disturbances
that change sign; loss: squared, huber:S, cauchy:S, soft-l1:S; name: default body:X(terms);
replace: replace a stored fit of that name; store=False: fit only. Returns a Fit.)doc")
      .def(
          "fits",
          [](py::handle self, const py::object& body) {
            return database_of(self).fits(body.is_none() ? "" : body.cast<std::string>());
          },
          "body"_a = py::none(), "The stored fits (of one body), by name: a list of Fit.");
}

}  // namespace hydrocoef_python
