// An off-screen GL context with the render command's renderer, drawing a world's current frame into an image.
#pragma once

#include <memory>
#include <vector>

#include "core/image.hpp"
#include "render/frame_mesh.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "render/settings.hpp"
#include "sim/step/world.hpp"

namespace softbody_python {

class FrameRenderer {
 public:
  // A context from `backend` (auto: EGL, then OSMesa); throws std::runtime_error when none can be made.
  FrameRenderer(render::GlBackend backend, const render::RenderSettings& settings);

  // The world's bodies as the render command draws them (output::snapshot_surfaces, then the renderer), read back:
  // top row first, 8-bit sRGB RGB, the pixels its PNG files hold. Later calls must draw the same world's bodies.
  softbody::Image draw(const sim::World& world);

  int width() const { return renderer_.settings().width_px; }
  int height() const { return renderer_.settings().height_px; }

 private:
  std::unique_ptr<render::GlContext> context_;
  render::Renderer renderer_;
  std::vector<render::FrameMesh> meshes_;
};

}  // namespace softbody_python
