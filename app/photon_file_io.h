// POV-Ray's photon save_file and load_file on disk: the photons of a render written whole or not at all, and read
// back by a later render of the scene instead of its photon pass.
#pragma once

#include <filesystem>
#include <memory>

#include "photons/photon_file.h"

namespace wardray::app {

/// The photons of a load_file, or null after a warning when it cannot be read (the render then shoots photons, as
/// if the scene had no load_file).
std::shared_ptr<const photons::ShotPhotons> load_photon_file(const std::filesystem::path& file);

/// Writes a save_file under a temporary name renamed when complete; false after an error message when it cannot.
bool save_photon_file(const photons::ShotPhotons& shot, const std::filesystem::path& file);

}  // namespace wardray::app
