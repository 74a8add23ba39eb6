// The workspace of a model.
#include "sim/model/workspace.hpp"

#include <algorithm>
#include <thread>

namespace sim {
namespace {

int force_threads(const Solver& solver) {
  const int wanted = solver.threads > 0 ? solver.threads : static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(wanted, 1, kMostForceThreads);
}

}  // namespace

Workspace::Workspace(const Model& model)
    : forces(force_threads(model.solver)), integrator(make_integrator(model.solver)) {
  forces.area_sums.resize(model.bodies.size());
  integrator->set_up(model, *forces.runner);
}

}  // namespace sim
