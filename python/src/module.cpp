// The compiled part of the Python module `hydrocoef` (hydrocoef._hydrocoef):
// the public C++ API (include/hydrocoef/) with numpy arrays in and out. It
// holds no pipeline logic of its own: every call is one call of the C++ API,
// which is what the command-line tool calls too. python/hydrocoef/__init__.py
// adds the pure-Python conveniences (Table.to_pandas, dict vehicles).
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

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "hydrocoef/hydrocoef.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

using hydrocoef::Database;
using hydrocoef::Surface;

/// A new 1-D numpy array that owns the vector's storage (no copy).
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& values) {
  auto owned = std::make_unique<std::vector<T>>(std::move(values));
  const auto size = static_cast<py::ssize_t>(owned->size());
  T* data = owned->data();
  py::capsule owner(owned.get(), [](void* p) { delete static_cast<std::vector<T>*>(p); });
  owned.release();
  return py::array_t<T>(size, data, owner);
}

/// Texts as a numpy array of Python str (dtype object), as pandas keeps them.
py::array to_numpy_strings(const std::vector<std::string>& texts) {
  py::list list(texts.size());
  for (std::size_t i = 0; i < texts.size(); ++i) list[i] = py::str(texts[i]);
  return py::module_::import("numpy").attr("array")(list, "dtype"_a = "object");
}

/// Whether `self` holds its C++ Database: false for an object made by
/// __new__ alone (Database.__new__(Database), object.__new__, a base class's
/// __new__), whose storage pybind11 never filled.
bool holds_database(py::handle self) {
  if (!py::isinstance<Database>(self))
    throw py::type_error("expected a hydrocoef.Database, got " +
                         py::str(py::type::handle_of(self).attr("__name__")).cast<std::string>());
  auto* instance = reinterpret_cast<py::detail::instance*>(self.ptr());
  auto holder = instance->get_value_and_holder(py::detail::get_type_info(typeid(Database)), false);
  return holder && holder.holder_constructed();
}

/// The Database of a method's self. pybind11 would run a method on an
/// instance whose C++ object was never made on uninitialised memory; this
/// refuses it instead (and a self of another type, given to a method called
/// from the class).
Database& database_of(py::handle self) {
  if (!holds_database(self))
    throw py::type_error(
        "this hydrocoef.Database was made by __new__ without __init__; open one with "
        "hydrocoef.Database(path)");
  auto* instance = reinterpret_cast<py::detail::instance*>(self.ptr());
  return *instance->get_value_and_holder(py::detail::get_type_info(typeid(Database)), false).value_ptr<Database>();
}

/// tp_new of the classes whose objects only the module makes (Surface, Fit,
/// SurfaceInfo, ImportedFile, ImportSummary): refuses. It is the type's own
/// slot (py::custom_type_setup), not a Python __new__ attribute, so that
/// every way to one (Surface(), Surface.__new__(Surface), object.__new__ or
/// Surface.__mro__[1].__new__(Surface), whose "is not safe" check compares
/// the slots) raises TypeError: no such object exists without its C++ part,
/// on which pybind11 would run methods on uninitialised memory.
PyObject* refuse_new(PyTypeObject* type, PyObject*, PyObject*) {
  const char* dot = std::strrchr(type->tp_name, '.');
  const std::string name = dot ? dot + 1 : type->tp_name;
  const std::string from = name == "Surface"       ? "Database.surface(name)"
                           : name == "Fit"         ? "Database.fit(...) and Database.fits()"
                           : name == "SurfaceInfo" ? "Database.surfaces() and Database.build_surface(...)"
                                                   : "Database.import_files(...)";
  PyErr_SetString(PyExc_TypeError,
                  ("hydrocoef." + name + " objects come from " + from + "; they cannot be made directly").c_str());
  return nullptr;
}

/// The attributes of a class whose objects only the module makes: its
/// __new__ refuses, and it cannot be subclassed (a subclass's __new__ could
/// reach pybind11's).
py::custom_type_setup made_by_the_module_only() {
  return py::custom_type_setup([](PyHeapTypeObject* heap_type) { heap_type->ht_type.tp_new = refuse_new; });
}

std::string fspath(const py::handle& path) {
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

/// A list of run ids (None: empty).
std::vector<std::int64_t> run_ids(const py::object& value, const char* what) {
  if (value.is_none()) return {};
  try {
    return value.cast<std::vector<std::int64_t>>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string(what) + ": expected a list of run ids (int)");
  }
}

