// Drawing one frame of a world with the render command's renderer.
#include "frame_renderer.hpp"

#include "output/mesh_snapshot.hpp"

namespace softbody_python {

FrameRenderer::FrameRenderer(render::GlBackend backend, const render::RenderSettings& settings)
    : context_(render::create_offscreen_context(backend)), renderer_(*context_, settings) {}

softbody::Image FrameRenderer::draw(const sim::World& world) {
  context_->make_current();  // the renderer draws on the calling thread
  output::snapshot_surfaces(world, meshes_);
  renderer_.draw(meshes_);
  softbody::Image image;
  renderer_.read_back(image);
  return image;
}

}  // namespace softbody_python
