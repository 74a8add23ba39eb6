// The Python module's simulation: the prepared run, stepped frame by frame.
#include "simulation.hpp"

#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "app/run_camera.hpp"
#include "core/errors.hpp"
#include "frames/frame_loop.hpp"
#include "frames/stop_request.hpp"
#include "render/gl_backend_choice.hpp"
#include "render/settings.hpp"
#include "sim/model/model.hpp"

namespace softbody_python {

Simulation::Simulation(scene::Scene scene) : run_(app::prepare_run(std::move(scene))), initial_(run_.world.state) {}

std::optional<Frame> Simulation::next_frame(sim::StopQuery stop) {
  if (diverged_) throw softbody::DivergedError(*diverged_);
  if (!frame_handed_out_) {
    frame_handed_out_ = true;
    return frame();
  }
  if (frame_ >= run_.clock.frame_count) return std::nullopt;
  sim::State before = run_.world.state;  // a copy is a checkpoint: restoring it gives the same bits
  try {
    const frames::Advance advance = frames::advance_to_frame(run_.world, run_.clock, frame_, frame_ + 1, nullptr, stop);
    if (advance.stopped) {
      run_.world.state = std::move(before);
      throw StepsStopped{};
    }
  } catch (const softbody::DivergedError& e) {
    diverged_ = e.what();
    run_.world.state = std::move(before);
    throw;
  }
  ++frame_;
  return frame();
}

Frame Simulation::frame() const { return {frame_, frames::frame_time_s(run_.clock, frame_)}; }

void Simulation::check_idle() const {
  if (stepping_) {
    throw std::runtime_error(
        "the simulation is busy in another thread (stepping to its next frame, or rendering): use it there, or once "
        "that is done");
  }
}

void Simulation::check_body(std::size_t body) const {
  if (body >= body_count()) {
    throw std::out_of_range("body " + std::to_string(body) + ": the simulation has " + std::to_string(body_count()) +
                            " bodies (0 .. " + std::to_string(body_count() - 1) + ")");
  }
}

std::span<const softbody::Vec3> Simulation::positions(std::size_t body) const {
  check_body(body);
  return sim::Model::of(run_.world.model.bodies[body], run_.world.state.x);
}

output::CsvRow Simulation::row(std::size_t body) const {
  check_body(body);
  return output::csv_row(frame_, frames::frame_time_s(run_.clock, frame_), run_.world, body);
}

const output::MotionTrack& Simulation::motion_of_the_run(sim::StopQuery stop) {
  if (!motion_) {
    sim::State now = run_.world.state;
    run_.world.state = initial_;
    try {
      motion_ = app::motion_of_the_run(run_, nullptr, stop);  // returns to frame 0's state
    } catch (const frames::Interrupted&) {
      run_.world.state = std::move(now);
      throw StepsStopped{};
    } catch (...) {
      run_.world.state = std::move(now);
      throw;
    }
    run_.world.state = std::move(now);
  }
  return *motion_;
}

softbody::Image Simulation::render(int width_px, int height_px, sim::StopQuery stop) {
  if (!renderer_ || renderer_->width() != width_px || renderer_->height() != height_px) {
    renderer_.reset();
    render::RenderSettings settings = render::settings_from_scene(run_.scene);
    render::use_world_colliders(settings, run_.world.model.colliders);
    settings.width_px = width_px;
    settings.height_px = height_px;
    if (!run_.scene.camera.given) app::frame_the_motion(settings, motion_of_the_run(stop));
    const render::GlBackendRequest backend =
        render::choose_gl_backend(run_.scene.render.backend, std::getenv("SOFTBODY_GL"));
    renderer_ = std::make_unique<FrameRenderer>(backend.backend, settings);
  }
  return renderer_->draw(run_.world);
}

}  // namespace softbody_python