/// A str or a list of str (None: empty).
std::vector<std::string> texts(const py::object& value, const char* what) {
  if (value.is_none()) return {};
  if (py::isinstance<py::str>(value)) return {value.cast<std::string>()};
  try {
    return value.cast<std::vector<std::string>>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string(what) + ": expected a str or a list of str, got " +
                         py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>());
  }
}

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

// ---- Surface calls ------------------------------------------------------------

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

// ---- Database ---------------------------------------------------------------

hydrocoef::OpenMode parse_mode(const std::string& mode) {
  if (mode == "r") return hydrocoef::OpenMode::ReadOnly;
  if (mode == "rw") return hydrocoef::OpenMode::ReadWrite;
  if (mode == "create") return hydrocoef::OpenMode::Create;
  throw py::value_error("mode '" + mode +
                        "': expected 'r' (read only), 'rw' (read and write an existing database) "
                        "or 'create' (read and write, made when missing)");
}

constexpr const char* kVelocityNames[] = {"u", "v", "w", "p", "q", "r"};
constexpr const char* kForceNames[] = {"X", "Y", "Z", "K", "M", "N"};

py::dict runs_dict(hydrocoef::RunTable&& table) {
  py::dict out;
  out["id"] = to_numpy(std::move(table.id));
  out["body"] = to_numpy_strings(table.body);
  for (std::size_t c = 0; c < 6; ++c) out[kVelocityNames[c]] = to_numpy(std::move(table.velocity[c]));
  for (auto& [name, column] : table.disturbances) {
    // A disturbance named like a fixed column (an identifier such as "id" or "X") is kept apart.
    const std::string key =
        out.contains(name) || name == "source" || name == "history_flags" ||
                std::find(std::begin(kForceNames), std::end(kForceNames), name) != std::end(kForceNames) ||
                name.ends_with("_std_error")
            ? "disturbance." + name
            : name;
    out[py::str(key)] = to_numpy(std::move(column));
  }
  for (std::size_t c = 0; c < 6; ++c) out[kForceNames[c]] = to_numpy(std::move(table.force[c]));
  for (std::size_t c = 0; c < 6; ++c)
    out[py::str(std::string(kForceNames[c]) + "_std_error")] = to_numpy(std::move(table.force_std_error[c]));
  out["source"] = to_numpy_strings(table.source);
  out["history_flags"] = to_numpy_strings(table.history_flags);
  return out;
}

template <class Map>
Map mapping(const py::object& value, const char* what) {
  if (value.is_none()) return {};
  try {
    return value.cast<Map>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string(what) + ": expected a dict of str to str");
  }
}

/// A settings dict ({"rho": 998.2, "axes": "-x,y,-z", "ref_point": [0, 0, 0.1]})
/// as the C++ API takes it: str values as they are, others as JSON.
std::map<std::string, std::string> settings_texts(const py::object& settings) {
  std::map<std::string, std::string> out;
  if (settings.is_none()) return out;
  if (!py::isinstance<py::dict>(settings)) throw py::type_error("settings: expected a dict of sidecar keys");
  const auto dumps = py::module_::import("json").attr("dumps");
  for (const auto& item : settings.cast<py::dict>()) {
    const auto key = py::cast<std::string>(item.first);
    out[key] = py::isinstance<py::str>(item.second) ? item.second.cast<std::string>()
                                                    : dumps(item.second, "allow_nan"_a = false).cast<std::string>();
  }
  return out;
}

