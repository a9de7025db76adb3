// The plots of include/hydrocoef/plot.hpp as module functions: each draws its
// figure through gnuplot (image, values beside it, script) and returns a
// PlotFiles with the files written and the series drawn (plot_coefficient: the
// runs' non-dimensional coefficients).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;

std::string text_of(const py::object& value) {
  if (value.is_none()) return {};
  if (py::hasattr(value, "__fspath__")) return py::str(value.attr("__fspath__")());
  return value.cast<std::string>();
}

hydrocoef::ImageOptions image_options(const py::object& image, const py::object& size) {
  hydrocoef::ImageOptions out;
  out.image = text_of(image);
  out.size = text_of(size);
  return out;
}

constexpr const char* kImageDoc =
    "image: FILE.png or FILE.svg (FILE.dat with the values and FILE.gp with the gnuplot script beside it; None: a "
    "name from the plot's kind and subject in the working directory); size: 'WIDTHxHEIGHT' in pixels (None: the "
    "plot's default). Returns a PlotFiles (image, data, script, format, width, height, series; text() and json() "
    "as `hydrocoef plot` prints them). Needs gnuplot. Raises InputError as the CLI would.";

}  // namespace

void bind_plots(py::module_& m) {
  py::class_<hydrocoef::PlotFiles>(
      m, "PlotFiles", py::is_final(),
      made_by_the_module_only("hydrocoef's plot functions (plot_fit, plot_curves, plot_surface, plot_history, "
                              "plot_simulation, plot_steady, plot_coefficient)"),
      "The files a plot wrote and what it drew.")
      .def_readonly("title", &hydrocoef::PlotFiles::title)
      .def_readonly("image", &hydrocoef::PlotFiles::image)
      .def_readonly("data", &hydrocoef::PlotFiles::data)
      .def_readonly("script", &hydrocoef::PlotFiles::script)
      .def_readonly("format", &hydrocoef::PlotFiles::format)
      .def_readonly("width", &hydrocoef::PlotFiles::width)
      .def_readonly("height", &hydrocoef::PlotFiles::height)
      .def_property_readonly("series",
                             [](const hydrocoef::PlotFiles& f) {
                               py::list out;
                               for (const auto& s : f.series)
                                 out.append(py::dict("panel"_a = s.panel, "title"_a = s.title, "points"_a = s.points));
                               return out;
                             })
      .def("text", &hydrocoef::PlotFiles::text)
      .def("json", &hydrocoef::PlotFiles::json);

  m.def(
      "plot_fit",
      [](py::handle database, const std::string& name, const py::object& image, const py::object& size) {
        const auto& db = database_of(database);
        const auto options = image_options(image, size);
        py::gil_scoped_release release;
        return hydrocoef::plot_fit(db, name, options);
      },
      "database"_a, "name"_a, py::kw_only(), "image"_a = py::none(), "size"_a = py::none(),
      (std::string("A stored fit: force against velocity, its runs as points and the law as a curve (`hydrocoef "
                   "plot fit`). ") +
       kImageDoc)
          .c_str());
  m.def(
      "plot_curves",
      [](py::handle database, const py::object& name, const py::object& body, const py::object& dof,
         const py::object& terms, const py::object& by, const std::string& curve, const py::object& image,
         const py::object& size) {
        const auto& db = database_of(database);
        hydrocoef::CurvesPlotOptions options;
        options.name = text_of(name);
        options.body = text_of(body);
        options.dof = text_of(dof);
        options.terms = text_of(terms);
        options.by = text_of(by);
        options.curve = curve;
        const auto files = image_options(image, size);
        py::gil_scoped_release release;
        return hydrocoef::plot_curves(db, options, files);
      },
      "database"_a, "name"_a = py::none(), py::kw_only(), "body"_a = py::none(), "dof"_a = py::none(),
      "terms"_a = py::none(), "by"_a = py::none(), "curve"_a = "polynomial:2", "image"_a = py::none(),
      "size"_a = py::none(),
      (std::string("Each coefficient of per-level fits against their disturbance (`hydrocoef plot curves`). ") +
       kImageDoc)
          .c_str());
  m.def(
      "plot_surface",
      [](py::handle database, const std::string& name, const py::object& output, const py::object& image,
         const py::object& size) {
        const auto& db = database_of(database);
        const std::string which = text_of(output);
        const auto files = image_options(image, size);
        py::gil_scoped_release release;
        return hydrocoef::plot_surface(db, name, which, files);
      },
      "database"_a, "name"_a, py::kw_only(), "output"_a = py::none(), "image"_a = py::none(), "size"_a = py::none(),
      (std::string("A stored surface: a curve (1 axis) or a colour map (2 axes) with its runs (`hydrocoef plot "
                   "surface`); output: the surface's output to draw (None: its first). ") +
       kImageDoc)
          .c_str());
  m.def(
      "plot_history",
      [](py::handle database, std::int64_t run, const py::object& image, const py::object& size) {
        const auto& db = database_of(database);
        const auto files = image_options(image, size);
        py::gil_scoped_release release;
        return hydrocoef::plot_history(db, run, files);
      },
      "database"_a, "run"_a, py::kw_only(), "image"_a = py::none(), "size"_a = py::none(),
      (std::string("One run's stored force history with its windows and statistics (`hydrocoef plot history`). ") +
       kImageDoc)
          .c_str());
  m.def(
      "plot_simulation",
      [](const py::object& trajectory, const py::object& experiment, const std::string& component,
         const py::object& image, const py::object& size) {
        const std::string csv = text_of(trajectory), measured = text_of(experiment);
        const auto files = image_options(image, size);
        py::gil_scoped_release release;
        return hydrocoef::plot_simulation(csv, measured, component, files);
      },
      "trajectory"_a, py::kw_only(), "experiment"_a = py::none(), "component"_a = "r", "image"_a = py::none(),
      "size"_a = py::none(),
      (std::string("A velocity component against time from a trajectory CSV (simulate(..., out=...)), a measured "
                   "record overlaid (`hydrocoef plot simulation`). ") +
       kImageDoc)
          .c_str());
  m.def(
      "plot_steady",
      [](const std::string& vehicle, const py::object& database, const std::string& dof,
         const std::vector<double>& taus, const py::object& tau_from, const py::object& tau_to, std::size_t count,
         const py::object& experiment_points, std::size_t samples, std::uint64_t seed,
         const std::vector<double>& percentiles, const py::object& image, const py::object& size) {
        hydrocoef::SteadyPlotOptions options;
        options.vehicle = vehicle;
        options.database = text_of(database);
        options.dof = dof;
        options.taus = taus;
        constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
        options.tau_from = tau_from.is_none() ? kNaN : tau_from.cast<double>();
        options.tau_to = tau_to.is_none() ? kNaN : tau_to.cast<double>();
        options.count = count;
        options.experiment_points = text_of(experiment_points);
        options.sampling.samples = samples;
        options.sampling.seed = seed;
        options.sampling.percentiles = percentiles;
        const auto files = image_options(image, size);
        py::gil_scoped_release release;
        return hydrocoef::plot_steady(options, files);
      },
      "vehicle"_a, "database"_a = py::none(), py::kw_only(), "dof"_a = "N", "taus"_a = std::vector<double>{},
      "tau_from"_a = py::none(), "tau_to"_a = py::none(), "count"_a = 6, "experiment_points"_a = py::none(),
      "samples"_a = 0, "seed"_a = 1, "percentiles"_a = std::vector<double>{}, "image"_a = py::none(),
      "size"_a = py::none(),
      (std::string("Steady velocity against a constant force in one DOF (`hydrocoef plot steady`): forces taus "
                   "[N or N m] and `count` forces from tau_from to tau_to; samples > 0 shades the band over the "
                   "damping's uncertainty. vehicle: a JSON file or its text; database: where its stored fits and "
                   "surfaces are read. ") +
       kImageDoc)
          .c_str());
  m.def(
      "plot_coefficient",
      [](py::handle database, const std::string& coefficient, const std::string& against, const py::object& area,
         const py::object& body, const py::object& where, const py::object& exclude_runs, const py::object& image,
         const py::object& size) {
        const auto& db = database_of(database);
        hydrocoef::CoefficientPlotOptions options;
        options.coefficient = coefficient;
        options.against = against;
        options.runs.area = text_of(area);
        options.runs.body = text_of(body);
        options.runs.where = texts(where, "where");
        options.runs.exclude_runs = run_ids(exclude_runs, "exclude_runs");
        const auto files = image_options(image, size);
        py::gil_scoped_release release;
        return hydrocoef::plot_coefficient(db, options, files);
      },
      "database"_a, py::kw_only(), "coefficient"_a = "C_X", "against"_a = "Re", "area"_a = py::none(),
      "body"_a = py::none(), "where"_a = py::none(), "exclude_runs"_a = py::none(), "image"_a = py::none(),
      "size"_a = py::none(),
      (std::string("A non-dimensional coefficient of the runs (C_X..C_N, as run_coefficients gives them) against "
                   "Re, Fn or U, one set of points per body (`hydrocoef plot coefficient`). ") +
       kImageDoc)
          .c_str());
}

}  // namespace hydrocoef_python
