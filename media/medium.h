// Medium: what the space between surfaces does to light along a ray segment (fog today, media next).
#pragma once

#include "core/vec3.h"

namespace wardray::media {

/// A stretch of ray between its origin and the surface it reaches (or the sky, at infinite length).
struct Segment {
    Vec3 origin;
    Vec3 direction;  ///< unit
    double length = 0.0;
};

/// What a medium does to the light travelling back along a ray segment: absorbs some and adds its own.
class Medium {
public:
    virtual ~Medium() = default;
    /// The colour arriving at the segment's origin when `colour` leaves its far end.
    virtual Vec3 along_segment(const Vec3& colour, const Segment& segment) const = 0;
    /// What passes along the segment without what the medium adds: POV-Ray's attenuation of shadow rays.
    virtual Vec3 transmittance(const Segment& segment) const = 0;
};

}  // namespace wardray::media
