// Color: POV-Ray's five-component colour, shared by the scene description and every layer after it.
#pragma once

#include "core/vec3.h"

namespace wardray {

/// POV-Ray's five-component colour: linear RGB plus filter and transmit.
struct Color {
    double r = 0.0;
    double g = 0.0;
    double b = 0.0;
    double filter = 0.0;
    double transmit = 0.0;

    Vec3 rgb() const { return {r, g, b}; }
    bool operator==(const Color&) const = default;
};

/// The luminance of linear RGB (Rec. 709 weights), for image metrics and the cache's adaptive gathers.
inline double luminance(const Vec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

}  // namespace wardray
