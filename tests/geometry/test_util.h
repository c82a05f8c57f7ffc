// Helpers shared by the geometry tests: seeded random transforms, rays and scenes.
#pragma once

#include <cstdint>
#include <random>

#include "parser/scene.h"

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
inline parser::Object make_object(const parser::Shape& shape, const Transform& xf = Transform()) {
    parser::Object o;
    o.shape = shape;
    o.transform = xf;
    return o;
}

/// A random sphere, box or (when allowed) plane in object space.
inline parser::Shape random_shape(Random& rng, bool allow_plane) {
    const int kind = rng.integer(0, allow_plane ? 2 : 1);
    if (kind == 0) return parser::Sphere{rng.vec(-1.0, 1.0), rng.uniform(0.2, 1.5)};
    if (kind == 1) return parser::Box{rng.vec(-1.5, 1.5), rng.vec(-1.5, 1.5)};
    return parser::Plane{rng.vec(-2.0, 2.0), rng.uniform(-3.0, 3.0)};
}

}  // namespace wardray::geometry::test
