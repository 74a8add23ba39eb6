// build/bench_accuracy: the integrator accuracy benchmark as its own program (same as softbody bench accuracy).
#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "app/exit_status.hpp"
#include "core/errors.hpp"

int main(int argc, char** argv) {
  CLI::App cli("bench_accuracy: run time against error of softbody's integrators on a scene");
  const app::Action action = app::add_accuracy_options(cli);
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = cli.exit(e);
    return status == 0 ? softbody::kExitOk : softbody::kExitBadInput;
  }
  return app::run_reporting_errors(action);
}
