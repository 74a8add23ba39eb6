// The settings that shape a run's output files beyond the simulation (which the scene's hash covers): the
// image size, camera and light of frames, the format of meshes. Two runs with equal settings and scene hash
// write the same bytes: farm chunks that agree share a folder, and a resumed run must agree with the run it
// continues.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/scene.hpp"

namespace app {

// (key, value) in a fixed order, keys named as the scene file names them ("render.width").
using OutputSettings = std::vector<std::pair<std::string, std::string>>;

// render's: render.*, camera.* (or "camera": framed from the motion), light.*, output.pattern.
OutputSettings render_output_settings(const scene::Scene& scene);

// export's: the file format.
OutputSettings export_output_settings(const std::string& format);

// One line naming the command, the scene's simulation hash and every setting: equal for the chunks of one run.
std::string run_identity(const std::string& command, const scene::Scene& scene, const OutputSettings& settings);

}  // namespace app
