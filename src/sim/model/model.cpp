// Building a model body by body, with its initial state.
#include "sim/model/model.hpp"

namespace sim {

Model make_model(const Vec3& gravity_m_per_s2, std::optional<Floor> floor, const Solver& solver) {
  Model model;
  model.gravity_m_per_s2 = gravity_m_per_s2;
  model.floor = floor;
  model.solver = solver;
  return model;
}

State initial_state(const Model& model) {
  State state;
  state.next_dt_s = model.solver.dt_s;
  return state;
}

void add_body(Model& model, State& state, Body body, const std::vector<Vec3>& x0, const Vec3& v0) {
  body.first_vertex = static_cast<int>(state.x.size());
  body.vertex_count = static_cast<int>(x0.size());
  body.constraints = distance_constraints(body);
  model.mass_kg.insert(model.mass_kg.end(), body.masses.kg.begin(), body.masses.kg.end());
  model.inverse_mass.insert(model.inverse_mass.end(), body.masses.inverse.begin(), body.masses.inverse.end());
  model.initial_x.insert(model.initial_x.end(), x0.begin(), x0.end());
  model.bodies.push_back(std::move(body));
  state.x.insert(state.x.end(), x0.begin(), x0.end());
  state.v.insert(state.v.end(), x0.size(), v0);
  state.forget_carry();
}

}  // namespace sim
