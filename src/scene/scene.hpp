// The validated description of a whole run: plain structs with defaults, units in the comments.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/gl_backend.hpp"
#include "core/vec.hpp"
#include "mesh/mesh_limits.hpp"
#include "mesh/repair_options.hpp"
#include "sim/model/intent.hpp"
#include "sim/model/settings.hpp"

namespace scene {

using softbody::GlBackend;
using softbody::Vec3;

// A pattern painted on a body in its own (initial-shape) coordinates, so that its rotation shows.
enum class Pattern { None, Checker, Stripes };

struct Body {
  std::string mesh = "icosphere:3";  // "icosphere:L", "cube:N" or a mesh file path
  std::filesystem::path mesh_file;   // resolved path when `mesh` is a file, empty for generators
  Vec3 position_m = Vec3::Zero();    // where the mesh's origin is placed
  Vec3 rotation_deg = Vec3::Zero();  // Euler angles about world X, then Y, then Z (core/euler_rotation.hpp) [°]
  double scale = 1.0;                // uniform scale applied to the mesh before placing it
  Vec3 velocity_m_per_s = Vec3::Zero();
  double mass_kg = 1.0;               // whole body, lumped to vertices by area (a third of each face)
  double stiffness_N_per_m = 1000.0;  // each edge spring (Hooke)
  double damping_N_s_per_m = 1.0;     // each spring's damper, along the spring
  double pressure_J = 50.0;           // nRT of the enclosed gas (Pa·m³); 0 switches the gas off
  double bending_N_per_m = 0.0;       // "bending": k_b of the bending links (sim/forces/bending.hpp) [N/m]; 0: none
  bool split = false;                 // "split": each separate closed part of the mesh becomes its own body
  bool self_collision = false;        // "self_collision": its vertices touch its own triangles (sim::Body)
  mesh::RepairOptions repair;         // "repair": true or {"holes": ..., "parts": ...}: fix the mesh before validation
  // "resolution": N simulates the body on an isotropic remesh of its mesh with about N vertices (the proxy),
  // or {"edge_length": L} on one with edges of about L [m, placed]; the mesh itself follows the proxy for
  // render and export. Neither (0): the mesh is simulated as it is.
  int resolution_vertices = 0;
  double resolution_edge_length_m = 0.0;
  Pattern pattern = Pattern::None;  // checker: 8 × 4 cells by direction from the centre; stripes: 8 meridians
  sim::BodyIntent intent;  // "stiffness": {...}, "damping": {"ratio": ζ}, "pressure": {"inflation": f, "start": ...},
                           // "bending": {"ratio": r}
                           // instead of numbers, resolved against the mesh by sim/model/intent.hpp
  std::array<float, 3> color = {0.80f, 0.12f, 0.07f};  // linear RGB in [0, 1] (a tomato red once sRGB-encoded)
};

struct RenderSettings {
  int width_px = 1280;                                      // even (video encoders need it)
  int height_px = 720;                                      // even
  int msaa = 4;                                             // samples per pixel: 1 (off), 2 or 4
  bool shadows = true;                                      // the body casts a shadow-mapped shadow on the floor
  std::array<float, 3> background = {0.62f, 0.72f, 0.85f};  // linear RGB
  int figure_frames = 8;                // frames in the contact sheet figure.png, chosen from the motion (0: no figure)
  std::vector<int> figure_frame_list;   // "figure_frames": [0, 19, 24, ...] instead: exactly these frames
  GlBackend backend = GlBackend::Auto;  // "auto" | "egl" | "osmesa"
};

struct Camera {
  bool given = false;  // the scene has a "camera" key; without one, render frames the bodies' whole trajectory
  Vec3 position_m{0.0, 2.5, 9.0};
  Vec3 target_m{0.0, 1.2, 0.0};
  Vec3 up{0.0, 1.0, 0.0};
  double fov_deg = 45.0;  // vertical field of view
};

struct Light {
  Vec3 direction{-0.4, -1.0, -0.35};  // the direction the light travels (towards the scene)
  std::array<float, 3> color = {1.0f, 1.0f, 1.0f};
  float ambient = 0.25f;  // fraction of light that reaches every surface
};

struct Output {
  std::filesystem::path dir;  // default: out/<scene name>
  std::string pattern = "frame_%04d.png";
};

// "limits" of the whole scene: vertices and triangles summed over every body's mesh and simulation proxy
// (setup/scene_totals.hpp), so that many bodies cannot together exhaust the memory.
struct SceneTotals {
  long long max_vertices = 4'000'000;
  long long max_triangles = 8'000'000;
};

// A "mesh" collider's file (or generator), which setup reads into the collider's shape (setup/collider_meshes.hpp).
struct ColliderMeshSource {
  std::size_t collider = 0;          // its index in Scene::colliders
  std::string mesh;                  // as written: a file path relative to the scene, or a generator
  std::filesystem::path mesh_file;   // the resolved path when `mesh` is a file, empty for a generator
  double scale = 1.0;                // uniform scale applied to the mesh before it is turned and placed
  double thickness_m = 0.01;         // an open mesh's thickness [m]
  std::filesystem::path cache_file;  // "cache": a PC2 point cache moving the mesh's vertices (empty: none), or
                                     // a numbered OBJ sequence's pattern ("dir/collider_0_%04d.obj")
  bool cache_sequence = false;       // cache_file is a numbered sequence's pattern
  double cache_fps = 0.0;            // "cache_fps": the cache's frames per second (0: the scene's fps)
};

struct Scene {
  std::filesystem::path source;  // the scene file ("" when built in code)
  // The validated document with --set applied, less the keys that do not change the simulation (name,
  // render, camera, light, output), as compact JSON: what a state cache's scene hash covers (with the
  // mesh files' bytes, setup/scene_hash.hpp).
  std::string simulation_json;
  std::string name = "scene";
  double duration_s = 3.0;  // simulated seconds
  int fps = 30;             // frames per simulated second
  // The scene file's request (with --set). The model copies it (setup::build_world) and sim::resolve_step
  // resolves its substeps and automatic dt there: the world's model.solver is the copy in force.
  sim::Solver solver;
  Vec3 gravity_m_per_s2{0.0, -9.81, 0.0};
  std::optional<sim::Floor> floor;                  // no floor when absent
  std::vector<sim::Collider> colliders;             // static shapes; their contact keys default to the floor's
  std::vector<ColliderMeshSource> collider_meshes;  // one per "mesh" collider, read by setup
  mesh::MeshLimits limits;                          // "limits": the most a mesh file may hold (raisable)
  SceneTotals totals;                               // "limits": the most the whole scene may hold (raisable)
  std::vector<Body> bodies;
  sim::BodyContact collisions;  // between bodies, when there are several
  RenderSettings render;
  Camera camera;
  Light light;
  Output output;
  // What the file asks that the run will not use (e.g. a solver key its integrator does not read), said as notes
  // before the run: not errors, so that a scene can carry the keys of several integrators.
  std::vector<std::string> notes;
};

}  // namespace scene
