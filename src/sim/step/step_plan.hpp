// The step a run takes, resolved from the model before its first step: xpbd's substeps per frame interval
// (a number or "auto") and "dt": "auto" become the model's solver.dt_s, the one copy every later reader takes.
#pragma once

#include <string>

#include "core/after_phase.hpp"
#include "sim/model/model.hpp"
#include "sim/model/state.hpp"

namespace sim {

// What resolve_step chose, for the notes a command prints.
struct StepPlan {
  double dt_s = 0.0;  // the step in force: model.solver.dt_s after resolve_step [s]
  // xpbd: substeps per frame interval, dt_s = frame interval / substeps; 0: dt_s is the requested or automatic dt.
  int substeps = 0;
  bool substeps_chosen = false;  // xpbd: the substeps were chosen from the stability estimate ("auto")
  bool dt_chosen = false;        // another integrator: dt_s was chosen from the stability estimate ("dt": "auto")
  double travel_dt_s = 0.0;      // substeps_chosen, or given below travel_substeps: the contact travel limit [s]
  // Substeps given as a number, fewer than the contact travel limit needs (sim::travel_substeps), which this is; 0
  // where they keep it or were not given.
  int travel_substeps = 0;
  double stable_dt_s = 0.0;  // dt_chosen: the estimate's stable dt of the integrator [s]
  // The dt is the scene's request, which the frame clock may round down to divide the frame interval.
  bool dt_requested() const { return substeps == 0 && !dt_chosen; }
};

// Resolves model.solver.dt_s for frames of `frame_interval_s`: xpbd with solver.substeps (or "auto", or with
// "dt": "auto", both sim::auto_substeps) takes dt = frame interval / substeps; another integrator with
// "dt": "auto" takes sim::auto_dt, also as state.next_dt_s (rk45's first trial step). Otherwise the requested dt
// stays. `after_phase` is called after an estimate ("estimating the stable substep" / "... step"). Throws
// softbody::InputError starting with `context` (the scene file) when "auto" finds no stable dt.
StepPlan resolve_step(Model& model, State& state, double frame_interval_s, const std::string& context,
                      const softbody::AfterPhase& after_phase = {});

}  // namespace sim
