// Scratch that one step uses and the next overwrites: the force passes' buffers and threads, the
// integrator's stages, the contact search's grid, and the state a rejected step returns to. Built for one
// model; nothing in it is needed to continue a run (that is all in State).
#pragma once

#include <memory>

#include "sim/contact/body_collision.hpp"
#include "sim/forces/dynamics.hpp"
#include "sim/integrators/integrators.hpp"
#include "sim/model/model.hpp"
#include "sim/model/state.hpp"

namespace sim {

struct Workspace {
  // For `model`: its integrator, and solver.threads (0: one per core) capped at kMostForceThreads.
  explicit Workspace(const Model& model);

  ForceScratch forces;
  std::unique_ptr<Integrator> integrator;
  BodyCollider collider;
  State saved;  // the state before a step that may be rejected (solver.retry, adaptive integrators)
  // With colliders: every vertex at the start of the step being taken, and that time [s], for the colliders'
  // continuous contact (sim/contact/collider_sweep.hpp). Empty without colliders.
  std::vector<Vec3> step_start_x;
  double step_start_time_s = 0.0;

  // What the contact phases found during the last step() (all its substeps) or advance_to() (all its steps
  // and attempts), for checks and benchmarks: how deep a vertex got into the floor before it was put back [m].
  double deepest_floor_penetration_m = 0.0;
  double deepest_collider_penetration_m = 0.0;  // the same for the colliders (any of them) [m]
};

}  // namespace sim
