// Runs a command's action and turns its errors into one line on stderr and the documented exit status.
#pragma once

#include "app/commands.hpp"

namespace app {

// 0 ok, 2 bad input (softbody::InputError), 3 diverged (softbody::DivergedError), 1 anything else.
int run_reporting_errors(const Action& action);

}  // namespace app
