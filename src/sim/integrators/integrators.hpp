// Time integrators. Each sees the system only through Dynamics ("forces and accelerations of this state",
// and the model for the methods that solve a step over the mesh), so forces, contacts and guards are written once
// for all of them. An integrator object holds scratch only: what it carries from one step to the next lives
// in State::carry, so a copied State is a checkpoint.
//
// Every integrator advances the smooth equations of motion ẋ = v, v̇ = a(x, v). Impulse contacts (the
// paper's floor, the friction floor, contact between bodies) are not part of them: sim::step projects the
// state after each step. A step that contains such an event is therefore only first order (the event is
// resolved at step granularity) whatever the integrator; steps without contact keep the integrator's order.
#pragma once

#include <memory>

#include "sim/forces/dynamics.hpp"
#include "sim/model/settings.hpp"
#include "sim/model/state.hpp"

namespace sim {

class AdaptiveIntegrator;

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Builds what depends on the model alone (vbd: its colouring, blocks and thread layouts) before the first step, so
  // that a run's setup pays for it and its steps' time is their own; step() builds what was not.
  virtual void set_up(const Model& /*model*/, PartRunner& /*runner*/) {}
  // Fills what the next step needs from `state` itself and has not been carried over (e.g. Verlet's and
  // rk45's first acceleration), so that a State saved after prepare() holds it too.
  virtual void prepare(Dynamics& /*dynamics*/, State& /*state*/) {}
  // Advances `state` by dt seconds (adaptive methods: one step of exactly dt, without error control).
  // Call prepare() first.
  virtual void step(Dynamics& dynamics, State& state, double dt) = 0;
  // Non-null for integrators that choose their own step size.
  virtual AdaptiveIntegrator* adaptive() { return nullptr; }
};

// An integrator with an error estimate: it tries a step and says how large its error was; sim::advance_to
// accepts or rejects the attempt and chooses the next step size (sim/step/step_size.hpp).
class AdaptiveIntegrator : public Integrator {
 public:
  // Advances `state` by dt and returns the step's scaled error norm (<= 1: within the tolerance; NaN or
  // infinite: the step failed). The state is advanced whatever the error: the caller restores it.
  virtual double attempt(Dynamics& dynamics, State& state, double dt) = 0;
  AdaptiveIntegrator* adaptive() override { return this; }
};

// The integrator `solver` names, with its options (rk45's tolerance, vbd's sweeps).
std::unique_ptr<Integrator> make_integrator(const Solver& solver);

}  // namespace sim
