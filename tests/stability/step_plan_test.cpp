// sim::resolve_step: xpbd's substeps and "dt": "auto" resolved on the model's copy of the solver settings.
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "sim/step/stability.hpp"
#include "sim/step/step_plan.hpp"
#include "test_helpers.hpp"

namespace {

using testing_support::world_from_text;

constexpr double kFrame_s = 1.0 / 30;

// scenes/bounce.json's ball, coarser, above the floor.
std::string ball(const std::string& solver) {
  return R"({ "fps": 30, "floor": { "height": 0 }, "solver": )" + solver +
         R"(, "bodies": [ { "mesh": "icosphere:2", "position": [0, 1, 0], "stiffness": 3000, "damping": 0.5, "pressure": 30 } ] })";
}

TEST(StepPlan, RequestedDtStaysAsItIs) {
  sim::World world = world_from_text(ball(R"({ "integrator": "symplectic", "dt": 1e-4 })"));
  const sim::StepPlan plan = sim::resolve_step(world.model, world.state, kFrame_s, "s.json");
  EXPECT_TRUE(plan.dt_requested());
  EXPECT_EQ(plan.dt_s, 1e-4);
  EXPECT_EQ(world.model.solver.dt_s, 1e-4);
}

TEST(StepPlan, XpbdSubstepsDivideTheFrameInterval) {
  sim::World world = world_from_text(ball(R"({ "integrator": "xpbd", "substeps": 7 })"));
  const sim::StepPlan plan = sim::resolve_step(world.model, world.state, kFrame_s, "s.json");
  EXPECT_FALSE(plan.dt_requested());
  EXPECT_FALSE(plan.substeps_chosen);
  EXPECT_EQ(plan.substeps, 7);
  EXPECT_EQ(plan.dt_s, 1.0 / 30 / 7);
  EXPECT_EQ(world.model.solver.dt_s, plan.dt_s);
}

// scenes/bump.json, colliders.json, paddle.json and stairs.json take vbd with "dt": "auto"; a whole number of substeps
// set beside it (`--set solver.substeps=8`) is the step, not replaced by the automatic choice as it was.
TEST(StepPlan, GivenSubstepsWinOverDtAuto) {
  for (const char* integrator : {"xpbd", "vbd"}) {
    sim::World world =
        world_from_text(ball(std::string(R"({ "integrator": ")") + integrator + R"(", "dt": "auto", "substeps": 8 })"));
    const sim::StepPlan plan = sim::resolve_step(world.model, world.state, kFrame_s, "s.json");
    EXPECT_FALSE(plan.substeps_chosen) << integrator;
    EXPECT_EQ(plan.substeps, 8) << integrator;
    EXPECT_EQ(world.model.solver.dt_s, kFrame_s / 8) << integrator;
  }
  sim::World world = world_from_text(ball(R"({ "integrator": "vbd", "dt": "auto" })"));
  const sim::StepPlan plan = sim::resolve_step(world.model, world.state, kFrame_s, "s.json");
  EXPECT_TRUE(plan.substeps_chosen) << "without substeps, dt auto still chooses them";
}

// Substeps given as a number are kept, but where a contact after the step (here the ball's paper floor) needs more for
// its travel limit, the plan says how many ("auto"'s choice for vbd); a smooth floor, inside vbd's energy, needs none.
TEST(StepPlan, GivenSubstepsBelowTheTravelLimitAreFlagged) {
  const auto plan_of = [](const std::string& solver, const std::string& floor) {
    const std::string plain = R"("floor": { "height": 0 })";
    std::string text = ball(solver);
    text.replace(text.find(plain), plain.size(), R"("floor": { "height": 0, "contact": ")" + floor + R"(" })");
    sim::World world = world_from_text(text);
    const sim::StabilityEstimate estimate = sim::estimate_stability(world.model, world.state, false);
    const int needed = sim::travel_substeps(world.model.solver.integrator, world.model, estimate, kFrame_s);
    return std::pair{sim::resolve_step(world.model, world.state, kFrame_s, "s.json"), needed};
  };
  const auto [one, needed] = plan_of(R"({ "integrator": "vbd", "substeps": 1 })", "paper");
  EXPECT_GT(needed, 1);
  EXPECT_EQ(one.substeps, 1) << "kept";
  EXPECT_EQ(one.travel_substeps, needed);
  EXPECT_GT(one.travel_dt_s, 0.0);
  const auto [enough, unused] =
      plan_of(R"({ "integrator": "vbd", "substeps": )" + std::to_string(needed) + " }", "paper");
  EXPECT_EQ(enough.travel_substeps, 0);
  const auto [smooth, none] = plan_of(R"({ "integrator": "vbd", "substeps": 1 })", "smooth");
  EXPECT_EQ(smooth.travel_substeps, 0);
  EXPECT_EQ(none, 1);
}

TEST(StepPlan, XpbdAutoSubstepsComeFromTheEstimate) {
  sim::World world = world_from_text(ball(R"({ "integrator": "xpbd", "substeps": "auto" })"));
  const sim::StabilityEstimate estimate = sim::estimate_stability(world.model, world.state);
  std::string phases;
  const sim::StepPlan plan = sim::resolve_step(world.model, world.state, kFrame_s, "s.json",
                                               [&](const std::string& phase) { phases += phase; });
  EXPECT_TRUE(plan.substeps_chosen);
  EXPECT_EQ(plan.substeps, sim::auto_substeps(world.model.solver.integrator, world.model, estimate, kFrame_s));
  EXPECT_EQ(world.model.solver.substeps, plan.substeps);
  EXPECT_EQ(world.model.solver.dt_s, kFrame_s / plan.substeps);
  EXPECT_EQ(plan.travel_dt_s, estimate.travel_dt_s);
  EXPECT_EQ(phases, "estimating the stable substep");
}

TEST(StepPlan, DtAutoIsAlsoTheFirstTrialStep) {
  sim::World world = world_from_text(ball(R"({ "integrator": "rk45", "dt": "auto" })"));
  const sim::StabilityEstimate estimate = sim::estimate_stability(world.model, world.state);
  const sim::StepPlan plan = sim::resolve_step(world.model, world.state, kFrame_s, "s.json");
  EXPECT_TRUE(plan.dt_chosen);
  EXPECT_EQ(plan.dt_s, sim::auto_dt(estimate, sim::IntegratorKind::Rk45, kFrame_s, "s.json"));
  EXPECT_EQ(plan.stable_dt_s, estimate.stable_dt(sim::IntegratorKind::Rk45));
  EXPECT_EQ(world.model.solver.dt_s, plan.dt_s);
  EXPECT_EQ(world.state.next_dt_s, plan.dt_s);
}

TEST(StepPlan, DtAutoRefusesForwardEulerWithoutDampers) {
  sim::World world = world_from_text(
      R"({ "solver": { "integrator": "euler", "dt": "auto" }, "bodies": [ { "mesh": "icosphere:1", "damping": 0 } ] })");
  EXPECT_THROW(sim::resolve_step(world.model, world.state, kFrame_s, "s.json"), softbody::InputError);
}

}  // namespace
