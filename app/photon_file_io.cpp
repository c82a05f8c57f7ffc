// load_photon_file and save_photon_file: the files around photons/photon_file.h's format.
#include "app/photon_file_io.h"

#include <fstream>
#include <iostream>
#include <string>

#include "app/whole_file.h"

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
    return write_whole_file(file, "photon file", [&](std::ostream& out) { photons::write_photon_file(out, shot); });
}

}  // namespace wardray::app
