// Everything about a run that changes from step to step: positions, velocities, time, and what the
// integrator, the contacts, the retry and the guard carry from one step to the next. A copy of a State is a
// checkpoint: stepping from the copy gives the same bits as never having copied (tests/checkpoint_test.cpp).
#pragma once

#include <vector>

#include "core/vec.hpp"

namespace sim {

using softbody::Vec3;

// What an integrator carries from one step to the next besides x and v.
struct IntegratorCarry {
  // An acceleration of every vertex that the next step starts from [m/s²]; empty when none is carried (then
  // the next step evaluates it). Velocity Verlet: a(x', v*) of the last step, for the first kick. rk45: a(x, v)
  // of the state (the FSAL stage). Invalidated when a contact moves the state under the integrator.
  std::vector<Vec3> acceleration;
  // xpbd's carried form: every body's edge and bending-link constraints' forces of the last substep, T = −Δλ/h²
  // [N], body by body (its edges, then its links); empty at the start (none carried: zero; the next substep is then
  // a run's first, which kicks by h/2: sim/integrators/xpbd.hpp).
  std::vector<double> edge_tension_N;
  // vbd's BDF2 history: the state one step back, x_{n−1} [m] and v_{n−1} [m/s], and the size of the step from it [s];
  // empty at the start and after a contact moved the state (the next step is then backward Euler:
  // sim/integrators/vertex_block_descent.hpp).
  std::vector<Vec3> previous_x;
  std::vector<Vec3> previous_v;
  double previous_dt_s = 0.0;
  // ... and the state one step further back, x_{n−2} and v_{n−2}, with the size of the step from it to x_{n−1} [s]
  // (after two steps of h, a step of 2h takes BDF2's history from there).
  std::vector<Vec3> older_x;
  std::vector<Vec3> older_v;
  double older_dt_s = 0.0;
  // rk45's step-size controller.
  double previous_error = 1e-4;  // err of the last accepted step (PI control)
  bool rejected_last = false;    // the last attempt was rejected: do not grow the step now
};

// What the divergence guard carries: its energy budget and how long since its last full check.
struct GuardCarry {
  std::vector<double> budget_J;  // per body; empty: the next full check takes it from the state it sees
  int steps_since_full_check = 0;
};

struct State {
  std::vector<Vec3> x;  // m, every vertex of every body, bodies one after another (Body::first_vertex)
  std::vector<Vec3> v;  // m/s

  double time_s = 0.0;
  long long steps = 0;           // accepted steps
  long long rejected_steps = 0;  // adaptive integrators: attempts rejected by the error estimate or the guard
  long long retried_steps = 0;   // solver.retry: steps redone in retry substeps
  int retry_substeps = 1;        // solver.retry: each step of dt is now this many substeps (not xpbd's
                                 // solver.substeps, which divide the frame interval)
  double next_dt_s = 1e-4;       // adaptive integrators: the step tried next
  double last_dt_s = 0.0;        // the last step taken, for messages

  IntegratorCarry carry;
  // The vertices whose velocity the paper's floor reversed at the end of the last step (v ← −v). Symplectic
  // Euler skips their next kick, so that the reversal is the time reversal of its own motion
  // (sim/integrators/symplectic_euler.hpp); the other integrators need nothing.
  std::vector<int> coasting;
  GuardCarry guard;

  // Forget what is carried about the motion (after x or v were changed from outside, e.g. by a test): the
  // next step evaluates what it needs afresh and the guard takes a new energy budget.
  void forget_carry() {
    carry.acceleration.clear();
    carry.edge_tension_N.clear();
    carry.previous_x.clear();
    carry.previous_v.clear();
    carry.older_x.clear();
    carry.older_v.clear();
    coasting.clear();
    guard.budget_J.clear();
  }
};

}  // namespace sim
