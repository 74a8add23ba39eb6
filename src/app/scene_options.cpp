// Shared scene options.
#include "app/commands.hpp"

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

}  // namespace app
