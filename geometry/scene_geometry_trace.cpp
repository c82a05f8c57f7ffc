// SceneGeometry's queries: the Embree callbacks, which refine every candidate in double precision, and
// intersect() / occluded() around Embree's traversal.
#include "geometry/scene_geometry.h"
#include "geometry/scene_geometry_data.h"

namespace wardray::geometry {

using namespace detail;

namespace detail {

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
    *q->out = *hit;
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
    const auto& mesh = *static_cast<const MeshTrace*>(args->geometryUserPtr);
    // Written straight into the caller's result: face_hit_into() leaves it as it was when it refuses the face.
    if (!mesh.inst->visible_to(q->kind) ||
        !mesh.inst->face_hit_into(q->origin, q->direction, RTCHitN_primID(args->hit, args->N, 0), q->t_min,
                                  q->t_best, *q->out, mesh.flat_normals.empty() ? nullptr : mesh.flat_normals.data())) {
        args->valid[0] = 0;
        return;
    }
    q->t_best = q->out->t;
    q->has_hit = true;
}

namespace {

// True when Embree's float hit (ray parameter t_float past the query's shift, geometric normal ng) lies so far inside
// (t_min, t_best) that the double-precision crossing must too: the plane crossing's rounding is about 1e-7 of the
// scene's size over the cosine, the margin 1e-4 of it at cosines of at least 0.05.
// The span first: a hit near an end (a light in a surface) fails it, and the cosine's square root is not taken.
bool clearly_between(const GeometryData& impl, const QueryContext& q, float t_float, const Vec3& ng) {
    if (!std::isfinite(t_float)) return false;
    const double dir_len = q.dir_length;
    const double t = q.t_shift + static_cast<double>(t_float);
    const double margin = 1e-4 * (impl.magnitude + max_abs_component(q.origin)) / dir_len + 1e-4 * std::fabs(t);
    if (!(t - margin > q.t_min && t + margin < q.t_best)) return false;
    return std::fabs(dot(ng, q.direction)) >= 0.05 * length(ng) * dir_len;
}

}  // namespace

void triangle_occluded_filter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || args->valid[0] == 0) return;
    auto* q = reinterpret_cast<QueryContext*>(const_cast<RTCIntersectContext*>(args->context));
    const auto& mesh = *static_cast<const MeshTrace*>(args->geometryUserPtr);
    const ShapeInstance& inst = *mesh.inst;
    if (!inst.visible_to(RayKind::Shadow)) {
        args->valid[0] = 0;
        return;
    }
    // Blocked for sure when the float hit is well inside the shadow ray's span: no double-precision crossing
    // needed (face_hit() keeps the crossing of the triangle's plane, so only its t can disagree).
    const Vec3 ng{RTCHitN_Ng_x(args->hit, args->N, 0), RTCHitN_Ng_y(args->hit, args->N, 0),
                  RTCHitN_Ng_z(args->hit, args->N, 0)};
    if (clearly_between(*q->impl, *q, RTCRayN_tfar(args->ray, args->N, 0), ng)) {
        q->has_hit = true;
        return;
    }
    // Near the ends (a light in a surface: cornell's lights lie in its ceiling) the face's double t decides, most
    // often against it; the normal only for a crossing that counts (face_hit() also refuses a non-finite normal).
    const unsigned face = RTCHitN_primID(args->hit, args->N, 0);
    if (!inst.face_crossed(q->origin, q->direction, face, q->t_min, q->t_best) ||
        !(mesh.flat_normals.empty() ? inst.face_hit(q->origin, q->direction, face, q->t_min, q->t_best).has_value()
                                    : is_finite(mesh.flat_normals[face]))) {
        args->valid[0] = 0;
        return;
    }
    q->has_hit = true;
}

}  // namespace detail

