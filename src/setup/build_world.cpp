// Building the world of a scene.
#include "setup/build_world.hpp"

#include <algorithm>
#include <cstdio>

#include "core/errors.hpp"
#include "core/euler_rotation.hpp"
#include "geometry/mesh_repair.hpp"
#include "mesh/check.hpp"
#include "mesh/load.hpp"
#include "mesh/parts.hpp"
#include "setup/bind_skin.hpp"
#include "setup/collider_meshes.hpp"
#include "setup/derived_quantities.hpp"
#include "setup/scene_totals.hpp"
#include "setup/simulation_proxy.hpp"
#include "setup/start_overlaps.hpp"
#include "sim/forces/bending.hpp"
#include "sim/model/intent.hpp"

namespace setup {
namespace {

// A placed body lies within this distance of the origin [m] and is at least this large [m] (its bounding
// box's diagonal): beyond, squares and products of positions lose all precision or overflow, and the
// stable step of a micrometre body needs more steps per frame than any run takes.
constexpr double kMaxReach_m = 1e7;
constexpr double kMinSize_m = 1e-6;

void check_placed(const std::vector<softbody::Vec3>& x, const std::string& key_path) {
  softbody::Vec3 lo = x.front(), hi = x.front();
  double reach = 0.0;
  for (const softbody::Vec3& p : x) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    reach = std::max(reach, p.cwiseAbs().maxCoeff());
  }
  const double size = (hi - lo).norm();
  char text[320];
  if (!(reach <= kMaxReach_m)) {
    std::snprintf(text, sizeof text,
                  "%s: the placed mesh reaches %.3g m from the origin (position + scale x mesh "
                  "coordinates), beyond the limit of %.0e m: expected a smaller scale or position",
                  key_path.c_str(), reach, kMaxReach_m);
    throw softbody::InputError(text);
  }
  if (!(size >= kMinSize_m)) {
    std::snprintf(text, sizeof text,
                  "%s: the placed mesh is %.3g m across (scale x the mesh's size), below the limit "
                  "of %.0e m: expected a larger scale",
                  key_path.c_str(), size, kMinSize_m);
    throw softbody::InputError(text);
  }
}

// The meshes a body's mesh becomes: itself, or with "split" one per separate closed part (each validated:
// a part may be wound inside out on its own), with their shares of the body's mass and nRT.
struct BodyPart {
  mesh::TriMesh mesh;
  double mass_share = 1.0;      // by surface area, as the mass is lumped to the vertices by area
  double pressure_share = 1.0;  // by enclosed volume: nRT_i / V_i = nRT / V, the same pressure in every part
};

std::vector<BodyPart> parts_of(mesh::LoadedMesh& loaded, const scene::Body& spec, const std::string& key_path,
                               std::vector<std::string>& notes) {
  if (!spec.split) return {BodyPart{std::move(loaded.mesh)}};
  const mesh::MeshParts parts = mesh::edge_connected_parts(loaded.mesh);
  if (parts.count < 2) {
    notes.push_back(key_path + ".split: the mesh is one connected part: nothing to split");
    return {BodyPart{std::move(loaded.mesh)}};
  }
  std::vector<BodyPart> bodies;
  double area = 0.0, volume = 0.0;
  for (mesh::TriMesh& part : mesh::split_parts(loaded.mesh, parts)) {
    mesh::validate_closed(part, notes);
    bodies.push_back({std::move(part)});
    area += mesh::surface_area(bodies.back().mesh);
    volume += mesh::signed_volume(bodies.back().mesh);
  }
  for (BodyPart& part : bodies) {
    part.mass_share = mesh::surface_area(part.mesh) / area;
    part.pressure_share = mesh::signed_volume(part.mesh) / volume;
  }
  notes.push_back(key_path + ".split: the mesh's " + std::to_string(parts.count) + " separate closed parts are " +
                  std::to_string(parts.count) + " bodies");
  return bodies;
}

}  // namespace

std::vector<softbody::Vec3> place_mesh(const mesh::TriMesh& mesh, const scene::Body& spec) {
  std::vector<softbody::Vec3> x;
  x.reserve(mesh.vertices.size());
  if (spec.rotation_deg.isZero(0.0)) {  // no rotation: the placement as it always was, byte for byte
    for (const softbody::Vec3& p : mesh.vertices) x.push_back(spec.position_m + spec.scale * p);
    return x;
  }
  const softbody::Mat3 rotation = softbody::rotation_xyz_degrees(spec.rotation_deg);
  for (const softbody::Vec3& p : mesh.vertices) x.push_back(spec.position_m + rotation * (spec.scale * p));
  return x;
}

// A body placed below the floor: an error where its centre (the mean of its vertices) is under the floor, so that
// more than about half of it would start inside; a note where only a part of it is in the floor, which the contact
// pushes out in the first steps (a mistake that the run would otherwise show as a collapse or a jump).
void check_above_floor(const std::vector<softbody::Vec3>& x, const std::optional<sim::Floor>& floor,
                       const std::string& key_path, std::vector<std::string>& notes) {
  if (!floor) return;
  double lowest = x.front().y(), highest = lowest, centre = 0.0;
  for (const softbody::Vec3& p : x) {
    lowest = std::min(lowest, p.y());
    highest = std::max(highest, p.y());
    centre += p.y();
  }
  centre /= static_cast<double>(x.size());
  const double floor_y = floor->height_m;
  char text[400];
  if (centre < floor_y) {
    std::snprintf(text, sizeof text,
                  "%s.position: the body starts under the floor: its centre at y = %.4g m, its top at %.4g m, the "
                  "floor at %.4g m (floor.height): expected a position whose body is above the floor",
                  key_path.c_str(), centre, highest, floor_y);
    throw softbody::InputError(text);
  }
  // Deeper than a millionth of its height: not the round-off of a body set on the floor.
  if (floor_y - lowest > 1e-6 * (highest - lowest)) {
    std::snprintf(text, sizeof text,
                  "%s starts %.4g m into the floor (its lowest vertex at y = %.4g m, the floor at %.4g m): the "
                  "contact pushes it out in the first steps",
                  key_path.c_str(), floor_y - lowest, lowest, floor_y);
    notes.push_back(text);
  }
}

