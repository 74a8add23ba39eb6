// softbody.Simulation, its frames() iterator and the Frame it yields; positions() and row() read the current frame.
// Ctrl-C (SIGINT) reaches Python between two steps: the frame in progress is dropped and KeyboardInterrupt raised.
// The steps run without Python's lock (the GIL); the simulation is then refused to other threads until they end.
#include <optional>
#include <stdexcept>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "output/csv_row.hpp"
#include "python_signals.hpp"
#include "simulation.hpp"
#include "stepping_mark.hpp"

namespace py = pybind11;

namespace softbody_python {
namespace {

// The frames of one simulation, continuing from the frame it is at. The steps run with Python's lock released, so
// that other Python threads run meanwhile (and simulations in several threads step side by side).
struct FrameIterator {
  Simulation* simulation;
  Frame next() {
    simulation->check_idle();
    std::optional<Frame> frame;
    try {
      const SteppingMark stepping(*simulation);  // cleared after the lock is taken back
      const py::gil_scoped_release unlocked;
      frame = simulation->next_frame(python_signal_raised);
    } catch (const StepsStopped&) {
      throw py::error_already_set();  // the KeyboardInterrupt the handler raised
    }
    if (!frame) throw py::stop_iteration();
    return *frame;
  }
};

std::size_t body_index(const Simulation& simulation, py::ssize_t body) {
  if (body < 0) {
    throw py::index_error("body " + std::to_string(body) + ": the simulation has " +
                          std::to_string(simulation.body_count()) + " bodies, numbered from 0");
  }
  return static_cast<std::size_t>(body);
}

py::array_t<double> positions(const Simulation& simulation, py::ssize_t body) {
  simulation.check_idle();
  const std::span<const softbody::Vec3> x = simulation.positions(body_index(simulation, body));
  py::array_t<double> array({static_cast<py::ssize_t>(x.size()), py::ssize_t{3}});
  auto out = array.mutable_unchecked<2>();
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) out(static_cast<py::ssize_t>(i), axis) = x[i][axis];
  }
  return array;
}

py::dict row(const Simulation& simulation, py::ssize_t body) {
  simulation.check_idle();
  const output::CsvRow row = simulation.row(body_index(simulation, body));
  py::dict columns;
  columns["frame"] = row.frame;
  columns["time"] = row.time_s;
  columns["body"] = row.body;
  for (std::size_t c = 0; c < output::kCsvBodyColumns.size(); ++c)
    columns[py::str(std::string(output::kCsvBodyColumns[c]))] = row.values[c];
  return columns;
}

}  // namespace

void register_simulation(py::module_& module) {
  py::class_<Frame>(module, "Frame", "A frame handed out by Simulation.frames().")
      .def_readonly("index", &Frame::index, "The frame's number: 0 is the initial state (the CSV's frame column).")
      .def_readonly("time", &Frame::time_s, "Simulated time [s]: index / fps (the CSV's time column).")
      .def("__repr__", [](const Frame& frame) {
        return "<softbody.Frame " + std::to_string(frame.index) + " at " +
               py::repr(py::float_(frame.time_s)).cast<std::string>() + " s>";
      });

  py::class_<FrameIterator>(module, "FrameIterator")
      .def("__iter__", [](FrameIterator& self) -> FrameIterator& { return self; })
      .def("__next__", &FrameIterator::next);

  py::class_<Simulation>(module, "Simulation",
                         "A scene's run, stepped frame by frame as `softbody simulate` steps it (the same numbers).")
      .def(py::init<scene::Scene>(), py::arg("scene"),
           "Builds the bodies (meshes loaded and prepared) and plans the steps; notes go to standard error. "
           "Raises SceneError.")
      .def(
          "frames", [](Simulation& self) { return FrameIterator{&self}; }, py::keep_alive<0, 1>(),
          "Iterates over the frames from the one the simulation is at: frame 0 (the initial state) first, then one "
          "frame interval of steps each, to the scene's duration. Raises DivergedError, and KeyboardInterrupt on "
          "Ctrl-C between two steps (the simulation stays at the last frame handed out).")
      .def_property_readonly(
          "frame",
          [](const Simulation& self) {
            self.check_idle();
            return self.frame();
          },
          "The frame the simulation is at.")
      .def_property_readonly("last_frame", &Simulation::last_frame, "The run's last frame: ceil(duration * fps).")
      .def_property_readonly("body_count", &Simulation::body_count,
                             "The bodies simulated (a body split into parts counts each part, as the CSV does).")
      .def_property_readonly(
          "scene", [](const Simulation& self) { return self.scene(); }, "The scene it runs.")
      .def("positions", &positions, py::arg("body"),
           "The vertices of `body` at this frame [m]: a new numpy array, (n, 3) float64.")
      .def("row", &row, py::arg("body"),
           "The CSV's row of `body` at this frame: a dict of the columns frame, time, body, com_x, com_y, com_z, "
           "vel_x, vel_y, vel_z, volume, kinetic_energy, total_energy, min_y (the same numbers).");
}

}  // namespace softbody_python
