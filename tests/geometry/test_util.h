// Helpers shared by the geometry tests: seeded random transforms, rays and scenes.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>

#include "geometry/instance.h"
#include "scene/scene.h"

namespace wardray::geometry::test {

/// A seeded random source with the draws the tests need.
class Random {
public:
    explicit Random(std::uint64_t seed) : m_engine(seed) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(m_engine); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(m_engine); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }
    Vec3 vec(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    /// A uniformly distributed unit vector.
    Vec3 direction() {
        for (;;) {
            const Vec3 v = vec(-1.0, 1.0);
            const double l2 = dot(v, v);
            if (l2 > 1e-4 && l2 <= 1.0) return v / std::sqrt(l2);
        }
    }
    /// Non-uniform scale, then rotation, then translation, as POV-Ray applies `scale rotate translate`.
    Transform transform(double translate_range = 5.0) {
        return Transform::scaling(vec(0.3, 3.0))
            .then(Transform::rotation(vec(-180.0, 180.0)))
            .then(Transform::translation(vec(-translate_range, translate_range)));
    }

private:
    std::mt19937_64 m_engine;
};

/// An object holding `shape` with the given transform and no flags.
inline scene::Object make_object(const scene::Shape& shape, const Transform& xf = Transform()) {
    scene::Object o;
    o.shape = shape;
    o.transform = xf;
    return o;
}

/// A random triangle soup of `n` faces around the origin: each face's corners within `spread` of a centre in
/// [-2, 2]³, and with chance `smooth` (none drawn when 0) a normal at each corner.
inline scene::Mesh random_soup(Random& rng, int n, double spread, double smooth = 0.0) {
    scene::Mesh m;
    for (int i = 0; i < n; ++i) {
        const Vec3 c = rng.vec(-2, 2);
        scene::Mesh::Face f;
        for (int k = 0; k < 3; ++k) {
            f.v[k] = static_cast<int>(m.vertices.size());
            m.vertices.push_back(c + rng.vec(-spread, spread));
        }
        if (smooth > 0.0 && rng.chance(smooth)) {
            for (int k = 0; k < 3; ++k) {
                f.n[k] = static_cast<int>(m.normals.size());
                m.normals.push_back(rng.direction());
            }
        }
        m.faces.push_back(f);
    }
    return m;
}

/// A random sphere, box or (when allowed) plane in object space.
inline scene::Shape random_shape(Random& rng, bool allow_plane) {
    const int kind = rng.integer(0, allow_plane ? 2 : 1);
    if (kind == 0) return scene::Sphere{rng.vec(-1.0, 1.0), rng.uniform(0.2, 1.5)};
    if (kind == 1) return scene::Box{rng.vec(-1.5, 1.5), rng.vec(-1.5, 1.5)};
    return scene::Plane{rng.vec(-2.0, 2.0), rng.uniform(-3.0, 3.0)};
}

/// Size of an object for relative tolerances: its bounds' magnitude, or 10 for unbounded objects.
inline double object_scale(const ShapeInstance& inst) {
    if (const auto& b = inst.world_bounds()) return std::fmax(b->magnitude(), max_abs_component(b->upper - b->lower));
    return 10.0;
}

/// A random ray aimed at a point near the object's centre (drawn within ±spread in object space) from a random
/// place 0.5 to 20 units away, with a direction of random length.
struct AimedRay {
    Vec3 origin;
    Vec3 direction;
};
inline AimedRay aim_random_ray(Random& rng, const scene::Object& obj, double spread) {
    const Vec3 target = obj.transform.point(rng.vec(-spread, spread));
    const Vec3 origin = target + rng.direction() * rng.uniform(0.5, 20.0);
    return {origin, (target - origin) * rng.uniform(0.1, 10.0)};
}

/// What crossing i of `hits` along `ray` must satisfy for any shape: a finite t not below the previous one, a
/// unit normal, a point on the surface (implicit function within tolerance × the object's scale) and an
/// entering flag that agrees with the normal.
inline void expect_valid_crossing(const ShapeInstance& inst, const SurfaceHits& hits, std::size_t i,
                                  const AimedRay& ray, double surface_tolerance) {
    const SurfaceHit& h = hits[i];
    ASSERT_TRUE(std::isfinite(h.t));
    ASSERT_NEAR(length(h.normal), 1.0, 1e-12);
    EXPECT_NEAR(inst.object_implicit(ray.origin + h.t * ray.direction), 0.0,
                surface_tolerance * object_scale(inst));
    EXPECT_EQ(h.entering, dot(h.normal, ray.direction) < 0.0);
    if (i > 0) {
        EXPECT_GE(h.t, hits[i - 1].t);
    }
}

/// Checks random rays against random objects from `make`: every crossing lies on the surface (implicit ≈ 0
/// relative to the object's size), has a unit normal, an entering flag that matches the normal, and, for solid
/// shapes, inside just behind the normal and outside just in front of it.
inline void check_shape(const std::function<scene::Shape(Random&)>& make, bool solid, std::uint64_t seed,
                 double surface_tolerance = 1e-9, int min_hits = 150, int trials = 300) {
    Random rng(seed);
    int checked = 0;
    int inside_failures = 0;
    for (int trial = 0; trial < trials; ++trial) {
        scene::Object obj = make_object(make(rng), rng.transform());
        const auto inst = ShapeInstance::create(obj, 3);
        ASSERT_TRUE(inst.has_value()) << "trial " << trial;
        const double scale = test::object_scale(*inst);
        const test::AimedRay ray = test::aim_random_ray(rng, obj, 0.8);
        const SurfaceHits hits = inst->intersect_all(ray.origin, ray.direction, 0.0, 1e30);
        for (std::size_t i = 0; i < hits.size(); ++i) {
            const SurfaceHit& h = hits[i];
            const Vec3 p = ray.origin + h.t * ray.direction;
            SCOPED_TRACE("trial " + std::to_string(trial));
            test::expect_valid_crossing(*inst, hits, i, ray, surface_tolerance);
            EXPECT_EQ(h.leaf, &obj);
            if (solid) {
                const double eps = 1e-6 * scale;
                // Points near edges and rims may leave the solid sideways: count, do not fail on each.
                inside_failures += inst->inside(p + eps * h.normal) || !inst->inside(p - eps * h.normal);
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, min_hits);
    EXPECT_LE(inside_failures, checked / 100) << "of " << checked;
}

/// Crossings of `shape` and of its copies scaled by 1e-4 and 1e4, along rays from `distance` away aimed within
/// ±0.5 of the origin (scaled alike), agree: the same count, t within `t_tolerance` (relative), normals within
/// `normal_tolerance`, all finite. Returns how many crossings were compared.
inline int check_scale_invariance(const scene::Shape& shape, std::uint64_t seed, int rays, double distance,
                                  double t_tolerance, double normal_tolerance) {
    Random rng(seed);
    const auto unit = ShapeInstance::create(make_object(shape), 0);
    EXPECT_TRUE(unit);
    if (!unit) return 0;
    int compared = 0;
    for (double s : {1e-4, 1e4}) {
        const auto scaled = ShapeInstance::create(make_object(shape, Transform::scaling({s, s, s})), 0);
        EXPECT_TRUE(scaled);
        if (!scaled) return compared;
        for (int k = 0; k < rays; ++k) {
            const Vec3 o = rng.direction() * distance;
            const Vec3 d = rng.vec(-0.5, 0.5) - o;
            const SurfaceHits a = unit->intersect_all(o, d, 0.0, 1e30);
            const SurfaceHits b = scaled->intersect_all(o * s, d * s, 0.0, 1e30);
            EXPECT_EQ(a.size(), b.size()) << "scale " << s << " ray " << k;
            for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
                EXPECT_TRUE(std::isfinite(b[i].t) && is_finite(b[i].normal));
                EXPECT_NEAR(a[i].t, b[i].t, t_tolerance * a[i].t);
                EXPECT_NEAR(dot(a[i].normal, b[i].normal), 1.0, normal_tolerance);
                ++compared;
            }
        }
    }
    return compared;
}

}  // namespace wardray::geometry::test
