// `wardray diff A B`: image error as docs/metrics.md defines it, for people and scripts.
#pragma once

#include <string>
#include <vector>

namespace wardray::app {

/// Runs `wardray diff IMAGE REFERENCE [--json] [-o DIFF.png]`; returns the exit status (0, 1 unreadable, 2 usage).
int run_diff_command(const std::vector<std::string>& args);

}  // namespace wardray::app
