// Gamma: POV-Ray 3.7's transfer functions and their transcoding, as its documentation and behaviour define them.
#include "core/gamma.h"

#include <algorithm>
#include <cmath>

namespace wardray {

namespace {

// POV-Ray compat: a power law whose encoding exponent is within 1 % of 1 counts as no gamma at all.
bool nearly_one(double encoding_exponent) { return std::fabs(1.0 - encoding_exponent) <= 0.01; }

GammaCurve power_law_by_encoding(double encoding_exponent) {
    if (nearly_one(encoding_exponent)) return GammaCurve::neutral();
    return {GammaCurve::Kind::PowerLaw, 1.0 / encoding_exponent};
}

}  // namespace

GammaCurve GammaCurve::power_law(double decoding_gamma) { return power_law_by_encoding(1.0 / decoding_gamma); }

double GammaCurve::encode(double x) const {
    switch (kind) {
        case Kind::Neutral: return x;
        case Kind::PowerLaw: return std::pow(std::max(x, 0.0), 1.0 / gamma);
        case Kind::Srgb: return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
    }
    return x;
}

double GammaCurve::decode(double x) const {
    switch (kind) {
        case Kind::Neutral: return x;
        case Kind::PowerLaw: return std::pow(std::max(x, 0.0), gamma);
        case Kind::Srgb: return x < 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
    }
    return x;
}

bool GammaCurve::matches(const GammaCurve& other) const {
    if (kind != other.kind) return false;
    // Two power laws match when their exponents are within 1 % of each other.
    return kind != Kind::PowerLaw || nearly_one(other.gamma / gamma);
}

GammaTranscoding transcoding(const GammaCurve& working, const GammaCurve& target) {
    if (working.is_neutral()) return {GammaCurve::neutral(), target};
    if (working.matches(target)) return {};
    if (working.kind == GammaCurve::Kind::PowerLaw && target.kind != GammaCurve::Kind::Srgb)
        return {GammaCurve::neutral(), power_law_by_encoding(working.gamma / target.approximate_gamma())};
    return {working, target};
}

}  // namespace wardray
