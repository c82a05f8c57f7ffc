// The photons a photon pass stored, before the maps are built from them, and POV-Ray's `save_file`/`load_file`
// for them: a file of wardray's own that a later render reads instead of shooting again.
#pragma once

#include <iosfwd>
#include <stdexcept>
#include <vector>

#include "photons/photon_map.h"

namespace wardray::photons {

/// What shooting stored, in the order shooting stored it: the maps built from it are then the same whether it
/// was shot or read back from a file.
struct ShotPhotons {
    std::vector<Photon> surface;
    std::vector<Photon> media;
    int surface_offset = 0;  ///< flux_exponent_offset of each set
    int media_offset = 0;
    double spacing = 0.0;  ///< the surface spacing they were shot at (for --stats)
};

/// A photon file that cannot be read: not one of wardray's, of another version, or cut short.
struct PhotonFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Writes `shot` in wardray's photon file format (a header line, then fixed-size little-endian records).
void write_photon_file(std::ostream& out, const ShotPhotons& shot);
/// Reads what write_photon_file wrote; throws PhotonFileError, with what is wrong, for anything else.
ShotPhotons read_photon_file(std::istream& in);

}  // namespace wardray::photons
