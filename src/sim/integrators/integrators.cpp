// The integrator factory: the settings' kinds to implementations (one file each under integrators/).
#include "sim/integrators/integrators.hpp"

#include "sim/integrators/dormand_prince.hpp"
#include "sim/integrators/euler.hpp"
#include "sim/integrators/runge_kutta4.hpp"
#include "sim/integrators/symplectic_euler.hpp"
#include "sim/integrators/velocity_verlet.hpp"
#include "sim/integrators/vertex_block_descent.hpp"
#include "sim/integrators/xpbd.hpp"

namespace sim {

std::unique_ptr<Integrator> make_integrator(const Solver& solver) {
  switch (solver.integrator) {
    case IntegratorKind::Euler: return std::make_unique<ForwardEuler>();
    case IntegratorKind::Symplectic: return std::make_unique<SymplecticEuler>();
    case IntegratorKind::Verlet: return std::make_unique<VelocityVerlet>();
    case IntegratorKind::Rk4: return std::make_unique<RungeKutta4>();
    case IntegratorKind::Rk45: return std::make_unique<DormandPrince>(solver.tolerance);
    case IntegratorKind::Xpbd: return std::make_unique<Xpbd>();
    case IntegratorKind::Vbd:
      return std::make_unique<VertexBlockDescent>(
          solver.sweep_control, solver.iterations, true,
          solver.coarse_space_auto ? VertexBlockDescent::kAutoAggregates : solver.coarse_space,
          vbd_impact_phase(solver));
  }
  return nullptr;
}

}  // namespace sim
