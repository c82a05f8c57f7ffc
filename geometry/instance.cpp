// ShapeInstance: parent-to-object mapping of rays, normals by the inverse transpose, clipping and bounds.
#include "geometry/instance.h"

#include <cmath>
#include <type_traits>

#include "core/sanitizer.h"

namespace wardray::geometry {

namespace {

// CSG nodes nest at most this deep once the parser has flattened what it can (nested unions, intersections and
// merges): building, tracing and freeing a tree recurse once per level on ordinary thread stacks, which 4,000
// levels of `difference { A difference { ... } }` overflowed. 1,000 levels render.
// Sanitizers' frames are several times larger: 1,000 levels overflow 8 MB under AddressSanitizer.
constexpr int k_max_csg_depth = k_address_sanitizer ? 250 : 1000;
thread_local int t_csg_depth = 0;
// The innermost refusal of the current top-level create (the first one wins: it is the deepest part refused).
thread_local SkipReason t_skip;
thread_local bool t_skip_set = false;
// Calls of ShapeInstance::create alive on this thread (clips and bounds nest without a CSG level).
thread_local int t_create_depth = 0;
struct CreateDepthGuard {
    CreateDepthGuard() { ++t_create_depth; }
    ~CreateDepthGuard() { --t_create_depth; }
    CreateDepthGuard(const CreateDepthGuard&) = delete;
    CreateDepthGuard& operator=(const CreateDepthGuard&) = delete;
};

std::nullopt_t refuse(const scene::Object& object, bool too_deep) {
    if (!t_skip_set) {
        t_skip = SkipReason{too_deep, object.loc};
        t_skip_set = true;
    }
    return std::nullopt;
}

// One CSG level of ShapeInstance::create's recursion while it is alive (a leaf adds none).
struct CsgDepthGuard {
    explicit CsgDepthGuard(bool csg) : m_csg(csg) { t_csg_depth += m_csg; }
    ~CsgDepthGuard() { t_csg_depth -= m_csg; }
    CsgDepthGuard(const CsgDepthGuard&) = delete;
    CsgDepthGuard& operator=(const CsgDepthGuard&) = delete;
    int m_csg;
};

template <typename Shape, typename Description>
std::optional<AnyShape> wrap(const Description& d) {
    if (auto r = Shape::create(d)) return AnyShape(std::move(*r));
    return std::nullopt;
}

// True when geometry type G is built from scene shape S (it has `G::create(const S&)`).
template <typename G, typename S>
constexpr bool builds = requires(const S& s) { G::create(s); };

// How many alternatives of AnyShape are built from scene shape S.
template <typename S, typename... G>
constexpr int builder_count(const std::variant<G...>*) {
    return (0 + ... + (builds<G, S> ? 1 : 0));
}

// Builds the first alternative of AnyShape that is built from `s`.
template <typename S, typename G, typename... Rest>
std::optional<AnyShape> build_first(const S& s, const std::variant<G, Rest...>*) {
    if constexpr (builds<G, S>) return wrap<G>(s);
    else return build_first(s, static_cast<const std::variant<Rest...>*>(nullptr));
}

// The geometry factory: each scene shape of WARDRAY_SHAPES (and Csg) becomes the one geometry type whose `create`
// takes it, so a shape without a geometry, or with two, fails to compile here.
template <typename S>
std::optional<AnyShape> make_geometry(const S& s) {
    constexpr const AnyShape* any = nullptr;
    static_assert(builder_count<S>(any) == 1, "each scene shape needs exactly one geometry type with create()");
    return build_first(s, any);
}

// Prisms have three: outlines swept straight are solved exactly (linear ones in POV-Ray's arithmetic, spline ones
// by their cubic); conic sweeps are meshes.
std::optional<AnyShape> make_geometry(const scene::Prism& s) {
    if (s.spline == scene::Prism::Spline::Linear && !s.conic) return wrap<LinearPrismShape>(s);
    if (!s.conic) return wrap<SplinePrismShape>(s);
    return wrap<MeshShape>(s);
}

std::optional<AnyShape> make_shape(const scene::Shape& shape) {
    return std::visit([](const auto& s) { return make_geometry(s); }, shape);
}

// The inside region's object-space bounds: shapes that know theirs say so, closed shapes use their surface's.
template <typename S>
std::optional<Bounds> shape_region(const S& s) {
    if constexpr (requires { s.region_bounds(); }) return s.region_bounds();
    else return s.bounds();
}

bool matrix_is_finite(const Transform::Matrix34& m) {
    for (const auto& row : m)
        for (double v : row)
            if (!std::isfinite(v)) return false;
    return true;
}

// World bounds of the object-space box under the transform: the hull of its eight transformed corners.
Bounds transform_bounds(const Bounds& b, const Transform& xf) {
    Bounds out{xf.point(b.lower), xf.point(b.lower)};
    for (int i = 1; i < 8; ++i) {
        const Vec3 corner{(i & 1) ? b.upper.x : b.lower.x, (i & 2) ? b.upper.y : b.lower.y,
                          (i & 4) ? b.upper.z : b.lower.z};
        const Vec3 p = xf.point(corner);
        out.lower = min(out.lower, p);
        out.upper = max(out.upper, p);
    }
    return out;
}

// Exact world bounds of a transformed sphere (an ellipsoid): the half extent along world axis i is
// r times the length of row i of the linear part.
Bounds ellipsoid_bounds(const SphereShape& s, const Transform& xf) {
    const Vec3 c = xf.point(s.center());
    const auto& m = xf.matrix();
    Vec3 half;
    for (int i = 0; i < 3; ++i)
        half[i] = s.radius() * std::sqrt(m[i][0] * m[i][0] + m[i][1] * m[i][1] + m[i][2] * m[i][2]);
    return {c - half, c + half};
}

}  // namespace

const SkipReason& last_skip_reason() { return t_skip; }

int max_csg_depth() { return k_max_csg_depth; }

ShapeInstance::ShapeInstance(AnyShape shape, const scene::Object& object, std::uint32_t index)
    : m_shape(std::move(shape)),
      m_to_object(object.transform.inverse_matrix()),
      m_object(&object),
      m_index(index),
      m_inverse(object.inverse),
      m_no_shadow(object.no_shadow),
      m_no_image(object.no_image),
      m_no_reflection(object.no_reflection),
      m_no_radiosity(object.no_radiosity) {}

void ShapeInstance::cull_by_bounds() { m_cull_by_bounds = m_parts && !m_parts->clips.empty() && m_has_world_bounds; }

const Transform& ShapeInstance::transform() const {
    return m_parts && m_parts->transform ? *m_parts->transform : m_object->transform;
}

bool ShapeInstance::is_plain_mesh() const {
    return std::holds_alternative<MeshShape>(m_shape) &&
           (!m_parts || (m_parts->clips.empty() && m_parts->bounds.empty()));
}

std::optional<ShapeInstance> ShapeInstance::create(const scene::Object& object, std::uint32_t index,
                                                   bool flip_inverse, ObjectLifetime lifetime) {
    // A top-level create starts with no reason recorded; the parts it builds record theirs.
    if (t_create_depth == 0) t_skip_set = false;
    const CreateDepthGuard nesting;
    // Degenerate objects are skipped here and reported by the app; they must never reach Embree.
    const Transform& xf = object.transform;
    if (!xf.is_invertible() || !matrix_is_finite(xf.matrix()) || !matrix_is_finite(xf.inverse_matrix()))
        return refuse(object, false);
    // POV-Ray compat: an inverted CSG pushes the inversion down to its children and turns into its dual operation
    // (csg.h); other shapes flip their inside and normals.
    const bool inverted = object.inverse != flip_inverse;
    const auto* csg = std::get_if<scene::Csg>(&object.shape);
    // A CSG nested too deep is skipped (the whole top-level object, reported by the app), not a stack overflow.
    const CsgDepthGuard depth(csg != nullptr);
    if (t_csg_depth > k_max_csg_depth) return refuse(object, true);
    std::optional<AnyShape> shape;
    if (csg) {
        if (auto c = CsgShape::create(*csg, inverted, lifetime)) shape = AnyShape(std::move(*c));
    } else {
        shape = make_shape(object.shape);
    }
    if (!shape) return refuse(object, false);
    // POV-Ray compat: an inverted plane is the plane with its normal and distance negated (Plane::Invert).
    const auto* plane = std::get_if<PlaneShape>(&*shape);
    if (plane && inverted) shape = AnyShape(plane->inverted());
    ShapeInstance inst(std::move(*shape), object, index);
    // What few instances have: clips, bounds, and the copy of a transform whose object may not live on.
    std::shared_ptr<Parts> parts;
    auto more = [&]() -> Parts& {
        if (!parts) parts = std::make_shared<Parts>();
        return *parts;
    };
    inst.m_inverse = inverted && !csg && !plane;
    // POV-Ray compat: a cylinder meets rays and answers inside tests through POV-Ray's one matrix to its unit
    // cylinder (clipped ones keep the object-space path their clips need).
    if (auto* cone = std::get_if<ConeShape>(&inst.m_shape); cone && object.clipped_by.empty()) cone->place(xf);
    std::optional<Bounds> local = std::visit([](const auto& s) { return s.bounds(); }, inst.m_shape);
    std::optional<Bounds> region = std::visit([](const auto& s) { return shape_region(s); }, inst.m_shape);
    if (!object.clipped_by.empty()) {
        // Only the parts of the surface inside every clipping object remain.
        std::vector<ShapeInstance>& clips = more().clips;
        clips.reserve(object.clipped_by.size());
        // POV-Ray compat (Quadric::Compute_BBox at clipped_by): a clipped quadric's box is its own where it has
        // one, within the clips'.
        if (const auto* q = std::get_if<QuadricShape>(&inst.m_shape)) local = q->clipped_bounds();
        for (const scene::Object& c : object.clipped_by) {
            auto ci = create(c, index, false, lifetime);
            if (!ci) return refuse(c, false);
            local = intersect_bounds(local, ci->region_bounds());
            region = intersect_bounds(region, ci->region_bounds());
            clips.push_back(std::move(*ci));
        }
        inst.keep_all_crossings();
        if (local && local->empty()) local = Bounds{local->lower, local->lower};
        if (region && region->empty()) region = Bounds{region->lower, region->lower};
    }
    if (!object.bounded_by.empty()) {
        std::vector<ShapeInstance>& bounds = more().bounds;
        bounds.reserve(object.bounded_by.size());
        for (const scene::Object& b : object.bounded_by) {
            auto bi = create(b, index, false, lifetime);
            if (!bi) return refuse(b, false);
            bounds.push_back(std::move(*bi));
        }
    }
    const auto* sphere = std::get_if<SphereShape>(&inst.m_shape);
    inst.m_has_world_bounds = (sphere && object.clipped_by.empty()) || local;
    if (sphere && object.clipped_by.empty()) {
        inst.m_world_bounds = ellipsoid_bounds(*sphere, xf);
    } else if (local) {
        inst.m_world_bounds = transform_bounds(*local, xf);
    }
    inst.m_has_region_bounds = region && !inst.m_inverse;
    if (inst.m_has_region_bounds) inst.m_region_bounds = transform_bounds(*region, xf);
    if (inst.m_has_world_bounds &&
        (!is_finite(inst.m_world_bounds.lower) || !is_finite(inst.m_world_bounds.upper)))
        return refuse(object, false);
    if (lifetime == ObjectLifetime::MayEnd) more().transform = object.transform;
    inst.m_parts = std::move(parts);
    return inst;
}

SurfaceHits ShapeInstance::intersect_all(const Vec3& origin, const Vec3& direction, double t_min,
                                         double t_max) const {
    SurfaceHits hits;
    for (const SurfaceHit& h : object_crossings(origin, direction, t_min, t_max))
        if (const auto hit = to_parent(h)) hits.push(*hit);
    return hits;
}

std::optional<LocalRay> ShapeInstance::bounded_local_ray(const Vec3& origin, const Vec3& direction) const {
    if (m_cull_by_bounds) {
        // POV-Ray's Intersect_BBox: the box must be met from MIN_ISECT_DEPTH (1e-4 along the unit direction) on.
        double s0 = 0.0, s1 = 0.0;
        if (!slab_interval(m_world_bounds.lower, m_world_bounds.upper, origin, direction, s0, s1) ||
            s1 < 1e-4 / length(direction))
            return std::nullopt;
    }
    // An affine map keeps the ray parameter: M⁻¹(o + t d) = M⁻¹o + t M⁻¹d; only for rays the bounds let through.
    const LocalRay local{Transform::point_through(m_to_object, origin),
                         Transform::vector_through(m_to_object, direction)};
    if (m_parts && !m_parts->bounds.empty() && !ray_in_bounds(local)) return std::nullopt;
    return local;
}

SurfaceHits ShapeInstance::object_crossings(const Vec3& origin, const Vec3& direction, double t_min,
                                            double t_max) const {
    const std::optional<LocalRay> bounded = bounded_local_ray(origin, direction);
    if (!bounded) return {};
    const LocalRay& local = *bounded;
    SurfaceHits object_hits = std::visit(
        [&](const auto& s) {
            if constexpr (std::is_same_v<std::decay_t<decltype(s)>, ConeShape>)
                if (s.placed()) return s.intersect_parent(origin, direction, t_min, t_max);
            // POV-Ray compat (MIN_ISECT_DEPTH): POV-Ray discards crossings within 1e-4 of a ray's origin; shapes
            // whose crossings are found only to a tolerance (julia_fractal) would see their own surface there.
            if constexpr (requires { s.k_min_isect_depth; })
                return s.intersect_all(local, t_min, t_max, s.k_min_isect_depth / length(direction));
            else return s.intersect_all(local, t_min, t_max);
        },
        m_shape);
    if (!m_parts || m_parts->clips.empty()) return object_hits;
    SurfaceHits kept;
    for (const SurfaceHit& h : object_hits) {
        const Vec3 p = local.origin + h.t * local.direction;
        bool inside_clips = true;
        for (const ShapeInstance& c : m_parts->clips) inside_clips = inside_clips && c.inside(p);
        if (inside_clips) kept.push(h);
    }
    return kept;
}

std::optional<SurfaceHit> ShapeInstance::to_parent(const SurfaceHit& h) const {
    const Vec3 n = normalize(Transform::normal_through(m_to_object, h.normal));
    if (!is_finite(n) || !std::isfinite(h.t)) return std::nullopt;
    return SurfaceHit{h.t, m_inverse ? -n : n, m_inverse ? !h.entering : h.entering, h.leaf ? h.leaf : m_object};
}

bool ShapeInstance::ray_in_bounds(const LocalRay& ray) const {
    // POV-Ray compat (Ray_In_Bound): the whole ray counts, from MIN_ISECT_DEPTH (1e-4 along the unit direction) on,
    // whatever part of it the caller asks about; all hits of the shape then count, also those beyond the bound.
    const double t_start = 1e-4 / length(transform().vector(ray.direction));
    for (const ShapeInstance& b : m_parts->bounds)
        if (!b.inside(ray.origin) && !b.crosses(ray.origin, ray.direction, t_start, INFINITY))
            return false;
    return true;
}

template <typename Take>
void ShapeInstance::crossings_until(const Vec3& origin, const Vec3& direction, double t_min, double t_max,
                                   Take&& take) const {
    // Shapes that find their crossings one at a time (a torus: each a root of its quartic, refined only when reached)
    // stop where `take` does. Clipped, the first crossings may be clipped away, so those go the common way.
    if (!(m_parts && !m_parts->clips.empty())) {
        bool one_at_a_time = false;
        std::visit(
            [&](const auto& s) {
                if constexpr (requires(const LocalRay& r) { s.intersect_until(r, t_min, t_max, take); }) {
                    one_at_a_time = true;
                    if (const std::optional<LocalRay> local = bounded_local_ray(origin, direction))
                        s.intersect_until(*local, t_min, t_max, take);
                }
            },
            m_shape);
        if (one_at_a_time) return;
    }
    for (const SurfaceHit& crossing : object_crossings(origin, direction, t_min, t_max))
        if (take(crossing)) return;
}

std::optional<Hit> ShapeInstance::nearest(const Vec3& origin, const Vec3& direction, double t_min,
                                          double t_max) const {
    // The crossings come sorted by t: only the first one with a finite normal needs its normal mapped.
    std::optional<Hit> nearest;
    crossings_until(origin, direction, t_min, t_max, [&](const SurfaceHit& crossing) {
        const auto h = to_parent(crossing);
        if (!h) return false;
        Hit& hit = nearest.emplace();
        hit.t = h->t;
        hit.position = origin + h->t * direction;
        hit.normal = h->normal;
        hit.object = m_index;
        hit.leaf = h->leaf;
        return true;
    });
    return nearest;
}

bool ShapeInstance::crosses(const Vec3& origin, const Vec3& direction, double t_min, double t_max) const {
    bool found = false;
    crossings_until(origin, direction, t_min, t_max, [&](const SurfaceHit& crossing) {
        found = to_parent(crossing).has_value();
        return found;
    });
    return found;
}

bool ShapeInstance::face_crossed(const Vec3& origin, const Vec3& direction, std::size_t face, double t_min,
                                 double t_max) const {
    const auto* mesh = std::get_if<MeshShape>(&m_shape);
    if (mesh == nullptr || face >= mesh->faces().size()) return false;
    const LocalRay local{Transform::point_through(m_to_object, origin),
                         Transform::vector_through(m_to_object, direction)};
    return mesh->face_crossed(local, face, t_min, t_max);
}

std::optional<Hit> ShapeInstance::face_hit(const Vec3& origin, const Vec3& direction, std::size_t face,
                                           double t_min, double t_max) const {
    Hit hit;
    if (!face_hit_into(origin, direction, face, t_min, t_max, hit)) return std::nullopt;
    return hit;
}

Vec3 ShapeInstance::face_world_normal(std::size_t face, const MeshShape::FaceCrossing& crossing) const {
    const Vec3 n = normalize(
        Transform::normal_through(m_to_object, std::get<MeshShape>(m_shape).face_normal(face, crossing, Vec3{})));
    return m_inverse ? -n : n;
}

bool ShapeInstance::face_hit_into(const Vec3& origin, const Vec3& direction, std::size_t face, double t_min,
                                  double t_max, Hit& out, const Vec3* flat_normals) const {
    const auto* mesh = std::get_if<MeshShape>(&m_shape);
    if (mesh == nullptr || face >= mesh->faces().size()) return false;
    const LocalRay local{Transform::point_through(m_to_object, origin),
                         Transform::vector_through(m_to_object, direction)};
    MeshShape::FaceCrossing c;
    if (!mesh->face_crossing(local, face, t_min, t_max, true, c)) return false;
    const Vec3 n = flat_normals ? flat_normals[face] : face_world_normal(face, c);
    if (!is_finite(n)) return false;
    const auto params = mesh->params_at(face, c.u, c.v);
    out.t = c.t;
    out.position = origin + c.t * direction;
    out.normal = n;
    out.object = m_index;
    out.leaf = m_object;
    out.face = mesh->faces()[face].source;
    out.bary_u = c.u;
    out.bary_v = c.v;
    out.has_params = params.has_value();
    out.params = params ? *params : Vec3{};
    return true;
}

bool ShapeInstance::inside(const Vec3& p_world) const {
    const Vec3 p = Transform::point_through(m_to_object, p_world);
    // POV-Ray compat: a clipped object is inside only within all its clipping objects (inverse leaves them be).
    if (m_parts)
        for (const ShapeInstance& c : m_parts->clips)
            if (!c.inside(p)) return false;
    const auto* cone = std::get_if<ConeShape>(&m_shape);
    const bool in = cone && cone->placed() ? cone->inside_parent(p_world)
                                           : std::visit([&](const auto& s) { return s.inside(p); }, m_shape);
    return in != m_inverse;
}

double ShapeInstance::object_implicit(const Vec3& p_world) const {
    const Vec3 p = Transform::point_through(m_to_object, p_world);
    return std::visit([&](const auto& s) { return s.implicit(p); }, m_shape);
}

}  // namespace wardray::geometry
