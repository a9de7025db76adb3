// The helpers of the Python module's bindings that several topics use
// (python/src/bindings.hpp): classes whose objects only the module makes, and
// the arguments given as a list of run ids or of names.
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include <pybind11/numpy.h>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

/// The call that makes each class's objects, by type (set as the class is
/// made, read by refuse_new; both run holding the GIL).
std::map<const PyTypeObject*, std::string>& made_by_of_type() {
  static std::map<const PyTypeObject*, std::string> made_by;
  return made_by;
}

/// tp_new of the classes whose objects only the module makes (Surface, Fit,
/// ImportSummary and every result class): refuses. It is the type's own
/// slot (py::custom_type_setup), not a Python __new__ attribute, so that
/// every way to one (Surface(), Surface.__new__(Surface), object.__new__ or
/// Surface.__mro__[1].__new__(Surface), whose "is not safe" check compares
/// the slots) raises TypeError: no such object exists without its C++ part,
/// on which pybind11 would run methods on uninitialised memory.
PyObject* refuse_new(PyTypeObject* type, PyObject*, PyObject*) {
  const char* dot = std::strrchr(type->tp_name, '.');
  const std::string name = dot ? dot + 1 : type->tp_name;
  const auto found = made_by_of_type().find(type);
  const std::string from = found != made_by_of_type().end() ? found->second : "the module's functions";
  PyErr_SetString(PyExc_TypeError,
                  ("hydrocoef." + name + " objects come from " + from + "; they cannot be made directly").c_str());
  return nullptr;
}

}  // namespace

py::custom_type_setup made_by_the_module_only(std::string made_by) {
  return py::custom_type_setup([made_by = std::move(made_by)](PyHeapTypeObject* heap_type) {
    made_by_of_type()[&heap_type->ht_type] = made_by;
    heap_type->ht_type.tp_new = refuse_new;
  });
}

double or_nan(const py::object& value) {
  return value.is_none() ? std::numeric_limits<double>::quiet_NaN() : value.cast<double>();
}

std::vector<double> numbers(const py::object& value) {
  if (value.is_none()) return {};
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array || array.ndim() != 1) throw py::type_error("expected a one-dimensional sequence of numbers");
  return std::vector<double>(array.data(), array.data() + array.size());
}

std::optional<std::string> optional_text(const py::object& value) {
  if (value.is_none()) return std::nullopt;
  return py::str(value).cast<std::string>();  // a str or a path
}

std::vector<std::int64_t> run_ids(const py::object& value, const char* what) {
  if (value.is_none()) return {};
  try {
    return value.cast<std::vector<std::int64_t>>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string(what) + ": expected a list of run ids (int)");
  }
}

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

}  // namespace hydrocoef_python
