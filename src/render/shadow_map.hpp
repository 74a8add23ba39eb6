// The directional light's shadow map: a depth texture of the bodies seen from the light, refitted each
// frame around the bodies so that its texels are spent where the shadows are cast.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "render/gl_objects.hpp"

namespace render {

// An axis-aligned box around every shadow caster [m].
struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
};

// The volume the shadow map covers: an orthographic box along the light.
struct LightFrustum {
  glm::mat4 view_projection{1.0f};  // world → shadow-map clip space
  float width_m = 0.0f;             // side of the box across the light; a texel is width_m / map size
};

// The box for light travelling along `direction` around the bounding sphere of `casters`. Only casters
// need to be inside it: a receiver beside the box samples the texture border (depth 1, lit), and one
// beyond the far plane is compared at depth 1, so it is shadowed exactly where a caster was drawn
// (lighting.glsl).
LightFrustum fit_light_frustum(const glm::vec3& direction, const Bounds& casters);

class ShadowMap {
 public:
  explicit ShadowMap(int size_px);

  // Binds the depth framebuffer, sets the viewport and clears depth: draw the casters next.
  void begin_pass() const;
  // The depth texture, set up for sampler2DShadow (compare on, linear filtering, border depth 1).
  GLuint texture() const { return depth_.get(); }
  int size_px() const { return size_; }

 private:
  int size_;
  GlTexture depth_;
  GlFramebuffer framebuffer_;
};

}  // namespace render
