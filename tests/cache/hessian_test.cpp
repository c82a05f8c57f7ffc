// Tests of the gather's tangent Hessian against finite differences of exact irradiance, and of Hessian spacing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "cache/gather.h"
#include "cache/irradiance_record.h"

namespace wardray::cache {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// An emitting rectangle corner + s·u + t·v (s, t in [0, 1]) of uniform radiance.
struct Panel {
    Vec3 corner, u, v;
    Vec3 radiance;
};

/// Rectangles that never occlude one another from the points tested, over a black background: ray casting for the
/// gather, Lambert's formula for the exact irradiance.
struct PanelRoom {
    std::vector<Panel> panels;
    double scale = 1.0;  ///< every length multiplied by this

    RadianceFunction radiance_at(const Vec3& origin) const {
        return [this, origin](const Vec3& dir) {
            RadianceSample best{{}, kInf};
            for (const Panel& q : panels) {
                const Vec3 c = q.corner * scale, u = q.u * scale, v = q.v * scale;
                const Vec3 normal = cross(u, v);
                const double denom = dot(dir, normal);
                if (std::fabs(denom) < 1e-300) continue;
                const double t = dot(c - origin, normal) / denom;
                if (!(t > 0.0) || t >= best.distance) continue;
                const Vec3 rel = origin + dir * t - c;
                const double s = dot(rel, u) / dot(u, u), w = dot(rel, v) / dot(v, v);
                if (s >= 0.0 && s <= 1.0 && w >= 0.0 && w <= 1.0) best = {q.radiance, t};
            }
            return best;
        };
    }

