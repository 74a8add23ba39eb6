// The whole render path on a short simulated run (tests/scenes/render_track.json, 11 frames at
// 160×120): files written, pictures sane, and the body drawn where the simulation has it.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "frames/frame_clock.hpp"
#include "frames/frame_loop.hpp"
#include "output/frame_pattern.hpp"
#include "output/png_codec.hpp"
#include "output/tile_label.hpp"
#include "render/render_sink.hpp"
#include "render/renderer.hpp"
#include "scene/scene_json.hpp"
#include "setup/build_world.hpp"
#include "sim/step/diagnostics.hpp"
#include "test_context.hpp"

namespace {

// Records each frame's centre of mass, for comparison with where the body appears in the image.
class CentreOfMassSink final : public frames::FrameSink {
 public:
  void on_frame(int, double, const sim::World& world) override {
    centres.push_back(sim::diagnose(world.model, world.state, 0).com_m);
  }
  void finish(bool) override {}
  std::vector<softbody::Vec3> centres;
};

// The body is pure red (linear 0.8, 0.02, 0.02): its pixels, lit or not, are far redder than the grey
// floor, its grey shadow and the blue sky.
bool is_body_pixel(const std::uint8_t* p) { return p[0] > 60 && p[0] > 2 * p[1] + 20 && p[0] > 2 * p[2] + 20; }

struct BodyPixels {
  long count = 0;
  double x = 0.0;  // centroid, pixel centres at half-integers like render::project_to_pixel
  double y = 0.0;
};

BodyPixels find_body(const softbody::Image& image) {
  BodyPixels body;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!is_body_pixel(image.pixel(x, y))) continue;
      ++body.count;
      body.x += x + 0.5;
      body.y += y + 0.5;
    }
  }
  if (body.count > 0) {
    body.x /= static_cast<double>(body.count);
    body.y /= static_cast<double>(body.count);
  }
  return body;
}

double mean_absolute_difference(const softbody::Image& a, const softbody::Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(int(a.rgb[i]) - int(b.rgb[i]));
  return sum / static_cast<double>(a.rgb.size());
}

class RenderPipeline : public testing::Test {
 protected:
  // One simulated and rendered run shared by every test of the suite (it is the slow part).
  static void SetUpTestSuite() {
    run_ = Run{};
    run_->scene = scene::load_scene(std::filesystem::path(SOFTBODY_TEST_SCENES_DIR) / "render_track.json");
    run_->dir = render_test::fresh_output_dir("pipeline");
    const frames::FrameClock clock =
        frames::plan_frames(run_->scene.duration_s, run_->scene.fps, run_->scene.solver.dt_s);
    std::vector<std::string> notes;
    sim::World world = setup::build_world(run_->scene, notes);
    render::Renderer renderer(render_test::gl_context(), render::settings_from_scene(run_->scene));
    run_->camera = renderer.camera();

    render::RenderOutputs outputs;
    outputs.dir = run_->dir;
    outputs.figure_frames = run_->scene.render.figure_frames;
    outputs.last_frame = clock.frame_count;
    render::RenderSink render_sink(renderer, outputs);
    CentreOfMassSink centres;
    frames::FrameSink* sinks[] = {&centres, &render_sink};
    frames::run_frames(world, clock, sinks);

    run_->centres = centres.centres;
    for (int i = 0; i <= clock.frame_count; ++i) {
      run_->frames.push_back(output::read_png(run_->dir / output::frame_file_name(outputs.pattern, i)));
    }
  }
  static void TearDownTestSuite() { run_.reset(); }

  struct Run {
    scene::Scene scene;
    std::filesystem::path dir;
    render::CameraMatrices camera;
    std::vector<softbody::Vec3> centres;
    std::vector<softbody::Image> frames;
  };
  static std::optional<Run> run_;
};
std::optional<RenderPipeline::Run> RenderPipeline::run_;

TEST_F(RenderPipeline, WritesOnePngPerFrameAndNoTemporaryFiles) {
  ASSERT_EQ(run_->frames.size(), 11u);  // frame 0 (initial state) + 1 s at 10 fps
  for (const auto& entry : std::filesystem::directory_iterator(run_->dir)) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << "left behind: " << name;
  }
  for (const softbody::Image& frame : run_->frames) {
    EXPECT_EQ(frame.width, 160);
    EXPECT_EQ(frame.height, 120);
  }
}

