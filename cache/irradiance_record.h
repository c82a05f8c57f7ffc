// IrradianceRecord: one cached irradiance value with its reuse radius and gradients, and how a gather becomes one.
#pragma once

#include <algorithm>
#include <cstdint>

#include "cache/gather.h"
#include "scene/scene.h"
#include "core/vec3.h"

namespace wardray::cache {

/// One entry of the irradiance cache (Ward, Rubinstein & Clear 1988), in POV-Ray's normalisation (no π).
struct IrradianceRecord {
    Vec3 position;     ///< world space
    Vec3 normal;       ///< unit, world space
    Vec3 irradiance;   ///< RGB, cosine-weighted mean radiance
    double radius = 0.0;  ///< R_i: reuse radius in world units (> 0, finite)
    ChannelGradients rotational{};     ///< ∇r E per channel (see GatherResult)
    ChannelGradients translational{};  ///< ∇t E per channel, after the limits of make_record()
    std::int32_t depth = 0;  ///< bounce depth: 0 for records seen from camera-ray hits
    std::int32_t pass = 0;   ///< the pass that made it (statistics only)
};

/// What the validity test reads of a record (interpolation.h), packed in one cache line and kept by the octree beside
/// the records, so that a lookup reads a whole record only for those it uses.
struct alignas(64) RecordGeometry {
    Vec3 position;        ///< IrradianceRecord::position
    Vec3 normal;          ///< IrradianceRecord::normal
    double radius = 0.0;  ///< IrradianceRecord::radius
};

/// A record's position, normal and radius.
inline RecordGeometry geometry_of(const IrradianceRecord& record) {
    return {record.position, record.normal, record.radius};
}

/// The rest of a record: what a lookup reads of the records it uses, and their bookkeeping.
struct RecordValues {
    Vec3 irradiance;                   ///< IrradianceRecord::irradiance
    ChannelGradients rotational{};     ///< IrradianceRecord::rotational
    ChannelGradients translational{};  ///< IrradianceRecord::translational
    std::int32_t depth = 0;            ///< IrradianceRecord::depth
    std::int32_t pass = 0;             ///< IrradianceRecord::pass
};

/// A record's irradiance, gradients, depth and pass.
inline RecordValues values_of(const IrradianceRecord& record) {
    return {record.irradiance, record.rotational, record.translational, record.depth, record.pass};
}

/// The record made of its two parts again.
inline IrradianceRecord record_of(const RecordGeometry& geometry, const RecordValues& values) {
    return {geometry.position, geometry.normal,      values.irradiance, geometry.radius,
            values.rotational, values.translational, values.depth,      values.pass};
}

/// The range a record's radius is clamped into, in world units.
struct RadiusLimits {
    double min = 0.0;
    double max = 0.0;
};

/// The radius range at `depth` for a point `distance_to_camera` from the camera: POV-Ray's
/// [minimum_reuse, maximum_reuse] × distance × 2^depth, intersected with the caller's pixel-footprint range
/// [footprint_min, footprint_max] (pass 0 and +infinity to leave that out). When the two ranges do not overlap the
/// lower bound wins, so records never get denser than the footprint allows.
RadiusLimits radius_limits(const scene::RadiositySettings& settings, int depth, double distance_to_camera,
                           double footprint_min = 0.0, double footprint_max = 1e300);

/// Switches for the improvements over POV-Ray, so that each can be measured on and off.
struct RecordOptions {
    bool gradients = true;            ///< keep the gradients (off: stored as zero, as POV-Ray 3.7)
    bool gradient_radius_cap = true;  ///< R ≤ E/|∇t E| (Křivánek et al. 2006)
};

/// Makes a record from a gather: radius from the harmonic mean distance, capped by E/|∇t E| and clamped to `limits`;
/// the translational gradient scaled down when the radius was clamped up; always finite.
IrradianceRecord make_record(const Vec3& position, const Vec3& normal, const GatherResult& gathered, int depth,
                             const RadiusLimits& limits, const RecordOptions& options = {});

/// Neighbour clamping (Křivánek et al. 2006), one way: `record`'s radius bounded by R_j + |p − p_j| for `neighbour` j.
inline double clamped_radius(const RecordGeometry& record, const IrradianceRecord& neighbour) {
    return std::min(record.radius, neighbour.radius + length(neighbour.position - record.position));
}
inline double clamped_radius(const IrradianceRecord& record, const IrradianceRecord& neighbour) {
    return clamped_radius(geometry_of(record), neighbour);
}

/// Neighbour clamping (Křivánek et al. 2006): R_a ≤ R_b + |p_a − p_b| and R_b ≤ R_a + |p_a − p_b|.
/// Returns true when either radius changed.
bool neighbour_clamp(IrradianceRecord& a, IrradianceRecord& b);

}  // namespace wardray::cache
