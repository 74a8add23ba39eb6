// softbody.load_scene(path, set={...}) and the Scene it returns: the command line's scene loading and --set, with
// its checks and messages (scene::load_scene).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"

namespace py = pybind11;

namespace softbody_python {
namespace {

// The --set arguments ("PATH=VALUE") of `overrides`: a str value is VALUE as the command line reads it (JSON when
// it parses as JSON, else a plain string: "rk4"); any other value is written as JSON (json.dumps: 1e-4, True,
// [0, 1, 0]), which reads back as the same number.
std::vector<std::string> set_arguments(const py::dict& overrides) {
  const py::object dumps = py::module_::import("json").attr("dumps");
  std::vector<std::string> arguments;
  for (const auto& [key, value] : overrides) {
    const std::string text =
        py::isinstance<py::str>(value) ? value.cast<std::string>() : dumps(value).cast<std::string>();
    arguments.push_back(py::str(key).cast<std::string>() + "=" + text);
  }
  return arguments;
}

}  // namespace

void register_scene(py::module_& module) {
  py::class_<scene::Scene>(module, "Scene",
                           "A scene file read, --set overrides applied and checked: what Simulation(scene) runs.")
      .def_property_readonly(
          "name", [](const scene::Scene& scene) { return scene.name; }, "The scene's name.")
      .def_property_readonly(
          "path", [](const scene::Scene& scene) { return scene.source; }, "The scene file.")
      .def_property_readonly(
          "fps", [](const scene::Scene& scene) { return scene.fps; }, "Frames per simulated second.")
      .def_property_readonly(
          "duration", [](const scene::Scene& scene) { return scene.duration_s; }, "Simulated seconds.")
      .def("__repr__", [](const scene::Scene& scene) {
        return "<softbody.Scene '" + scene.name + "' from " + scene.source.string() + ">";
      });

  module.def(
      "load_scene",
      [](const std::filesystem::path& path, const std::optional<py::dict>& overrides) {
        return scene::load_scene(path, overrides ? set_arguments(*overrides) : std::vector<std::string>{});
      },
      py::arg("path"), py::arg("set") = py::none(),
      "Reads a scene file (JSON, // comments allowed) with the same keys and checks as the softbody program.\n\n"
      "set: overrides as the program's --set PATH=VALUE, e.g. {\"duration\": 1.0, \"bodies.0.stiffness\": 800,\n"
      "\"solver.integrator\": \"rk4\"}: a str value is read as the command line reads VALUE (JSON when it parses,\n"
      "else a plain word), other values are written as JSON. Raises SceneError with the program's message.");
}

}  // namespace softbody_python
