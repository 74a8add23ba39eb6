// Building the world of a scene.
#include "setup/build_world.hpp"

#include "mesh/load.hpp"
#include "sim/intent.hpp"

namespace setup {

std::vector<softbody::Vec3> place_mesh(const mesh::TriMesh& mesh, const scene::Body& spec) {
  std::vector<softbody::Vec3> x;
  x.reserve(mesh.vertices.size());
  for (const softbody::Vec3& p : mesh.vertices) x.push_back(spec.position_m + spec.scale * p);
  return x;
}

sim::World build_world(const scene::Scene& scene, std::vector<std::string>& notes) {
  sim::Model model = sim::make_model(scene.gravity_m_per_s2, scene.floor, scene.solver);
  model.body_contact = scene.collisions;
  sim::State state = sim::initial_state(model);
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const scene::Body& spec = scene.bodies[b];
    const std::string key_path = scene.source.string() + ": bodies." + std::to_string(b);
    mesh::LoadedMesh loaded = mesh::load_closed_mesh(spec.mesh, spec.mesh_file, key_path + ".mesh");
    notes.insert(notes.end(), loaded.notes.begin(), loaded.notes.end());
    const std::vector<softbody::Vec3> x0 = place_mesh(loaded.mesh, spec);
    sim::Body body = sim::build_body(x0, loaded.mesh.triangles, spec.mass_kg);
    const sim::Params raw{spec.stiffness_N_per_m, spec.damping_N_s_per_m, spec.pressure_J};
    body.params = sim::resolve_params(raw, spec.intent, body, x0, key_path);
    sim::add_body(model, state, std::move(body), x0, spec.velocity_m_per_s);
  }
  return sim::World(std::move(model), std::move(state));
}

}  // namespace setup
