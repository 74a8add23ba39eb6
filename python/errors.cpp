// The program's errors as Python exceptions, with the program's messages: bad input (exit status 2) is
// softbody.SceneError, a diverged simulation (exit status 3) softbody.DivergedError.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "core/errors.hpp"

namespace py = pybind11;

namespace softbody_python {

void register_errors(py::module_& module) {
  py::register_exception<softbody::InputError>(module, "SceneError", PyExc_ValueError).attr("__doc__") =
      "Bad input: a scene, a --set override or a mesh file that cannot be used (the program's exit status 2). "
      "The message names the file, the key or value, and what is expected.";
  py::register_exception<softbody::DivergedError>(module, "DivergedError", PyExc_RuntimeError).attr("__doc__") =
      "The simulation left its stable range (the program's exit status 3). The message says which body, when, "
      "and what to change.";
}

}  // namespace softbody_python
