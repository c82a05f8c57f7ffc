// Debian's povray.conf read permissions, as wardray's default beyond the scene's folder and the include path.
#include "app/read_policy.h"

namespace wardray::app {

std::vector<parser::ParseOptions::PermittedFolder> povray_permitted_reads(const std::string& home,
                                                                          const std::filesystem::path& cwd) {
    // POV-Ray compat: the entries of Debian's povray.conf, in its order; `*` (subfolders too) on all but ".".
    std::vector<parser::ParseOptions::PermittedFolder> folders = {
        {"/usr/share/povray-3.7/include", true},
        {"/usr/share/doc/povray/examples", true},
        {"/etc/povray", true},
    };
    if (!home.empty()) folders.push_back({home, true});
    folders.push_back({"/tmp", true});
    if (!cwd.empty()) folders.push_back({cwd, false});
    return folders;
}

}  // namespace wardray::app
