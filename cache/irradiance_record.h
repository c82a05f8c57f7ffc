// IrradianceRecord: one cached irradiance value with its reuse radius and gradients, and how a gather becomes one.
#pragma once

#include <algorithm>
#include <array>
#include <cfloat>
#include <cstdint>

#include "cache/gather.h"
#include "scene/scene.h"
#include "core/vec3.h"

namespace wardray::cache {

/// One entry of the irradiance cache (Ward, Rubinstein & Clear 1988), in POV-Ray's normalisation (no π).
/// make_record() rounds both gradients to single precision, as the octree keeps them (PackedGradients).
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

/// A record's three gradient vectors in single precision, x, y, z per channel: make_record() rounds them so, and
/// the octree keeps them so (a gradient is a first-order correction; 36 bytes instead of 72 a kind and record).
using PackedGradients = std::array<float, 9>;

/// The gradients rounded to single precision (to nearest; beyond its range, its largest finite value).
inline PackedGradients pack(const ChannelGradients& g) {
    PackedGradients out;
    for (int c = 0; c < 3; ++c)
        for (int a = 0; a < 3; ++a)
            out[3 * c + a] = static_cast<float>(std::clamp(g[c][a], -double{FLT_MAX}, double{FLT_MAX}));
    return out;
}
inline ChannelGradients unpack(const PackedGradients& g) {
    return {Vec3{g[0], g[1], g[2]}, Vec3{g[3], g[4], g[5]}, Vec3{g[6], g[7], g[8]}};
}

/// The rest of a record: what a lookup reads of the records it uses, and their bookkeeping.
struct RecordValues {
    Vec3 irradiance;                  ///< IrradianceRecord::irradiance
    PackedGradients rotational{};     ///< IrradianceRecord::rotational
    PackedGradients translational{};  ///< IrradianceRecord::translational
    std::int32_t depth = 0;           ///< IrradianceRecord::depth
    std::int32_t pass = 0;            ///< IrradianceRecord::pass
};

/// A record's irradiance, gradients, depth and pass (the gradients exactly when make_record() made them).
inline RecordValues values_of(const IrradianceRecord& record) {
    return {record.irradiance, pack(record.rotational), pack(record.translational), record.depth, record.pass};
}

/// The record made of its two parts again.
inline IrradianceRecord record_of(const RecordGeometry& geometry, const RecordValues& values) {
    return {geometry.position,         geometry.normal,
            values.irradiance,         geometry.radius,
            unpack(values.rotational), unpack(values.translational),
            values.depth,              values.pass};
}

/// The range a record's radius is clamped into, in world units.
struct RadiusLimits {
    double min = 0.0;
    double max = 0.0;
    /// The pixel footprint at the point (radius_limits()' footprint_min): with RecordOptions::geometry_floor, the
    /// least radius a record near geometry may have below `min`.
    double footprint = 0.0;
};

/// The radius range at `depth` for a point `distance_to_camera` from the camera: POV-Ray's
/// [minimum_reuse, maximum_reuse] × distance × 2^depth, intersected with the caller's pixel-footprint range
/// [footprint_min, footprint_max] (pass 0 and +infinity to leave that out). When the two ranges do not overlap the
/// lower bound wins, so records never get denser than the footprint allows. `footprint` keeps footprint_min.
RadiusLimits radius_limits(const scene::RadiositySettings& settings, int depth, double distance_to_camera,
                           double footprint_min = 0.0, double footprint_max = 1e300);

/// Where a record's radius comes from before its limits (`--gi-spacing`).
enum class RadiusSpacing {
    Harmonic,  ///< the harmonic mean distance of the gather's hits (Ward, Rubinstein & Clear 1988)
    Hessian,   ///< the distance at which the irradiance Hessian's error reaches a target (hessian_radius())
};

/// Switches for the improvements over POV-Ray, so that each can be measured on and off.
struct RecordOptions {
    bool gradients = true;            ///< keep the gradients (off: stored as zero, as POV-Ray 3.7)
    bool gradient_radius_cap = true;  ///< R ≤ E/|∇t E| (Křivánek et al. 2006)
    /// Hessian needs gradients and a gather with second_order; without them, Harmonic.
    RadiusSpacing spacing = RadiusSpacing::Harmonic;
    double error_bound = 1.0;  ///< the final pass's error_bound at the record's depth (Hessian spacing)
    /// `--gi-reuse-floor=geometry`: at depth 0, the lower limit (POV-Ray's minimum_reuse, a fraction of the distance
    /// to the camera) gives way to kGeometryFloorFraction of the gather's harmonic mean distance where that is
    /// smaller, but never to less than the pixel footprint (RadiusLimits::footprint). Off: POV-Ray 3.7's floor.
    bool geometry_floor = false;
};

/// The fraction of its harmonic mean distance (the distance to the surfaces its hemisphere sees) that a record near
/// geometry may have as its radius below POV-Ray's minimum_reuse (RecordOptions::geometry_floor). Over the
/// comparison's ladder (docs/reports/reuse_floor.md): 0.25, 0.35 and 0.5 lowered the error of stackerday, patio and
/// rad_def_test_37 alike, and of stackernight by 36 %, 34 % and 28 % at c400; 0.7 and 1 gained less. 0.5 costs box
/// 1-2.5 % more records; 0.25 was not measured on every scene.
inline constexpr double kGeometryFloorFraction = 0.5;

/// The fraction of error_bound that Hessian spacing allows as relative error at the edge of a record's reach: 1,
/// the error there equals error_bound × E. With 0.5 instead, cornell (256x256) and box at c40/e0.7 and c80/e0.5
/// made 14-53 % more records than harmonic spacing, with 2 about as many; the radius is often set by the limits
/// instead (docs/reports/radiosity.md).
inline constexpr double kHessianErrorFraction = 1.0;

/// The radius at which first-order extrapolation's estimated error reaches kHessianErrorFraction × error_bound of
/// the record's irradiance at the edge of its reach, error_bound × R (see irradiance_record.cpp); +infinity when
/// the gather saw no curvature. Proportional to the scene's scale: the Hessian goes as E / length².
double hessian_radius(const GatherResult& gathered, double error_bound);

/// Makes a record from a gather: radius from the harmonic mean distance (or hessian_radius()), capped by
/// E/|∇t E| and clamped to `limits`; the translational gradient scaled down when the radius was clamped up; always
/// finite.
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
