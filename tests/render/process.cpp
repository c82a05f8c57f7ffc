// Test helper: popen-based command runner.
#include "process.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>

namespace wardray::test {

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) {
        if (c == '\'') out += "'\\''";
        else out += c;
    }
    return out + "'";
}

ProcessResult run_command(const std::string& command, const std::string& working_dir) {
    std::filesystem::create_directories(working_dir);
    const std::string full = "cd " + shell_quote(working_dir) + " && " + command + " 2>&1 </dev/null";
    ProcessResult result;
    FILE* pipe = ::popen(full.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    if (status != -1 && WIFEXITED(status)) result.exit_status = WEXITSTATUS(status);
    return result;
}

}  // namespace wardray::test
