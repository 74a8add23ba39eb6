// The off-screen renderer: draws the bodies of one frame over a checkerboard floor and among the static colliders,
// with shadows, into an sRGB image. It knows surfaces (FrameMesh) and nothing of the simulation behind them.
//
//   FrameMesh per body ──► normals (CPU) ──► upload positions + normals
//                                              │
//        shadow pass (bodies, from the light) ─┤ (when shadows are on)
//                                              ▼
//        main pass: floor + bodies, lit, 4× MSAA, sRGB ──► resolve ──► read back (flip) ──► Image
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/image.hpp"
#include "render/body_mesh.hpp"
#include "render/camera.hpp"
#include "render/collider_surface.hpp"
#include "render/floor_mesh.hpp"
#include "render/frame_mesh.hpp"
#include "render/gl_context.hpp"
#include "render/render_targets.hpp"
#include "render/settings.hpp"
#include "render/shaders.hpp"
#include "render/shadow_map.hpp"

namespace render {

class Renderer {
 public:
  // Makes `context` current on this thread (it must outlive the renderer and the renderer is used from
  // this thread only), compiles the shaders, makes the framebuffers and uploads the floor.
  Renderer(GlContext& context, RenderSettings settings);

  // Draws one frame and waits until it is finished (so that timing it measures the drawing). The first
  // frame uploads each body's triangles; later frames must have the same bodies and triangles.
  void draw(std::span<const FrameMesh> bodies);

  // Moves the keyframed colliders to their pose at time t (nothing without any): the next draw() shows them there.
  void pose_colliders(double time_s);

  // Copies the last drawn frame into `image` (resized to fit): top row first, 8-bit sRGB RGB.
  void read_back(softbody::Image& image);

  const RenderSettings& settings() const { return settings_; }
  const CameraMatrices& camera() const { return camera_; }
  int msaa_samples() const { return targets_.samples(); }

 private:
  void upload(std::span<const FrameMesh> bodies);
  LightFrustum draw_shadow_pass(std::span<const FrameMesh> bodies);
  void draw_main_pass(const LightFrustum& light);
  void set_lighting(const ShaderProgram& program, const LightFrustum& light) const;
  void upload_colliders();
  // The colliders' surfaces: the bounded ones first (they cast shadows), then the planes; sets collider_bounds_.
  std::vector<ColliderSurface> collider_surfaces(std::span<const sim::ColliderGeometry> colliders);

  GlContext& context_;  // current on this thread from here on
  RenderSettings settings_;
  CameraMatrices camera_;
  RenderTargets targets_;
  ShaderProgram lit_body_program_;
  ShaderProgram lit_floor_program_;
  ShaderProgram lit_collider_program_;
  ShaderProgram shadow_program_;
  std::optional<ShadowMap> shadow_map_;
  std::optional<FloorMesh> floor_;
  float floor_fade_start_m_ = 0.0f;
  float floor_fade_end_m_ = 0.0f;
  std::vector<BodyMesh> body_meshes_;
  std::vector<BodyMesh> collider_meshes_;     // uploaded once; a keyframed collider's moved by pose_colliders
  std::optional<Bounds> collider_bounds_;     // the bounded colliders' box (they cast shadows; planes do not)
  std::size_t shadow_casting_colliders_ = 0;  // collider_meshes_ starts with the bounded ones
  std::vector<glm::vec3> normals_scratch_;
};

}  // namespace render