sim::World build_world(const scene::Scene& scene, std::vector<std::string>& notes,
                       std::vector<int>* bodies_per_scene_body, const softbody::AfterPhase& after_phase,
                       int threads_when_auto) {
  const auto phase_done = [&](const std::string& phase) {
    if (after_phase) after_phase(phase);
  };
  sim::Solver solver = scene.solver;  // the scene file's request, completed by the command's thread default
  if (solver.threads == 0) solver.threads = threads_when_auto;
  sim::Model model = sim::make_model(scene.gravity_m_per_s2, scene.floor, solver);
  model.body_contact = scene.collisions;
  model.colliders = scene.colliders;
  SceneTotals totals(scene);
  totals.check();  // generators' sizes and proxies' counts are known before any mesh is built
  load_collider_meshes(scene, model.colliders, notes, totals);
  sim::State state = sim::initial_state(model);
  double heaviest_vertex_kg = 0.0;
  std::vector<std::string> body_names;  // per model body, its scene key
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const scene::Body& spec = scene.bodies[b];
    const std::string key_path = scene.source.string() + ": bodies." + std::to_string(b);
    const std::string key = "bodies." + std::to_string(b);
    mesh::LoadedMesh loaded = mesh::load_closed_mesh(spec.mesh, spec.mesh_file, key_path + ".mesh", scene.limits,
                                                     {spec.repair, geometry::repair_mesh}, after_phase);
    MeshSize size{static_cast<long long>(loaded.mesh.vertices.size()),
                  static_cast<long long>(loaded.mesh.triangles.size())};
    totals.count(b, size);
    totals.check();  // as each mesh file is read
    for (std::string& note : loaded.notes) {
      if (spec.split && note.find("separate closed parts") != std::string::npos) continue;  // split below
      notes.push_back(std::move(note));
    }
    const std::vector<BodyPart> parts = parts_of(loaded, spec, key_path, notes);
    for (const BodyPart& part : parts) {
      const bool proxied = wants_proxy(spec);
      const mesh::TriMesh proxy = proxied ? simulation_proxy(part.mesh, spec, key_path, notes) : mesh::TriMesh{};
      if (proxied) {
        size.vertices += static_cast<long long>(proxy.vertices.size());
        size.triangles += static_cast<long long>(proxy.triangles.size());
        totals.count(b, size);
        totals.check();
        phase_done("remeshing " + key + " into its simulation proxy");
      }
      const mesh::TriMesh& simulated = proxied ? proxy : part.mesh;
      const std::vector<softbody::Vec3> x0 = place_mesh(simulated, spec);
      check_placed(x0, key_path);
      check_above_floor(x0, scene.floor, key_path, notes);
      sim::Body body = sim::build_body(x0, simulated.triangles, spec.mass_kg * part.mass_share);
      sim::Params raw{spec.stiffness_N_per_m, spec.damping_N_s_per_m, spec.pressure_J * part.pressure_share};
      raw.bending_N_per_m = spec.bending_N_per_m;
      body.params = sim::resolve_params(raw, spec.intent, body, x0, key_path, notes);
      check_body_quantities(body, spec, scene.source.string(), key);
      for (const double m : body.masses.kg) heaviest_vertex_kg = std::max(heaviest_vertex_kg, m);
      if (body.params.bending_N_per_m > 0.0) sim::add_bending_links(body, x0);  // none: no links, no cost
      body.self_collision = spec.self_collision;
      phase_done("resolving the parameters of " + key);
      if (proxied) {
        const int index = static_cast<int>(model.bodies.size());
        model.skins.push_back(
            bind_skin(place_mesh(part.mesh, spec), part.mesh.triangles, x0, simulated.triangles, index));
        model.skins.back().corner_uvs = part.mesh.corner_uvs;
        phase_done("binding the mesh of " + key + " to its proxy");
      }
      if (!proxied && part.mesh.has_uvs())
        model.surface_uvs.push_back({static_cast<int>(model.bodies.size()), part.mesh.corner_uvs});
      sim::add_body(model, state, std::move(body), x0, spec.velocity_m_per_s);
    }
    if (bodies_per_scene_body) bodies_per_scene_body->push_back(static_cast<int>(parts.size()));
    for (std::size_t p = 0; p < parts.size(); ++p)
      body_names.push_back(parts.size() == 1 ? key : key + " (part " + std::to_string(p + 1) + ")");
  }
  check_contact_quantities(scene, heaviest_vertex_kg);
  std::vector<std::string> overlaps;
  note_overlapping_bodies(model, state, body_names, overlaps);
  note_bodies_in_colliders(model, state, body_names, overlaps);
  for (const std::string& note : overlaps) notes.push_back(scene.source.string() + ": " + note);
  return sim::World(std::move(model), std::move(state));
}

}  // namespace setup
