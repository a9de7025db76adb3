// Surfaces in Python: hydrocoef.Surface (a stored surface, called on numpy
// arrays, tabulated for a controller), SurfaceInfo (what `hydrocoef surface
// list` shows), the reports of the surface commands (SurfaceReport,
// SurfaceList, SurfaceBuildReport, SurfaceRebuildReport, SurfaceQueryResult),
// and the Database methods that list, build, rebuild, show, query and read
// surfaces (the C++ API's calls of include/hydrocoef/surface.hpp).
//
// Surface calls take numpy arrays where they are: a float64 array that is
// contiguous, or one-dimensional with a stride that is a whole number of
// doubles, is read in place (a scalar is read once for every point); other
// arrays (other dtypes, other byte orders, N-D views that are not contiguous)
// are converted into a new array first. The evaluation runs without the GIL
// on every core (the C++ batch engine, src/surface/batch_evaluation).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;
using hydrocoef::Database;
using hydrocoef::Surface;

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

std::string shape_text(const std::vector<py::ssize_t>& shape) {
  std::string out = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) out += (i ? ", " : "") + std::to_string(shape[i]);
  return out + (shape.size() == 1 ? ",)" : ")");
}

/// One axis's values, ready for the batch: an array kept alive while the
/// batch reads it, and the column the batch reads.
struct AxisValues {
  py::array array;
  hydrocoef::ConstColumn column;
  bool scalar = false;
  std::vector<py::ssize_t> shape;
};

AxisValues axis_values(const std::string& axis, const py::handle& value) {
  py::array array;
  if (py::isinstance<py::array>(value)) {
    array = py::reinterpret_borrow<py::array>(value);
  } else {
    array = py::array::ensure(value);  // a float, an int, a list ...
    if (!array)
      throw py::type_error("axis '" + axis + "': expected numbers (a float, a sequence or a numpy array), got " +
                           py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>());
  }
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error("axis '" + axis + "': expected real numbers, got an array of dtype " +
                         py::str(array.dtype()).cast<std::string>());
  const auto aligned = [&] { return reinterpret_cast<std::uintptr_t>(array.data()) % alignof(double) == 0; };
  const bool in_place = array.dtype().equal(py::dtype::of<double>()) && aligned() &&
                        (array.ndim() == 0 || (array.ndim() == 1 && array.strides(0) % 8 == 0) ||
                         (array.flags() & py::array::c_style) != 0);
  if (!in_place) {
    // Another dtype or byte order, misaligned, or an N-D view with no single
    // stride: a converted copy (a plain ndarray, aligned, C order).
    array = py::module_::import("numpy").attr("array")(array, "dtype"_a = "float64", "order"_a = "C", "copy"_a = true);
  }
  AxisValues out;
  out.array = array;
  out.scalar = array.ndim() == 0;
  for (py::ssize_t d = 0; d < array.ndim(); ++d) out.shape.push_back(array.shape(d));
  out.column.data = static_cast<const double*>(array.data());
  out.column.stride = out.scalar          ? 0
                      : array.ndim() == 1 ? array.strides(0) / static_cast<py::ssize_t>(sizeof(double))
                                          : 1;
  return out;
}

