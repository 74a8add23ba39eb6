// The parts of the Python module `softbody`: each file registers its own types and functions on the module.
#pragma once

#include <pybind11/pybind11.h>

namespace softbody_python {

void register_errors(pybind11::module_& module);      // SceneError, DivergedError
void register_scene(pybind11::module_& module);       // Scene, load_scene()
void register_simulation(pybind11::module_& module);  // Simulation, Frame, frames()
void register_render(pybind11::module_& module);      // render()
void register_png(pybind11::module_& module);         // read_png(), write_png()

}  // namespace softbody_python
