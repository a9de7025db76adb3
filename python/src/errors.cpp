// hydrocoef.InputError: the C++ library's InputError as a ValueError whose
// message is the CLI's one line.
#include "python/src/bindings.hpp"

namespace hydrocoef_python {

void bind_errors(py::module_& m) {
  py::register_exception<hydrocoef::InputError>(m, "InputError", PyExc_ValueError);
  m.attr("InputError").attr("__doc__") =
      "Bad input: a file that cannot be read, a bad option, a point outside a surface, a NaN, a damaged or foreign "
      "database, a closed database. The message is the one line the hydrocoef command-line tool prints after "
      "'hydrocoef: error: '. A subclass of ValueError.";
}

}  // namespace hydrocoef_python
