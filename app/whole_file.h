// The one way the run writes its own files (statistics, the radiosity and photon files): whole or not at all.
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>

namespace wardray::app {

/// Writes `file` through render::write_atomically, `write` filling the stream of its temporary; on failure prints
/// "wardray: error: <what>: <reason>" and returns false.
bool write_whole_file(const std::filesystem::path& file, const char* what,
                      const std::function<void(std::ostream&)>& write);

}  // namespace wardray::app
