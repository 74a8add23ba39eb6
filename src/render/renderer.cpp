// The renderer's passes.
#include "render/renderer.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "render/collider_surface.hpp"
#include "render/normals.hpp"

namespace render {
namespace {

constexpr int kShadowMapSize_px = 1024;  // fitted around the bodies each frame: ~2 mm texels for a 1 m ball
constexpr int kShadowTextureUnit = 0;
constexpr float kShadowNormalOffset_texels = 1.5f;  // covers the PCF taps one texel either side
constexpr float kSquareSize_m = 1.0f;               // checker squares
const glm::vec3 kLightSquare{0.78f, 0.78f, 0.76f};  // linear RGB
const glm::vec3 kDarkSquare{0.30f, 0.30f, 0.32f};
const glm::vec3 kDefaultBodyColor{0.80f, 0.12f, 0.07f};  // the scene default (scene::Body::color)
const glm::vec3 kColliderColor{0.34f, 0.40f, 0.48f};     // linear RGB: a slate grey-blue, apart from floor and bodies

// The floor fades into the background between these multiples of the camera's distance to its target,
// which hides the floor's edge and the aliasing near the horizon; the square reaches a bit beyond.
constexpr float kFadeStart = 3.0f;
constexpr float kFadeEnd = 7.0f;
constexpr float kMaxFadeEnd_m = 400.0f;  // within the camera's far plane (500 m)

// Makes `context` current before any member touches GL.
GlContext& made_current(GlContext& context) {
  context.make_current();
  return context;
}

Bounds bounds_of(std::span<const FrameMesh> bodies) {
  Bounds box{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(std::numeric_limits<float>::lowest())};
  for (const FrameMesh& body : bodies) {
    for (const glm::vec3& p : body.positions) {
      box.min = glm::min(box.min, p);
      box.max = glm::max(box.max, p);
    }
  }
  return box;
}

}  // namespace

Renderer::Renderer(GlContext& context, RenderSettings settings)
    : context_(made_current(context)),
      settings_(std::move(settings)),
      camera_(camera_matrices(settings_.camera,
                              static_cast<float>(settings_.width_px) / static_cast<float>(settings_.height_px))),
      targets_(settings_.width_px, settings_.height_px, settings_.msaa_samples),
      lit_body_program_({"surface.vert"}, {"lighting.glsl", "body.frag"}),
      lit_floor_program_({"surface.vert"}, {"lighting.glsl", "floor.frag"}),
      lit_collider_program_({"surface.vert"}, {"lighting.glsl", "collider.frag"}),
      shadow_program_({"shadow.vert"}, {"shadow.frag"}) {
  if (settings_.shadows) shadow_map_.emplace(kShadowMapSize_px);
  const float view_distance = glm::length(settings_.camera.target - settings_.camera.position);
  floor_fade_start_m_ = std::min(kFadeStart * view_distance, kMaxFadeEnd_m * kFadeStart / kFadeEnd);
  floor_fade_end_m_ = std::min(kFadeEnd * view_distance, kMaxFadeEnd_m);
  upload_colliders();
  if (settings_.floor_height_m) {
    const glm::vec2 under_camera(settings_.camera.position.x, settings_.camera.position.z);
    floor_.emplace(*settings_.floor_height_m, under_camera, floor_fade_end_m_ * 1.1f);
  }
  glEnable(GL_DEPTH_TEST);
  check_gl("setting up the renderer");
}

std::vector<ColliderSurface> Renderer::collider_surfaces(std::span<const sim::ColliderGeometry> colliders) {
  std::vector<ColliderSurface> surfaces;
  collider_bounds_.reset();
  for (const sim::ColliderGeometry& geometry : colliders) {
    if (geometry.shape == sim::ColliderShape::Plane) continue;
    surfaces.push_back(bounded_collider_surface(geometry));
    Bounds box{surfaces.back().positions.front(), surfaces.back().positions.front()};
    if (collider_bounds_) box = *collider_bounds_;
    for (const glm::vec3& p : surfaces.back().positions) {
      box.min = glm::min(box.min, p);
      box.max = glm::max(box.max, p);
    }
    collider_bounds_ = box;
  }
  shadow_casting_colliders_ = surfaces.size();
  // A plane: a square reaching as far as the floor's fade, around its point nearest the camera's target.
  for (const sim::ColliderGeometry& geometry : colliders) {
    if (geometry.shape == sim::ColliderShape::Plane) {
      surfaces.push_back(plane_square(geometry, settings_.camera.target, floor_fade_end_m_ * 1.1f));
    }
  }
  return surfaces;
}

void Renderer::upload_colliders() {
  for (const ColliderSurface& surface : collider_surfaces(settings_.colliders)) {
    collider_meshes_.emplace_back(surface.positions.size(), surface.triangles);
    collider_meshes_.back().update(surface.positions, surface.normals, {});
  }
}

void Renderer::pose_colliders(double time_s) {
  if (settings_.moving_colliders.empty()) return;
  auto moving = settings_.moving_colliders.begin();
  for (sim::ColliderGeometry& geometry : settings_.colliders) {
    if (moving == settings_.moving_colliders.end()) break;
    if (geometry.velocity.moving) geometry = sim::collider_at(*moving++, time_s);
  }
  const std::vector<ColliderSurface> surfaces = collider_surfaces(settings_.colliders);
  for (std::size_t c = 0; c < surfaces.size(); ++c)
    collider_meshes_[c].update(surfaces[c].positions, surfaces[c].normals, {});
}

void Renderer::draw(std::span<const FrameMesh> bodies) {
  upload(bodies);
  const LightFrustum light = draw_shadow_pass(bodies);
  // Linear shader output is sRGB-encoded on store (the clear colour too), and the resolve decodes the
  // samples, averages them in linear light and encodes the result: the one conversion, done right.
  glEnable(GL_FRAMEBUFFER_SRGB);
  draw_main_pass(light);
  targets_.resolve();
  glDisable(GL_FRAMEBUFFER_SRGB);  // read back the stored bytes as they are
  glFinish();
  check_gl("drawing a frame");
}

void Renderer::read_back(softbody::Image& image) { targets_.read_rgb(image); }

void Renderer::upload(std::span<const FrameMesh> bodies) {
  if (body_meshes_.empty()) {
    for (const FrameMesh& body : bodies) body_meshes_.emplace_back(body.positions.size(), body.triangles);
  }
  if (bodies.size() != body_meshes_.size()) {
    throw std::logic_error("Renderer::draw: the number of bodies changed during the run");
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    area_weighted_normals(bodies[b].positions, bodies[b].triangles, normals_scratch_);
    body_meshes_[b].update(bodies[b].positions, normals_scratch_, bodies[b].rest_positions);
  }
}

LightFrustum Renderer::draw_shadow_pass(std::span<const FrameMesh> bodies) {
  if (!shadow_map_ || bodies.empty()) return {};
  Bounds casters = bounds_of(bodies);
  if (collider_bounds_)
    casters = {glm::min(casters.min, collider_bounds_->min), glm::max(casters.max, collider_bounds_->max)};
  const LightFrustum light = fit_light_frustum(settings_.light.direction, casters);
  shadow_map_->begin_pass();
  shadow_program_.use();
  shadow_program_.set("light_view_projection", light.view_projection);
  // Both faces are stored, so the map holds the surface nearest the light: the floor right at a
  // body's contact edge is then clearly behind it and shadowed (storing only back faces, which lie on
  // the floor there, let a lit seam through). The lit side's self-shadowing acne is held off by the
  // slope-scaled offset here and the normal offset of the lookup (surface.vert).
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 2.0f);
  for (const BodyMesh& mesh : body_meshes_) mesh.draw();
  for (std::size_t c = 0; c < shadow_casting_colliders_; ++c) collider_meshes_[c].draw();
  glDisable(GL_POLYGON_OFFSET_FILL);
  return light;
}