/// surface(u=..., v=...) or surface({"u": ..., "v": ...}): every output (and
/// with gradient, every dOUT/dAXIS) at every point, shaped like the inputs.
py::dict call_surface(const Surface& surface, const py::args& args, py::kwargs kwargs) {
  bool gradient = false, uncertainty = false;
  long threads = 0;
  if (kwargs.contains("gradient")) gradient = py::cast<bool>(kwargs.attr("pop")("gradient"));
  if (kwargs.contains("uncertainty")) uncertainty = py::cast<bool>(kwargs.attr("pop")("uncertainty"));
  if (kwargs.contains("threads")) threads = py::cast<long>(kwargs.attr("pop")("threads"));
  if (threads < 0 || threads > 4096)
    throw py::value_error("threads=" + std::to_string(threads) + ": expected 0 (every core) to 4096");
  const auto& axes = surface.axes();
  const std::string usage = "surface '" + surface.name() + "' takes one value or array per axis: " + joined(axes);

  // Where each axis's values come from: keywords, or one mapping (a dict, a
  // Table of runs) whose other keys are left alone.
  py::object source = kwargs;
  if (args.size() == 1 && kwargs.empty() && py::hasattr(args[0], "keys")) {
    source = args[0];
  } else if (!args.empty()) {
    throw py::type_error("positional values are not taken; " + usage + ", as keywords (" + axes.front() +
                         "=...) or as one mapping");
  } else {
    for (const auto& item : kwargs) {
      const auto name = py::cast<std::string>(item.first);
      if (std::find(axes.begin(), axes.end(), name) == axes.end())
        throw py::type_error("'" + name + "' is not an axis; " + usage);
    }
  }
  std::vector<AxisValues> values;
  std::vector<std::string> missing;
  for (const auto& axis : axes) {
    if (!source.attr("__contains__")(axis).cast<bool>()) {
      missing.push_back(axis);
      continue;
    }
    values.push_back(axis_values(axis, source[py::str(axis)]));
  }
  if (!missing.empty()) throw py::type_error("no value for " + joined(missing) + "; " + usage);

  // One shape for every array; scalars stand for every point.
  std::optional<std::vector<py::ssize_t>> shape;
  std::size_t shaped_axis = 0;
  for (std::size_t a = 0; a < values.size(); ++a) {
    if (values[a].scalar) continue;
    if (!shape) {
      shape = values[a].shape;
      shaped_axis = a;
    } else if (*shape != values[a].shape) {
      throw py::value_error("axes " + axes[shaped_axis] + " and " + axes[a] + " have different shapes " +
                            shape_text(*shape) + " and " + shape_text(values[a].shape) +
                            "; expected one shape for every array (or scalars)");
    }
  }
  const auto& outputs = surface.outputs();
  const std::size_t n_axes = axes.size(), n_out = outputs.size();
  py::dict result;
  if (!shape) {
    // One point: the C++ point evaluation, whose errors are `hydrocoef query`'s word for word.
    std::vector<double> point(n_axes);
    for (std::size_t a = 0; a < n_axes; ++a) point[a] = *values[a].column.data;
    const auto float64 = py::module_::import("numpy").attr("float64");
    // Outputs, then their standard deviations, then the gradient: the batch's order.
    std::vector<double> value, deviation, slope;
    if (uncertainty) {
      auto answer = surface.evaluate_with_standard_deviation(point);
      value = std::move(answer.values);
      deviation = std::move(answer.standard_deviation);
    }
    if (gradient) {
      auto answer = surface.evaluate_with_gradient(point);
      value = std::move(answer.values);
      slope = std::move(answer.gradient);
    }
    if (!uncertainty && !gradient) value = surface.evaluate(point);
    for (std::size_t k = 0; k < n_out; ++k) result[py::str(outputs[k])] = float64(value[k]);
    for (std::size_t k = 0; k < deviation.size(); ++k) result[py::str("sigma_" + outputs[k])] = float64(deviation[k]);
    for (std::size_t k = 0; k < n_out && gradient; ++k)
      for (std::size_t a = 0; a < n_axes; ++a)
        result[py::str("d" + outputs[k] + "/d" + axes[a])] = float64(slope[k * n_axes + a]);
    return result;
  }

  std::size_t count = 1;
  for (const auto extent : *shape) count *= static_cast<std::size_t>(extent);
  std::vector<py::array_t<double>> out_arrays, gradient_arrays, sd_arrays;
  std::vector<hydrocoef::Column> out_columns, gradient_columns, sd_columns;
  for (std::size_t k = 0; k < n_out; ++k) {
    out_arrays.emplace_back(*shape);
    out_columns.push_back({out_arrays.back().mutable_data(), 1});
  }
  if (uncertainty)
    for (std::size_t k = 0; k < n_out; ++k) {
      sd_arrays.emplace_back(*shape);
      sd_columns.push_back({sd_arrays.back().mutable_data(), 1});
    }
  if (gradient)
    for (std::size_t g = 0; g < n_out * n_axes; ++g) {
      gradient_arrays.emplace_back(*shape);
      gradient_columns.push_back({gradient_arrays.back().mutable_data(), 1});
    }
  std::vector<hydrocoef::ConstColumn> in_columns;
  for (const auto& v : values) in_columns.push_back(v.column);
  {
    py::gil_scoped_release release;
    surface.evaluate_batch(count, in_columns, out_columns, gradient_columns, static_cast<unsigned>(threads),
                           sd_columns);
  }
  for (std::size_t k = 0; k < n_out; ++k) result[py::str(outputs[k])] = out_arrays[k];
  for (std::size_t k = 0; k < n_out && uncertainty; ++k) result[py::str("sigma_" + outputs[k])] = sd_arrays[k];
  for (std::size_t k = 0; k < n_out && gradient; ++k)
    for (std::size_t a = 0; a < n_axes; ++a)
      result[py::str("d" + outputs[k] + "/d" + axes[a])] = gradient_arrays[k * n_axes + a];
  return result;
}

/// The calls that make the report classes here.
constexpr const char* kSurfacesMadeBy =
    "the Database's surface methods (surface_show, surface_list, surface_build, surface_rebuild, query_surface)";

