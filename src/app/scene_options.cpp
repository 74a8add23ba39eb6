// Options the scene commands share: the scene and --set; --profile and its table.
#include <cstdio>

#include "app/commands.hpp"
#include "core/profile.hpp"
#include "setup/collider_point_caches.hpp"

namespace app {

void add_scene_options(CLI::App& command, SceneOptions& options) {
  command.add_option("scene", options.scene_file, "Scene file (JSON, // comments allowed)")->required();
  command
      .add_option("--set", options.overrides,
                  "Override a scene key before validation, e.g. --set bodies.0.stiffness=800 "
                  "--set solver.dt=5e-5 (repeatable; VALUE is JSON or a bare word)")
      ->type_name("PATH=VALUE")
      ->allow_extra_args(false);
}

std::vector<output::InputFile> scene_inputs(const scene::Scene& scene) {
  std::vector<output::InputFile> inputs{{scene.source, "the scene file"}};
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    if (!scene.bodies[b].mesh_file.empty())
      inputs.push_back({scene.bodies[b].mesh_file, "the mesh file of bodies." + std::to_string(b)});
  }
  for (const scene::ColliderMeshSource& collider : scene.collider_meshes) {
    if (!collider.mesh_file.empty())
      inputs.push_back({collider.mesh_file, "the mesh file of colliders." + std::to_string(collider.collider)});
    for (const std::filesystem::path& file : setup::point_cache_files(collider))
      inputs.push_back({file, "the point cache of colliders." + std::to_string(collider.collider)});
  }
  return inputs;
}

void add_profile_option(CLI::App& command, bool& profile) {
  command.add_flag("--profile", profile,
                   "At the end, print to standard error the time of each phase (setup, step, forces, gas, constraint "
                   "sweeps, contacts, guard, outputs): total, share of the wall time, calls, mean per call");
}

ProfiledRun::ProfiledRun(bool on) : on_(on) {
  if (on_) softbody::start_profiling();
}

ProfiledRun::~ProfiledRun() {
  if (!on_) return;
  softbody::stop_profiling();
  try {
    std::fputs(softbody::format_profile(softbody::profile_report()).c_str(), stderr);
  } catch (...) {
    // A destructor must not throw (an error may be on its way out): no table then.
  }
}

}  // namespace app
