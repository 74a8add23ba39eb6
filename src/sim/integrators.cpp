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

std::unique_ptr<Integrator> make_integrator(scene::Integrator kind, double tolerance) {
  switch (kind) {
    case scene::Integrator::Euler: return std::make_unique<ForwardEuler>();
    case scene::Integrator::Symplectic: return std::make_unique<SymplecticEuler>();
    case scene::Integrator::Verlet: return std::make_unique<VelocityVerlet>();
    case scene::Integrator::Rk4: return std::make_unique<RungeKutta4>();
    case scene::Integrator::Rk45: return std::make_unique<DormandPrince>(tolerance);
    case scene::Integrator::Implicit: return std::make_unique<ImplicitEuler>();
  }
  return nullptr;
}

}  // namespace sim
