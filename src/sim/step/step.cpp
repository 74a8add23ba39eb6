// The phases of a step and the drivers that run them: fixed steps (with retry) and adaptive steps.
#include "sim/step/step.hpp"

#include <algorithm>
#include <optional>
#include <sstream>

#include "core/profile.hpp"
#include "sim/contact/body_collision.hpp"
#include "sim/contact/collider_contact.hpp"
#include "sim/contact/collider_point_cache.hpp"
#include "sim/contact/contact.hpp"
#include "sim/step/diverged.hpp"
#include "sim/step/guard.hpp"
#include "sim/step/stability.hpp"
#include "sim/step/step_size.hpp"

namespace sim {
namespace {

constexpr int kMostRetrySubsteps = 1024;  // solver.retry gives up past this many substeps per step

// Phase 1: the integrator advances x and v (forces evaluated inside). Adaptive integrators return their
// error estimate (<= 1: within the tolerance), fixed-step ones 0.
double integrate(const Model& model, State& state, Workspace& workspace, double h, bool with_error) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::integrate);
  if (!model.colliders.empty()) {  // the colliders' continuous contact sweeps from here
    workspace.step_start_x = state.x;
    workspace.step_start_time_s = state.time_s;
  }
  Dynamics dynamics(model, workspace.forces);
  workspace.integrator->prepare(dynamics, state);
  if (with_error) return workspace.integrator->adaptive()->attempt(dynamics, state, h);
  workspace.integrator->step(dynamics, state, h);
  return 0.0;
}

// Phase 2: impulses between bodies after a step of h (a single body does no search; the smooth contact is a
// force inside phase 1). Returns the contacts resolved.
int resolve_body_contacts(const Model& model, State& state, Workspace& workspace, double h) {
  if (!searches_body_contact(model.bodies) || model.body_contact.contact == BodyContactModel::Smooth)
    return 0;  // smooth: a force
  const softbody::ProfileScope profile(softbody::ProfilePhase::body_contact);
  const PushLimit push{h, model.body_contact.push_speed_m_per_s,
                       !integrator_info(model.solver.integrator).position_based};
  return workspace.collider.resolve(model.bodies, model.inverse_mass, state, model.body_contact.material, push);
}

// Phase 3: the floor's contact model, after every step of h (xpbd: every substep). Returns the vertices it
// moved. The paper's model lists the vertices it reversed in state.coasting (symplectic Euler's next step
// reads them). A position-based integrator's friction floor is the positional constraint with static friction
// (sim/contact/contact.hpp); the paper's model already is one (y ← floor, v ← −v). The smooth contact is a force and
// moves none.
int resolve_floor(const Model& model, State& state, Workspace& workspace, double h) {
  if (!model.floor) return 0;
  const softbody::ProfileScope profile(softbody::ProfilePhase::floor_contact);
  FloorContactFound found;
  switch (model.floor->contact) {
    case FloorContact::Paper:
      state.coasting.clear();
      found = resolve_floor_paper(model.floor->height_m, state.x, state.v, state.coasting);
      break;
    case FloorContact::Friction:
      if (integrator_info(model.solver.integrator).position_based) {
        found = resolve_floor_positional(model.floor->height_m, model.floor->material, h, state.x, state.v);
      } else {
        found = resolve_floor_friction(model.floor->height_m, model.floor->material, state.x, state.v);
      }
      break;
    case FloorContact::Smooth:  // a force inside the dynamics: nothing to project, only the depth to report
      found.deepest_m = deepest_below_floor(model.floor->height_m, state.x);
      break;
  }
  workspace.deepest_floor_penetration_m = std::max(workspace.deepest_floor_penetration_m, found.deepest_m);
  return found.below;
}

