// The Python module `softbody`: load a scene, step it frame by frame, read its numbers and render its frames, with
// the same code (and the same bits) as the command line.
#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(softbody, module) {
  module.doc() =
      "Pressure-model soft bodies (Matyka & Ollila 2003), simulated and rendered off-screen: the softbody program's "
      "scenes, frames, CSV numbers and pictures, bit for bit, as numpy arrays.";
  module.attr("__version__") = SOFTBODY_VERSION;
  softbody_python::register_errors(module);
  softbody_python::register_scene(module);
  softbody_python::register_simulation(module);
  softbody_python::register_render(module);
  softbody_python::register_png(module);
}
