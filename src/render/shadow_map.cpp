// Shadow map texture, framebuffer and light matrices.
#include "render/shadow_map.hpp"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace render {

LightFrustum fit_light_frustum(const glm::vec3& direction, const Bounds& casters) {
  const glm::vec3 centre = 0.5f * (casters.min + casters.max);
  // A little margin so that PCF taps at the silhouette still fall inside the map.
  const float radius = 0.5f * glm::length(casters.max - casters.min) * 1.05f + 0.01f;
  const glm::vec3 travel = glm::normalize(direction);
  const glm::vec3 up = std::abs(travel.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  // The eye sits two radii back along the light: the sphere spans distances radius .. 3 radius from it,
  // inside the near and far planes with half a radius to spare on each side.
  const glm::mat4 view = glm::lookAt(centre - travel * (2.0f * radius), centre, up);
  return {glm::ortho(-radius, radius, -radius, radius, radius * 0.5f, radius * 3.5f) * view, 2.0f * radius};
}

ShadowMap::ShadowMap(int size_px) : size_(size_px) {
  glBindTexture(GL_TEXTURE_2D, depth_.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size_, size_, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float far_depth[] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, far_depth);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);

  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.get(), 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("the shadow-map framebuffer is incomplete");
  }
  check_gl("creating the shadow map");
}

void ShadowMap::begin_pass() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glViewport(0, 0, size_, size_);
  glClear(GL_DEPTH_BUFFER_BIT);
}

}  // namespace render
