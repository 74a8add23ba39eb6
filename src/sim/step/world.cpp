// Worlds built in code.
#include "sim/step/world.hpp"

namespace sim {

World one_body_world(const Vec3& gravity_m_per_s2, std::optional<Floor> floor, const Solver& solver, Body body,
                     const std::vector<Vec3>& x0, const Vec3& v0) {
  Model model = make_model(gravity_m_per_s2, floor, solver);
  State state = initial_state(model);
  add_body(model, state, std::move(body), x0, v0);
  return World(std::move(model), std::move(state));
}

}  // namespace sim