/// The values of `source` (a mapping or the keywords) for each axis, as lists of breakpoints.
std::vector<std::vector<double>> breakpoints_of(const Surface& surface, const py::args& args,
                                                const py::kwargs& kwargs) {
  const auto& axes = surface.axes();
  const std::string usage =
      "surface '" + surface.name() + "' is tabulated on breakpoints for each axis: " + joined(axes);
  py::object source = kwargs;
  if (args.size() == 1 && kwargs.empty() && py::hasattr(args[0], "keys"))
    source = args[0];
  else if (!args.empty())
    throw py::type_error("positional values are not taken; " + usage + ", as keywords or as one mapping");
  std::vector<std::vector<double>> out;
  for (const auto& axis : axes) {
    if (!source.attr("__contains__")(axis).cast<bool>())
      throw py::type_error("no breakpoints for " + axis + "; " + usage);
    const auto array = py::module_::import("numpy").attr("asarray")(source[py::str(axis)], "dtype"_a = "float64");
    out.push_back(array.attr("ravel")().cast<std::vector<double>>());
  }
  if (args.empty() && py::len(source) != axes.size())  // keywords: each an axis (a mapping may hold more)
    for (const auto& item : source.attr("keys")())
      if (std::find(axes.begin(), axes.end(), py::cast<std::string>(item)) == axes.end())
        throw py::type_error("'" + py::cast<std::string>(item) + "' is not an axis; " + usage);
  return out;
}

/// A table as a dict: each axis's breakpoints (1-D), each output's values and
/// "sigma_OUT" (when stated), shaped (n_axis0, n_axis1, ...).
py::dict table_dict(const hydrocoef::SurfaceTable& table) {
  py::dict out;
  std::vector<py::ssize_t> shape, strides;
  py::ssize_t stride = sizeof(double);
  for (std::size_t a = 0; a < table.axes.size(); ++a) {
    out[py::str(table.axes[a])] =
        py::array_t<double>(static_cast<py::ssize_t>(table.breakpoints[a].size()), table.breakpoints[a].data());
    shape.push_back(static_cast<py::ssize_t>(table.breakpoints[a].size()));
    strides.push_back(stride);
    stride *= shape.back();
  }
  // Flat index i_0 + n_0 (i_1 + ...): the first axis fastest, Fortran order.
  const auto array = [&](const std::vector<double>& values) {
    py::array_t<double> result(shape, strides);
    std::copy(values.begin(), values.end(), result.mutable_data());
    return result;
  };
  for (std::size_t k = 0; k < table.outputs.size(); ++k) out[py::str(table.outputs[k])] = array(table.values[k]);
  for (std::size_t k = 0; k < table.standard_deviation.size(); ++k)
    out[py::str("sigma_" + table.outputs[k])] = array(table.standard_deviation[k]);
  return out;
}

/// The points where each output's standard deviation is largest, {output: [{"point": {axis: x}, "sd": s}, ...]}.
py::dict peaks_dict(const Surface& surface, std::size_t count) {
  const auto peaks = surface.largest_standard_deviations(count);
  py::dict out;
  for (std::size_t k = 0; k < peaks.size(); ++k) {
    py::list list;
    for (const auto& peak : peaks[k]) {
      py::dict point;
      for (std::size_t a = 0; a < surface.axes().size(); ++a) point[py::str(surface.axes()[a])] = peak.point[a];
      list.append(py::dict("point"_a = point, "sd"_a = peak.standard_deviation));
    }
    out[py::str(surface.outputs()[k])] = list;
  }
  return out;
}

/// The keywords of build_surface and surface_build as SurfaceBuildOptions.
hydrocoef::SurfaceBuildOptions build_options(
    const std::string& name, const std::string& body, const py::object& axes, const py::object& outputs,
    const std::string& method, const py::object& extrapolate, const py::object& where, const py::object& exclude_runs,
    const py::object& mirror, const py::object& mirror_odd, const std::string& rbf_kernel, int rbf_degree,
    double rbf_smoothing, const py::object& resample, const std::string& resample_method, double far_threshold,
    bool replace, const std::string& gp_kernel, int gp_degree, int gp_starts, unsigned gp_seed) {
  hydrocoef::SurfaceBuildOptions options;
  options.name = name;
  options.body = body;
  options.axes = texts(axes, "axes");
  options.outputs = texts(outputs, "outputs");
  options.method = method;
  options.extrapolate = texts(extrapolate, "extrapolate");
  options.where = texts(where, "where");
  options.exclude_runs = run_ids(exclude_runs, "exclude_runs");
  options.mirror = texts(mirror, "mirror");
  options.mirror_odd = texts(mirror_odd, "mirror_odd");
  options.rbf_kernel = rbf_kernel;
  options.rbf_degree = rbf_degree;
  options.rbf_smoothing = rbf_smoothing;
  if (!resample.is_none()) {
    try {
      options.resample = resample.cast<std::vector<std::vector<double>>>();
    } catch (const py::cast_error&) {
      throw py::type_error("resample: expected one list of numbers per axis");
    }
  }
  options.resample_method = resample_method;
  options.far_threshold = far_threshold;
  options.replace = replace;
  options.gp_kernel = gp_kernel;
  options.gp_degree = gp_degree;
  options.gp_starts = gp_starts;
  options.gp_seed = gp_seed;
  return options;
}

