// POV-Ray's metallic tint, shared by metallic highlights and metallic reflection.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/vec3.h"

namespace wardray::lighting {

/// POV-Ray's metallic tint 1 + metallic·(1 − F)·(pigment − 1), F its empirical Fresnel curve of the angle
/// θ = acos(`cos_angle`): F(x) = 0.014567225/(x − 1.12)² − 0.011612903 with x = θ/(π/2), clamped to [0, 1], so the
/// pigment tints fully at normal incidence and not at all at grazing angles.
inline Vec3 metallic_tint(const Vec3& pigment, double metallic, double cos_angle) {
    const double x = std::fabs(std::acos(std::clamp(cos_angle, -1.0, 1.0))) / (std::numbers::pi / 2.0);
    const double f = std::clamp(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903, 0.0, 1.0);
    return Vec3{1.0, 1.0, 1.0} + (pigment - Vec3{1.0, 1.0, 1.0}) * (metallic * (1.0 - f));
}

}  // namespace wardray::lighting
