// The camera a rendered run gets when its scene has none: one that frames the box the bodies sweep over the whole
// run, known from a silent pass over it. The render command and the Python module's render() share it, so that
// both draw the same frame from the same camera.
#pragma once

#include "app/prepared_run.hpp"
#include "frames/frame_loop.hpp"
#include "frames/stop_request.hpp"
#include "output/motion_track.hpp"
#include "render/settings.hpp"

namespace app {

// One silent pass over every frame, for what must be known before frame 0 is drawn: the box the bodies
// sweep (the camera of a scene without one) and the moments figure.png shows. The pass starts from and
// returns to the same State (a copy is a checkpoint), so the run afterwards gives the same bits, and every
// farm chunk gets the same camera and figure; with `checkpoints` (--from-cache) it reads them instead of stepping.
// A divergence ends the pass at the frame before it (the run proper reports it); a stop request (`stop`, asked
// before every step) throws frames::Interrupted with no frame complete.
output::MotionTrack motion_of_the_run(PreparedRun& run, const frames::Checkpoints* checkpoints,
                                      sim::StopQuery stop = frames::stop_requested);

// `settings.camera` becomes the camera that frames the box every body sweeps in `motion` and the bounded colliders
// take (a keyframed one over the frames' times), at the settings' aspect and field of view (render/camera_framing.hpp);
// nothing changes when `motion` has no frame.
void frame_the_motion(render::RenderSettings& settings, const output::MotionTrack& motion);

}  // namespace app