py::dict trajectory_dict(hydrocoef::Trajectory&& trajectory) {
  py::dict out;
  for (std::size_t c = 0; c < trajectory.columns.size(); ++c) {
    py::array_t<double> column(static_cast<py::ssize_t>(trajectory.rows));
    std::copy_n(trajectory.values.data() + c * trajectory.rows, trajectory.rows, column.mutable_data());
    out[py::str(trajectory.columns[c])] = column;
  }
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

PYBIND11_MODULE(_hydrocoef, m) {
  m.doc() = "hydrocoef's compiled core: the public C++ API with numpy arrays (import hydrocoef, not this).";
  m.attr("__version__") = hydrocoef::kVersion;

  py::register_exception<hydrocoef::InputError>(m, "InputError", PyExc_ValueError);
  m.attr("InputError").attr("__doc__") =
      "Bad input: a file that cannot be read, a bad option, a point outside a surface, a NaN, a damaged or foreign "
      "database, a closed database. The message is the one line the hydrocoef command-line tool prints after "
      "'hydrocoef: error: '. A subclass of ValueError.";

  // ---- Surface ----
  // Surface.__call__ takes **axes: its docstring gives the signature, not pybind11's "*args, **kwargs".
  auto surface_class = py::class_<Surface>(m, "Surface", py::is_final(), made_by_the_module_only(),
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

  // ---- records ----
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
          [](const hydrocoef::FitSummary& f) {
            py::dict out;
            for (const auto& c : f.coefficients) out[py::str(c.term)] = c.value;
            return out;
          },
          "{term: coefficient}, in the units of `units`.")
      .def_property_readonly(
          "std_errors",
          [](const hydrocoef::FitSummary& f) {
            py::dict out;
            for (const auto& c : f.coefficients) out[py::str(c.term)] = c.std_error;
            return out;
          },
          "{term: one-sigma standard error} (nan when undefined).")
      .def_property_readonly(
          "units",
          [](const hydrocoef::FitSummary& f) {
            py::dict out;
            for (const auto& c : f.coefficients) out[py::str(c.term)] = c.unit;
            return out;
          },
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

  py::class_<hydrocoef::SurfaceInfo>(m, "SurfaceInfo", py::is_final(), made_by_the_module_only(),
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

  py::class_<hydrocoef::ImportedFile>(m, "ImportedFile", py::is_final(), made_by_the_module_only(),
                                      "What an import did with one input.")
      .def_readonly("path", &hydrocoef::ImportedFile::path)
      .def_readonly("format", &hydrocoef::ImportedFile::format)
      .def_readonly("runs", &hydrocoef::ImportedFile::runs, "Runs the input holds.")
      .def_readonly("runs_created", &hydrocoef::ImportedFile::runs_created)
      .def_readonly("runs_extended", &hydrocoef::ImportedFile::runs_extended)
      .def_readonly("already_imported", &hydrocoef::ImportedFile::already_imported)
      .def_readonly("replaced", &hydrocoef::ImportedFile::replaced)
      .def_readonly("notes", &hydrocoef::ImportedFile::notes)
      .def("__repr__", [](const hydrocoef::ImportedFile& f) {
        return "<hydrocoef.ImportedFile " + f.path + ": " + f.format + ", " + std::to_string(f.runs) + " runs (" +
               std::to_string(f.runs_created) + " new, " + std::to_string(f.runs_extended) + " extended" +
               (f.already_imported ? ", already imported" : "") + ")>";
      });

  py::class_<hydrocoef::ImportSummary>(m, "ImportSummary", py::is_final(), made_by_the_module_only(),
                                       "What Database.import_files did.")
      .def_readonly("files", &hydrocoef::ImportSummary::files, "One ImportedFile per input (folders expanded).")
      .def_readonly("notes", &hydrocoef::ImportSummary::notes)
      .def_readonly("excluded", &hydrocoef::ImportSummary::excluded, "Files left out by include/exclude.")
      .def_readonly("runs_created", &hydrocoef::ImportSummary::runs_created)
      .def_readonly("runs_extended", &hydrocoef::ImportSummary::runs_extended)
      .def_readonly("already_imported", &hydrocoef::ImportSummary::already_imported)
      .def("__repr__", [](const hydrocoef::ImportSummary& s) {
        return "<hydrocoef.ImportSummary " + std::to_string(s.files.size()) +
               " inputs: " + std::to_string(s.runs_created) + " new runs, " + std::to_string(s.runs_extended) +
               " extended, " + std::to_string(s.already_imported) + " already imported>";
      });

  // ---- Database ----
  py::class_<Database>(m, "Database",
                       R"doc(A hydrocoef run database (an SQLite file), as the command-line tool reads and writes it.

    db = hydrocoef.Database("asr-v.db")            # mode="create": made when missing
    db.import_files(["surge.csv"], body="asr-v", settings={"sign": "opposing", "rho": 998.2})
    fit = db.fit(body="asr-v", output="X", terms="1,u,u|u|")
    runs = db.runs(where=["u>=0"])                  # dict of numpy columns; runs.to_pandas()
    s = db.surface("asr-v-surge")

mode: "r" (read only: never writes), "rw" (the file must exist) or "create".
Units SI; body axes x forward, y starboard, z down; forces on the body.
Errors in the input raise hydrocoef.InputError with the CLI's message. Every
write is one transaction. Close it with close() or a with block; any call
after that raises InputError "PATH: database is closed".)doc")
      .def(py::init([](const py::object& path, const std::string& mode) {
             return Database::open(fspath(path), parse_mode(mode));
           }),
           "path"_a, "mode"_a = "create")
      .def_property_readonly("path", [](py::handle self) { return database_of(self).path(); })
      .def_property_readonly("closed", [](py::handle self) { return !database_of(self).is_open(); })
      .def_property_readonly("read_only", [](py::handle self) { return database_of(self).read_only(); })
      .def(
          "close", [](py::handle self) { database_of(self).close(); },
          "Closes the file; surfaces already read stay valid.")
      .def("__enter__",
           [](py::object self) {
             database_of(self);
             return self;
           })
      .def("__exit__", [](py::handle self, const py::args&) { database_of(self).close(); })
      .def(
          "runs",
          [](py::handle self, const py::object& where, const py::object& body, const py::object& exclude_runs) {
            const Database& d = database_of(self);
            return runs_dict(d.runs(texts(where, "where"), body.is_none() ? "" : body.cast<std::string>(),
                                    run_ids(exclude_runs, "exclude_runs")));
          },
          "where"_a = py::none(), "body"_a = py::none(), "exclude_runs"_a = py::none(),
          R"doc(The runs as a dict of numpy columns (hydrocoef.Table: to_pandas()), as `hydrocoef runs` lists them.

where: selection clauses combined with AND ("u>=0", "v=0", "u=0.1:0.3", "current_v!=0");
body: one body's runs; exclude_runs: ids left out.
Columns: id, body, u v w [m/s], p q r [rad/s], each disturbance by name [SI,
nan where a run has none], X Y Z [N] and K M N [N m] (forces on the body, nan
where missing), X_std_error ... N_std_error (standard error of a mean over a
force history, nan where none), source (files, ';'-separated), history_flags.)doc")
      .def(
          "import_files",
          [](py::handle self, const py::object& paths, const py::object& body, const std::string& format,
             const py::object& settings, const py::object& columns, const py::object& units,
             const py::object& disturbance_columns, const py::object& ignore, const py::object& monitors,
             std::size_t average_last, const py::object& include, const py::object& exclude,
             const py::object& key_from_name, const py::object& manifest, bool sidecars, bool prefer_surfaces,
             bool replace, const std::string& also, unsigned jobs) {
            Database& d = database_of(self);
            std::vector<std::string> inputs;
            if (py::isinstance<py::str>(paths) || py::hasattr(paths, "__fspath__")) {
              inputs.push_back(fspath(paths));
            } else {
              for (const auto& p : paths) inputs.push_back(fspath(p));
            }
            hydrocoef::ImportOptions options;
            options.format = format;
            options.body = body.is_none() ? "" : body.cast<std::string>();
            options.settings = settings_texts(settings);
            options.columns = mapping<std::map<std::string, std::string>>(columns, "columns");
            options.units = mapping<std::map<std::string, std::string>>(units, "units");
            options.disturbance_columns = texts(disturbance_columns, "disturbance_columns");
            options.ignored_columns = texts(ignore, "ignore");
            options.monitors = mapping<std::map<std::string, std::string>>(monitors, "monitors");
            options.average_last = average_last;
            options.include = texts(include, "include");
            options.exclude = texts(exclude, "exclude");
            options.key_from_name = key_from_name.is_none() ? "" : key_from_name.cast<std::string>();
            options.manifest = manifest.is_none() ? "" : fspath(manifest);
            options.use_sidecars = sidecars;
            options.prefer_surfaces = prefer_surfaces;
            options.replace = replace;
            options.also = also;
            options.jobs = jobs;
            py::gil_scoped_release release;
            return d.import_files(inputs, options);
          },
          "paths"_a, py::kw_only(), "body"_a = py::none(), "format"_a = "auto", "settings"_a = py::none(),
          "columns"_a = py::none(), "units"_a = py::none(), "disturbance_columns"_a = py::none(),
          "ignore"_a = py::none(), "monitors"_a = py::none(), "average_last"_a = 1, "include"_a = py::none(),
          "exclude"_a = py::none(), "key_from_name"_a = py::none(), "manifest"_a = py::none(), "sidecars"_a = true,
          "prefer_surfaces"_a = false, "replace"_a = false, "also"_a = "", "jobs"_a = 0,
          R"doc(Imports files, folders and case folders in one transaction, as `hydrocoef import` does.

paths: a path or a list of paths. body: the runs' body (default 'vehicle').
format: auto, table, monitor, history, cfdpost or vtk.
settings: run settings as a sidecar holds them, above every other source:
  {"rho": 998.2, "nu": 1.004e-6, "axes": "-x,y,-z", "sign": "opposing",
   "ref_point": [0, 0, 0.1], "disturbances": {"current_v": 0.05}, "u": 0.2, ...}
columns / units / monitors: {component: header} maps (the CLI's --column, --unit, --monitor);
disturbance_columns, ignore: table headers; include / exclude: globs for folders;
key_from_name: e.g. 'u{u}_v{v}'; manifest: a sweep CSV; sidecars: read FILE.json and
hydrocoef-run.json; replace / also: see `hydrocoef import --help`; jobs: 0 every core.
Returns an ImportSummary. Every input is read before the database is written:
a bad one raises InputError and leaves the database as it was. The GIL is released.)doc")
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
          "body"_a = py::none(), "The stored fits (of one body), by name: a list of Fit.")
      .def(
          "surfaces",
          [](py::handle self, const py::object& body) {
            return database_of(self).surfaces(body.is_none() ? "" : body.cast<std::string>());
          },
          "body"_a = py::none(), "The stored surfaces (of one body), by name: a list of SurfaceInfo.")
      .def(
          "build_surface",
          [](py::handle self, const std::string& name, const std::string& body, const py::object& axes,
             const py::object& outputs, const std::string& method, const py::object& extrapolate,
             const py::object& where, const py::object& exclude_runs, const py::object& mirror,
             const py::object& mirror_odd, const std::string& rbf_kernel, int rbf_degree, double rbf_smoothing,
             const py::object& resample, const std::string& resample_method, double far_threshold, bool replace,
             const std::string& gp_kernel, int gp_degree, int gp_starts) {
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
            Database& d = database_of(self);
            py::gil_scoped_release release;
            return d.build_surface(options);
          },
          "name"_a, py::kw_only(), "body"_a, "axes"_a, "outputs"_a, "method"_a = "linear", "extrapolate"_a = py::none(),
          "where"_a = py::none(), "exclude_runs"_a = py::none(), "mirror"_a = py::none(), "mirror_odd"_a = py::none(),
          "rbf_kernel"_a = "cubic", "rbf_degree"_a = 1, "rbf_smoothing"_a = 0.0, "resample"_a = py::none(),
          "resample_method"_a = "linear", "far_threshold"_a = 0.25, "replace"_a = false, "gp_kernel"_a = "matern52",
          "gp_degree"_a = 1, "gp_starts"_a = 5,
          R"doc(Builds a surface from the selected runs and stores it, as `hydrocoef surface build`.

axes: velocity components (u..r) or disturbance names; outputs: X..N (forces on the body).
method: nearest, linear, pchip, makima, natural-spline (runs on a grid), rbf or gp (scattered runs;
gp: a Gaussian process whose surface also gives each value's standard deviation, s(..., uncertainty=True)).
extrapolate: one policy for every axis or "AXIS=POLICY" entries (error, clamp, linear, method;
rbf: error, clamp, extrapolate). where / exclude_runs / mirror / mirror_odd: as for fit().
rbf_kernel, rbf_degree, rbf_smoothing, resample (one list of breakpoints per axis),
resample_method, far_threshold: the RBF options. gp_kernel (matern52, squared-exponential), gp_degree
(its mean, 0 to 2), gp_starts: the GP options. replace: replace a stored surface of that name.
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
          "One stored surface, read whole (it stays valid after close()). InputError listing the names when absent.")
      .def("__repr__", [](py::handle self) {
        const Database& d = database_of(self);
        return "<hydrocoef.Database '" + d.path() + "'" +
               (d.is_open() ? (d.read_only() ? ", read only" : "") : ", closed") + ">";
      });

  // __init__ on a Database that has one already (open or closed): pybind11
  // runs a constructor once and ignores a second call silently; this
  // refuses it. The wrapper is not named __init__, a name pybind11 takes for
  // a constructor (and ignores again).
  {
    py::object database_class = m.attr("Database");
    py::object construct = database_class.attr("__init__");
    database_class.attr("__init__") = py::cpp_function(
        [construct](py::handle self, const py::object& path, const py::object& mode) {
          if (holds_database(self))
            throw std::runtime_error("this hydrocoef.Database has been opened already (on " + database_of(self).path() +
                                     "); __init__ runs once: make a new hydrocoef.Database(path)");
          construct(self, path, mode);
        },
        py::name("open"), py::is_method(database_class), "path"_a, "mode"_a = "create",
        "Opens the database at path (mode: 'r', 'rw' or 'create'); once per object.");
  }

  // The public classes say they are hydrocoef's (help(), repr of the type), not the extension's
  // (Database is: hydrocoef.Database is its Python subclass in __init__.py).
  for (const char* name : {"Surface", "Fit", "SurfaceInfo", "ImportedFile", "ImportSummary", "InputError"})
    m.attr(name).attr("__module__") = "hydrocoef";

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
