// Scene description, interiors: what is inside an object (index of refraction, fade, media).
#pragma once

#include <vector>

#include "core/color.h"
#include "scene/media.h"

namespace wardray::scene {

/// POV-Ray's on/off/unset photon flags of objects and lights (PH_RFR_ON_FLAG and PH_RFR_OFF_FLAG, and the
/// reflection pair).
enum class PhotonSwitch : unsigned char { Unset, On, Off };

/// The inside of an object: index of refraction and POV-Ray's fade of light passing through.
struct Interior {
    double ior = 1.0;
    double fade_distance = 0.0;
    double fade_power = 0.0;
    Color fade_color;
    /// `hollow`: fog (and media) fill the object's inside; POV-Ray's default is not hollow.
    bool hollow = false;
    /// `caustics C`: POV-Ray's fake caustics, stored as POV-Ray keeps it (C · 45); 0 leaves shadows alone.
    double caustics = 0.0;
    /// `dispersion D`: the ratio of the violet band's index to the red band's (POV-Ray spreads the index over the
    /// spectrum as ior · D^-(λ - λc)/Δλ); 1 disperses nothing.
    double dispersion = 1.0;
    /// `dispersion_samples N` (at least 2): the spectral bands a ray splits into at a dispersive surface.
    int dispersion_samples = 7;
    /// POV-Ray 3.1's `refraction R` (POV-Ray's Old_Refract): the light refracted through the surface, and the photons
    /// landing on it, are scaled by R. Set from a plain texture's finish when the object is placed (1 unless that
    /// finish says otherwise), as POV-Ray's Post_Process does.
    double refraction = 1.0;
    /// `media { }` blocks inside the object, in their order (all of them act together).
    std::vector<Media> media;
    bool operator==(const Interior&) const = default;
};

}  // namespace wardray::scene
