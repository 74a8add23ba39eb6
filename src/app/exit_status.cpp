// Error reporting shared by the CLI and the stand-alone benchmark programs.
#include "app/exit_status.hpp"

#include <iostream>

#include "core/errors.hpp"
#include "frames/stop_request.hpp"

namespace app {

int run_reporting_errors(const Action& action) {
  try {
    return action();
  } catch (const softbody::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return softbody::kExitBadInput;
  } catch (const frames::Interrupted& e) {
    std::cerr << "interrupted: " << e.what() << "\n";
    return 128 + e.signal();
  } catch (const softbody::DivergedError& e) {
    std::cerr << "diverged: " << e.what() << "\n";
    return softbody::kExitDiverged;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return softbody::kExitFailure;
  }
}

}  // namespace app
