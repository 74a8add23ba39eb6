// The output settings of render and export, as key = value text.
#include "app/output_settings.hpp"

#include <cstdio>

#include "setup/scene_hash.hpp"

namespace app {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);  // round-trips exactly
  return text;
}

// Built with += : GCC 12 at -O3 reports a false -Wrestrict on "[" + std::string.
std::string triple(double x, double y, double z) {
  std::string text = "[";
  text += number(x);
  text += ", ";
  text += number(y);
  text += ", ";
  text += number(z);
  return text += "]";
}

std::string vector_text(const softbody::Vec3& v) { return triple(v.x(), v.y(), v.z()); }

std::string color_text(const std::array<float, 3>& c) { return triple(c[0], c[1], c[2]); }

std::string frame_list_text(const std::vector<int>& frames) {
  std::string text = "[";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (i > 0) text += ", ";
    text += std::to_string(frames[i]);
  }
  return text += "]";
}

}  // namespace

OutputSettings render_output_settings(const scene::Scene& scene) {
  const scene::RenderSettings& render = scene.render;
  OutputSettings settings = {
      {"render.width", std::to_string(render.width_px)},
      {"render.height", std::to_string(render.height_px)},
      {"render.msaa", std::to_string(render.msaa)},
      {"render.shadows", render.shadows ? "true" : "false"},
      {"render.background", color_text(render.background)},
      {"render.figure_frames", render.figure_frame_list.empty() ? std::to_string(render.figure_frames)
                                                                : frame_list_text(render.figure_frame_list)},
  };
  if (scene.camera.given) {
    settings.insert(settings.end(), {{"camera.position", vector_text(scene.camera.position_m)},
                                     {"camera.target", vector_text(scene.camera.target_m)},
                                     {"camera.up", vector_text(scene.camera.up)},
                                     {"camera.fov", number(scene.camera.fov_deg)}});
  } else {
    settings.emplace_back("camera", "framed from the motion");
  }
  settings.insert(settings.end(), {{"light.direction", vector_text(scene.light.direction)},
                                   {"light.color", color_text(scene.light.color)},
                                   {"light.ambient", number(scene.light.ambient)},
                                   {"output.pattern", scene.output.pattern}});
  return settings;
}

OutputSettings export_output_settings(const std::string& format) { return {{"export.format", format}}; }

std::string run_identity(const std::string& command, const scene::Scene& scene, const OutputSettings& settings) {
  std::string identity = command + " scene " + setup::hash_text(setup::simulation_hash(scene));
  for (const auto& [key, value] : settings) identity += "; " + key + " = " + value;
  return identity;
}

}  // namespace app
