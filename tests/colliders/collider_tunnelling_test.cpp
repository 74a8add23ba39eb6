// No tunnelling: a ball thrown at 5 m/s onto a 1 cm board (a box collider) never has a vertex end a step behind the
// board, for every integrator at the step "auto" chooses and every contact model. The continuous check is what holds
// them: with it switched off the same scenes let vertices through (the smooth contact's spring lets a vertex sink
// about v τ = 1 cm, the whole board, before it has stopped it, and past the board's middle it pushes the vertex out
// of the far side), so the test can fail.
#include <algorithm>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "frames/frame_clock.hpp"
#include "setup/build_world.hpp"
#include "sim/step/step_plan.hpp"
#include "sim/step/world.hpp"
#include "test_helpers.hpp"

namespace {

using softbody::Vec3;

constexpr double kHalfThickness_m = 0.005;  // the board: 1 cm thick, its top at y = +5 mm
constexpr double kSpeed_m_per_s = 5.0;

// The board's shape keys: a box, or a 0.6 m square sheet (tests/data/quad.obj) 1 cm thick, a mesh collider.
constexpr const char* kBoxBoard = R"("shape": "box", "size": [0.6, 0.01, 0.6])";
constexpr const char* kSheetBoard = R"("shape": "mesh", "mesh": "data/quad.obj", "scale": 0.3, "thickness": 0.01)";

std::string ball_at_board(const std::string& contact, const sim::IntegratorInfo& integrator,
                          const std::string& board = kBoxBoard) {
  const std::string step = integrator.frame_substeps ? R"("substeps": "auto")" : R"("dt": "auto")";
  return R"({ "duration": 0.1, "fps": 100, "solver": { "integrator": ")" + std::string(integrator.name) + R"(", )" +
         step + R"( }, "colliders": [ { )" + board + R"(, "contact": ")" + contact +
         R"(", "restitution": 0.3, "friction": 0.3 } ],
      "bodies": [ { "mesh": "icosphere:2", "scale": 0.05, "position": [0, 0.06, 0], "velocity": [0, )" +
         std::to_string(-kSpeed_m_per_s) + R"(, 0],
                    "mass": 0.2, "stiffness": 300, "damping": {"ratio": 0.3}, "pressure": {"inflation": 0.05} } ] })";
}

// The lowest any vertex over the board's area got below the board's top, after any step (adaptive: any frame of a
// 0.1 ms clock) [m]: below 2 half thicknesses it has passed through.
double deepest_below_top(const std::string& text, bool continuous) {
  double deepest = 0.0;
  testing_support::run_scene_steps(
      text,
      [&](const sim::World& world) {
        for (const Vec3& x : world.state.x) {
          if (std::max(std::abs(x.x()), std::abs(x.z())) < 0.3) deepest = std::max(deepest, kHalfThickness_m - x.y());
        }
      },
      [&](sim::World& world) { world.model.colliders.at(0).continuous = continuous; });
  return deepest;
}

TEST(ColliderTunnelling, NoVertexEndsAStepBehindAThinBoard) {
  int discrete_passes = 0, smooth_discrete_passes = 0;
  for (const char* contact : {"paper", "friction", "smooth"}) {
    for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
      const std::string text = ball_at_board(contact, integrator);
      const double with_check = deepest_below_top(text, true), discrete = deepest_below_top(text, false);
      const bool passes = discrete > 2.0 * kHalfThickness_m;
      discrete_passes += passes;
      if (std::string(contact) == "smooth") smooth_discrete_passes += passes;
      std::printf("%-8s %-10s deepest below the top: %.2f mm continuous, %.2f mm discrete%s\n", contact,
                  std::string(integrator.name).c_str(), 1e3 * with_check, 1e3 * discrete,
                  passes ? " (through the board)" : "");
      EXPECT_LT(with_check, 2.0 * kHalfThickness_m) << contact << ", " << integrator.name;
    }
  }
  std::printf("without the continuous check %d of the runs pass through (%d smooth)\n", discrete_passes,
              smooth_discrete_passes);
  EXPECT_GT(smooth_discrete_passes, 0);  // the check is what holds them
}

// The same against a sheet mesh collider of the board's size and thickness: its continuous check crosses the sheet's
// triangles instead of a box's slabs.
TEST(ColliderTunnelling, NoVertexEndsAStepBehindAThinSheetMesh) {
  int discrete_passes = 0;
  for (const char* contact : {"paper", "friction", "smooth"}) {
    for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
      const std::string text = ball_at_board(contact, integrator, kSheetBoard);
      const double with_check = deepest_below_top(text, true), discrete = deepest_below_top(text, false);
      discrete_passes += discrete > 2.0 * kHalfThickness_m;
      std::printf("sheet %-8s %-10s deepest below the top: %.2f mm continuous, %.2f mm discrete\n", contact,
                  std::string(integrator.name).c_str(), 1e3 * with_check, 1e3 * discrete);
      EXPECT_LT(with_check, 2.0 * kHalfThickness_m) << contact << ", " << integrator.name;
    }
  }
  std::printf("without the continuous check %d of the runs pass through the sheet\n", discrete_passes);
  EXPECT_GT(discrete_passes, 0);  // the check is what holds them
}

}  // namespace
