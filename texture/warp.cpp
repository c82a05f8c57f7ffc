// Warps: POV-Ray 3.7's warp list (transforms, turbulence, repeat, black_hole and the mapping warps) carrying a
// point of the enclosing space into pattern space, and normals into and out of it (Warp_EPoint, Warp_Normal).
#include <cmath>
#include <numbers>

#include "core/constants.h"
#include "texture/noise.h"
#include "texture/normal.h"
#include "texture/pattern.h"

namespace wardray::texture {

namespace {

using Type = scene::Pattern::Type;
using WType = scene::Warp::Type;

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kCoordinateLimit = 1.0e17;  // POV-Ray's COORDINATE_LIMIT

TurbulenceParams params(const scene::Turbulence& t) { return {t.octaves, t.omega, t.lambda}; }

Vec3 turbulate(const Vec3& p, const scene::Turbulence& t) { return p + dturbulence(p, params(t)) * t.amount; }

Vec3 repeat(const scene::Warp& w, const Vec3& p) {
    Vec3 r = p;
    const int axis = w.axis;
    // POV-Ray compat: the block number is kept as a single-precision float.
    const double block = static_cast<double>(static_cast<float>(std::floor(p[axis] / w.width)));
    r[axis] = p[axis] - block * w.width;
    if (static_cast<int>(block) & 1) {
        r = r * w.flip;
        if (w.flip[axis] < 0.0) r[axis] = w.width + r[axis];
    }
    return r + w.offset * block;
}

Vec3 black_hole(const scene::Warp& w, const Vec3& p) {
    Vec3 center = w.center;
    if (w.repeat) {
        int block[3] = {0, 0, 0};
        for (int i = 0; i < 3; ++i)
            if (w.repeat_vector[i] >= kPovEpsilon) block[i] = static_cast<int>(std::floor(p[i] / w.repeat_vector[i]));
        if (w.uncertain) {
            const std::size_t seed = static_cast<std::size_t>(hash3d(block[0], block[1], block[2]));
            for (int i = 0; i < 3; ++i) center[i] += pattern_rand(seed + i) * w.uncertainty[i];
        }
        for (int i = 0; i < 3; ++i) center[i] += w.repeat_vector[i] * block[i];
    }
    const Vec3 delta = p - center;
    const double len = length(delta);
    if (len >= w.radius || w.hole_type != 0) return p;
    const double proportion = (w.radius - len) / w.radius;
    double strength = std::pow(proportion, w.falloff) * w.strength;
    if (strength > 1.0) strength = 1.0;
    return p + delta * (w.inverse ? -strength : strength);
}

// POV-Ray's angle of (x, z) from +x, 0..2π, as its mapping warps compute it.
double angle_xz(double x, double z, double len) {
    if (z == 0.0) return x > 0.0 ? 0.0 : std::numbers::pi;
    const double theta = std::acos(x / len);
    return z < 0.0 ? kTwoPi - theta : theta;
}

// The mapping warps place (u, v, distance) along an orientation vector; <0,0,1> keeps them as x, y, z.
Vec3 orient(const Vec3& o, double x, double y, double z) {
    if (o.x == 0.0 && o.y == 0.0 && o.z == 1.0) return {x, y, z};
    return {o.x * z + o.y * x + o.z * x, o.x * y + o.y * -z + o.z * y, o.x * -x + o.y * y + o.z * z};
}

double dist_scale(double dist_exp, double len) {
    if (dist_exp == 1.0) return len;
    if (dist_exp != 0.0) return std::pow(len, dist_exp);
    return 1.0;
}

Vec3 cylindrical(const scene::Warp& w, const Vec3& p) {
    const double len = std::sqrt(p.x * p.x + p.z * p.z);
    if (len == 0.0) return p;
    const double theta = angle_xz(p.x, p.z, len) / kTwoPi * dist_scale(w.dist_exp, len);
    return orient(w.orientation, theta, p.y, len);
}

Vec3 spherical(const scene::Warp& w, const Vec3& p) {
    const double dist = length(p);
    if (dist == 0.0) return p;
    const Vec3 u = p / dist;
    double phi = 0.5 + std::asin(u.y) / std::numbers::pi;
    const double len = std::sqrt(u.x * u.x + u.z * u.z);
    double theta = len == 0.0 ? 0.0 : angle_xz(u.x, u.z, len) / kTwoPi;
    const double s = dist_scale(w.dist_exp, dist);
    theta *= s;
    phi *= s;
    return orient(w.orientation, theta, phi, dist);
}

Vec3 toroidal(const scene::Warp& w, const Vec3& p) {
    double len = std::sqrt(p.x * p.x + p.z * p.z);
    if (len == 0.0) return p;
    double theta = 0.0 - angle_xz(p.x, p.z, len);
    const double x = len - w.major_radius;
    len = std::sqrt(x * x + p.y * p.y);
    double phi = std::acos(-x / len);
    if (p.y > 0.0) phi = kTwoPi - phi;
    theta /= -kTwoPi;
    phi /= kTwoPi;
    const double s = dist_scale(w.dist_exp, len);
    theta *= s;
    phi *= s;
    return orient(w.orientation, theta, phi, len);
}

Vec3 cubic(const Vec3& p) {
    const double x = p.x, y = p.y, z = p.z;
    const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
    constexpr double third = 1.0 / 3.0;
    if (x >= 0 && x >= ay && x >= az) return {0.75 - 0.25 * (z / x + 1.0) / 2.0, third + third * (y / x + 1.0) / 2.0, x};
    if (y >= 0 && y >= ax && y >= az) return {0.25 + 0.25 * (x / y + 1.0) / 2.0, 1.0 - third * (z / y + 1.0) / 2.0, y};
    if (z >= 0 && z >= ax && z >= ay) return {0.25 + 0.25 * (x / z + 1.0) / 2.0, third + third * (y / z + 1.0) / 2.0, z};
    if (x < 0 && x <= -ay && x <= -az) return {0.25 * (z / -x + 1.0) / 2.0, third + third * (y / -x + 1.0) / 2.0, -x};
    if (y < 0 && y <= -ax && y <= -az) return {0.25 + 0.25 * (x / -y + 1.0) / 2.0, third * (z / -y + 1.0) / 2.0, -y};
    return {1.0 - 0.25 * (x / -z + 1.0) / 2.0, third + third * (y / -z + 1.0) / 2.0, -z};
}

Vec3 apply_warp(const scene::Warp& w, const Vec3& p) {
    switch (w.type) {
        case WType::Transform:
            return w.transform.inverse_point(p);
        case WType::Turbulence:
            return turbulate(p, w.turbulence);
        case WType::Repeat:
            return repeat(w, p);
        case WType::BlackHole:
            return black_hole(w, p);
        case WType::Cylindrical:
            return cylindrical(w, p);
        case WType::Spherical:
            return spherical(w, p);
        case WType::Toroidal:
            return toroidal(w, p);
        case WType::Planar:
            return orient(w.orientation, p.x, p.y, w.plane_offset);
        case WType::Cubic:
            return cubic(p);
    }
    return p;
}

// Normals go into pattern space with the transpose of the pattern→world matrix (POV-Ray's MInvTransNormal).
Vec3 into_pattern(const Transform& tr, const Vec3& u) {
    if (tr.is_identity()) return u;
    const auto& m = tr.matrix();
    return {m[0][0] * u.x + m[1][0] * u.y + m[2][0] * u.z, m[0][1] * u.x + m[1][1] * u.y + m[2][1] * u.z,
            m[0][2] * u.x + m[1][2] * u.y + m[2][2] * u.z};
}

}  // namespace

Vec3 warp_point(const scene::Pattern& pattern, const Vec3& p) {
    Vec3 q = pattern.transform.is_identity() ? p : pattern.transform.inverse_point(p);
    if (!pattern.warps.empty()) {
        for (const scene::Warp& w : pattern.warps) q = apply_warp(w, q);
        for (int i = 0; i < 3; ++i) q[i] = std::fmin(std::fmax(q[i], -kCoordinateLimit), kCoordinateLimit);
    }
    // The classic turbulence is the last warp; marble and wood apply it themselves.
    if (pattern.params->turbulence && pattern.type != Type::Marble && pattern.type != Type::Wood) {
        const scene::Turbulence& t = *pattern.params->turbulence;
        if (!(t.amount == Vec3{})) q = turbulate(q, t);
    }
    return q;
}

// POV-Ray compat (Warp_Normal, UnWarp_Normal): normalized before and after unless `no_bump_scale`.
Vec3 warp_normal(const scene::Pattern& pattern, const Vec3& n) {
    return warp_normal(pattern, n, pattern.no_bump_scale);
}

Vec3 unwarp_normal(const scene::Pattern& pattern, const Vec3& n) {
    return unwarp_normal(pattern, n, pattern.no_bump_scale);
}

Vec3 warp_normal(const scene::Pattern& pattern, const Vec3& n, bool keep) {
    const bool unit = !keep;
    Vec3 t = into_pattern(pattern.transform, unit ? normalize(n) : n);
    for (const scene::Warp& w : pattern.warps)
        if (w.type == WType::Transform) t = into_pattern(w.transform, t);
    return unit ? normalize(t) : t;
}

Vec3 unwarp_normal(const scene::Pattern& pattern, const Vec3& n, bool keep) {
    const bool unit = !keep;
    Vec3 t = unit ? normalize(n) : n;
    for (auto it = pattern.warps.rbegin(); it != pattern.warps.rend(); ++it)
        if (it->type == WType::Transform) t = it->transform.normal(t);
    if (!pattern.transform.is_identity()) t = pattern.transform.normal(t);
    return unit ? normalize(t) : t;
}

}  // namespace wardray::texture
