// Dispersion: the spectral band a ray or photon carries, the index of refraction of a dispersive interior for that
// band and the band's hue, as POV-Ray 3.7 splits light at a surface with `interior { dispersion D }`.
#pragma once

#include "core/vec3.h"

namespace wardray::photons {

/// POV-Ray's visible spectrum, in nanometres: violet to red, and its centre (where the index is the nominal one).
inline constexpr double kSpectrumViolet = 380.0;
inline constexpr double kSpectrumRed = 730.0;
inline constexpr double kSpectrumWidth = kSpectrumRed - kSpectrumViolet;
inline constexpr double kSpectrumCentre = (kSpectrumViolet + kSpectrumRed) / 2.0;

/// A ray's share of the spectrum: band `index` of `count` equal bands, violet first; `count` 0 is white light
/// (the whole spectrum), which a dispersive surface splits (POV-Ray's SpectralBand and its MonochromaticRay flag).
struct SpectralBand {
    int index = 0;
    int count = 0;

    /// True once a dispersive surface has split the ray: it keeps its band through later surfaces.
    bool monochromatic() const { return count > 0; }
    /// The band's centre wavelength in nanometres (the spectrum's centre for white light).
    double wavelength() const {
        return count > 0 ? kSpectrumViolet + kSpectrumWidth * ((index + 0.5) / count) : kSpectrumCentre;
    }
    /// The band's width in nanometres.
    double bandwidth() const { return count > 0 ? kSpectrumWidth / count : kSpectrumWidth; }
    bool operator==(const SpectralBand&) const = default;
};

/// The relative index `ior` (outside over inside, as the refraction code keeps it) for `band` across a surface
/// whose relative dispersion is `dispersion`: ior · dispersion^-(λ − λc)/Δλ, so the band at the spectrum's centre
/// keeps `ior` and the violet and red ends are `dispersion`^±½ away (POV-Ray's GetDispersionIOR).
double dispersion_ior(double ior, double dispersion, const SpectralBand& band);

/// The colour a band of light carries, scaled so that white light splits into bands whose hues average to white:
/// the sum over the `count` bands of band_hue is `count` · (1, 1, 1).
Vec3 band_hue(const SpectralBand& band);

/// The fraction of each colour channel's response that lies at wavelengths up to `nm` (0 at violet, 1 at red):
/// the integral of wardray's hue model, which band_hue differentiates over a band.
Vec3 hue_integral(double nm);

}  // namespace wardray::photons
