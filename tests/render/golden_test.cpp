// Golden-image smoke tests: small scenes built in code (no simulation, so physics changes cannot move
// them) rendered at 160×120 and compared with tests/golden/*.png.
//
// Tolerance: a pixel differs when a channel is off by more than 16 of 255; up to 0.3 % of the pixels
// (58 of 19200) may differ. Another Mesa version may rasterise silhouettes and shadow edges a sample
// differently (MSAA keeps most such pixels under 16 levels), while a lost shadow (about 1 % of the
// picture), a wrong light, normal, colour space or flip, or a missing floor changes far more.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "image_compare.hpp"
#include "mesh/generators.hpp"
#include "render/renderer.hpp"
#include "test_context.hpp"

namespace {

const render_test::Tolerance kGoldenTolerance{16, 0.003};

// A generated mesh scaled per axis and moved, as a renderer input.
render::FrameMesh placed(const mesh::TriMesh& shape, glm::vec3 scale, glm::vec3 position) {
  render::FrameMesh frame;
  for (const softbody::Vec3& v : shape.vertices) {
    frame.positions.push_back(position + scale * glm::vec3(float(v.x()), float(v.y()), float(v.z())));
  }
  for (const softbody::Triangle& t : shape.triangles) frame.triangles.emplace_back(t[0], t[1], t[2]);
  return frame;
}

render::RenderSettings small_settings() {
  render::RenderSettings settings;
  settings.width_px = 160;
  settings.height_px = 120;
  settings.floor_height_m = 0.0f;
  settings.body_colors = {{0.80f, 0.12f, 0.07f}, {0.1f, 0.35f, 0.8f}};
  return settings;
}

softbody::Image render_once(const render::RenderSettings& settings, const std::vector<render::FrameMesh>& bodies) {
  render::Renderer renderer(render_test::gl_context(), settings);
  renderer.draw(bodies);
  softbody::Image image;
  renderer.read_back(image);
  return image;
}

TEST(Golden, BallInTheAirOverTheFloor) {
  // Frame 0 of the bounce: ball above the floor, its shadow on the checkerboard, 4× MSAA.
  const softbody::Image image = render_once(small_settings(), {placed(mesh::icosphere(3), glm::vec3(1.0f), {0, 3, 0})});
  const std::string failure = render_test::check_against_golden(image, "ball_in_the_air", kGoldenTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(Golden, SquashedBallOnTheFloor) {
  // The landing: a flattened ball touching the floor. Its normals come from the deformed mesh, so the
  // highlight sits on the flat top, not where a sphere's would be.
  const softbody::Image image =
      render_once(small_settings(), {placed(mesh::icosphere(3), glm::vec3(1.35f, 0.6f, 1.35f), {1.5f, 0.6f, 0.0f})});
  const std::string failure = render_test::check_against_golden(image, "squashed_ball", kGoldenTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(Golden, TwoBodiesWithoutFloorShadowsOrMultisampling) {
  render::RenderSettings settings = small_settings();
  settings.floor_height_m.reset();
  settings.shadows = false;
  settings.msaa_samples = 1;
  const softbody::Image image = render_once(settings, {placed(mesh::icosphere(2), glm::vec3(0.8f), {-1.2f, 1.5f, 0.0f}),
                                                       placed(mesh::cube(2), glm::vec3(1.4f), {1.3f, 1.0f, 0.5f})});
  const std::string failure = render_test::check_against_golden(image, "two_bodies_plain", kGoldenTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(Shadow, FallsOnTheFloorWhereTheLightSendsIt) {
  // The shadow of a sphere in parallel light is an ellipse centred on the shadow of its centre: the
  // pixels that darken when shadows are switched on must gather around that point's projection.
  // Ball at height 3, where the floor lies far beyond the light frustum fitted around the ball.
  render::RenderSettings settings = small_settings();
  const glm::vec3 centre(0.0f, 3.0f, 0.0f);
  const std::vector<render::FrameMesh> ball = {placed(mesh::icosphere(3), glm::vec3(1.0f), centre)};
  const softbody::Image shadowed = render_once(settings, ball);
  settings.shadows = false;
  const softbody::Image unshadowed = render_once(settings, ball);

  long darker = 0;
  double sum_x = 0.0, sum_y = 0.0;
  for (int y = 0; y < shadowed.height; ++y) {
    for (int x = 0; x < shadowed.width; ++x) {
      const std::uint8_t* on = shadowed.pixel(x, y);
      const std::uint8_t* off = unshadowed.pixel(x, y);
      if (int(off[0]) + off[1] + off[2] - (int(on[0]) + on[1] + on[2]) < 30) continue;
      ++darker;
      sum_x += x + 0.5;
      sum_y += y + 0.5;
    }
  }
  ASSERT_GT(darker, 40) << "no shadow on the floor";
  const glm::vec3 travel = glm::normalize(settings.light.direction);
  const glm::vec3 shadow_centre = centre + travel * (centre.y / -travel.y);
  render::Renderer renderer(render_test::gl_context(), settings);
  const glm::vec2 expected = render::project_to_pixel(renderer.camera(), shadow_centre, 160, 120);
  EXPECT_NEAR(sum_x / double(darker), expected.x, 2.0);
  EXPECT_NEAR(sum_y / double(darker), expected.y, 2.0);
}

}  // namespace