void GeometryData::brute_force(QueryContext& q, bool shadow) const {
    for (const auto* list : {&bounded, &meshes})
    for (const ShapeInstance& inst : *list) {
        if (!inst.visible_to(shadow ? RayKind::Shadow : q.kind)) continue;
        if (const auto hit = inst.nearest(q.origin, q.direction, q.t_min, q.t_best)) {
            q.t_best = hit->t;
            if (q.out) *q.out = *hit;
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
    if (q.t_min >= 0.0 && lo.x <= o_world.x && o_world.x <= hi.x && lo.y <= o_world.y && o_world.y <= hi.y &&
        lo.z <= o_world.z && o_world.z <= hi.z) {
        // From inside the box (gather and shadow rays) the ray entered before t_min: the query is empty when it
        // leaves before t_start, by the quotients slab_interval() keeps for that side. A quotient (a nonnegative
        // distance over |direction|) is surely at least t_start when t_start |direction| is below a quarter of
        // the distance, rounding included; only otherwise is it divided out and compared.
        for (int k = 0; k < 3; ++k) {
            const double d = q.direction[k];
            if (d == 0.0) continue;
            const double distance = (d > 0.0 ? hi[k] : lo[k]) - o_world[k];
            if (!(t_start * std::fabs(d) < 0.25 * std::fabs(distance)) && !(t_start <= distance / d)) return;
        }
    } else {
        double t_enter = 0.0, t_exit = inf;
        if (!slab_interval(lo, hi, q.origin, q.direction, t_enter, t_exit)) return;
        t_start = max_of(q.t_min, t_enter);
        if (!(t_start <= t_exit)) return;
    }
    if (!(t_start <= q.t_best)) return;
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

// A ray's t_min raised to MIN_ISECT_DEPTH (`dir_length` is length(ray.direction)); a query that reaches behind its
// origin (t_min < 0) asks for the whole line and keeps its range.
double first_t(const GeometryData& impl, const Ray& ray, double dir_length) {
    return ray.t_min < 0.0 ? ray.t_min : max_of(ray.t_min, min_isect_depth_of(impl, dir_length));
}

// Nothing to trace: a ray that is not finite, has no direction or an empty span. A sum of the six coordinates
// times zero is zero when all are finite (else NaN, or a finite sum too large: then each is tested).
bool unusable(const Ray& ray) {
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    if (!(0.0 * (((o.x + o.y) + (o.z + d.x)) + (d.y + d.z)) == 0.0) && (!is_finite(o) || !is_finite(d))) return true;
    return dot(d, d) == 0.0 || std::isnan(ray.t_min) || std::isnan(ray.t_max) || !(ray.t_min < ray.t_max);
}

}  // namespace

std::optional<Hit> SceneGeometry::intersect(const Ray& ray) const {
    // The callbacks write the nearest hit straight into the result, which is returned without a copy.
    std::optional<Hit> result;
    if (unusable(ray)) return result;
    QueryContext q;
    const double dir_length = length(ray.direction);
    q.t_min = first_t(*m_impl, ray, dir_length);
    // POV-Ray compat (Trace::FindIntersection): the nearest crossing must lie nearer than BOUND_HUGE, the depth an
    // Intersection starts with; the closed-form quartic's invented roots far out along grazing rays are not seen.
    q.t_best = std::fmin(ray.t_max, k_bound_huge / dir_length);
    if (!(q.t_min < q.t_best)) return result;
    rtcInitIntersectContext(&q.base);
    q.impl = m_impl.get();
    q.origin = ray.origin;
    q.direction = ray.direction;
    q.kind = ray.kind;
    q.out = &result.emplace();
    // Unbounded shapes first: their nearest hit shortens the BVH traversal.
    for (const ShapeInstance& inst : m_impl->unbounded) {
        if (!inst.visible_to(ray.kind)) continue;
        if (const auto hit = inst.nearest(q.origin, q.direction, q.t_min, q.t_best)) {
            q.t_best = hit->t;
            *q.out = *hit;
            q.has_hit = true;
        }
    }
    m_impl->trace(q, false);
    if (!q.has_hit) result.reset();
    return result;
}

bool SceneGeometry::occluded(const Ray& ray) const {
    if (unusable(ray)) return false;
    const double dir_length = length(ray.direction);
    const double t_min = first_t(*m_impl, ray, dir_length);
    if (!(t_min < ray.t_max)) return false;
    for (const ShapeInstance& inst : m_impl->unbounded)
        if (inst.visible_to(RayKind::Shadow) && inst.crosses(ray.origin, ray.direction, t_min, ray.t_max))
            return true;
    QueryContext q;
    rtcInitIntersectContext(&q.base);
    q.impl = m_impl.get();
    q.origin = ray.origin;
    q.direction = ray.direction;
    q.t_min = t_min;
    q.t_best = ray.t_max;
    q.dir_length = dir_length;
    q.kind = RayKind::Shadow;
    m_impl->trace(q, true);
    return q.has_hit;
}

}  // namespace wardray::geometry
