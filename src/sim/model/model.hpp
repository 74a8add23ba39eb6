// What never changes during a run: every body (topology, rest shape, masses, force constants), gravity,
// the floor, contact and solver settings. Built once (src/setup/ from a scene, or in code), then const.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "sim/model/body.hpp"
#include "sim/model/settings.hpp"
#include "sim/model/skin.hpp"
#include "sim/model/state.hpp"

namespace sim {

struct Model {
  std::vector<Body> bodies;
  std::vector<double> mass_kg;       // per vertex, all bodies (the bodies' masses, side by side)
  std::vector<double> inverse_mass;  // per vertex, all bodies [1/kg]
  Vec3 gravity_m_per_s2{0.0, -9.81, 0.0};
  std::optional<Floor> floor;           // none: no floor
  std::vector<Collider> colliders;      // static shapes against which every vertex collides (none: no cost)
  BodyContact body_contact;             // between bodies (searched only when there are several)
  Solver solver;                        // the integrator and its options (dt_s: the step a run asks for)
  std::vector<Vec3> initial_x;          // every vertex where the model placed it: the stable-dt advice's state
  std::vector<Skin> skins;              // detailed meshes carried by bodies simulated on a proxy ("resolution");
                                        // read by render and export only, in body order
  std::vector<SurfaceUvs> surface_uvs;  // texture coordinates of the bodies simulated on their own mesh (the
                                        // file's UVs); export only, in body order

  // The skin body `body` carries, or null when render and export show its simulated surface.
  const Skin* skin_of(int body) const {
    for (const Skin& skin : skins) {
      if (skin.body == body) return &skin;
    }
    return nullptr;
  }

  // The corner UVs of the triangles body `body` shows (its skin's, or its own faces'); empty when none.
  std::span<const softbody::CornerUvs> shown_corner_uvs(int body) const {
    if (const Skin* skin = skin_of(body)) return skin->corner_uvs;
    for (const SurfaceUvs& uvs : surface_uvs) {
      if (uvs.body == body) return uvs.corner_uvs;
    }
    return {};
  }

  std::size_t vertex_count() const { return mass_kg.size(); }
  // A body's slice of a per-vertex array (positions, velocities, forces, masses: a vector or a span, const or
  // not): the one way sim/ spells "this body's vertices".
  template <class PerVertex>
  static auto of(const Body& body, PerVertex&& all) {
    return std::span(all).subspan(static_cast<std::size_t>(body.first_vertex),
                                  static_cast<std::size_t>(body.vertex_count));
  }
};

// Appends `body` (its params set) to the model, its vertices starting at `x0` (world coordinates) with the
// common velocity `v0` in `state`; sets body.first_vertex and builds body.constraints.
void add_body(Model& model, State& state, Body body, const std::vector<Vec3>& x0, const Vec3& v0);

// A model with these settings and no bodies yet, and its state at t = 0.
Model make_model(const Vec3& gravity_m_per_s2, std::optional<Floor> floor, const Solver& solver);
State initial_state(const Model& model);

}  // namespace sim
