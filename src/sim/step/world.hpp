// A model, its state and the workspace that steps it, together: what the frame loops, the commands and the
// tests drive. The three parts are public; step() and advance_to() are sim/step/step.hpp's functions.
#pragma once

#include "sim/model/model.hpp"
#include "sim/model/state.hpp"
#include "sim/model/workspace.hpp"
#include "sim/step/step.hpp"

namespace sim {

struct World {
  // Takes the model (const from here on) and its state, and builds the workspace for the model.
  World(Model model_in, State state_in) : model(std::move(model_in)), state(std::move(state_in)), workspace(model) {}

  Model model;  // never changed during a run: the step functions take it const
  State state;
  Workspace workspace;

  void step(double dt) { sim::step(model, state, workspace, dt); }
  bool advance_to(double end_time_s, StopQuery stop = nullptr) {
    return sim::advance_to(model, state, workspace, end_time_s, stop);
  }
  void check_before_frame() { sim::check_before_frame(model, state); }
  // True when the integrator chooses its own steps (rk45): drive it with advance_to().
  bool adaptive() const { return integrator_info(model.solver.integrator).adaptive; }
};

// A world of one body built in code: `body` (its params set) at x0 with the common velocity v0.
World one_body_world(const Vec3& gravity_m_per_s2, std::optional<Floor> floor, const Solver& solver, Body body,
                     const std::vector<Vec3>& x0, const Vec3& v0);

}  // namespace sim