// Phase 3b: each collider's contact model, as the floor's (phase 3) against its surface at its pose at the step's
// end, and, unless switched off, its continuous check from the step's start (sim/contact/collider_sweep.hpp). The
// paper's model appends the vertices it reversed to state.coasting (cleared here when the floor's paper model has
// not just filled it).
int resolve_colliders(const Model& model, State& state, Workspace& workspace, double h) {
  if (model.colliders.empty()) return 0;
  const softbody::ProfileScope profile(softbody::ProfilePhase::floor_contact);
  const bool floor_filled_coasting = model.floor && model.floor->contact == FloorContact::Paper;
  if (!floor_filled_coasting) state.coasting.clear();
  const bool position_based = integrator_info(model.solver.integrator).position_based;
  const double start_s = workspace.step_start_time_s;
  int touched = 0;
  for (const Collider& collider : model.colliders) {
    const ColliderGeometry begin = collider_at(collider, start_s), end = collider_at(collider, start_s + h);
    const ColliderStepStart step_start{&begin, workspace.step_start_x, largest_vertex_travel(begin, end)};
    const ColliderStepStart* sweep = collider.continuous ? &step_start : nullptr;
    FloorContactFound found;
    switch (collider.contact) {
      case FloorContact::Paper: found = resolve_collider_paper(end, state.x, state.v, state.coasting, sweep); break;
      case FloorContact::Friction:
        found = position_based ? resolve_collider_positional(end, collider.material, h, state.x, state.v, sweep)
                               : resolve_collider_friction(end, collider.material, state.x, state.v, sweep);
        break;
      case FloorContact::Smooth:  // a force inside the dynamics: only tunnelling to undo, and the depth to report
        if (sweep) found = resolve_collider_tunnelling(end, *sweep, state.x, state.v);
        found.deepest_m = std::max(found.deepest_m, deepest_inside_collider(end, state.x));
        break;
    }
    workspace.deepest_collider_penetration_m = std::max(workspace.deepest_collider_penetration_m, found.deepest_m);
    touched += found.below;
  }
  return touched;
}

// Phase 4: the guard. Finite values every step; energy and volume every kFullCheckInterval steps, or every
// step when `full` (a rejected step can be retried).
std::optional<Divergence> guard(const Model& model, State& state, bool full) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::guard);
  if (full || ++state.guard.steps_since_full_check >= kFullCheckInterval) {
    state.guard.steps_since_full_check = 0;
    return check_all(model, state);
  }
  return check_finite(model, state);
}

// Phases 2, 3 and 3b after a successful integration. A contact moved the state under the integrator: what it
// carried about the old state is stale (a step with such an event is only first order, whatever the method).
void resolve_contacts(const Model& model, State& state, Workspace& workspace, double h) {
  const int touched = resolve_body_contacts(model, state, workspace, h) + resolve_floor(model, state, workspace, h) +
                      resolve_colliders(model, state, workspace, h);
  if (touched > 0) {
    state.carry.acceleration.clear();
    state.carry.previous_x.clear();  // vbd: a BDF2 step across the jump would extrapolate it
    state.carry.previous_v.clear();
    state.carry.older_x.clear();
    state.carry.older_v.clear();
  }
}

// The fixed-step phases of one step of h: integrate → body contacts → floor → guard.
std::optional<Divergence> fixed_step_phases(const Model& model, State& state, Workspace& workspace, double h) {
  integrate(model, state, workspace, h, /*with_error=*/false);
  resolve_contacts(model, state, workspace, h);
  return guard(model, state, /*full=*/model.solver.retry);
}

// A step of dt as state.retry_substeps substeps, each checked: the first problem found. Each substep sees its own
// start time (a moving collider's pose); the step's caller then advances state.time_s by dt.
std::optional<Divergence> run_retry_substeps(const Model& model, State& state, Workspace& workspace, double dt) {
  const double start_s = state.time_s;
  std::optional<Divergence> found;
  for (int s = 0; s < state.retry_substeps && !found; ++s) {
    if (s > 0) state.time_s = start_s + s * (dt / state.retry_substeps);
    found = fixed_step_phases(model, state, workspace, dt / state.retry_substeps);
  }
  state.time_s = start_s;
  return found;
}

// The stable-dt estimate at the model's initial state (the diverged state says nothing about it).
StabilityEstimate estimate_at_start(const Model& model) {
  StabilityEstimate estimate = estimate_stability(model.bodies, model.initial_x);
  scale_for_contacts(estimate, model);
  return estimate;
}

// Throws the divergence of a state at time_s, produced by step `step` of size dt.
[[noreturn]] void throw_diverged(const Model& model, const Divergence& found, double time_s, long long step,
                                 double dt) {
  const StabilityEstimate estimate = estimate_at_start(model);
  const IntegratorKind integrator = model.solver.integrator;
  throw DivergedError(DivergenceReport{found, time_s, step, dt, integrator, estimate.stable_dt(integrator),
                                       model.solver.travel_dt_exceeded_s});
}

// Keeps the state before a step that may be rejected, with what the step needs from it already evaluated.
void save_before_step(const Model& model, State& state, Workspace& workspace) {
  Dynamics dynamics(model, workspace.forces);
  workspace.integrator->prepare(dynamics, state);
  workspace.saved = state;
}

