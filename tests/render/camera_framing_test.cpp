// The framing camera of scenes without `camera`: every corner of the swept box inside the picture with the
// margin, the fit tight (some corner on the margin's edge), and the floor's horizon in view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/camera.hpp"
#include "render/camera_framing.hpp"

namespace {

// The largest |x| and |y| of the box's corners in normalised device coordinates (−1..1 is the picture).
glm::vec2 largest_corner_ndc(const render::CameraSettings& camera, const render::Bounds& box, float aspect) {
  const render::CameraMatrices matrices = render::camera_matrices(camera, aspect);
  glm::vec2 largest(0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p{(corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                      (corner & 4) ? box.max.z : box.min.z};
    const glm::vec4 clip = matrices.projection * matrices.view * glm::vec4(p, 1.0f);
    EXPECT_GT(clip.w, 0.0f) << "a corner is behind the camera";
    largest = glm::max(largest, glm::abs(glm::vec2(clip) / clip.w));
  }
  return largest;
}

struct Case {
  render::Bounds box;
  float aspect;
};

TEST(CameraFraming, EveryCornerInsideTheMarginAndTheFitTight) {
  const Case cases[] = {
      {{{-1.0f, 0.0f, -1.0f}, {2.6f, 4.0f, 1.0f}}, 16.0f / 9.0f},  // the bounce: wide and tall
      {{{-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}}, 16.0f / 9.0f},  // a ball at rest
      {{{-6.0f, 0.0f, -1.0f}, {6.0f, 1.0f, 1.0f}}, 4.0f / 3.0f},   // a long roll: width decides
      {{{-0.5f, 0.0f, -0.5f}, {0.5f, 8.0f, 0.5f}}, 16.0f / 9.0f},  // a high drop: height decides
      {{{-1.0f, 0.0f, -8.0f}, {1.0f, 1.0f, 3.0f}}, 1.0f},          // along the view: depth decides
  };
  const float edge = 1.0f - render::kFramingMargin;
  for (const Case& c : cases) {
    const render::CameraSettings camera = render::frame_swept_box(c.box, c.aspect, 45.0f);
    const glm::vec2 largest = largest_corner_ndc(camera, c.box, c.aspect);
    EXPECT_LE(largest.x, edge + 1e-4f);
    EXPECT_LE(largest.y, edge + 1e-4f);
    // Tight: some corner touches the margin in x or y (a camera twice as far would pass the bounds above).
    EXPECT_NEAR(std::max(largest.x, largest.y), edge, 1e-3f) << "box max y " << c.box.max.y;
  }
}

TEST(CameraFraming, TheFloorsHorizonIsInView) {
  const render::Bounds box{{-1.0f, 0.0f, -1.0f}, {2.6f, 4.0f, 1.0f}};
  const render::CameraSettings camera = render::frame_swept_box(box, 16.0f / 9.0f, 45.0f);
  // A floor point far ahead of the camera along its view direction projects inside the picture's height.
  const glm::vec3 ahead =
      glm::normalize(glm::vec3(camera.target.x - camera.position.x, 0.0f, camera.target.z - camera.position.z));
  const glm::vec3 far_floor = glm::vec3(camera.position.x, 0.0f, camera.position.z) + 300.0f * ahead;
  const render::CameraMatrices matrices = render::camera_matrices(camera, 16.0f / 9.0f);
  const glm::vec4 clip = matrices.projection * matrices.view * glm::vec4(far_floor, 1.0f);
  EXPECT_LT(std::abs(clip.y / clip.w), 1.0f);
  EXPECT_GT(clip.y / clip.w, 0.0f);  // above the middle: the camera looks slightly down
}

}  // namespace
