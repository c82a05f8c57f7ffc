// SceneGeometry: the Embree device and scene (the only file that includes embree3/rtcore.h), with analytic
// shapes and CSG as user geometry computed in double precision, meshes as native triangles refined in double,
// and unbounded shapes intersected outside the BVH.
#include "geometry/scene_geometry.h"
#include "geometry/float_padding.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "geometry/instance.h"
#include "geometry/shape.h"

namespace wardray::geometry {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// POV-Ray's BOUND_HUGE: no intersection is nearer than this along a unit direction.
constexpr double k_bound_huge = 2.0e10;

// Nearest float not above x (Embree's ray and bounds are float; rounding must stay conservative).
float float_down(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}

// Nearest float not below x.
float float_up(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

/// Per-query state handed to the callbacks through Embree's context (Embree's documented extension idiom:
/// the RTCIntersectContext comes first). It lives on the querying thread's stack, so callbacks may write it.
struct QueryContext {
    RTCIntersectContext base;
    Vec3 origin;          ///< the original double-precision world ray
    Vec3 direction;
    double t_min = 0.0;
    double t_best = inf;  ///< nearest accepted hit so far (double)
    double t_shift = 0.0; ///< Embree's ray starts at origin + t_shift * direction
    double dir_length = 0.0;  ///< length(direction), for occlusion's float test (clearly_between)
    RayKind kind = RayKind::Camera;
    bool has_hit = false;
    Hit hit;
};
static_assert(std::is_standard_layout_v<QueryContext>);

struct GeometryData;

/// One Embree user geometry: the bounded instances that the same kinds of ray see (Embree's mask is per geometry).
struct UserGroup {
    const GeometryData* impl = nullptr;
    std::vector<std::uint32_t> prims;  ///< Embree primID -> index into GeometryData::bounded
    const std::vector<Bounds>* padded = nullptr;  ///< per bounded instance: the boxes this geometry's BVH holds
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
    std::vector<std::uint32_t> mesh_of_geometry;  ///< Embree geomID -> index into meshes
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

    // The mesh that an Embree triangle geometry holds.
    const ShapeInstance& mesh(unsigned geom_id) const { return meshes[mesh_of_geometry[geom_id]]; }
    // Runs the Embree traversal over the bounded instances, continuing from the state in q.
    void trace(QueryContext& q, bool shadow) const;
    // Brute-force fallback when the ray cannot be expressed in float (huge coordinates).
    void brute_force(QueryContext& q, bool shadow) const;
};

}  // namespace

struct SceneGeometry::Impl : GeometryData {};

namespace {

// The kinds of ray that see an instance, a bit per RayKind, as Embree's geometry mask: a ray then never meets (nor
// calls back for) an object it cannot see, such as cornell's light patch (no_shadow) on every shadow ray.
unsigned visibility_mask(const ShapeInstance& inst) {
    unsigned mask = 0;
    for (const RayKind kind : {RayKind::Camera, RayKind::Reflection, RayKind::Shadow, RayKind::Gather})
        if (inst.visible_to(kind)) mask |= 1u << static_cast<unsigned>(kind);
    return mask;
}

// A ray's mask: its kind's bit.
unsigned ray_mask(RayKind kind) { return 1u << static_cast<unsigned>(kind); }

// With a far BVH, the near boxes' masks are the kinds' bits shifted by this (past RayKind's 4 bits).
constexpr unsigned kFarShift = 4;

void on_embree_error(void* user, RTCError code, const char* message) {
    auto* impl = static_cast<GeometryData*>(user);
    // Only record while building (single-threaded); queries never write shared state.
    if (!impl->building.load(std::memory_order_relaxed) || !impl->error.empty()) return;
    impl->error = message ? message : ("code " + std::to_string(static_cast<int>(code)));
}

void bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* group = static_cast<const UserGroup*>(args->geometryUserPtr);
    const Bounds& b = (*group->padded)[group->prims[args->primID]];
    RTCBounds* out = args->bounds_o;
    out->lower_x = float_down(b.lower.x);
    out->lower_y = float_down(b.lower.y);
    out->lower_z = float_down(b.lower.z);
    out->upper_x = float_up(b.upper.x);
    out->upper_y = float_up(b.upper.y);
    out->upper_z = float_up(b.upper.z);
}

void intersect_callback(const RTCIntersectFunctionNArguments* args) {
    // rtcIntersect1 always calls with one ray.
    if (args->N != 1 || !args->valid[0]) return;
    auto* q = reinterpret_cast<QueryContext*>(args->context);
    const auto* group = static_cast<const UserGroup*>(args->geometryUserPtr);
    const ShapeInstance& inst = group->impl->bounded[group->prims[args->primID]];
    if (!inst.visible_to(q->kind)) return;
    // Double precision on the original ray, limited by the best double hit so far (not Embree's float tfar).
    const auto hit = inst.nearest(q->origin, q->direction, q->t_min, q->t_best);
    if (!hit) return;
    q->t_best = hit->t;
    q->hit = *hit;
    q->has_hit = true;
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    rh->ray.tfar = float_up(hit->t - q->t_shift);
    rh->hit.Ng_x = static_cast<float>(hit->normal.x);
    rh->hit.Ng_y = static_cast<float>(hit->normal.y);
    rh->hit.Ng_z = static_cast<float>(hit->normal.z);
    rh->hit.u = 0.0f;
    rh->hit.v = 0.0f;
    rh->hit.primID = args->primID;
    rh->hit.geomID = args->geomID;
    rh->hit.instID[0] = args->context->instID[0];
}

void occluded_callback(const RTCOccludedFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* q = reinterpret_cast<QueryContext*>(args->context);
    const auto* group = static_cast<const UserGroup*>(args->geometryUserPtr);
    const ShapeInstance& inst = group->impl->bounded[group->prims[args->primID]];
    if (!inst.visible_to(RayKind::Shadow)) return;
    if (!inst.crosses(q->origin, q->direction, q->t_min, q->t_best)) return;
    q->has_hit = true;
    reinterpret_cast<RTCRay*>(args->ray)->tfar = -std::numeric_limits<float>::infinity();
}

// Embree found a triangle in float: recompute its crossing in double and keep it only when it is nearer than
// every hit so far (the query's double t_best), so user geometry and triangles are compared in double.
void triangle_intersect_filter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || args->valid[0] == 0) return;
    auto* q = reinterpret_cast<QueryContext*>(const_cast<RTCIntersectContext*>(args->context));
    const auto* impl = static_cast<const GeometryData*>(args->geometryUserPtr);
    const ShapeInstance& inst = impl->mesh(RTCHitN_geomID(args->hit, args->N, 0));
    const auto hit = inst.visible_to(q->kind)
                         ? inst.face_hit(q->origin, q->direction, RTCHitN_primID(args->hit, args->N, 0), q->t_min,
                                         q->t_best)
                         : std::nullopt;
    if (!hit) {
        args->valid[0] = 0;
        return;
    }
    q->t_best = hit->t;
    q->hit = *hit;
    q->has_hit = true;
}

