// Resolving the step from the model: xpbd's substeps and "dt": "auto".
#include "sim/step/step_plan.hpp"

#include "sim/step/stability.hpp"

namespace sim {

StepPlan resolve_step(Model& model, State& state, double frame_interval_s, const std::string& context,
                      const softbody::AfterPhase& after_phase) {
  Solver& solver = model.solver;
  StepPlan plan;
  plan.dt_s = solver.dt_s;
  const bool substepped = integrator_info(solver.integrator).frame_substeps;
  plan.substeps = substepped ? solver.substeps : 0;
  // "dt": "auto" picks the substeps where they are not given; a whole number of them is the user's and stays.
  if (substepped && (solver.substeps_auto || (solver.dt_auto && solver.substeps == 0))) {
    // vbd's substeps need only the contact's travel limit, not the bodies' modes.
    const StabilityEstimate estimate = estimate_stability(model, state, solver.integrator != IntegratorKind::Vbd);
    plan.substeps = auto_substeps(solver.integrator, model, estimate, frame_interval_s);
    plan.substeps_chosen = true;
    plan.travel_dt_s = estimate.travel_dt_s;
    if (after_phase) after_phase("estimating the stable substep");
  }
  if (substepped && !plan.substeps_chosen && plan.substeps > 0 && contact_after_step(model)) {
    // Substeps given as a number: said where they are longer than the contact travel limit (the run keeps them).
    const StabilityEstimate estimate = estimate_stability(model, state, false);
    const int needed = travel_substeps(solver.integrator, model, estimate, frame_interval_s);
    if (plan.substeps < needed) {
      plan.travel_substeps = needed;
      plan.travel_dt_s = estimate.travel_dt_s;
      solver.travel_dt_exceeded_s = estimate.travel_dt_s;
    }
  }
  if (plan.substeps > 0) {
    solver.substeps = plan.substeps;
    plan.dt_s = frame_interval_s / plan.substeps;
  } else if (solver.dt_auto) {
    const StabilityEstimate estimate = estimate_stability(model, state);
    plan.dt_s = auto_dt(estimate, solver.integrator, frame_interval_s, context);
    plan.dt_chosen = true;
    plan.stable_dt_s = estimate.stable_dt(solver.integrator);
    if (after_phase) after_phase("estimating the stable step");
    state.next_dt_s = plan.dt_s;
  }
  solver.dt_s = plan.dt_s;
  return plan;
}

}  // namespace sim
