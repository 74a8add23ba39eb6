// softbody.render(sim, width=, height=): the simulation's current frame as the render command draws it, as a numpy
// image.
#include <optional>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "numpy_image.hpp"
#include "python_signals.hpp"
#include "simulation.hpp"
#include "stepping_mark.hpp"

namespace py = pybind11;

namespace softbody_python {
namespace {

constexpr int kMaxSidePx = 16384;

int checked_side(const char* name, int value) {
  if (value < 1 || value > kMaxSidePx) {
    throw py::value_error(std::string(name) + " = " + std::to_string(value) + ": expected 1 .. " +
                          std::to_string(kMaxSidePx) + " pixels");
  }
  return value;
}

}  // namespace

void register_render(py::module_& module) {
  module.def(
      "render",
      [](Simulation& simulation, std::optional<int> width, std::optional<int> height) {
        simulation.check_idle();
        const scene::RenderSettings& scene_size = simulation.scene().render;
        const int width_px = checked_side("width", width.value_or(scene_size.width_px));
        const int height_px = checked_side("height", height.value_or(scene_size.height_px));
        softbody::Image image;
        try {
          const SteppingMark busy(simulation);  // cleared after the lock is taken back
          const py::gil_scoped_release unlocked;
          image = simulation.render(width_px, height_px, python_signal_raised);
        } catch (const StepsStopped&) {
          throw py::error_already_set();  // the KeyboardInterrupt the handler raised during the framing pass
        }
        return to_numpy(image);
      },
      py::arg("sim"), py::kw_only(), py::arg("width") = py::none(), py::arg("height") = py::none(),
      "The simulation's current frame drawn off-screen as `softbody render` draws it (the same pixels on the same "
      "GL backend): a numpy array (height, width, 3) uint8, sRGB, top row first. The size defaults to the scene's "
      "render.width and render.height. A scene without camera gets the render command's camera, which frames the "
      "whole run: the first render() makes a silent pass over it, as the command does.");
}

}  // namespace softbody_python
