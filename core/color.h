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

}  // namespace wardray