// True when Embree's float hit (ray parameter t_float past the query's shift, geometric normal ng) lies so far inside
// (t_min, t_best) that the double-precision crossing must too: the plane crossing's rounding is about 1e-7 of the
// scene's size over the cosine, the margin 1e-4 of it at cosines of at least 0.05.
bool clearly_between(const GeometryData& impl, const QueryContext& q, float t_float, const Vec3& ng) {
    const double dir_len = q.dir_length;
    const double ng_len = length(ng);
    if (!(std::fabs(dot(ng, q.direction)) >= 0.05 * ng_len * dir_len) || !std::isfinite(t_float)) return false;
    const double t = q.t_shift + static_cast<double>(t_float);
    const double margin = 1e-4 * (impl.magnitude + max_abs_component(q.origin)) / dir_len + 1e-4 * std::fabs(t);
    return t - margin > q.t_min && t + margin < q.t_best;
}

void triangle_occluded_filter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || args->valid[0] == 0) return;
    auto* q = reinterpret_cast<QueryContext*>(const_cast<RTCIntersectContext*>(args->context));
    const auto* impl = static_cast<const GeometryData*>(args->geometryUserPtr);
    const ShapeInstance& inst = impl->mesh(RTCHitN_geomID(args->hit, args->N, 0));
    if (!inst.visible_to(RayKind::Shadow)) {
        args->valid[0] = 0;
        return;
    }
    // Blocked for sure when the float hit is well inside the shadow ray's span: no double-precision crossing
    // needed (face_hit() keeps the crossing of the triangle's plane, so only its t can disagree).
    const Vec3 ng{RTCHitN_Ng_x(args->hit, args->N, 0), RTCHitN_Ng_y(args->hit, args->N, 0),
                  RTCHitN_Ng_z(args->hit, args->N, 0)};
    if (clearly_between(*impl, *q, RTCRayN_tfar(args->ray, args->N, 0), ng)) {
        q->has_hit = true;
        return;
    }
    // Near the ends (a light in a surface: cornell's lights lie in its ceiling) the face's double t decides, most
    // often against it; the full hit only for a crossing that counts (face_hit() also refuses a non-finite normal).
    const unsigned face = RTCHitN_primID(args->hit, args->N, 0);
    if (!inst.face_crossed(q->origin, q->direction, face, q->t_min, q->t_best) ||
        !inst.face_hit(q->origin, q->direction, face, q->t_min, q->t_best)) {
        args->valid[0] = 0;
        return;
    }
    q->has_hit = true;
}

