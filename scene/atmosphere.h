// Scene description, the atmosphere: sky_sphere, fog and rainbow.
#pragma once

#include <optional>
#include <vector>

#include "core/color.h"
#include "core/diagnostics.h"
#include "core/transform.h"
#include "core/vec3.h"
#include "scene/texture.h"

namespace wardray::scene {

/// `sky_sphere { pigment {...} ... emission C transforms }`: pigments looked up by ray direction, each later one
/// layered over the earlier ones through its filter and transmit.
struct SkySphere {
    std::vector<Pigment> pigments;
    Transform transform;  ///< sky space to world (rotates the directions)
    Color emission{1.0, 1.0, 1.0};
    /// POV-Ray compat: a scene whose effective #version is below 3.7 (none given counts as 3.62) layers the
    /// pigments by POV-Ray 3.6's rule, not as a layered texture.
    bool legacy_layering = false;
    bool operator==(const SkySphere&) const = default;
};

/// `fog { fog_type 1|2 distance D color C fog_offset O fog_alt A up U turbulence T ... }`: POV-Ray's constant
/// fog (type 1) or ground fog (type 2, density 1 below `fog_offset` and 1/(1 + h²) at h = height/fog_alt above).
struct Fog {
    int type = 1;
    double distance = 0.0;
    Color color;
    double offset = 0.0;        ///< fog_offset: the height where ground fog starts thinning
    double alt = 0.0;           ///< fog_alt: the height scale of its thinning
    Vec3 up{0.0, 1.0, 0.0};     ///< unit; rotated and scaled by the fog's transforms
    std::optional<Turbulence> turbulence;  ///< turbulence, octaves, omega, lambda (any of them makes one)
    double turb_depth = 0.5;
    SourceLoc loc;
    bool operator==(const Fog&) const = default;
};

/// `rainbow { angle A width W distance D direction V up U arc_angle a falloff_angle f jitter J color_map {...} }`
/// as POV-Ray keeps it after parsing: unit vectors made perpendicular, angles in radians.
struct Rainbow {
    double angle = 0.0;          ///< radians: the inner edge of the bow (the given angle less half the width)
    double width = 0.0;          ///< radians
    double distance = 1.0e7;     ///< POV-Ray's MAX_DISTANCE by default
    double jitter = 0.0;
    double arc_angle = 0.0;      ///< radians, half of the given arc_angle
    double falloff_angle = 0.0;  ///< radians, half of the given falloff_angle
    double falloff_width = 0.0;  ///< arc_angle − falloff_angle
    Vec3 antisolar;              ///< direction, unit
    Vec3 up{0.0, 1.0, 0.0};      ///< unit, perpendicular to antisolar
    Vec3 right{1.0, 0.0, 0.0};   ///< unit, up × antisolar
    std::optional<Pigment> pigment;  ///< a gradient x over the colour map; none: no rainbow
    SourceLoc loc;
    bool operator==(const Rainbow&) const = default;
};

}  // namespace wardray::scene
