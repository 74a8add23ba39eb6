// Force assembly: per body, gravity, the springs and dampers (fused), the smooth floor contact, then the gas,
// handed out per vertex.
#include "sim/forces/dynamics.hpp"

#include "core/profile.hpp"
#include "sim/contact/smooth_collider.hpp"
#include "sim/forces/forces.hpp"

namespace sim {

Dynamics::Dynamics(const Model& model, ForceScratch& scratch) : model_(model), scratch_(scratch) {
  if (model.floor && model.floor->contact == FloorContact::Smooth) smooth_floor_ = resolve_smooth_floor(*model.floor);
  if (searches_body_contact(model.bodies) && model.body_contact.contact == BodyContactModel::Smooth) {
    smooth_bodies_ = resolve_smooth_response(model.body_contact.smooth, model.body_contact.material);
  }
}

bool Dynamics::body_contact_forces(const State& state) {
  if (!smooth_bodies_) return false;
  const softbody::ProfileScope profile(softbody::ProfilePhase::smooth_contact);
  scratch_.contact_force.assign(state.x.size(), Vec3::Zero());
  scratch_.collider.add_smooth_forces(model_.bodies, model_.mass_kg, state.x, state.v, *smooth_bodies_,
                                      scratch_.contact_force);
  return true;
}

void Dynamics::floor_contact_forces(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v,
                                    std::span<Vec3> f) const {
  if (!smooth_floor_) return;
  const softbody::ProfileScope profile(softbody::ProfilePhase::smooth_contact);
  add_smooth_floor_forces(*smooth_floor_, body.masses.kg, x, v, f);
}

void Dynamics::collider_contact_forces(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v,
                                       double time_s, std::span<Vec3> f) const {
  for (const Collider& collider : model_.colliders) {
    if (collider.contact != FloorContact::Smooth) continue;
    const softbody::ProfileScope profile(softbody::ProfilePhase::smooth_contact);
    add_smooth_collider_forces(resolve_smooth_collider(collider, time_s), body.masses.kg, x, v, f);
  }
}

void Dynamics::gravity_and_spring_forces(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v,
                                         std::span<Vec3> f) const {
  const softbody::ProfileScope profile(softbody::ProfilePhase::forces);
  start_with_gravity(body.masses.kg, model_.gravity_m_per_s2, f);  // starts the sum: no zeroing pass
  add_spring_dampers(body.constraints, x, v, f);                   // the edges and the bending links
}

double Dynamics::gas_face_pass(std::size_t b, std::span<const Vec3> x) {
  const Body& body = model_.bodies[b];
  if (body.params.pressure_J == 0.0) return 0.0;
  const softbody::ProfileScope profile(softbody::ProfilePhase::gas);
  const double volume = volume_and_area_sums(body.topology.faces, x, scratch_.area_sums[b]);
  return gas_force_per_area_sum(body.params.pressure_J, volume, body.rest.volume_m3);
}

namespace {

// Hands vertices [begin, end) of a body their net force, use(first + i, f_i + per_area_sum · g_i), with
// g the gas's area sums (per_area_sum = 0: no gas, g not read).
template <class Use>
void hand_out_net_forces(std::size_t first, std::size_t begin, std::size_t end, std::span<const Vec3> f,
                         std::span<const Vec3> area_sums, double per_area_sum, Use& use) {
  if (per_area_sum == 0.0) {
    for (std::size_t i = begin; i < end; ++i) use(first + i, f[i]);
  } else {
    for (std::size_t i = begin; i < end; ++i) use(first + i, Vec3(f[i] + per_area_sum * area_sums[i]));
  }
}

}  // namespace

namespace {

// f += the body contact's share of these vertices.
void add_contact_forces(std::span<const Vec3> contact, std::span<Vec3> f) {
  for (std::size_t i = 0; i < f.size(); ++i) f[i] += contact[i];
}

}  // namespace

template <class Use>
void Dynamics::visit_net_forces(const State& state, std::vector<Vec3>& partial, Use use) {
  partial.resize(state.x.size());
  const bool body_contact = body_contact_forces(state);
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    const Body& body = model_.bodies[b];
    const auto first = static_cast<std::size_t>(body.first_vertex);
    const auto count = static_cast<std::size_t>(body.vertex_count);
    const std::span<Vec3> f = Model::of(body, partial);
    if (scratch_.threads > 1 && count >= kParallelMinVertices) {
      visit_body_forces_in_parallel(b, state, f, body_contact, use);
      continue;
    }
    const std::span<const Vec3> x = Model::of(body, state.x), v = Model::of(body, state.v);
    gravity_and_spring_forces(body, x, v, f);
    floor_contact_forces(body, x, v, f);
    collider_contact_forces(body, x, v, state.time_s, f);
    if (body_contact) add_contact_forces(Model::of(body, scratch_.contact_force), f);
    const double per_area_sum = gas_face_pass(b, x);
    const std::span<const Vec3> area_sums = per_area_sum == 0.0 ? std::span<const Vec3>() : scratch_.area_sums[b];
    hand_out_net_forces(first, 0, count, f, area_sums, per_area_sum, use);
  }
}