// One top-level mesh as a native Embree triangle geometry with world-space float vertices.
void attach_mesh(GeometryData& impl, std::uint32_t mesh_index) {
    const ShapeInstance& inst = impl.meshes[mesh_index];
    const auto& mesh = std::get<MeshShape>(inst.shape());
    RTCGeometry geom = rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    impl.check("triangle geometry creation");
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.vertices().size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), mesh.faces().size()));
    impl.check("triangle buffers");
    for (std::size_t i = 0; i < mesh.vertices().size(); ++i) {
        const Vec3 p = inst.transform().point(mesh.vertices()[i]);
        for (int k = 0; k < 3; ++k) vertices[3 * i + k] = static_cast<float>(p[k]);
    }
    for (std::size_t i = 0; i < mesh.faces().size(); ++i)
        for (int k = 0; k < 3; ++k) indices[3 * i + k] = static_cast<unsigned>(mesh.faces()[i].v[k]);
    rtcSetGeometryUserData(geom, &impl);
    rtcSetGeometryMask(geom, visibility_mask(inst));
    rtcSetGeometryIntersectFilterFunction(geom, triangle_intersect_filter);
    rtcSetGeometryOccludedFilterFunction(geom, triangle_occluded_filter);
    rtcCommitGeometry(geom);
    const unsigned id = rtcAttachGeometry(impl.scene, geom);
    rtcReleaseGeometry(geom);
    impl.check("triangle geometry setup");
    if (impl.mesh_of_geometry.size() <= id) impl.mesh_of_geometry.resize(id + 1, 0);
    impl.mesh_of_geometry[id] = mesh_index;
}

}  // namespace

void GeometryData::brute_force(QueryContext& q, bool shadow) const {
    for (const auto* list : {&bounded, &meshes})
    for (const ShapeInstance& inst : *list) {
        if (!inst.visible_to(shadow ? RayKind::Shadow : q.kind)) continue;
        if (const auto hit = inst.nearest(q.origin, q.direction, q.t_min, q.t_best)) {
            q.t_best = hit->t;
            q.hit = *hit;
            q.has_hit = true;
            if (shadow) return;
        }
    }
}

