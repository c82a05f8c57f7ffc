// Fog against closed forms and quadrature: ground fog's density integral, several fogs, filter and transmit
// colours, turbulence, the up vector, and scale invariance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "media/fog.h"
#include "media/ground_fog.h"
#include "texture/noise.h"

namespace wardray::media {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Ground fog's density at fog height h: 1 at and below 0, 1/(1 + h²) above.
double density_at(double h) { return h <= 0.0 ? 1.0 : 1.0 / (1.0 + h * h); }

// ∫ density along a segment, by composite Simpson's rule with n (even) steps, in world units.
double optical_depth(const scene::Fog& fog, const Segment& s, int n = 20000) {
    auto f = [&](double t) { return density_at((dot(s.origin + s.direction * t, fog.up) - fog.offset) / fog.alt); };
    const double h = s.length / n;
    double sum = f(0.0) + f(s.length);
    for (int i = 1; i < n; ++i) sum += f(i * h) * (i % 2 == 1 ? 4.0 : 2.0);
    return sum * h / 3.0;
}

scene::Fog ground(double distance, double offset, double alt, const Color& c = {0.5, 0.6, 0.7}) {
    scene::Fog f;
    f.type = 2;
    f.distance = distance;
    f.offset = offset;
    f.alt = alt;
    f.color = c;
    return f;
}

TEST(GroundFog, MeanDensityIsTheIntegralOfOneOverOnePlusHSquared) {
    // Against quadrature of the density over h: below, crossing the ground (both ways), above, and level.
    const double cases[][2] = {{-3.0, -1.0}, {-2.0, 1.5}, {2.5, -0.5}, {0.2, 4.0}, {3.0, 0.5}, {-1.0, 0.0}};
    for (const auto& c : cases) {
        const double a = c[0];
        const double b = c[1];
        const int n = 20000;
        const double h = (b - a) / n;
        double sum = density_at(a) + density_at(b);
        for (int i = 1; i < n; ++i) sum += density_at(a + i * h) * (i % 2 == 1 ? 4.0 : 2.0);
        EXPECT_NEAR(ground_fog_density(a, b), sum * h / 3.0 / (b - a), 1e-9) << a << " .. " << b;
    }
    EXPECT_DOUBLE_EQ(ground_fog_density(2.0, 2.0), 1.0 / 5.0);
    EXPECT_DOUBLE_EQ(ground_fog_density(-4.0, -4.0), 1.0);
}

TEST(GroundFog, AttenuationIsExpOfTheOpticalDepthOverDistance) {
    const scene::Fog fog = ground(3.0, 0.5, 2.0);
    const Segment rising{{0.0, -1.0, 0.0}, normalize(Vec3{1.0, 0.7, 0.2}), 9.0};
    EXPECT_NEAR(fog_attenuation(fog, rising, 2), std::exp(-optical_depth(fog, rising) / 3.0), 1e-9);
    const Segment falling{{0.0, 6.0, 1.0}, normalize(Vec3{0.3, -0.9, 0.1}), 8.0};
    EXPECT_NEAR(fog_attenuation(fog, falling, 2), std::exp(-optical_depth(fog, falling) / 3.0), 1e-9);
    // Below fog_offset it is a constant fog.
    const Segment low{{0.0, -5.0, 0.0}, {1.0, 0.0, 0.0}, 4.0};
    EXPECT_NEAR(fog_attenuation(fog, low, 2), std::exp(-4.0 / 3.0), 1e-12);
}

TEST(GroundFog, TheUpVectorSetsWhichWayIsHeight) {
    scene::Fog sideways = ground(2.0, 0.0, 1.0);
    sideways.up = {1.0, 0.0, 0.0};
    // Moving along y keeps the height along x: density 1/(1 + 2²) everywhere.
    const Segment s{{2.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 5.0};
    EXPECT_NEAR(fog_attenuation(sideways, s, 2), std::exp(-5.0 / 5.0 / 2.0), 1e-12);
}

TEST(GroundFog, ARayToTheSkyIsFiniteAndSeesTheFogAboveIt) {
    // Straight up from the ground: ∫0^∞ 1/(1 + (y/alt)²) dy = alt·π/2, so exp(−alt·π/2/distance).
    const scene::Fog fog = ground(4.0, 0.0, 1.5);
    const double att = fog_attenuation(fog, Segment{{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, kInf}, 2);
    EXPECT_NEAR(att, std::exp(-1.5 * std::numbers::pi / 2.0 / 4.0), 1e-6);
    // Level with the ground, forever: all gone, and no NaN.
    EXPECT_EQ(fog_attenuation(fog, Segment{{0.0, -1.0, 0.0}, {1.0, 0.0, 0.0}, kInf}, 2), 0.0);
}

TEST(Fogs, SeveralFogsMultiplyTheirAttenuationsAndAddTheirColours) {
    scene::Fog a;
    a.distance = 2.0;
    a.color = {1.0, 0.0, 0.0};
    const scene::Fog b = ground(5.0, 10.0, 1.0, {0.0, 0.0, 1.0});  // everything below 10: constant
    const Fogs fogs({a, b}, 2);
    const Segment s{{}, {0.0, 0.0, 1.0}, 3.0};
    const double ta = std::exp(-3.0 / 2.0);
    const double tb = std::exp(-3.0 / 5.0);
    const Vec3 behind{0.2, 0.4, 0.8};
    const Vec3 expected = Vec3{1.0 - ta, 0.0, 1.0 - tb} + behind * (ta * tb);
    const Vec3 got = fogs.along_segment(behind, s);
    EXPECT_NEAR(got.x, expected.x, 1e-12);
    EXPECT_NEAR(got.y, expected.y, 1e-12);
    EXPECT_NEAR(got.z, expected.z, 1e-12);
    const Vec3 t = fogs.transmittance(s);
    EXPECT_NEAR(t.x, ta * tb, 1e-12);
}

TEST(Fogs, FilterTintsWhatPassesAndTransmitBoundsIt) {
    scene::Fog f;
    f.distance = 1.0;
    f.color = {0.5, 1.0, 0.25, 1.0, 0.3};  // filter 1: what passes is tinted by the colour; at least 0.3 passes
    const Fogs fogs({f}, 2);
    const Vec3 t = fogs.transmittance(Segment{{}, {1.0, 0.0, 0.0}, 50.0});
    EXPECT_NEAR(t.x, 0.3 * 0.5, 1e-12);
    EXPECT_NEAR(t.y, 0.3 * 1.0, 1e-12);
    EXPECT_NEAR(t.z, 0.3 * 0.25, 1e-12);
}

TEST(Fogs, TurbulenceChangesTheLengthByTheNoiseAtTheMidpoint) {
    // POV-Ray's rule: the length w becomes w·(1 − exp(−w/distance)·min(1, T·turb_depth)), T the turbulence at
    // the segment's midpoint times the turbulence vector; turb_depth 0 leaves the fog as it is.
    scene::Fog plain = ground(3.0, 0.0, 1.0);
    scene::Fog turbulent = plain;
    turbulent.turbulence = scene::Turbulence{{0.3, 0.5, 0.2}, 4, 0.6, 2.5};
    turbulent.turb_depth = 0.7;
    int changed = 0;
    for (int i = 0; i < 40; ++i) {
        const Segment s{{0.37 * i, -0.5, 0.11 * i}, normalize(Vec3{1.0, 0.2, 0.3}), 1.0 + 0.25 * i};
        const Vec3 mid = s.origin + s.direction * (s.length / 2.0);
        const double t = texture::turbulence(mid * Vec3{0.3, 0.5, 0.2}, {4, 0.6, 2.5}, 2);
        const double w = s.length * (1.0 - std::exp(-s.length / 3.0) * std::min(1.0, t * 0.7));
        const double end_h = dot(s.origin + s.direction * s.length, plain.up);
        const double density = ground_fog_density(s.origin.y, end_h);
        EXPECT_NEAR(fog_attenuation(turbulent, s, 2), std::exp(-w * density / 3.0), 1e-12);
        changed += std::fabs(fog_attenuation(turbulent, s, 2) - fog_attenuation(plain, s, 2)) > 1e-6 ? 1 : 0;
        scene::Fog none = turbulent;
        none.turb_depth = 0.0;
        EXPECT_DOUBLE_EQ(fog_attenuation(none, s, 2), fog_attenuation(plain, s, 2));
    }
    EXPECT_GT(changed, 30);
}

TEST(Fogs, AGroundFogScaledWithItsSceneAttenuatesAlike) {
    // Offset, altitude, distance and the segment scaled by the same factor give the same attenuation.
    const scene::Fog base = ground(3.0, 0.5, 2.0);
    const Segment s{{0.2, -1.0, 0.4}, normalize(Vec3{1.0, 0.7, 0.2}), 9.0};
    const Segment up_to_sky{{0.2, 0.1, 0.4}, normalize(Vec3{0.1, 0.5, 0.2}), kInf};
    for (const double k : {1e-4, 1e4}) {
        scene::Fog scaled = ground(3.0 * k, 0.5 * k, 2.0 * k);
        EXPECT_NEAR(fog_attenuation(scaled, Segment{s.origin * k, s.direction, s.length * k}, 2),
                    fog_attenuation(base, s, 2), 1e-9);
        const double sky = fog_attenuation(base, up_to_sky, 2);
        EXPECT_NEAR(fog_attenuation(scaled, Segment{up_to_sky.origin * k, up_to_sky.direction, kInf}, 2), sky,
                    0.01 * sky);
    }
}

}  // namespace
}  // namespace wardray::media