void Renderer::set_lighting(const ShaderProgram& program, const LightFrustum& light) const {
  program.use();
  program.set("view_projection", camera_.projection * camera_.view);
  program.set("light_view_projection", light.view_projection);
  const float texel_m = shadow_map_ ? light.width_m / static_cast<float>(shadow_map_->size_px()) : 0.0f;
  program.set("shadow_normal_offset", kShadowNormalOffset_texels * texel_m);
  program.set("light_direction", glm::normalize(settings_.light.direction));
  program.set("light_color", settings_.light.color);
  program.set("ambient", settings_.light.ambient);
  program.set("camera_position", settings_.camera.position);
  program.set("shadows_enabled", shadow_map_ ? 1 : 0);
  program.set("shadow_map", kShadowTextureUnit);
}

void Renderer::draw_main_pass(const LightFrustum& light) {
  targets_.bind_for_drawing();
  glClearColor(settings_.background.r, settings_.background.g, settings_.background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (shadow_map_) {
    glActiveTexture(GL_TEXTURE0 + kShadowTextureUnit);
    glBindTexture(GL_TEXTURE_2D, shadow_map_->texture());
  }
  if (floor_) {
    set_lighting(lit_floor_program_, light);
    lit_floor_program_.set("background", settings_.background);
    lit_floor_program_.set("square_size", kSquareSize_m);
    lit_floor_program_.set("fade_start", floor_fade_start_m_);
    lit_floor_program_.set("fade_end", floor_fade_end_m_);
    lit_floor_program_.set("light_square", kLightSquare);
    lit_floor_program_.set("dark_square", kDarkSquare);
    floor_->draw();
  }
  if (!collider_meshes_.empty()) {
    set_lighting(lit_collider_program_, light);
    lit_collider_program_.set("collider_color", kColliderColor);
    lit_collider_program_.set("background", settings_.background);
    lit_collider_program_.set("fade_start", floor_fade_start_m_);
    lit_collider_program_.set("fade_end", floor_fade_end_m_);
    for (const BodyMesh& mesh : collider_meshes_) mesh.draw();
  }
  set_lighting(lit_body_program_, light);
  for (std::size_t b = 0; b < body_meshes_.size(); ++b) {
    const bool has_color = b < settings_.body_colors.size();
    lit_body_program_.set("body_color", has_color ? settings_.body_colors[b] : kDefaultBodyColor);
    lit_body_program_.set("body_pattern", b < settings_.body_patterns.size() ? settings_.body_patterns[b] : 0);
    body_meshes_[b].draw();
  }
}

}  // namespace render