void GeometryData::trace(QueryContext& q, bool shadow) const {
    if (bounded.empty() && meshes.empty()) return;
    // Start Embree's float ray where the double ray enters the scene's box: the float origin then carries
    // rounding of the scene's size, not of a far camera's, and the padding of the bounds covers it.
    const Vec3& lo = padded_scene_bounds->lower;
    const Vec3& hi = padded_scene_bounds->upper;
    const Vec3& o_world = q.origin;
    double t_start = q.t_min;
    double t_exit = inf;
    if (q.t_min >= 0.0 && lo.x <= o_world.x && o_world.x <= hi.x && lo.y <= o_world.y && o_world.y <= hi.y &&
        lo.z <= o_world.z && o_world.z <= hi.z) {
        // From inside the box (gather and shadow rays) the ray entered before t_min: only where it leaves is
        // needed, the same quotients slab_interval() keeps for that side, in its order.
        for (int k = 0; k < 3; ++k)
            if (q.direction[k] != 0.0)
                t_exit = min_of(t_exit, ((q.direction[k] > 0.0 ? hi[k] : lo[k]) - o_world[k]) / q.direction[k]);
    } else {
        double t_enter = 0.0;
        if (!slab_interval(lo, hi, q.origin, q.direction, t_enter, t_exit)) return;
        t_start = max_of(q.t_min, t_enter);
    }
    if (!(t_start <= min_of(t_exit, q.t_best))) return;
    q.t_shift = t_start;
    const Vec3 o = q.origin + t_start * q.direction;
    const float tfar = float_up(q.t_best - t_start);
    const float org[3] = {static_cast<float>(o.x), static_cast<float>(o.y), static_cast<float>(o.z)};
    const float dir[3] = {static_cast<float>(q.direction.x), static_cast<float>(q.direction.y),
                          static_cast<float>(q.direction.z)};
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(org[k]) || !std::isfinite(dir[k])) {
            brute_force(q, shadow);
            return;
        }
    }
    if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f) {
        brute_force(q, shadow);
        return;
    }
    // Only the ray and the hit's ids are read; the rest of the hit is Embree's to write.
    alignas(16) RTCRayHit rh;
    RTCRay& ray = rh.ray;
    ray.org_x = org[0];
    ray.org_y = org[1];
    ray.org_z = org[2];
    ray.dir_x = dir[0];
    ray.dir_y = dir[1];
    ray.dir_z = dir[2];
    ray.tnear = 0.0f;
    ray.tfar = tfar;
    ray.time = 0.0f;
    ray.mask = ray_mask(q.kind);
    ray.id = 0;
    ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    const auto run = [&](RTCScene s) {
        if (shadow) rtcOccluded1(s, &q.base, &ray);
        else rtcIntersect1(s, &q.base, &rh);
    };
    if (!far_scene) {
        run(scene);
        return;
    }
    if (max_abs_component(o) <= near_magnitude) {
        // The near boxes hold for this origin: one traversal meets meshes and bounded instances alike.
        ray.mask |= ray.mask << kFarShift;
        run(scene);
        return;
    }
    // A far origin: the meshes (the only geometries left under the kind's own bit), then the loose boxes.
    if (!meshes.empty()) {
        run(scene);
        if (shadow && q.has_hit) return;
        ray.tfar = float_up(q.t_best - t_start);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    }
    run(far_scene);
}

namespace {
// The analytic shapes and CSG objects as one Embree user geometry (a primitive per object).
void attach_user_geometry(GeometryData& impl, RTCScene scene, std::vector<UserGroup>& groups,
                           const std::vector<Bounds>& padded, unsigned mask_shift);
}  // namespace

