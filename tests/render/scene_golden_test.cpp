// Golden images of the shipped scenes after simulation: scenes/roll.json (the ball rolling on) and
// scenes/pile.json (bodies stacked), rendered at 160×120 with the scene's own camera and light.
// They guard the whole chain scene → simulation → renderer; a deliberate physics change that moves the
// bodies needs the images regenerated (SOFTBODY_UPDATE_GOLDEN=1) after looking at them.
#include <cmath>

#include <gtest/gtest.h>

#include "image_compare.hpp"
#include "output/mesh_snapshot.hpp"
#include "render/renderer.hpp"
#include "render/settings.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "test_context.hpp"

namespace {

// Same tolerance as the code-built goldens (golden_test.cpp): > 16 of 255 in a channel, ≤ 0.3 % pixels.
const render_test::Tolerance kGoldenTolerance{16, 0.003};

scene::Scene shipped_scene(const std::string& scene_file) {
  return scene::load_scene(std::filesystem::path(SOFTBODY_SOURCE_DIR) / "scenes" / scene_file);
}

// The scene's own camera and light, rendered small.
render::RenderSettings small_settings(const scene::Scene& s) {
  render::RenderSettings settings = render::settings_from_scene(s);
  settings.width_px = 160;
  settings.height_px = 120;
  return settings;
}

void simulate_to(sim::World& world, const scene::Scene& s, double time_s) {
  for (long long n = std::llround(time_s / s.solver.dt_s); n > 0; --n) world.step(s.solver.dt_s);
}

// `world` as it is now, drawn by `renderer`.
softbody::Image draw(render::Renderer& renderer, const sim::World& world) {
  std::vector<render::FrameMesh> meshes;
  output::snapshot_surfaces(world, meshes);
  renderer.draw(meshes);
  softbody::Image image;
  renderer.read_back(image);
  return image;
}

// The scene simulated to `time_s` and rendered small.
softbody::Image scene_at(const std::string& scene_file, double time_s) {
  const scene::Scene s = shipped_scene(scene_file);
  std::vector<std::string> notes;
  sim::World world = setup::build_world(s, notes);
  simulate_to(world, s, time_s);
  render::Renderer renderer(render_test::gl_context(), small_settings(s));
  return draw(renderer, world);
}

TEST(SceneGolden, RollingBallAfterLanding) {
  const std::string failure =
      render_test::check_against_golden(scene_at("roll.json", 1.2), "roll_scene", kGoldenTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

// The pattern is painted on the body at rest, not on the first frame a renderer draws: a render that starts
// late (a farm chunk, a resumed run) paints frame N as a render from frame 0 does.
TEST(SceneGolden, PatternIsPaintedOnTheRestShapeWhicheverFrameComesFirst) {
  const scene::Scene s = shipped_scene("roll.json");
  std::vector<std::string> notes;
  sim::World world = setup::build_world(s, notes);
  render::Renderer from_the_start(render_test::gl_context(), small_settings(s));
  draw(from_the_start, world);  // frame 0
  simulate_to(world, s, 1.2);
  const softbody::Image continued = draw(from_the_start, world);
  render::Renderer started_late(render_test::gl_context(), small_settings(s));
  const softbody::Image late = draw(started_late, world);
  EXPECT_TRUE(continued.rgb == late.rgb) << "the same state painted differently";
}

TEST(SceneGolden, PileStacked) {
  const std::string failure =
      render_test::check_against_golden(scene_at("pile.json", 0.45), "pile_scene", kGoldenTolerance);
  EXPECT_TRUE(failure.empty()) << failure;
}

}  // namespace
