// The silent pass over a run and the camera that frames its motion.
#include "app/run_camera.hpp"

#include <chrono>
#include <cstdio>
#include <vector>

#include "core/errors.hpp"
#include "frames/stop_request.hpp"
#include "render/camera_framing.hpp"

namespace app {
namespace {

glm::vec3 to_glm(const softbody::Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

}  // namespace

output::MotionTrack motion_of_the_run(PreparedRun& run, const frames::Checkpoints* checkpoints, sim::StopQuery stop) {
  const sim::State start = run.world.state;
  output::MotionTrack motion;
  std::vector<frames::FrameSink*> sinks = {&motion};
  const auto started = std::chrono::steady_clock::now();
  try {
    frames::run_frames(run.world, run.clock, sinks, {},
                       {frames::FrameSelection::all(run.clock.frame_count), checkpoints, stop});
  } catch (const softbody::DivergedError&) {
    // The run proper diverges at the same step and reports it, after writing the frames before it: the
    // camera frames those.
  } catch (const frames::Interrupted& interrupted) {
    throw frames::Interrupted(interrupted.signal(), 0);  // SIGINT / SIGTERM before frame 0 was drawn: none complete
  }
  run.world.state = start;
  std::fprintf(
      stderr, "note: a pass over the run's %zu frames for the camera framing or the figure's frames took %.2f s\n",
      motion.samples().size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  return motion;
}

void frame_the_motion(render::RenderSettings& settings, const output::MotionTrack& motion) {
  if (motion.samples().empty()) return;
  std::vector<double> frame_times_s;
  for (const output::MotionSample& sample : motion.samples()) frame_times_s.push_back(sample.time_s);
  const render::Bounds bodies{to_glm(motion.swept_min()), to_glm(motion.swept_max())};
  const render::Bounds box = render::including_moving_colliders(render::including_colliders(bodies, settings.colliders),
                                                                settings.moving_colliders, frame_times_s);
  settings.camera = render::frame_swept_box(
      box, static_cast<float>(settings.width_px) / static_cast<float>(settings.height_px), settings.camera.fov_deg);
}

}  // namespace app
