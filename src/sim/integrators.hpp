// Time integrators. Each sees the system only through Dynamics ("accelerations of this state"), so
// forces, contacts and guards are written once for all of them.
#pragma once

#include <memory>
#include <vector>

#include "scene/scene.hpp"
#include "sim/body.hpp"

namespace sim {

class Dynamics {
 public:
  virtual ~Dynamics() = default;
  // a_i = f_i(x, v) / m_i for every vertex of `state` [m/s²]; `a` is resized by the callee.
  virtual void accelerations(const State& state, std::vector<Vec3>& a) = 0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Advances `state` by dt seconds.
  virtual void step(Dynamics& dynamics, State& state, double dt) = 0;
};

// Forward (explicit) Euler, the paper's method (Eq. 11), positions and velocities both from the state at
// the start of the step: x' = x + h v, v' = v + h a(x, v). First order; energy of an undamped oscillator
// of angular frequency ω grows by the factor (1 + h²ω²) every step.
class ForwardEuler final : public Integrator {
 public:
  void step(Dynamics& dynamics, State& state, double dt) override;

 private:
  std::vector<Vec3> a_;
};

std::unique_ptr<Integrator> make_integrator(scene::Integrator kind);

}  // namespace sim
