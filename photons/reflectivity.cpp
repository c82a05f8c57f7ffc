// POV-Ray's ComputeReflectivity: standard (min + (max − min)·(1 − cos θ)^falloff) and Fresnel reflection.
#include "photons/reflectivity.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace wardray::photons {

namespace {

double max3(const Vec3& c) { return std::max(c.x, std::max(c.y, c.z)); }

}  // namespace

// POV-Ray's ComputeReflectivity: the reflected fraction and the reflection ray's weight.
// Standard: min + (max − min)·(1 − cos θ)^falloff. Fresnel: the unpolarised Fresnel reflectance for the relative
// index `ior` (Cook & Torrance 1982, eq. 8 form), blending min and max.
Vec3 reflectivity(const scene::Finish& f, double cos_i, double ior, double& weight) {
    const Vec3 rmin = f.reflection_min.rgb();
    const Vec3 rmax = f.reflection_max.rgb();
    if (!f.reflection_fresnel) {
        weight *= std::max(max3(rmax), max3(rmin));
        const double frac = std::fabs(f.reflection_falloff - 1.0) > kPovEpsilon
                                ? std::pow(1.0 - cos_i, f.reflection_falloff)
                                : 1.0 - cos_i;
        if (std::fabs(frac) < kPovEpsilon) return rmin;
        if (std::fabs(frac - 1.0) < kPovEpsilon) return rmax;
        return rmax * frac + rmin * (1.0 - frac);
    }
    Vec3 r = rmax;
    const double sqx = ior * ior + cos_i * cos_i - 1.0;
    if (sqx > 0.0) {
        const double g = std::sqrt(sqx);
        const double a = (g - cos_i) / (g + cos_i);
        const double b = (cos_i * (g + cos_i) - 1.0) / (cos_i * (g - cos_i) + 1.0);
        const double fr = std::clamp(0.5 * a * a * (1.0 + b * b), 0.0, 1.0);
        r = rmax * fr + rmin * (1.0 - fr);
    }
    weight *= max3(r);
    return r;
}

}  // namespace wardray::photons