SceneGeometry::SceneGeometry(const scene::Scene& scene) : m_impl(std::make_unique<Impl>()) {
    Impl& impl = *m_impl;
    // Room for every object but the plain meshes (which go to Embree as triangles), so a scene of 20,000 objects
    // does not leave the list's growth holding twice its size at the peak of memory.
    std::size_t plain_meshes = 0;
    for (const scene::Object& o : scene.objects)
        plain_meshes += std::holds_alternative<scene::Mesh>(o.shape) && o.clipped_by.empty() && o.bounded_by.empty();
    impl.bounded.reserve(scene.objects.size() - plain_meshes);
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        auto inst = ShapeInstance::create(scene.objects[i], i);
        if (!inst) {
            impl.skipped.push_back(i);
            impl.skip_reasons.push_back(last_skip_reason());
            continue;
        }
        inst->cull_by_bounds();
        if (const auto& b = inst->world_bounds()) {
            impl.bounds = impl.bounds ? impl.bounds->merged(*b) : *b;
            if (inst->is_plain_mesh()) impl.meshes.push_back(std::move(*inst));
            else impl.bounded.push_back(std::move(*inst));
        } else {
            impl.unbounded.push_back(std::move(*inst));
        }
    }
    // Scene magnitude: bounded surfaces, plus where each plane passes nearest the world origin.
    if (impl.bounds) impl.magnitude = impl.bounds->magnitude();
    for (const ShapeInstance& inst : impl.unbounded) {
        // Lines through the origin along x, y and z: the nearest crossing is within sqrt(3) of the plane's distance.
        double nearest = inf;
        for (int k = 0; k < 3; ++k) {
            Vec3 axis;
            axis[k] = 1.0;
            for (const SurfaceHit& h : inst.intersect_all(Vec3{}, axis, -inf, inf))
                nearest = std::fmin(nearest, std::fabs(h.t));
        }
        if (std::isfinite(nearest)) impl.magnitude = std::fmax(impl.magnitude, nearest);
    }
    if (!std::isfinite(impl.magnitude)) impl.magnitude = 0.0;

    if (impl.bounded.empty() && impl.meshes.empty()) {
        impl.building = false;
        return;
    }
    // Pad every box by more than the float ray's rounding, for rays from anywhere in the scene.
    const double scene_pad = 1e-6 * impl.bounds->magnitude();
    std::vector<Bounds> boxes;
    boxes.reserve(impl.bounded.size());
    for (const ShapeInstance& inst : impl.bounded) boxes.push_back(*inst.world_bounds());
    impl.padded_bounds = padded_for_scene(boxes, impl.bounds->magnitude());
    const Vec3 v{2 * scene_pad, 2 * scene_pad, 2 * scene_pad};
    impl.padded_scene_bounds = Bounds{impl.bounds->lower - v, impl.bounds->upper + v};
    // Rays from near the objects need far less when one object makes the scene huge: a sky sphere of radius 1e6
    // pads a chair's 1 cm tubes by 1 unit, and each ray near them then calls back for dozens of objects.
    impl.near_magnitude = near_origin_magnitude(boxes, impl.bounds->magnitude());
    if (std::isfinite(impl.near_magnitude))
        impl.near_bounds = padded_for_origins(boxes, impl.padded_bounds, impl.near_magnitude);

    impl.device = rtcNewDevice(nullptr);
    if (!impl.device) throw std::runtime_error("Embree error: cannot create device");
    rtcSetDeviceErrorFunction(impl.device, on_embree_error, &impl);
    impl.scene = rtcNewScene(impl.device);
    impl.check("scene creation");
    rtcSetSceneFlags(impl.scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(impl.scene, RTC_BUILD_QUALITY_HIGH);

    for (std::uint32_t i = 0; i < impl.meshes.size(); ++i) attach_mesh(impl, i);
    if (!impl.bounded.empty()) {
        if (std::isfinite(impl.near_magnitude)) {
            // The near boxes in the scene with the meshes, under masks shifted past the ray kinds' bits so that a far
            // ray can meet the meshes alone there; the loose boxes in a BVH of their own.
            attach_user_geometry(impl, impl.scene, impl.user_groups, impl.near_bounds, kFarShift);
            impl.far_scene = rtcNewScene(impl.device);
            impl.check("scene creation");
            rtcSetSceneFlags(impl.far_scene, RTC_SCENE_FLAG_ROBUST);
            rtcSetSceneBuildQuality(impl.far_scene, RTC_BUILD_QUALITY_HIGH);
            attach_user_geometry(impl, impl.far_scene, impl.far_groups, impl.padded_bounds, 0);
            rtcCommitScene(impl.far_scene);
            impl.check("BVH build");
        } else {
            attach_user_geometry(impl, impl.scene, impl.user_groups, impl.padded_bounds, 0);
        }
    }
    rtcCommitScene(impl.scene);
    impl.check("BVH build");
    impl.building = false;
}

namespace {

void attach_user_geometry(GeometryData& impl, RTCScene scene, std::vector<UserGroup>& groups,
                           const std::vector<Bounds>& padded, unsigned mask_shift) {
    // A geometry per visibility mask, each listing its instances in scene order; one when every object is seen by
    // every ray, as most scenes are.
    std::uint32_t group_of_mask[16];
    std::fill(std::begin(group_of_mask), std::end(group_of_mask), UINT32_MAX);
    std::vector<unsigned> masks;
    for (std::uint32_t i = 0; i < impl.bounded.size(); ++i) {
        const unsigned mask = visibility_mask(impl.bounded[i]);
        if (group_of_mask[mask] == UINT32_MAX) {
            group_of_mask[mask] = static_cast<std::uint32_t>(groups.size());
            groups.push_back({&impl, {}, &padded});
            masks.push_back(mask);
        }
        groups[group_of_mask[mask]].prims.push_back(i);
    }
    for (std::size_t g = 0; g < groups.size(); ++g) {
        UserGroup& group = groups[g];
        RTCGeometry geom = rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_USER);
        impl.check("geometry creation");
        rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned>(group.prims.size()));
        rtcSetGeometryUserData(geom, &group);
        rtcSetGeometryMask(geom, masks[g] << mask_shift);
        rtcSetGeometryBoundsFunction(geom, bounds_callback, nullptr);
        rtcSetGeometryIntersectFunction(geom, intersect_callback);
        rtcSetGeometryOccludedFunction(geom, occluded_callback);
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        impl.check("geometry setup");
    }
}

}  // namespace

