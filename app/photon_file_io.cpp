// load_photon_file and save_photon_file: the files around photons/photon_file.h's format.
#include "app/photon_file_io.h"

#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "render/film.h"

namespace wardray::app {

std::shared_ptr<const photons::ShotPhotons> load_photon_file(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        std::cerr << "wardray: warning: cannot read photon file '" << file.string() << "'; shooting photons\n";
        return nullptr;
    }
    try {
        return std::make_shared<const photons::ShotPhotons>(photons::read_photon_file(in));
    } catch (const photons::PhotonFileError& e) {
        std::cerr << "wardray: warning: photon file '" << file.string() << "' not used: " << e.what()
                  << "; shooting photons\n";
        return nullptr;
    }
}

bool save_photon_file(const photons::ShotPhotons& shot, const std::filesystem::path& file) {
    auto write = [&](const std::filesystem::path& tmp) -> std::optional<std::string> {
        std::ofstream out(tmp, std::ios::binary);
        photons::write_photon_file(out, shot);
        out.close();
        if (!out) return std::string("write failed");
        return std::nullopt;
    };
    if (const auto error = render::write_atomically(file, write)) {
        std::cerr << "wardray: error: photon file: " << *error << "\n";
        return false;
    }
    return true;
}

}  // namespace wardray::app
