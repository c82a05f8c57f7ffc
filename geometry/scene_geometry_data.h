// SceneGeometry's internals shared by its two halves: scene_geometry.cpp builds the Embree scene,
// scene_geometry_trace.cpp answers queries through it. Included by those two files only.
#pragma once

#include <embree3/rtcore.h>

#include <atomic>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "geometry/instance.h"
#include "geometry/scene_geometry.h"
#include "geometry/shape.h"

namespace wardray::geometry::detail {

inline constexpr double inf = std::numeric_limits<double>::infinity();
// POV-Ray's BOUND_HUGE: no intersection is nearer than this along a unit direction.
inline constexpr double k_bound_huge = 2.0e10;

// Nearest float not above x (Embree's ray and bounds are float; rounding must stay conservative).
inline float float_down(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}

// std::nextafter(f, +infinity) for a float that is not NaN or +infinity, inline: float_up() needs it for about half
// of all rays' tfar, and the library call was a measurable part of a trace.
inline float next_float_up(float f) {
    if (f == 0.0f) return std::numeric_limits<float>::denorm_min();
    const auto bits = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0.0f ? bits + 1u : bits - 1u);
}

// Nearest float not below x.
inline float float_up(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? next_float_up(f) : f;
}

struct GeometryData;

/// Per-query state handed to the callbacks through Embree's context (Embree's documented extension idiom:
/// the RTCIntersectContext comes first). It lives on the querying thread's stack, so callbacks may write it.
struct QueryContext {
    RTCIntersectContext base;
    const GeometryData* impl = nullptr;
    Vec3 origin;          ///< the original double-precision world ray
    Vec3 direction;
    double t_min = 0.0;
    double t_best = inf;  ///< nearest accepted hit so far (double)
    double t_shift = 0.0; ///< Embree's ray starts at origin + t_shift * direction
    double dir_length = 0.0;  ///< length(direction), for occlusion's float test (clearly_between)
    RayKind kind = RayKind::Camera;
    bool has_hit = false;
    /// Where the nearest hit so far is written (the caller's result, so no Hit is copied); none for shadow rays.
    Hit* out = nullptr;
};
static_assert(std::is_standard_layout_v<QueryContext>);

struct GeometryData;

/// One Embree user geometry: the bounded instances that the same kinds of ray see (Embree's mask is per geometry).
struct UserGroup {
    const GeometryData* impl = nullptr;
    std::vector<std::uint32_t> prims;  ///< Embree primID -> index into GeometryData::bounded
    const std::vector<Bounds>* padded = nullptr;  ///< per bounded instance: the boxes this geometry's BVH holds
};

/// One top-level mesh as its Embree triangle geometry's callbacks read it.
struct MeshTrace {
    const ShapeInstance* inst = nullptr;
    /// ShapeInstance::face_world_normal() of each face where every face is flat (its normal the same at every
    /// crossing), made once so a hit copies it; empty for smooth meshes and past the memory budget.
    std::vector<Vec3> flat_normals;
};

// Everything the Embree callbacks read; SceneGeometry::Impl is this type (callbacks cannot name a private type).
struct GeometryData {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<ShapeInstance> bounded;    ///< in scene order; UserGroup::prims index it
    std::vector<UserGroup> user_groups;    ///< by visibility mask, the ones not empty
    std::vector<Bounds> padded_bounds;     ///< per bounded instance, grown for the float ray's rounding
    /// A second BVH of the bounded instances when one object (a sky sphere) makes the scene far larger than the
    /// rest: `scene` then holds them in boxes padded only for rays whose float origin is within near_magnitude,
    /// and `far_scene` in boxes padded for any origin (padded_bounds), for the other rays.
    RTCScene far_scene = nullptr;
    std::vector<UserGroup> far_groups;
    std::vector<Bounds> near_bounds;
    double near_magnitude = inf;
    std::vector<ShapeInstance> unbounded;  ///< planes: intersected directly, never in the BVH
    std::vector<ShapeInstance> meshes;     ///< native Embree triangle geometries
    std::vector<MeshTrace> mesh_traces;    ///< per mesh, its geometry's user data
    std::vector<std::uint32_t> skipped;
    std::vector<SkipReason> skip_reasons;  ///< per entry of skipped
    std::optional<Bounds> bounds;
    std::optional<Bounds> padded_scene_bounds;
    double magnitude = 0.0;                ///< largest coordinate scale of the scene, for offsets
    std::atomic<bool> building{true};
    std::string error;

    ~GeometryData() {
        if (far_scene) rtcReleaseScene(far_scene);
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }

    // Throws the first Embree error recorded by the error callback while building.
    void check(const char* step) {
        if (device && rtcGetDeviceError(device) != RTC_ERROR_NONE && error.empty()) error = "unknown error";
        if (!error.empty()) throw std::runtime_error(std::string("Embree error during ") + step + ": " + error);
    }

    // Runs the Embree traversal over the bounded instances, continuing from the state in q.
    void trace(QueryContext& q, bool shadow) const;
    // Brute-force fallback when the ray cannot be expressed in float (huge coordinates).
    void brute_force(QueryContext& q, bool shadow) const;
};

// The kinds of ray that see an instance, a bit per RayKind, as Embree's geometry mask: a ray then never meets (nor
// calls back for) an object it cannot see, such as cornell's light patch (no_shadow) on every shadow ray.
inline unsigned visibility_mask(const ShapeInstance& inst) {
    unsigned mask = 0;
    for (const RayKind kind : {RayKind::Camera, RayKind::Reflection, RayKind::Shadow, RayKind::Gather})
        if (inst.visible_to(kind)) mask |= 1u << static_cast<unsigned>(kind);
    return mask;
}

// A ray's mask: its kind's bit.
inline unsigned ray_mask(RayKind kind) { return 1u << static_cast<unsigned>(kind); }

// With a far BVH, the near boxes' masks are the kinds' bits shifted by this (past RayKind's 4 bits).
inline constexpr unsigned kFarShift = 4;

// The Embree callbacks (scene_geometry_trace.cpp) that the scene's geometries are built with.
void intersect_callback(const RTCIntersectFunctionNArguments* args);
void occluded_callback(const RTCOccludedFunctionNArguments* args);
void triangle_intersect_filter(const RTCFilterFunctionNArguments* args);
void triangle_occluded_filter(const RTCFilterFunctionNArguments* args);

// POV-Ray compat (MIN_ISECT_DEPTH): POV-Ray ignores every crossing nearer than 1e-4 to a ray's origin, which is
// how its users' idiom of a second surface a hair (1e-8) inside another, such as a drink's surface against its
// glass, renders: the second crossing is not seen. At scenes smaller than one unit the depth shrinks with the
// scene (1e-4 of its magnitude), so that a scene scaled down draws what it draws at unit size.
// `dir_length` is the length of the ray's direction.
inline double min_isect_depth_of(const GeometryData& impl, double dir_length) {
    return 1e-4 * min_of(1.0, impl.magnitude) / dir_length;
}

}  // namespace wardray::geometry::detail

namespace wardray::geometry {
struct SceneGeometry::Impl : detail::GeometryData {};
}  // namespace wardray::geometry
