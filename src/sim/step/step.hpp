// The step: one function per phase, in order, and the two ways of driving them (fixed steps, adaptive
// steps). Every function takes the const Model, the State it advances and the Workspace it scribbles in.
//
//   phases of one step of h                      what a rejected step does
//   1. integrate     forces inside (gravity,      fixed step, solver.retry: restore the State saved before
//                    springs, dampers, gas), as     the step and redo it as 2, 4, ... 1024 substeps
//                    often as the integrator needs  adaptive (rk45): restore the State saved before the
//                    (xpbd: one substep, h = 1/fps /  attempt and try the size the error estimate proposes
//                    solver.substeps)                 (or a quarter, after the guard rejected it)
//   2. body contacts impulses between bodies
//   3. floor         the floor's contact model (xpbd's friction floor: positional, with static friction)
//   4. guard         finite values every step;      otherwise: throw DivergedError with what, where, when
//                    energy and volume every 8th      and the dt the estimate finds stable
//                    (every step when a rejection
//                    can be retried)
#pragma once

#include "sim/model/model.hpp"
#include "sim/model/state.hpp"
#include "sim/model/workspace.hpp"

namespace sim {

// One step of dt seconds from state.time_s (rk45 too: one step of exactly dt without error control). With
// solver.retry, a step the guard rejects is redone from its start as 2, 4, .. 1024 substeps, and later steps
// keep the substep count that worked (a dt above the stable limit stays unstable). Otherwise, or if 1024
// fail too, throws sim::DivergedError.
void step(const Model& model, State& state, Workspace& workspace, double dt);

// Asked between steps whether to end early (the CLI's: SIGINT / SIGTERM was received); nullptr: never.
using StopQuery = bool (*)();

// Adaptive integrators: steps of the size the error estimate proposes, the last one clipped so that
// state.time_s lands exactly on `end_time_s`. Rejected attempts (error above the tolerance, or a step the
// guard rejects) are undone, counted in state.rejected_steps, and shrink the step. Throws
// sim::DivergedError when the step size underflows (the motion became unstable or the tolerance is
// unreachable), with the guard's last finding. Returns false when `stop` said so before an attempt (the state
// is then that after the last accepted step, short of end_time_s), true once it lands on end_time_s.
bool advance_to(const Model& model, State& state, Workspace& workspace, double end_time_s, StopQuery stop = nullptr);

// The guard's full check of the state (energy and volume too), which a fixed-step run does only every
// kFullCheckInterval steps: the frame loops call it before handing a frame out, so that no frame of a
// diverged state is written. Throws sim::DivergedError.
void check_before_frame(const Model& model, State& state);

}  // namespace sim
