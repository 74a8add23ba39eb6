// The framing camera of scenes without `camera`: every corner of the swept box inside the picture with the
// margin, the fit tight (some corner on the margin's edge), and the floor's horizon in view; a keyframed collider
// counted wherever it goes during the frames, and drawn from its first key's pose.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/camera.hpp"
#include "render/camera_framing.hpp"
#include "render/settings.hpp"

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

// A box 0.2 m wide, keyframed (linear) from x = −3 m at 0 s to +3 m at 1 s and back to 0 at 2 s; a last key at 5 s
// (x = 10 m) comes after the run.
sim::Collider swinging_box() {
  sim::Collider box;
  box.geometry.shape = sim::ColliderShape::Box;
  box.geometry.half_size_m = softbody::Vec3(0.1, 0.1, 0.1);
  for (const auto& [time_s, x_m] : {std::pair{0.0, -3.0}, {1.0, 3.0}, {2.0, 0.0}, {5.0, 10.0}}) {
    sim::ColliderKey key;
    key.time_s = time_s;
    key.position_m = softbody::Vec3(x_m, 0.5, 0.0);
    box.motion.keys.push_back(key);
  }
  return box;
}

TEST(CameraFraming, AKeyframedColliderCountsWhereverItGoesDuringTheFrames) {
  const sim::Collider box = swinging_box();
  const render::Bounds ball{{-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}};
  // The frames pass the turn at 1 s between them: the key itself counts; the key after the last frame does not.
  const double frame_times_s[] = {0.0, 0.7, 1.3, 2.0};
  const render::Bounds box_and_ball = render::including_moving_colliders(ball, {&box, 1}, frame_times_s);
  EXPECT_NEAR(box_and_ball.min.x, -3.1f, 1e-5f);
  EXPECT_NEAR(box_and_ball.max.x, 3.1f, 1e-5f);
  EXPECT_EQ(box_and_ball.min.y, 0.0f);
  EXPECT_EQ(box_and_ball.max.y, 1.0f);
  // Where it was first drawn only (the first key) leaves the rest of its path out.
  render::RenderSettings settings;
  render::use_world_colliders(settings, {&box, 1});
  EXPECT_NEAR(render::including_colliders(ball, settings.colliders).max.x, 0.5f, 1e-6f);
}

TEST(RenderSettings, AKeyframedColliderIsDrawnFromItsFirstKeysPose) {
  const sim::Collider box = swinging_box();
  render::RenderSettings settings;
  render::use_world_colliders(settings, {&box, 1});
  ASSERT_EQ(settings.colliders.size(), 1u);
  ASSERT_EQ(settings.moving_colliders.size(), 1u);
  EXPECT_EQ(settings.colliders[0].position_m, softbody::Vec3(-3.0, 0.5, 0.0));
  EXPECT_TRUE(settings.colliders[0].velocity.moving);  // so that each frame poses it at its time
}

}  // namespace
