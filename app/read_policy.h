// The folders a scene may read besides its own: those Debian's povray.conf permits POV-Ray 3.7 to read.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "parser/parse.h"

namespace wardray::app {

/// The read permissions of Debian's shipped /etc/povray/3.7/povray.conf ([File I/O Security] restricted,
/// [Permitted Paths]): POV-Ray's include folder, its examples, /etc/povray, the user's home folder (`home`, when
/// not empty) and /tmp with their subfolders, and the current folder `cwd` without its subfolders (`read+write =
/// .`). A scene's `../` file is readable where its parent folder lies inside one of these.
std::vector<parser::ParseOptions::PermittedFolder> povray_permitted_reads(const std::string& home,
                                                                          const std::filesystem::path& cwd);

}  // namespace wardray::app