template <class Use>
void Dynamics::visit_body_forces_in_parallel(std::size_t b, const State& state, std::span<Vec3> f, bool body_contact,
                                             Use& use) {
  const Body& body = model_.bodies[b];
  const auto first = static_cast<std::size_t>(body.first_vertex);
  const std::size_t n = f.size();
  const std::span<const Vec3> x = Model::of(body, state.x), v = Model::of(body, state.v);
  // 1. Gravity, springs and dampers into f on one thread; the gas's face pass into its area sums on the other.
  double per_area_sum = 0.0;
  scratch_.runner->run(2, [&](int part) {
    if (part == 0) {
      gravity_and_spring_forces(body, x, v, f);
      floor_contact_forces(body, x, v, f);
      collider_contact_forces(body, x, v, state.time_s, f);
      if (body_contact) add_contact_forces(Model::of(body, scratch_.contact_force), f);
    } else {
      per_area_sum = gas_face_pass(b, x);
    }
  });
  // 2. The net force of each vertex, in two vertex ranges.
  const std::span<const Vec3> area_sums = per_area_sum == 0.0 ? std::span<const Vec3>() : scratch_.area_sums[b];
  scratch_.runner->run(2, [&](int part) {
    const std::size_t begin = part == 0 ? 0 : n / 2, end = part == 0 ? n / 2 : n;
    hand_out_net_forces(first, begin, end, f, area_sums, per_area_sum, use);
  });
}

void Dynamics::forces(const State& state, std::vector<Vec3>& force) {
  visit_net_forces(state, force, [&](std::size_t i, const Vec3& f) { force[i] = f; });
}

void Dynamics::accelerations(const State& state, std::vector<Vec3>& a) {
  const std::vector<double>& inverse_mass = model_.inverse_mass;
  visit_net_forces(state, a, [&](std::size_t i, const Vec3& f) { a[i] = f * inverse_mass[i]; });
}

void Dynamics::gravity_and_gas_forces(const State& state, std::vector<Vec3>& force) {
  force.resize(state.x.size());
  const bool body_contact = body_contact_forces(state);
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    const Body& body = model_.bodies[b];
    const std::span<Vec3> f = Model::of(body, force);
    const std::span<const Vec3> x = Model::of(body, state.x), v = Model::of(body, state.v);
    start_with_gravity(body.masses.kg, model_.gravity_m_per_s2, f);
    floor_contact_forces(body, x, v, f);  // a smooth contact is a force like gravity here (none otherwise)
    collider_contact_forces(body, x, v, state.time_s, f);
    if (body_contact) add_contact_forces(Model::of(body, scratch_.contact_force), f);
    const double per_area_sum = gas_face_pass(b, x);
    if (per_area_sum == 0.0) continue;
    const std::vector<Vec3>& area_sums = scratch_.area_sums[b];
    for (std::size_t i = 0; i < f.size(); ++i) f[i] += per_area_sum * area_sums[i];
  }
}

template <FirstOrderUpdate kUpdate>
void Dynamics::fused_first_order_step(State& state, double dt) {
  const std::vector<double>& inverse_mass = model_.inverse_mass;
  visit_net_forces(state, scratch_.net_force, [&](std::size_t i, const Vec3& f) {
    apply_first_order_update(kUpdate, dt, f * inverse_mass[i], state.x[i], state.v[i]);
  });
}

void Dynamics::first_order_step(State& state, double dt, FirstOrderUpdate update) {
  if (update == FirstOrderUpdate::Forward) {
    fused_first_order_step<FirstOrderUpdate::Forward>(state, dt);
  } else {
    fused_first_order_step<FirstOrderUpdate::Symplectic>(state, dt);
  }
}

}  // namespace sim
