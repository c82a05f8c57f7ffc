// Scene description, light sources.
#pragma once

#include "core/color.h"
#include "core/diagnostics.h"
#include "core/vec3.h"

namespace wardray::scene {

struct Light {
    enum class Type { Point, Spot, Parallel, Cylinder };
    Type type = Type::Point;
    Vec3 position;
    Color color{1.0, 1.0, 1.0};
    double fade_distance = 0.0;  ///< 0: no fading
    double fade_power = 0.0;
    bool shadowless = false;
    // Spotlight and cylinder parameters (degrees), POV-Ray's defaults.
    Vec3 point_at{0.0, 0.0, 1.0};
    double radius = 30.0;
    double falloff = 45.0;
    double tightness = 0.0;
    // `area_light axis1, axis2, size1, size2` with its options, POV-Ray's defaults.
    bool area = false;
    Vec3 area_axis1;
    Vec3 area_axis2;
    int area_size1 = 1;
    int area_size2 = 1;
    int adaptive = 100;  ///< POV-Ray's default: subdivide to the full grid
    bool jitter = false;
    bool circular = false;
    bool orient = false;
    /// `media_attenuation`: fog dims the light on its way (POV-Ray's default: off); `media_interaction` (on).
    bool media_attenuation = false;
    bool media_interaction = true;
    SourceLoc loc;
    bool operator==(const Light&) const = default;
};

}  // namespace wardray::scene
