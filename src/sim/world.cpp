// The world step as phases, and building a world from a scene.
#include "sim/world.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <thread>

#include "core/errors.hpp"
#include "mesh/load.hpp"
#include "sim/contact.hpp"
#include "sim/forces.hpp"
#include "sim/intent.hpp"
#include "sim/stability.hpp"

namespace sim {

World::World(const Vec3& gravity_m_per_s2, std::optional<sim::Floor> floor, sim::IntegratorKind integrator)
    : World(gravity_m_per_s2, floor, sim::Solver{integrator}) {}

World::World(const Vec3& gravity_m_per_s2, std::optional<sim::Floor> floor, const sim::Solver& solver)
    : gravity_(gravity_m_per_s2),
      floor_(floor),
      integrator_(make_integrator(solver.integrator, solver.tolerance)),
      adaptive_dt_s_(solver.dt_s),
      integrator_kind_(solver.integrator),
      retry_(solver.retry),
      threads_(std::clamp(solver.threads > 0 ? solver.threads : static_cast<int>(std::thread::hardware_concurrency()),
                          1, kMostForceThreads)),
      part_runner_(std::make_unique<PartRunner>(threads_)) {
  guard_.configure(floor_ ? std::optional<double>(floor_->height_m) : std::nullopt, gravity_.norm());
}

void World::add_body(Topology topology, const Params& params, const std::vector<Vec3>& x0, const Vec3& v0) {
  Body body;
  body.first_vertex = static_cast<int>(state_.x.size());
  body.vertex_count = static_cast<int>(x0.size());
  body.params = params;
  mass_.insert(mass_.end(), topology.mass_kg.begin(), topology.mass_kg.end());
  inverse_mass_.insert(inverse_mass_.end(), topology.inverse_mass.begin(), topology.inverse_mass.end());
  body.topology = std::move(topology);
  state_.x.insert(state_.x.end(), x0.begin(), x0.end());
  state_.v.insert(state_.v.end(), x0.size(), v0);
  area_scratch_.emplace_back(x0.size());
  bodies_.push_back(std::move(body));
  initial_x_.insert(initial_x_.end(), x0.begin(), x0.end());
  integrator_->restart();
  guard_.rebase();
}

void World::step(double dt) {
  if (retry_) {
    backup_ = state_;
    backup_reversed_ = reversed_;  // what the integrator was told about the backed-up state
  }
  if (auto found = substep(dt)) {
    if (!retry_ || !retry_with_substeps(dt)) throw_diverged(*found, dt);
  }
  time_s_ += dt;
  last_dt_s_ = dt;
  ++step_count_;
}

std::optional<Divergence> World::integrate_and_check(double dt) {
  integrator_->step(*this, state_, dt);
  resolve_contacts();
  // Finite values every step; energy and volume every kFullCheckInterval steps (and before every frame,
  // check_state()), or every step when a failed step is to be retried.
  if (retry_ || ++steps_since_full_check_ >= kFullCheckInterval) {
    steps_since_full_check_ = 0;
    return guard_.check(bodies_, state_.x, state_.v);
  }
  return guard_.check_finite(bodies_, state_.x, state_.v);
}

void World::check_state() {
  steps_since_full_check_ = 0;
  if (auto found = guard_.check(bodies_, state_.x, state_.v)) throw_diverged(*found, 0.0);
}

std::optional<Divergence> World::substep(double dt) {
  for (int s = 0; s < substeps_; ++s) {
    if (auto found = integrate_and_check(dt / substeps_)) return found;
  }
  return std::nullopt;
}

bool World::retry_with_substeps(double dt) {
  constexpr int kMostSubsteps = 1024;
  while (substeps_ < kMostSubsteps) {
    substeps_ *= 2;
    state_ = backup_;
    integrator_->restart();
    if (!backup_reversed_.empty()) integrator_->velocities_reversed(backup_reversed_);
    if (!substep(dt)) {
      ++retried_step_count_;
      return true;
    }
  }
  return false;
}

void World::throw_diverged(const Divergence& found, double dt) const {
  std::ostringstream message;
  // dt = 0: the state after the last counted step (check_state), else the step of dt being taken.
  const bool counted = dt == 0.0;
  message << "diverged at t = " << time_s_ + dt << " s (step " << step_count_ + (counted ? 0 : 1) << ", dt = "
          << (counted ? last_dt_s_ : dt) << " s, "
          << sim::to_string(integrator_kind_) << "): body " << found.body;
  if (found.vertex >= 0) message << ", vertex " << found.vertex;
  StabilityEstimate estimate = estimate_stability(bodies_, initial_x_);  // the start: this state is gone
  if (floor_) scale_for_floor_contact(estimate, floor_->contact);
  message << " " << found.what << "; " << stable_dt_advice(estimate, integrator_kind_)
          << " (softbody info SCENE prints the estimate)";
  throw softbody::DivergedError(message.str());
}

void World::advance_to(double end_time_s) {
  AdaptiveIntegrator& adaptive = *integrator_->adaptive();
  std::optional<Divergence> last_finding;
  while (time_s_ < end_time_s) {
    const double remaining = end_time_s - time_s_;
    const bool last = adaptive_dt_s_ >= remaining;
    const double dt = last ? remaining : adaptive_dt_s_;
    constexpr double kSmallestStep = 1e-14;  // relative to the time: below this, t + dt == t in doubles
    if (dt <= kSmallestStep * std::max(1.0, end_time_s)) {
      if (last_finding) throw_diverged(*last_finding, dt);
      std::ostringstream message;
      message << "diverged at t = " << time_s_ << " s (step " << step_count_ << "): the adaptive step size "
              << "fell to " << dt << " s; the motion is unstable or solver.tolerance is too small";
      throw softbody::DivergedError(message.str());
    }
    backup_ = state_;
    const AdaptiveIntegrator::Attempt attempt = adaptive.attempt(*this, state_, dt);
    if (!attempt.accepted) {
      ++rejected_step_count_;
      adaptive_dt_s_ = attempt.next_dt_s;
      continue;
    }
    resolve_contacts();
    if (auto found = guard_.check(bodies_, state_.x, state_.v)) {
      // The error estimate let a diverging step through: undo it and try a quarter of the step.
      state_ = backup_;
      integrator_->restart();
      ++rejected_step_count_;
      adaptive_dt_s_ = 0.25 * dt;
      last_finding = found;
      continue;
    }
    last_finding.reset();
    // A step clipped to the frame boundary says little about the natural step: keep the larger one.
    adaptive_dt_s_ = last ? std::max(attempt.next_dt_s, adaptive_dt_s_) : attempt.next_dt_s;
    time_s_ += dt;
    ++step_count_;
    if (last) time_s_ = end_time_s;  // exactly, whatever the round-off of the sum
  }
}

void World::spring_forces(const Body& body, std::span<const Vec3> x, std::span<const Vec3> v, std::span<Vec3> f) const {
  const Topology& topology = body.topology;
  set_gravity(topology.mass_kg, gravity_, f);  // starts the sum: no separate zeroing pass
  const double k = body.params.stiffness_N_per_m, c = body.params.damping_N_s_per_m;
  if (k != 0.0 || c != 0.0) add_spring_dampers(topology.edges, topology.rest_length_m, k, c, x, v, f);
}

double World::gas_face_pass(std::size_t b, std::span<const Vec3> x) {
  const Body& body = bodies_[b];
  if (body.params.pressure_J == 0.0) return 0.0;
  const double volume = sum_area_vectors(body.topology.faces, x, area_scratch_[b]);
  return gas_force_per_area_sum(body.params.pressure_J, volume, body.topology.rest_volume_m3);
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

template <class Use>
void World::visit_net_forces(const State& state, std::vector<Vec3>& scratch, Use use) {
  scratch.resize(state.x.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    const auto first = static_cast<std::size_t>(body.first_vertex);
    const auto count = static_cast<std::size_t>(body.vertex_count);
    const std::span<Vec3> f(scratch.data() + first, count);
    if (threads_ > 1 && count >= kParallelMinVertices) {
      visit_body_forces_in_parallel(b, state, f, use);
      continue;
    }
    const std::span<const Vec3> x(state.x.data() + first, count), v(state.v.data() + first, count);
    spring_forces(body, x, v, f);
    const double per_area_sum = gas_face_pass(b, x);
    hand_out_net_forces(first, 0, count, f, area_scratch_[b], per_area_sum, use);
  }
}

template <class Use>
void World::visit_body_forces_in_parallel(std::size_t b, const State& state, std::span<Vec3> f, Use& use) {
  const Body& body = bodies_[b];
  const auto first = static_cast<std::size_t>(body.first_vertex);
  const std::size_t n = f.size();
  const std::span<const Vec3> x(state.x.data() + first, n), v(state.v.data() + first, n);
  // 1. Gravity, springs and dampers into f on one thread; the gas's face pass into its area sums on the other.
  double per_area_sum = 0.0;
  part_runner_->run(2, [&](int part) {
    if (part == 0) {
      spring_forces(body, x, v, f);
    } else {
      per_area_sum = gas_face_pass(b, x);
    }
  });
  // 2. The net force of each vertex, in two vertex ranges.
  part_runner_->run(2, [&](int part) {
    const std::size_t begin = part == 0 ? 0 : n / 2, end = part == 0 ? n / 2 : n;
    hand_out_net_forces(first, begin, end, f, area_scratch_[b], per_area_sum, use);
  });
}

void World::forces(const State& state, std::vector<Vec3>& force) {
  visit_net_forces(state, force, [&](std::size_t i, const Vec3& f) { force[i] = f; });
}

void World::accelerations(const State& state, std::vector<Vec3>& a) {
  visit_net_forces(state, a, [&](std::size_t i, const Vec3& f) { a[i] = f * inverse_mass_[i]; });
}

template <FirstOrderUpdate kUpdate>
void World::fused_first_order_step(State& state, double dt, std::vector<Vec3>& scratch) {
  visit_net_forces(state, scratch, [&](std::size_t i, const Vec3& f) {
    apply_first_order_update(kUpdate, dt, f * inverse_mass_[i], state.x[i], state.v[i]);
  });
}

void World::first_order_step(State& state, double dt, FirstOrderUpdate update, std::vector<Vec3>& scratch) {
  if (update == FirstOrderUpdate::Forward) {
    fused_first_order_step<FirstOrderUpdate::Forward>(state, dt, scratch);
  } else {
    fused_first_order_step<FirstOrderUpdate::Symplectic>(state, dt, scratch);
  }
}

void World::resolve_contacts() {
  int touched = 0;
  if (bodies_.size() > 1) touched += collider_.resolve(bodies_, inverse_mass_, state_, body_contact_);
  if (floor_) {
    switch (floor_->contact) {
      case FloorContact::Paper:
        reversed_.clear();
        touched += resolve_floor_paper(floor_->height_m, state_.x, state_.v, reversed_);
        break;
      case FloorContact::Friction:
        touched += resolve_floor_friction(floor_->height_m, floor_->material, state_.x, state_.v);
        break;
    }
  }
  // The projection moved the state under the integrator: caches of the old state are stale. A step with
  // such an event is only first order, whatever the integrator (see integrators.hpp).
  if (touched > 0) integrator_->restart();
  if (floor_ && floor_->contact == sim::FloorContact::Paper && !reversed_.empty()) {
    integrator_->velocities_reversed(reversed_);
  }
}

std::vector<SpringSet> World::spring_sets() const {
  std::vector<SpringSet> sets;
  for (const Body& body : bodies_) {
    sets.push_back({body.topology.edges, body.topology.rest_length_m, body.params.stiffness_N_per_m,
                    body.params.damping_N_s_per_m, body.first_vertex});
  }
  return sets;
}

std::span<const Vec3> World::positions(const Body& body) const {
  return {state_.x.data() + body.first_vertex, static_cast<std::size_t>(body.vertex_count)};
}

std::span<const Vec3> World::velocities(const Body& body) const {
  return {state_.v.data() + body.first_vertex, static_cast<std::size_t>(body.vertex_count)};
}

World build_world(const scene::Scene& scene, std::vector<std::string>& notes) {
  World world(scene.gravity_m_per_s2, scene.floor, scene.solver);
  world.set_body_contact(scene.collisions.material);
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const scene::Body& spec = scene.bodies[b];
    const std::string context = scene.source.string() + ": bodies." + std::to_string(b) + ".mesh";
    mesh::LoadedMesh loaded = mesh::load_closed_mesh(spec.mesh, spec.mesh_file, context);
    notes.insert(notes.end(), loaded.notes.begin(), loaded.notes.end());
    const std::vector<Vec3> x0 = place_mesh(loaded.mesh, spec);
    Topology topology = build_topology(x0, loaded.mesh.triangles, spec.mass_kg);
    const std::string key_path = scene.source.string() + ": bodies." + std::to_string(b);
    const Params params = resolve_params(spec, topology, x0, key_path);
    world.add_body(std::move(topology), params, x0, spec.velocity_m_per_s);
  }
  return world;
}

}  // namespace sim
