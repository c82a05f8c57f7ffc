// Scene description, image maps: a picture wrapped around an object as its pigment.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/vec3.h"

namespace wardray::scene {

/// An image's texels in the scene's working gamma, rows from the top.
struct ImageData {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  ///< width * height * 3
    bool has_alpha = false;  ///< the file has an alpha channel
    /// A true-colour image's alpha per texel (width * height, rows from the top, straight, not premultiplied);
    /// empty without an alpha channel and for palette images (their alpha is palette_alpha).
    std::vector<float> alpha;
    /// A palette image's colour index of each texel, rows from the top (POV-Ray's colour-mapped images); empty for
    /// other images.
    std::vector<std::uint8_t> index;
    int palette_size = 0;
    /// POV-Ray 3.7 keeps this file's texels as 8-bit grey read through a colour table (a grey PNG of 8 bits or
    /// fewer), so each decoded value is cut to a level of 255 (see the parser's image reading).
    bool table_grey8 = false;
    /// The encoding a PNG declares: an sRGB chunk, else a gAMA chunk's file gamma (0 without one).
    bool declared_srgb = false;
    double declared_file_gamma = 0.0;
    /// A palette PNG's alpha per palette entry (its tRNS chunk); empty for an opaque one.
    std::vector<float> palette_alpha;
    bool indexed() const { return !index.empty(); }
};

/// A palette entry's filter and transmit (image_map `filter N, F` and `transmit N, T`).
struct PaletteFT {
    float filter = 0.0f;
    float transmit = 0.0f;
    bool operator==(const PaletteFT&) const = default;
};

/// `image_map { png "file" map_type M interpolate I once filter all F transmit all T }` (POV-Ray 3.7).
struct ImageMap {
    std::shared_ptr<const ImageData> image;
    int map_type = 0;     ///< 0 planar, 1 spherical, 2 cylindrical, 5 torus
    int interpolate = 0;  ///< 0 none, 2 bilinear, 4 normalized distance
    bool once = false;    ///< no repetition: clear outside the unit square
    double filter_all = 0.0;
    double transmit_all = 0.0;
    /// A palette image's filter and transmit per entry, when the image_map sets any (then filter_all and
    /// transmit_all are in it, as POV-Ray stores them in the palette).
    std::vector<PaletteFT> palette_ft;
    /// bump_map and material_map: the palette index rather than the colour (`use_index`; a material_map always
    /// takes an index image's index).
    bool use_index = false;
    /// image_pattern `use_alpha`: the transmit (1 − alpha) of an image with alpha, the red channel of one without.
    bool use_alpha = false;
    bool operator==(const ImageMap&) const = default;
};

}  // namespace wardray::scene