namespace {

// POV-Ray compat (MIN_ISECT_DEPTH): POV-Ray ignores every crossing nearer than 1e-4 to a ray's origin, which is
// how its users' idiom of a second surface a hair (1e-8) inside another, such as a drink's surface against its
// glass, renders: the second crossing is not seen. At scenes smaller than one unit the depth shrinks with the
// scene (1e-4 of its magnitude), so that a scene scaled down draws what it draws at unit size.
double min_isect_depth_of(const GeometryData& impl, const Vec3& direction) {
    return 1e-4 * min_of(1.0, impl.magnitude) / length(direction);
}

// A ray's t_min raised to MIN_ISECT_DEPTH; a query that reaches behind its origin (t_min < 0) asks for the whole
// line and keeps its range.
double first_t(const GeometryData& impl, const Ray& ray) {
    return ray.t_min < 0.0 ? ray.t_min : max_of(ray.t_min, min_isect_depth_of(impl, ray.direction));
}

}  // namespace

SceneGeometry::~SceneGeometry() = default;

std::optional<Hit> SceneGeometry::intersect(const Ray& ray) const {
    if (!is_finite(ray.origin) || !is_finite(ray.direction) || dot(ray.direction, ray.direction) == 0.0 ||
        std::isnan(ray.t_min) || std::isnan(ray.t_max) || !(ray.t_min < ray.t_max))
        return std::nullopt;
    QueryContext q;
    rtcInitIntersectContext(&q.base);
    q.origin = ray.origin;
    q.direction = ray.direction;
    q.t_min = first_t(*m_impl, ray);
    // POV-Ray compat (Trace::FindIntersection): the nearest crossing must lie nearer than BOUND_HUGE, the depth an
    // Intersection starts with; the closed-form quartic's invented roots far out along grazing rays are not seen.
    q.t_best = std::fmin(ray.t_max, k_bound_huge / length(ray.direction));
    q.kind = ray.kind;
    if (!(q.t_min < q.t_best)) return std::nullopt;
    // Unbounded shapes first: their nearest hit shortens the BVH traversal.
    for (const ShapeInstance& inst : m_impl->unbounded) {
        if (!inst.visible_to(ray.kind)) continue;
        if (const auto hit = inst.nearest(q.origin, q.direction, q.t_min, q.t_best)) {
            q.t_best = hit->t;
            q.hit = *hit;
            q.has_hit = true;
        }
    }
    m_impl->trace(q, false);
    if (!q.has_hit) return std::nullopt;
    return q.hit;
}

bool SceneGeometry::occluded(const Ray& ray) const {
    if (!is_finite(ray.origin) || !is_finite(ray.direction) || dot(ray.direction, ray.direction) == 0.0 ||
        std::isnan(ray.t_min) || std::isnan(ray.t_max) || !(ray.t_min < ray.t_max))
        return false;
    const double t_min = first_t(*m_impl, ray);
    if (!(t_min < ray.t_max)) return false;
    for (const ShapeInstance& inst : m_impl->unbounded)
        if (inst.visible_to(RayKind::Shadow) && inst.crosses(ray.origin, ray.direction, t_min, ray.t_max))
            return true;
    QueryContext q;
    rtcInitIntersectContext(&q.base);
    q.origin = ray.origin;
    q.direction = ray.direction;
    q.t_min = t_min;
    q.t_best = ray.t_max;
    q.dir_length = length(ray.direction);
    q.kind = RayKind::Shadow;
    m_impl->trace(q, true);
    return q.has_hit;
}

std::optional<Bounds> SceneGeometry::bounds() const { return m_impl->bounds; }

const std::vector<std::uint32_t>& SceneGeometry::skipped_objects() const { return m_impl->skipped; }
const std::vector<SkipReason>& SceneGeometry::skip_reasons() const { return m_impl->skip_reasons; }

std::vector<Diagnostic> SceneGeometry::shape_warnings() const {
    // POV-Ray compat: only top-level objects report (CSG does not pass the message on to its children).
    std::vector<Diagnostic> out;
    for (const ShapeInstance& inst : m_impl->bounded)
        if (const auto* iso = std::get_if<IsosurfaceShape>(&inst.shape()))
            if (auto w = iso->gradient_warning()) out.push_back(std::move(*w));
    return out;
}

double SceneGeometry::min_isect_parameter(const Vec3& direction) const {
    return min_isect_depth_of(*m_impl, direction);
}

double SceneGeometry::self_intersection_offset(const Vec3& p) const {
    return 1e-9 * max_of(max_abs_component(p), 1e-6 * m_impl->magnitude);
}

double self_intersection_offset(const Vec3& p) {
    // The floor only keeps the result positive at the origin; SceneGeometry's version knows the scene's size.
    return 1e-9 * std::fmax(max_abs_component(p), std::numeric_limits<double>::min());
}

}  // namespace wardray::geometry