    /// E at `p` about `n` (no π): Σ L · (projected solid angle)/π, the projected solid angle by Lambert's formula
    /// ½ Σ_edges γ_e n·ĝ_e for polygons wholly above the tangent plane.
    Vec3 irradiance(const Vec3& p, const Vec3& n) const {
        Vec3 e;
        for (const Panel& q : panels) {
            const Vec3 c = q.corner * scale, u = q.u * scale, v = q.v * scale;
            const Vec3 corners[4] = {c - p, c + u - p, c + u + v - p, c + v - p};
            double phi = 0.0;
            for (int i = 0; i < 4; ++i) {
                const Vec3 a = normalize(corners[i]), b = normalize(corners[(i + 1) % 4]);
                const Vec3 g = cross(a, b);
                const double gamma = std::atan2(length(g), dot(a, b));
                phi += 0.5 * gamma * dot(n, normalize(g));
            }
            e += q.radiance * (std::fabs(phi) / std::numbers::pi);
        }
        return e;
    }
};

/// A corner of two walls of different colours standing on the floor z = 0, seen from points on the floor.
PanelRoom corner_room(double scale = 1.0) {
    PanelRoom room;
    room.scale = scale;
    room.panels.push_back({{1.0, -1.0, 0.0}, {0.0, 2.2, 0.0}, {0.0, 0.0, 1.5}, {1.0, 0.5, 0.2}});   // x = 1
    room.panels.push_back({{-2.0, 1.2, 0.0}, {3.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {0.2, 0.6, 1.0}});  // y = 1.2
    return room;
}

/// The exact tangent Hessian {tt, tb, bb} of one channel by central differences of the exact irradiance.
std::array<double, 3> exact_hessian(const PanelRoom& room, const Vec3& p, const Vec3& n, int channel, double h) {
    Vec3 t, b;
    orthonormal_basis(n, t, b);
    const auto e = [&](double x, double y) { return room.irradiance(p + t * x + b * y, n)[channel]; };
    const double e0 = e(0, 0);
    return {(e(h, 0) - 2.0 * e0 + e(-h, 0)) / (h * h),
            (e(h, h) - e(h, -h) - e(-h, h) + e(-h, -h)) / (4.0 * h * h),
            (e(0, h) - 2.0 * e0 + e(0, -h)) / (h * h)};
}

double frobenius(const std::array<double, 3>& m) { return std::sqrt(m[0] * m[0] + 2.0 * m[1] * m[1] + m[2] * m[2]); }

// The gather's Hessian (16384 rays) against central second differences of the exact irradiance, at floor points
// in front of the corner: the tangent-plane patches model is exact in expectation where nothing occludes.
TEST(GatherHessian, MatchesSecondDifferencesOfExactIrradianceInACorner) {
    const PanelRoom room = corner_room();
    const Vec3 n{0, 0, 1};
    const Vec3 points[] = {{0.2, 0.1, 0.0}, {0.7, 0.9, 0.0}, {-0.5, 0.6, 0.0}, {0.8, -0.6, 0.0}};
    for (const Vec3& p : points) {
        const GatherResult g = gather_seeded(p, n, strata_for_count(16384), room.radiance_at(p), 0x5EED, true);
        for (int c = 0; c < 3; ++c) {
            const std::array<double, 3> exact = exact_hessian(room, p, n, c, 1e-3);
            const std::array<double, 3>& est = g.hessian[c];
            const std::array<double, 3> diff{est[0] - exact[0], est[1] - exact[1], est[2] - exact[2]};
            const double err = frobenius(diff) / frobenius(exact);
            std::printf("(%.1f, %.1f) ch%d exact {%.4f %.4f %.4f} gathered {%.4f %.4f %.4f} err %.3f\n", p.x, p.y, c,
                        exact[0], exact[1], exact[2], est[0], est[1], est[2], err);
            EXPECT_LT(err, 0.08) << "point (" << p.x << ", " << p.y << ") channel " << c;
        }
    }
}

// Inside a uniformly bright sphere, E is the same everywhere: the Hessian sums to about zero, far below the size of
// one cell's term, E / r².
TEST(GatherHessian, VanishesInAUniformSphere) {
    const double radius = 3.0;
    const RadianceFunction sphere = [&](const Vec3&) { return RadianceSample{{1.0, 1.0, 1.0}, radius}; };
    const GatherResult g = gather_seeded({0, 0, 0}, {0, 0, 1}, strata_for_count(4096), sphere, 3, true);
    for (int c = 0; c < 3; ++c) EXPECT_LT(frobenius(g.hessian[c]), 0.05 / (radius * radius));
}

// The radius from the Hessian follows the scene's scale: the corner and the point scaled by 1e-3 and 1e3 give
// radii in the same proportion (the same seed, so the same directions).
TEST(HessianSpacing, RadiusScalesWithTheScene) {
    const Vec3 n{0, 0, 1};
    const Vec3 p{0.2, 0.1, 0.0};
    double unit = 0.0;
    for (const double scale : {1.0, 1e-3, 1e3}) {
        const PanelRoom room = corner_room(scale);
        const GatherResult g = gather_seeded(p * scale, n, strata_for_count(400), room.radiance_at(p * scale), 7, true);
        const double r = hessian_radius(g, 0.5);
        ASSERT_TRUE(std::isfinite(r) && r > 0.0);
        if (scale == 1.0) unit = r;
        EXPECT_NEAR(r / scale, unit, 1e-6 * unit) << "scale " << scale;
        RecordOptions options;
        options.spacing = RadiusSpacing::Hessian;
        options.gradient_radius_cap = false;
        options.error_bound = 0.5;
        const IrradianceRecord rec = make_record(p * scale, n, g, 0, {0.0, 1e3 * scale}, options);
        EXPECT_NEAR(rec.radius / scale, unit, 1e-6 * unit) << "scale " << scale;
    }
}

// The radius reaches the error target: at distance error_bound × R along the Hessian's steepest direction, the
// exact irradiance departs from first-order extrapolation by about kHessianErrorFraction × error_bound × E there
// (within the Hessian's noise and third-order terms), and never by much more.
TEST(HessianSpacing, ErrorAtTheEdgeOfReachMatchesTheTarget) {
    const PanelRoom room = corner_room();
    const Vec3 n{0, 0, 1};
    const Vec3 p{0.2, 0.1, 0.0};
    const GatherResult g = gather_seeded(p, n, strata_for_count(16384), room.radiance_at(p), 11, true);
    const double eb = 0.3;
    const double reach = eb * hessian_radius(g, eb);
    ASSERT_TRUE(std::isfinite(reach));
    Vec3 t, b;
    orthonormal_basis(n, t, b);
    // The largest second-order departure over directions, from the exact irradiance and its exact gradient.
    double worst = 0.0;
    const double h = 1e-4;
    for (int i = 0; i < 64; ++i) {
        const double a = 2.0 * std::numbers::pi * i / 64;
        const Vec3 dir = t * std::cos(a) + b * std::sin(a);
        for (int c = 0; c < 3; ++c) {
            const double e0 = room.irradiance(p, n)[c];
            const double slope = (room.irradiance(p + dir * h, n)[c] - room.irradiance(p - dir * h, n)[c]) / (2 * h);
            const double far = room.irradiance(p + dir * reach, n)[c];
            worst = std::max(worst, std::fabs(far - e0 - slope * reach));
        }
    }
    const double brightest = std::max({g.irradiance.x, g.irradiance.y, g.irradiance.z});
    const double target = kHessianErrorFraction * eb * brightest;
    std::printf("reach %.4f: worst departure %.5f, target %.5f\n", reach, worst, target);
    EXPECT_LT(worst, 1.5 * target);
    EXPECT_GT(worst, 0.1 * target);
}

}  // namespace
}  // namespace wardray::cache
