// softbody's command line: dispatches to the subcommands and maps errors to exit statuses.
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "app/exit_status.hpp"
#include "app/version.hpp"
#include "core/errors.hpp"

namespace {

constexpr const char* kFooter =
    "Exit status: 0 ok, 1 other failure, 2 bad input (scene, mesh, command line), 3 the simulation diverged,\n"
    "130 / 143 interrupted by SIGINT / SIGTERM (within one step; during setup when its phase ends).\n"
    "Environment: SOFTBODY_GL=auto|egl|osmesa chooses the GL backend of `render` and wins over the scene's\n"
    "render.backend.\n"
    "Scenes to start from: share/softbody/scenes/ where softbody is installed (bounce.json: the paper's Figure 1).\n"
    "Run 'softbody COMMAND --help' for a command's options, 'man softbody' for the whole manual.";

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli("softbody: pressure-model soft bodies (Matyka & Ollila 2003), simulated and rendered off-screen");
  cli.footer(kFooter);
  cli.set_version_flag("--version", app::version_text());
  cli.require_subcommand(1);
  std::map<std::string, app::Action> actions;
  actions["simulate"] = app::register_simulate(cli);
  actions["export"] = app::register_export(cli);
  actions["bench"] = app::register_bench(cli);
  actions["render"] = app::register_render(cli);
  actions["info"] = app::register_info(cli);
  actions["prepare"] = app::register_prepare(cli);
  actions["schema"] = app::register_schema(cli);

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = cli.exit(e);
    return status == 0 ? softbody::kExitOk : softbody::kExitBadInput;
  }
  for (const CLI::App* command : cli.get_subcommands())
    return app::run_reporting_errors(actions.at(command->get_name()));
  return softbody::kExitFailure;
}
