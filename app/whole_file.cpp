// write_whole_file: a stream over write_atomically's temporary file.
#include "app/whole_file.h"

#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "render/film.h"

namespace wardray::app {

bool write_whole_file(const std::filesystem::path& file, const char* what,
                      const std::function<void(std::ostream&)>& write) {
    auto fill = [&](const std::filesystem::path& tmp) -> std::optional<std::string> {
        std::ofstream out(tmp, std::ios::binary);
        write(out);
        out.close();
        if (!out) return std::string("write failed");
        return std::nullopt;
    };
    if (const auto error = render::write_atomically(file, fill)) {
        std::cerr << "wardray: error: " << what << ": " << *error << "\n";
        return false;
    }
    return true;
}

}  // namespace wardray::app
