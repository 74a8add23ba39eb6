// The integrator factory: scene names to implementations (one file each under integrators/).
#include "sim/integrators.hpp"

#include "sim/integrators/dormand_prince.hpp"
#include "sim/integrators/euler.hpp"
#include "sim/integrators/implicit_euler.hpp"
#include "sim/integrators/runge_kutta4.hpp"
#include "sim/integrators/symplectic_euler.hpp"
#include "sim/integrators/velocity_verlet.hpp"

namespace sim {

void Dynamics::first_order_step(State& state, double dt, FirstOrderUpdate update, std::vector<Vec3>& scratch) {
  accelerations(state, scratch);
  for (std::size_t i = 0; i < state.x.size(); ++i) apply_first_order_update(update, dt, scratch[i], state.x[i], state.v[i]);
}

std::unique_ptr<Integrator> make_integrator(sim::IntegratorKind kind, double tolerance) {
  switch (kind) {
    case sim::IntegratorKind::Euler: return std::make_unique<ForwardEuler>();
    case sim::IntegratorKind::Symplectic: return std::make_unique<SymplecticEuler>();
    case sim::IntegratorKind::Verlet: return std::make_unique<VelocityVerlet>();
    case sim::IntegratorKind::Rk4: return std::make_unique<RungeKutta4>();
    case sim::IntegratorKind::Rk45: return std::make_unique<DormandPrince>(tolerance);
    case sim::IntegratorKind::Implicit: return std::make_unique<ImplicitEuler>();
  }
  return nullptr;
}

}  // namespace sim
