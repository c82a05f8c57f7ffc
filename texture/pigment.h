// Pigment evaluation: the colour of a pigment (solid, colour-mapped or pigment-mapped pattern) at a point.
#pragma once

#include "scene/scene.h"
#include "core/vec3.h"
#include "texture/surface_point.h"

namespace wardray::texture {

/// POV-Ray's greyscale of a colour (its GREY_SCALE weights 0.297, 0.589, 0.114).
inline double grey(const Vec3& c) { return 0.297 * c.x + 0.589 * c.y + 0.114 * c.z; }

/// The five-component colour of `pigment` at `p` (in the pigment's enclosing space: world space for an object's
/// pigment). Solid pigments return their colour without evaluating anything. `surface` is the intersection
/// being shaded, if any (with the quick_color flag of the render's quality).
inline Color evaluate_pigment(const scene::Pigment& pigment, const Vec3& p, int noise_generator,
                              const SurfacePoint* surface = nullptr);

/// The pattern path of evaluate_pigment (POV-Ray's Compute_Pigment for patterned pigments).
Color evaluate_patterned_pigment(const scene::Pigment& pigment, const Vec3& p, int noise_generator,
                                 const SurfacePoint* surface);

inline Color evaluate_pigment(const scene::Pigment& pigment, const Vec3& p, int noise_generator,
                              const SurfacePoint* surface) {
    // POV-Ray compat (Compute_Pigment): at +Q0 to +Q5 a pigment with a quick_color is that colour, at any depth of
    // pigment maps and pigment_pattern.
    if (pigment.quick_color && surface != nullptr && surface->quick_colors) return *pigment.quick_color;
    if (pigment.is_solid()) return pigment.color;
    return evaluate_patterned_pigment(pigment, p, noise_generator, surface);
}

/// Linear interpolation of all five components: a + f·(b − a).
inline Color lerp(const Color& a, const Color& b, double f) {
    return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b),
            a.filter + f * (b.filter - a.filter), a.transmit + f * (b.transmit - a.transmit)};
}

}  // namespace wardray::texture
