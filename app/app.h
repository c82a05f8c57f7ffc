// The wardray command as a function, so main() stays a one-liner.
#pragma once

#include <string>
#include <vector>

namespace wardray::app {

constexpr int kExitOk = 0;
constexpr int kExitScene = 1;  ///< the scene could not be read or rendered (POV-Ray's convention)
constexpr int kExitUsage = 2;  ///< the command line was wrong

/// Runs the command with `args` (argv without the program name); returns the process exit status.
int run(const std::vector<std::string>& args, const std::string& argv0);

}  // namespace wardray::app