// After the step from workspace.saved failed: the saved state again, in twice the substeps, until a run of
// them passes the guard (true) or kMostRetrySubsteps fail too (false). Later steps keep the count that worked.
bool retry_in_more_substeps(const Model& model, State& state, Workspace& workspace, double dt) {
  while (state.retry_substeps < kMostRetrySubsteps) {
    const int substeps = 2 * state.retry_substeps;
    state = workspace.saved;
    state.retry_substeps = substeps;
    if (!run_retry_substeps(model, state, workspace, dt)) {
      ++state.retried_steps;
      return true;
    }
  }
  return false;
}

// An adaptive attempt rejected: the state saved before it again, the rejection counted and remembered by the
// step-size control, and the next attempt's size.
void reject_attempt(State& state, const Workspace& workspace, double next_dt_s) {
  state = workspace.saved;
  record_rejection(state.carry);
  ++state.rejected_steps;
  state.next_dt_s = next_dt_s;
}

}  // namespace

void step(const Model& model, State& state, Workspace& workspace, double dt) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::step);
  workspace.deepest_floor_penetration_m = 0.0;
  workspace.deepest_collider_penetration_m = 0.0;
  const bool retry = model.solver.retry;
  if (retry) save_before_step(model, state, workspace);
  if (const std::optional<Divergence> found = run_retry_substeps(model, state, workspace, dt)) {
    if (!retry || !retry_in_more_substeps(model, state, workspace, dt)) {
      throw_diverged(model, *found, state.time_s + dt, state.steps + 1, dt);
    }
  }
  state.time_s += dt;
  state.last_dt_s = dt;
  ++state.steps;
}

bool advance_to(const Model& model, State& state, Workspace& workspace, double end_time_s, StopQuery stop) {
  workspace.deepest_floor_penetration_m = 0.0;
  workspace.deepest_collider_penetration_m = 0.0;
  std::optional<Divergence> last_finding;
  while (state.time_s < end_time_s) {
    if (stop && stop()) return false;
    const softbody::ProfileScope profile(softbody::ProfilePhase::step);
    const double remaining = end_time_s - state.time_s;
    const bool last = state.next_dt_s >= remaining;
    const double dt = last ? remaining : state.next_dt_s;
    constexpr double kSmallestStep = 1e-14;  // relative to the time: below this, t + dt == t in doubles
    if (dt <= kSmallestStep * std::max(1.0, end_time_s)) {
      if (last_finding) throw_diverged(model, *last_finding, state.time_s + dt, state.steps + 1, dt);
      std::ostringstream what;
      what << "the adaptive step size fell to " << dt << " s; the motion is unstable or solver.tolerance is too small";
      throw DivergedError(DivergenceReport{{DivergenceKind::StepUnderflow, 0, -1, what.str()},
                                           state.time_s,
                                           state.steps,
                                           dt,
                                           model.solver.integrator,
                                           0.0});
    }
    // Phase 1 with the error estimate; a rejected attempt returns to the saved state.
    save_before_step(model, state, workspace);
    const double error = integrate(model, state, workspace, dt, /*with_error=*/true);
    const StepSizeDecision decision = decide_step_size(dt, error, state.carry);
    if (!decision.accepted) {
      reject_attempt(state, workspace, decision.next_dt_s);
      continue;
    }
    // Phases 2 to 4; the guard rejecting the step: undo it and try a quarter of the step.
    resolve_contacts(model, state, workspace, dt);
    if (auto found = guard(model, state, /*full=*/true)) {
      reject_attempt(state, workspace, 0.25 * dt);
      last_finding = found;
      continue;
    }
    last_finding.reset();
    // A step clipped to the frame boundary says little about the natural step: keep the larger one.
    state.next_dt_s = last ? std::max(decision.next_dt_s, state.next_dt_s) : decision.next_dt_s;
    state.time_s += dt;
    state.last_dt_s = dt;
    ++state.steps;
    if (last) state.time_s = end_time_s;  // exactly, whatever the round-off of the sum
  }
  return true;
}

void check_before_frame(const Model& model, State& state) {
  const softbody::ProfileScope profile(softbody::ProfilePhase::frame_guard);
  state.guard.steps_since_full_check = 0;
  if (auto found = check_all(model, state)) throw_diverged(model, *found, state.time_s, state.steps, state.last_dt_s);
}

}  // namespace sim
