// Dispersion: band wavelengths, the dispersive index of refraction and band hues from an analytic model of the
// red, green and blue responses over the visible spectrum.
#include "photons/dispersion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace wardray::photons {

namespace {

/// One lobe of a channel's response: a raised cosine 0.5 (1 + cos(π (x − centre) / half_width)) over
/// |x − centre| < half_width, in units of the spectrum's width (x = 0 at violet, 1 at red), times `height`.
struct Lobe {
    double centre, half_width, height;
};

// wardray's own hue model: each channel's response is one smooth lobe over the spectrum (red about 655 nm, green
// about 585 nm, blue about 470 nm, the blue lobe cut off at the violet end), and red has a small second lobe at the
// violet end, so the shortest bands look violet rather than blue. The lobes' places and widths were fitted by least
// squares to POV-Ray 3.7's rendered spectrum in scenes/parity/prism_dispersion.pov (its image against wardray's
// images of each band alone). Only the shapes matter: each channel is normalised to a unit integral over the
// spectrum, which makes white light split into bands that sum to white.
constexpr std::array<Lobe, 2> kRed{{{0.79, 0.32, 1.0}, {0.01, 0.06, 0.37}}};
constexpr std::array<Lobe, 1> kGreen{{{0.58, 0.33, 1.0}}};
constexpr std::array<Lobe, 1> kBlue{{{0.25, 0.37, 1.0}}};

/// The integral of one lobe from −∞ to x.
double lobe_integral(const Lobe& l, double x) {
    const double u = std::clamp(x - l.centre, -l.half_width, l.half_width);
    const double w = l.half_width;
    return l.height * 0.5 * (u + w + w / std::numbers::pi * std::sin(std::numbers::pi * u / w));
}

/// A channel's response integrated over [0, x], divided by its integral over [0, 1].
template <std::size_t N>
double channel_integral(const std::array<Lobe, N>& lobes, double x) {
    double part = 0.0, total = 0.0;
    for (const Lobe& l : lobes) {
        part += lobe_integral(l, x) - lobe_integral(l, 0.0);
        total += lobe_integral(l, 1.0) - lobe_integral(l, 0.0);
    }
    return part / total;
}

}  // namespace

double dispersion_ior(double ior, double dispersion, const SpectralBand& band) {
    return ior * std::pow(dispersion, -(band.wavelength() - kSpectrumCentre) / kSpectrumWidth);
}

Vec3 hue_integral(double nm) {
    const double x = std::clamp((nm - kSpectrumViolet) / kSpectrumWidth, 0.0, 1.0);
    return {channel_integral(kRed, x), channel_integral(kGreen, x), channel_integral(kBlue, x)};
}

Vec3 band_hue(const SpectralBand& band) {
    // The mean response over the band, relative to the mean over the whole spectrum (POV-Ray's GetHue).
    const double half = band.bandwidth() / 2.0;
    const Vec3 span = hue_integral(band.wavelength() + half) - hue_integral(band.wavelength() - half);
    return span * (kSpectrumWidth / band.bandwidth());
}

}  // namespace wardray::photons