TEST_F(RenderPipeline, FramesAreNotBlank) {
  for (std::size_t i = 0; i < run_->frames.size(); ++i) {
    const softbody::Image& frame = run_->frames[i];
    EXPECT_GT(find_body(frame).count, 100) << "frame " << i << " shows no body";
    double mean = 0.0, square = 0.0;
    for (std::uint8_t v : frame.rgb) mean += v, square += double(v) * v;
    mean /= double(frame.rgb.size());
    const double deviation = std::sqrt(square / double(frame.rgb.size()) - mean * mean);
    EXPECT_GT(deviation, 20.0) << "frame " << i << " is nearly uniform";
  }
}

TEST_F(RenderPipeline, SkyIsTheBackgroundColourEncodedOnceAsSrgbAtTheTop) {
  // Background (0.62, 0.72, 0.85) linear is (206, 221, 237) in sRGB: a missing conversion would give
  // (158, 184, 217), a double one (232, 239, 246). Being at the top also checks the image is not upside down.
  const std::uint8_t* sky = run_->frames[0].pixel(2, 2);
  EXPECT_NEAR(sky[0], 206, 1);
  EXPECT_NEAR(sky[1], 221, 1);
  EXPECT_NEAR(sky[2], 237, 1);
  const std::uint8_t* floor = run_->frames[0].pixel(80, 117);
  EXPECT_GT(std::abs(int(floor[2]) - 237), 20) << "the bottom row should be floor, not sky";
}

TEST_F(RenderPipeline, ConsecutiveFramesDifferWhileTheBodyMoves) {
  for (std::size_t i = 1; i < run_->frames.size(); ++i) {
    const double moved_m = (run_->centres[i] - run_->centres[i - 1]).norm();
    ASSERT_GT(moved_m, 0.02) << "the test scene should keep the body moving";
    EXPECT_GT(mean_absolute_difference(run_->frames[i], run_->frames[i - 1]), 0.3)
        << "frames " << i - 1 << " and " << i << " look the same although the body moved " << moved_m << " m";
  }
}

TEST_F(RenderPipeline, BodyAppearsWhereTheSimulationHasIt) {
  // The centroid of the body's pixels against its centre of mass projected with the renderer's camera.
  // 2 px tolerance: the ball is about 25 px across; perspective shifts a sphere's image centroid from its
  // projected centre by a fraction of a pixel here, and squashing moves mass and silhouette alike.
  for (std::size_t i = 0; i < run_->frames.size(); ++i) {
    const softbody::Vec3& c = run_->centres[i];
    const glm::vec2 expected =
        render::project_to_pixel(run_->camera, glm::vec3(float(c.x()), float(c.y()), float(c.z())),
                                 run_->frames[i].width, run_->frames[i].height);
    const BodyPixels body = find_body(run_->frames[i]);
    EXPECT_NEAR(body.x, expected.x, 2.0) << "frame " << i;
    EXPECT_NEAR(body.y, expected.y, 2.0) << "frame " << i;
  }
}

TEST_F(RenderPipeline, FigureHoldsTheChosenFramesInReadingOrder) {
  const softbody::Image figure = output::read_png(run_->dir / "figure.png");
  // 4 tiles → one row of 4 full-size frames with 8 px gaps.
  EXPECT_EQ(figure.width, 8 + 4 * (160 + 8));
  EXPECT_EQ(figure.height, 8 + 120 + 8);
  // Tile k shows frame round(k · 10 / 3): 0, 3, 7, 10; the shrink factor is 1, so each tile is its frame,
  // but for its time label ("t = 0.30 s") in the top-left corner, which must hold dark ink.
  const int shown[] = {0, 3, 7, 10};
  const int label_right = 2 + output::label_width_px(10, 1), label_bottom = 2 + output::label_height_px(1);
  for (int k = 0; k < 4; ++k) {
    const softbody::Image& frame = run_->frames[shown[k]];
    int largest_difference = 0, ink = 0;
    for (int y = 0; y < frame.height; ++y) {
      for (int x = 0; x < frame.width; ++x) {
        const std::uint8_t* tile = figure.pixel(8 + k * (160 + 8) + x, 8 + y);
        if (x < label_right && y < label_bottom) {
          ink += tile[0] < 64 ? 1 : 0;
          continue;
        }
        for (int c = 0; c < 3; ++c)
          largest_difference = std::max(largest_difference, std::abs(tile[c] - frame.pixel(x, y)[c]));
      }
    }
    EXPECT_LE(largest_difference, 1) << "tile " << k << " is not frame " << shown[k];
    EXPECT_GT(ink, 40) << "tile " << k << " has no time label";
  }
}

}  // namespace
