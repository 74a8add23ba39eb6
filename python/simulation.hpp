// A scene's run driven one frame at a time from Python: the command line's prepared run (app::prepare_run), stepped
// by the frame loop's own advance (frames::advance_to_frame), read with the CSV's rows and drawn by its renderer.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>

#include "app/prepared_run.hpp"
#include "frame_renderer.hpp"
#include "output/csv_row.hpp"
#include "output/motion_track.hpp"
#include "scene/scene.hpp"
#include "sim/step/step.hpp"

namespace softbody_python {

struct Frame {
  int index = 0;        // 0 is the initial state
  double time_s = 0.0;  // s, index / fps
};

// Thrown by Simulation::next_frame when its stop query said stop between two steps; the simulation is back at
// the frame it was at.
struct StepsStopped {};

class Simulation {
 public:
  // Builds the world as `softbody simulate` does (notes to standard error); throws softbody::InputError.
  explicit Simulation(scene::Scene scene);

  // The next frame: frame 0 (the initial state) first, then one frame interval of steps each (the guard's full
  // check before it is handed out); nothing after the run's last frame. `stop` is asked before every step; when it
  // says stop, the frame in progress is dropped and StepsStopped thrown. A divergence throws softbody::DivergedError
  // (again at every later call); the simulation then stays at the last frame handed out.
  std::optional<Frame> next_frame(sim::StopQuery stop);

  Frame frame() const;  // the frame the state is at
  int last_frame() const { return run_.clock.frame_count; }
  std::size_t body_count() const { return run_.world.model.bodies.size(); }
  const scene::Scene& scene() const { return run_.scene; }
  // The vertices of `body` (the model's bodies, as the CSV numbers them) [m]; throws std::out_of_range.
  std::span<const softbody::Vec3> positions(std::size_t body) const;
  // The CSV row of `body` at this frame; throws std::out_of_range.
  output::CsvRow row(std::size_t body) const;

  // While next_frame or render runs with Python's lock released (python/stepping_mark.hpp), every other use from
  // another thread is refused: check_idle() throws std::runtime_error saying so.
  void set_stepping(bool stepping) { stepping_ = stepping; }
  void check_idle() const;

  // This frame drawn at width x height pixels, with the scene's camera or, when it has none, the camera the render
  // command frames the whole run with (a silent pass over the run from frame 0, made once, which asks `stop` before
  // every step and throws StepsStopped when it says stop; the simulation stays where it was).
  softbody::Image render(int width_px, int height_px, sim::StopQuery stop);

 private:
  void check_body(std::size_t body) const;
  const output::MotionTrack& motion_of_the_run(sim::StopQuery stop);

  app::PreparedRun run_;
  sim::State initial_;  // frame 0's state: where the framing pass starts
  int frame_ = 0;
  bool frame_handed_out_ = false;  // frame_ was handed out by next_frame
  std::optional<std::string> diverged_;
  std::optional<output::MotionTrack> motion_;
  std::unique_ptr<FrameRenderer> renderer_;
  bool stepping_ = false;
};

}  // namespace softbody_python
