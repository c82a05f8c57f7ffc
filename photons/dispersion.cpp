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

// wardray's own hue model: each channel's response is one smooth lobe at the middle of what that channel of a
// display sees (red about 610 nm, green about 540 nm, blue about 455 nm), and red has a small second lobe at the
// violet end, so the shortest bands look violet rather than blue. Only the shapes matter: each channel is
// normalised to a unit integral over the spectrum, which makes white light split into bands that sum to white.
constexpr std::array<Lobe, 2> kRed{{{0.66, 0.30, 1.0}, {0.03, 0.10, 0.2}}};
constexpr std::array<Lobe, 1> kGreen{{{0.46, 0.25, 1.0}}};
constexpr std::array<Lobe, 1> kBlue{{{0.21, 0.24, 1.0}}};

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