/// Database.build_surface and surface_build: the same keywords made into the
/// build's options, then `build(database, options)` without the GIL.
template <class Build>
auto build_method(Build build) {
  return [build](py::handle self, const std::string& name, const std::string& body, const py::object& axes,
                 const py::object& outputs, const std::string& method, const py::object& extrapolate,
                 const py::object& where, const py::object& exclude_runs, const py::object& mirror,
                 const py::object& mirror_odd, const std::string& rbf_kernel, int rbf_degree, double rbf_smoothing,
                 const py::object& resample, const std::string& resample_method, double far_threshold, bool replace,
                 const std::string& gp_kernel, int gp_degree, int gp_starts, unsigned gp_seed) {
    const auto options = build_options(name, body, axes, outputs, method, extrapolate, where, exclude_runs, mirror,
                                       mirror_odd, rbf_kernel, rbf_degree, rbf_smoothing, resample, resample_method,
                                       far_threshold, replace, gp_kernel, gp_degree, gp_starts, gp_seed);
    Database& d = database_of(self);
    py::gil_scoped_release release;
    return build(d, options);
  };
}

}  // namespace

void bind_surfaces(py::module_& m, py::class_<Database>& database) {
  // Surface.__call__ takes **axes: its docstring gives the signature, not pybind11's "*args, **kwargs".
  auto surface_class =
      py::class_<Surface>(m, "Surface", py::is_final(), made_by_the_module_only("Database.surface(name)"),
                          R"doc(A coefficient surface read from a run database.

Call it with one value or numpy array per axis, by name, to get every output at
every point, as numpy arrays shaped like the inputs:

    s = db.surface("asr-v-yaw")            # N(r)
    s(r=0.15)["N"]                         # N m at r = 0.15 rad/s
    s(r=np.linspace(-0.3, 0.3, 101))["N"]  # 101 values
    s(u=u_grid, v=0.0, gradient=True)      # adds "dX/du", "dX/dv", ...

Axes are body velocity components u, v, w [m/s], p, q, r [rad/s] (body axes, x
forward, y starboard, z down) or disturbance parameters in SI units
(axis_units); outputs are forces on the body X, Y, Z [N], K, M, N [N m]
(a damping force is negative along the motion), or coefficients in
output_units. A point outside an axis whose policy is "error", or a NaN,
raises hydrocoef.InputError with the message `hydrocoef query` prints
(prefixed "point I: " for arrays, I the 0-based flat index of the first such
point). A Surface is immutable and stays valid after its Database is closed.)doc");
  surface_class
      .def_property_readonly(
          "name", [](const Surface& s) { return s.name(); }, "The surface's name in its database.")
      .def_property_readonly(
          "body", [](const Surface& s) { return s.body(); }, "The body whose runs it was built from.")
      .def_property_readonly(
          "method", [](const Surface& s) { return s.method(); },
          "'nearest', 'linear', 'pchip', 'makima', 'natural-spline' (gridded tables) or 'rbf'.")
      .def_property_readonly(
          "stale", [](const Surface& s) { return s.stale(); },
          "True when forces of the body changed since the surface was built.")
      .def_property_readonly(
          "axes", [](const Surface& s) { return s.axes(); }, "Axis names, in order.")
      .def_property_readonly(
          "outputs", [](const Surface& s) { return s.outputs(); }, "Output names, in order.")
      .def_property_readonly(
          "axis_units", [](const Surface& s) { return s.axis_units(); }, "One unit per axis ('m/s', 'rad/s', ...).")
      .def_property_readonly(
          "output_units", [](const Surface& s) { return s.output_units(); }, "One unit per output ('N', 'N m', ...).")
      .def_property_readonly(
          "bounds",
          [](const Surface& s) {
            py::dict out;
            for (std::size_t a = 0; a < s.axes().size(); ++a)
              out[py::str(s.axes()[a])] = py::make_tuple(s.lower(a), s.upper(a));
            return out;
          },
          "{axis: (lower, upper)}: the range the surface was built over, in axis units.")
      .def_property_readonly(
          "out_of_range",
          [](const Surface& s) {
            py::dict out;
            for (std::size_t a = 0; a < s.axes().size(); ++a) out[py::str(s.axes()[a])] = s.out_of_range(a);
            return out;
          },
          "{axis: policy}: 'error', 'clamp', 'linear' or 'method' (grids), 'error', 'clamp' or 'extrapolate' (rbf).")
      .def("__repr__", [](const Surface& s) {
        return "<hydrocoef.Surface '" + s.name() + "' of body '" + s.body() + "': " + joined(s.outputs()) + "(" +
               joined(s.axes()) + "), " + s.method() + (s.stale() ? ", STALE" : "") + ">";
      });

  {
    py::options options;
    options.disable_function_signatures();
    surface_class.def(
        "__call__", &call_surface,
        R"doc(__call__(self, values=None, /, *, gradient=False, uncertainty=False, threads=0, **axes) -> dict[str, numpy.ndarray]

Every output at every point. Give each axis a float or an array, by keyword
(s(u=..., v=...)), or one mapping holding them (s({"u": ..., "v": ...}), or a
Table of runs: keys other than the axes are left alone). Arrays must all have
one shape (scalars stand for every point); the results have that shape
(numpy.float64 values when every axis is a scalar). gradient=True adds
"dOUT/dAXIS" for every output and axis [output unit per axis unit];
uncertainty=True adds "sigma_OUT", each output's standard deviation (GP
surfaces, and grid and RBF surfaces built with their runs' uncertainty;
others raise InputError). threads:
0 uses every core. float64 arrays that are contiguous, or 1-D with any
stride, are read in place; others are converted first. The GIL is released
while the points are evaluated.

Raises hydrocoef.InputError (a ValueError) for a NaN or infinite value or a
value outside an axis whose policy is 'error'; TypeError for a missing or
unknown axis or values that are not real numbers; ValueError for arrays of
different shapes.)doc");
  }

  surface_class
      .def_property_readonly(
          "gridded", [](const Surface& s) { return s.gridded(); },
          "True for a gridded table (nearest .. natural-spline, or an RBF resampled on a grid); False for gp and rbf.")
      .def(
          "table",
          [](const Surface& s) {
            hydrocoef::SurfaceTable table;
            {
              py::gil_scoped_release release;
              table = s.table();
            }
            return table_dict(table);
          },
          R"doc(A gridded surface's own table: {axis: breakpoints (1-D)} and {output: node values}, with
{"sigma_OUT": standard deviation at each node} when the surface states one; the node arrays are
shaped (len(axis 0), len(axis 1), ...), a[i0, i1, ...] at (breakpoints0[i0], breakpoints1[i1], ...).
InputError for a surface that is not gridded (gp, rbf): tabulate() gives any surface on chosen breakpoints.)doc")
      .def(
          "tabulate",
          [](const Surface& s, const py::args& args, py::kwargs kwargs) {
            long threads = 0;
            if (kwargs.contains("threads")) threads = py::cast<long>(kwargs.attr("pop")("threads"));
            if (threads < 0 || threads > 4096)
              throw py::value_error("threads=" + std::to_string(threads) + ": expected 0 (every core) to 4096");
            const auto breakpoints = breakpoints_of(s, args, kwargs);
            hydrocoef::SurfaceTable table;
            {
              py::gil_scoped_release release;
              table = s.tabulate(breakpoints, static_cast<unsigned>(threads));
            }
            return table_dict(table);
          },
          R"doc(tabulate(self, breakpoints=None, /, *, threads=0, **axes) -> dict[str, numpy.ndarray]

The surface (a GP included) evaluated at every node of the grid of the given breakpoints (one
increasing sequence per axis, by keyword or as one mapping): a lookup table for a controller.
Returns the same dict as table(): the breakpoints, each output's values and, when the surface
states one, "sigma_OUT", shaped (len(axis 0), len(axis 1), ...). InputError for unordered or
non-finite breakpoints, or a node outside an axis whose policy is 'error'.)doc")
      .def(
          "largest_standard_deviations", [](const Surface& s, std::size_t count) { return peaks_dict(s, count); },
          "count"_a = 3,
          "{output: [{'point': {axis: value}, 'sd': sd}, ...]}: where each output's standard deviation is largest, "
          "largest first, as `hydrocoef surface show` lists them ({} when the surface states none).");

  py::class_<hydrocoef::SurfaceInfo>(m, "SurfaceInfo", py::is_final(),
                                     made_by_the_module_only("Database.surfaces() and Database.build_surface(...)"),
                                     "A stored surface, as `hydrocoef surface list` shows it.")
      .def_readonly("name", &hydrocoef::SurfaceInfo::name)
      .def_readonly("body", &hydrocoef::SurfaceInfo::body)
      .def_readonly("kind", &hydrocoef::SurfaceInfo::kind, "'grid' or 'rbf'.")
      .def_readonly("method", &hydrocoef::SurfaceInfo::method)
      .def_readonly("axes", &hydrocoef::SurfaceInfo::axes)
      .def_readonly("outputs", &hydrocoef::SurfaceInfo::outputs)
      .def_readonly("stale", &hydrocoef::SurfaceInfo::stale)
      .def_readonly("run_count", &hydrocoef::SurfaceInfo::run_count)
      .def_readonly("created_at", &hydrocoef::SurfaceInfo::created_at)
      .def("__repr__", [](const hydrocoef::SurfaceInfo& s) {
        return "<hydrocoef.SurfaceInfo '" + s.name + "': " + joined(s.outputs) + "(" + joined(s.axes) + "), " +
               s.method + ", " + std::to_string(s.run_count) + " runs" + (s.stale ? ", STALE" : "") + ">";
      });

  database
      .def(
          "surfaces",
          [](py::handle self, const py::object& body) {
            return database_of(self).surfaces(body.is_none() ? "" : body.cast<std::string>());
          },
          "body"_a = py::none(), "The stored surfaces (of one body), by name: a list of SurfaceInfo.")
      .def("build_surface",
           build_method([](Database& d, const hydrocoef::SurfaceBuildOptions& o) { return d.build_surface(o); }),
           "name"_a, py::kw_only(), "body"_a, "axes"_a, "outputs"_a, "method"_a = "linear",
           "extrapolate"_a = py::none(), "where"_a = py::none(), "exclude_runs"_a = py::none(), "mirror"_a = py::none(),
           "mirror_odd"_a = py::none(), "rbf_kernel"_a = "cubic", "rbf_degree"_a = 1, "rbf_smoothing"_a = 0.0,
           "resample"_a = py::none(), "resample_method"_a = "linear", "far_threshold"_a = 0.25, "replace"_a = false,
           "gp_kernel"_a = "matern52", "gp_degree"_a = 1, "gp_starts"_a = 5, "gp_seed"_a = 1u,
           R"doc(Builds a surface from the selected runs and stores it, as `hydrocoef surface build`.

axes: velocity components (u..r) or disturbance names; outputs: X..N (forces on the body).
method: nearest, linear, pchip, makima, natural-spline (runs on a grid), rbf or gp (scattered runs;
gp: a Gaussian process whose surface also gives each value's standard deviation, s(..., uncertainty=True)).
extrapolate: one policy for every axis or "AXIS=POLICY" entries (error, clamp, linear, method;
rbf: error, clamp, extrapolate). where / exclude_runs / mirror / mirror_odd: as for fit().
rbf_kernel, rbf_degree, rbf_smoothing, resample (one list of breakpoints per axis),
resample_method, far_threshold: the RBF options. gp_kernel (matern52, squared-exponential), gp_degree
(its mean, 0 to 2), gp_starts, gp_seed: the GP options. replace: replace a stored surface of that name.
Returns a SurfaceInfo; the surface keeps its build specification for rebuild_surfaces().)doc")
      .def(
          "rebuild_surfaces",
          [](py::handle self, const py::object& name, bool stale_only) {
            const std::string which = name.is_none() ? "" : name.cast<std::string>();
            Database& d = database_of(self);
            py::gil_scoped_release release;
            return d.rebuild_surfaces(which, stale_only);
          },
          "name"_a = py::none(), py::kw_only(), "stale_only"_a = false,
          "Builds stored surfaces again from the current runs with the options each was built with: the one named, "
          "else every one (only stale ones with stale_only=True). Returns a list of SurfaceInfo.")
      .def(
          "surface", [](py::handle self, const std::string& name) { return database_of(self).surface(name); }, "name"_a,
          "One stored surface, read whole (it stays valid after close()). InputError listing the names when absent.");

  // The reports of the surface commands: the numbers as attributes, and
  // text() / json(), what the CLI prints (and with --json).
  py::class_<hydrocoef::SurfaceAxisReport>(m, "SurfaceAxisReport", py::is_final(),
                                           made_by_the_module_only(kSurfacesMadeBy))
      .def_readonly("name", &hydrocoef::SurfaceAxisReport::name)
      .def_readonly("unit", &hydrocoef::SurfaceAxisReport::unit)
      .def_readonly("lower", &hydrocoef::SurfaceAxisReport::lower)
      .def_readonly("upper", &hydrocoef::SurfaceAxisReport::upper)
      .def_readonly("out_of_range", &hydrocoef::SurfaceAxisReport::out_of_range)
      .def_readonly("breakpoints", &hydrocoef::SurfaceAxisReport::breakpoints, "Gridded surfaces; [] otherwise.");
  py::class_<hydrocoef::SurfaceOutputReport>(m, "SurfaceOutputReport", py::is_final(),
                                             made_by_the_module_only(kSurfacesMadeBy))
      .def_readonly("name", &hydrocoef::SurfaceOutputReport::name)
      .def_readonly("unit", &hydrocoef::SurfaceOutputReport::unit)
      .def_readonly("loo_max", &hydrocoef::SurfaceOutputReport::loo_max)
      .def_readonly("loo_rms", &hydrocoef::SurfaceOutputReport::loo_rms)
      .def_readonly("worst_run", &hydrocoef::SurfaceOutputReport::worst_run)
      .def_readonly("worst_error", &hydrocoef::SurfaceOutputReport::worst_error)
      .def_property_readonly(
          "largest_sd",
          [](const hydrocoef::SurfaceOutputReport& o) {
            py::list out;
            for (const auto& peak : o.largest_sd) out.append(py::make_tuple(peak.point, peak.standard_deviation));
            return out;
          },
          "[(point as a list in axis order, sd), ...], largest first.");
  py::class_<hydrocoef::SurfaceReport>(m, "SurfaceReport", py::is_final(), made_by_the_module_only(kSurfacesMadeBy),
                                       "A stored surface described whole, as `hydrocoef surface show`.")
      .def_readonly("name", &hydrocoef::SurfaceReport::name)
      .def_readonly("body", &hydrocoef::SurfaceReport::body)
      .def_readonly("kind", &hydrocoef::SurfaceReport::kind)
      .def_readonly("method", &hydrocoef::SurfaceReport::method)
      .def_readonly("created_at", &hydrocoef::SurfaceReport::created_at)
      .def_readonly("stale", &hydrocoef::SurfaceReport::stale)
      .def_readonly("runs", &hydrocoef::SurfaceReport::runs)
      .def_readonly("built_from", &hydrocoef::SurfaceReport::built_from)
      .def_readonly("axes", &hydrocoef::SurfaceReport::axes)
      .def_readonly("outputs", &hydrocoef::SurfaceReport::outputs)
      .def("text", &hydrocoef::SurfaceReport::text)
      .def("json", &hydrocoef::SurfaceReport::json);
  py::class_<hydrocoef::SurfaceList>(m, "SurfaceList", py::is_final(), made_by_the_module_only(kSurfacesMadeBy),
                                     "The stored surfaces, as `hydrocoef surface list`.")
      .def_readonly("surfaces", &hydrocoef::SurfaceList::surfaces)
      .def("text", &hydrocoef::SurfaceList::text)
      .def("json", &hydrocoef::SurfaceList::json);
  py::class_<hydrocoef::SurfaceBuildReport>(m, "SurfaceBuildReport", py::is_final(),
                                            made_by_the_module_only(kSurfacesMadeBy),
                                            "A surface built and stored, as `hydrocoef surface build`.")
      .def_readonly("surface", &hydrocoef::SurfaceBuildReport::surface)
      .def_readonly("id", &hydrocoef::SurfaceBuildReport::id)
      .def_readonly("runs_measured", &hydrocoef::SurfaceBuildReport::runs_measured)
      .def_readonly("mirror_images", &hydrocoef::SurfaceBuildReport::mirror_images)
      .def_readonly("images_skipped", &hydrocoef::SurfaceBuildReport::images_skipped)
      .def_readonly("runs_skipped", &hydrocoef::SurfaceBuildReport::runs_skipped)
      .def_readonly("mirror", &hydrocoef::SurfaceBuildReport::mirror)
      .def("text", &hydrocoef::SurfaceBuildReport::text)
      .def("json", &hydrocoef::SurfaceBuildReport::json);
  py::class_<hydrocoef::SurfaceRebuildReport>(m, "SurfaceRebuildReport", py::is_final(),
                                              made_by_the_module_only(kSurfacesMadeBy),
                                              "Surfaces built again, as `hydrocoef surface rebuild`.")
      .def_readonly("rebuilt", &hydrocoef::SurfaceRebuildReport::rebuilt)
      .def("text", &hydrocoef::SurfaceRebuildReport::text)
      .def("json", &hydrocoef::SurfaceRebuildReport::json);
  py::class_<hydrocoef::SurfaceQueryResult>(m, "SurfaceQueryResult", py::is_final(),
                                            made_by_the_module_only(kSurfacesMadeBy),
                                            "The answer of `hydrocoef query`: a point, or a batch written as CSV.")
      .def_readonly("surface", &hydrocoef::SurfaceQueryResult::surface)
      .def_readonly("stale", &hydrocoef::SurfaceQueryResult::stale)
      .def_readonly("warnings", &hydrocoef::SurfaceQueryResult::warnings)
      .def_readonly("axes", &hydrocoef::SurfaceQueryResult::axes)
      .def_readonly("point", &hydrocoef::SurfaceQueryResult::point)
      .def_readonly("outputs", &hydrocoef::SurfaceQueryResult::outputs)
      .def_readonly("units", &hydrocoef::SurfaceQueryResult::units)
      .def_readonly("values", &hydrocoef::SurfaceQueryResult::values)
      .def_readonly("standard_deviation", &hydrocoef::SurfaceQueryResult::standard_deviation)
      .def_readonly("new_run_standard_deviation", &hydrocoef::SurfaceQueryResult::new_run_standard_deviation)
      .def_readonly("gradient", &hydrocoef::SurfaceQueryResult::gradient,
                    "gradient[k * len(axes) + a] = d output_k / d axis_a.")
      .def_readonly("points", &hydrocoef::SurfaceQueryResult::points)
      .def_readonly("output", &hydrocoef::SurfaceQueryResult::output)
      .def("text", &hydrocoef::SurfaceQueryResult::text)
      .def("json", &hydrocoef::SurfaceQueryResult::json)
      .def("note", &hydrocoef::SurfaceQueryResult::note);

  database
      .def("surface_build", build_method([](Database& d, const hydrocoef::SurfaceBuildOptions& o) {
             return hydrocoef::surface_build(d, o);
           }),
           "name"_a, py::kw_only(), "body"_a, "axes"_a, "outputs"_a, "method"_a = "linear",
           "extrapolate"_a = py::none(), "where"_a = py::none(), "exclude_runs"_a = py::none(), "mirror"_a = py::none(),
           "mirror_odd"_a = py::none(), "rbf_kernel"_a = "cubic", "rbf_degree"_a = 1, "rbf_smoothing"_a = 0.0,
           "resample"_a = py::none(), "resample_method"_a = "linear", "far_threshold"_a = 0.25, "replace"_a = false,
           "gp_kernel"_a = "matern52", "gp_degree"_a = 1, "gp_starts"_a = 5, "gp_seed"_a = 1u,
           "As build_surface (the same keywords), returning the SurfaceBuildReport `hydrocoef surface build` prints.")
      .def(
          "surface_rebuild",
          [](py::handle self, const py::object& name, const py::object& body, bool stale_only) {
            hydrocoef::SurfaceRebuildOptions options;
            options.name = name.is_none() ? "" : name.cast<std::string>();
            options.body = body.is_none() ? "" : body.cast<std::string>();
            options.stale_only = stale_only;
            Database& d = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::surface_rebuild(d, options);
          },
          "name"_a = py::none(), py::kw_only(), "body"_a = py::none(), "stale_only"_a = false,
          "Builds stored surfaces again (the one named, else every one, of body when given, only stale ones with "
          "stale_only=True), as `hydrocoef surface rebuild`: a SurfaceRebuildReport.")
      .def(
          "surface_list",
          [](py::handle self, const py::object& body) {
            Database& d = database_of(self);
            const std::string which = body.is_none() ? "" : body.cast<std::string>();
            py::gil_scoped_release release;
            return hydrocoef::surface_list(d, which);
          },
          "body"_a = py::none(), "The stored surfaces described, as `hydrocoef surface list`: a SurfaceList.")
      .def(
          "surface_show",
          [](py::handle self, const std::string& name) {
            Database& d = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::surface_show(d, name);
          },
          "name"_a, "One stored surface described whole, as `hydrocoef surface show`: a SurfaceReport.")
      .def(
          "query_surface",
          [](py::handle self, const std::string& name, const py::object& point, const py::object& input,
             const std::string& output, bool gradient, bool uncertainty) {
            hydrocoef::SurfaceQueryOptions options;
            options.name = name;
            if (!point.is_none())
              for (const auto& item : point.cast<py::dict>())
                options.point.emplace_back(py::cast<std::string>(item.first), py::cast<double>(item.second));
            options.input = input.is_none() ? "" : py::str(input).cast<std::string>();
            options.output = output;
            options.gradient = gradient;
            options.uncertainty = uncertainty;
            Database& d = database_of(self);
            py::gil_scoped_release release;
            return hydrocoef::query_surface(d, options);
          },
          "name"_a, "point"_a = py::none(), py::kw_only(), "input"_a = py::none(), "output"_a = "-",
          "gradient"_a = false, "uncertainty"_a = false,
          "A stored surface at a point ({axis: value}), or at every row of the CSV `input` written to `output`, as "
          "`hydrocoef query`: a SurfaceQueryResult (text() and json() are the CLI's).");
}

}  // namespace hydrocoef_python
