// Test helper: runs a shell command and captures its exit status and output.
#pragma once

#include <string>

namespace wardray::test {

struct ProcessResult {
    int exit_status = -1;  ///< the command's exit status, or -1 when it did not exit normally
    std::string output;    ///< stdout and stderr together
};

/// Runs `command` with /bin/sh in `working_dir` (created if missing), capturing stdout and stderr.
ProcessResult run_command(const std::string& command, const std::string& working_dir);

/// Quotes a string for /bin/sh.
std::string shell_quote(const std::string& s);

}  // namespace wardray::test
