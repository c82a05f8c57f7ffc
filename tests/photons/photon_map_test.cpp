// The photon map: POV-Ray's packing of colour and direction, the kd-tree gather against brute force, and the
// density estimate of photons spread evenly over a plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "photons/photon_map.h"
#include "photons/photon_random.h"

namespace wardray::photons {
namespace {

TEST(PhotonPacking, ColourKeepsEightBitsOfTheLargestChannel) {
    const Vec3 c{0.0123, 0.0071, 0.00042};
    const Photon p = make_photon({0, 0, 0}, c, {0, 1, 0});
    const Vec3 back = photon_colour(p);
    // RGBE truncates each channel to 1/256 of the shared exponent's range: never above, at most 1/128 below.
    for (double channel : {back.x - c.x, back.y - c.y, back.z - c.z}) {
        EXPECT_LE(channel, 1e-12);
        EXPECT_GE(channel, -c.x / 128.0);
    }
    EXPECT_EQ(photon_colour(make_photon({0, 0, 0}, {0, 0, 0}, {0, 1, 0})), (Vec3{0, 0, 0}));
}

TEST(PhotonPacking, ColourOfAPhotonKeepsItsValueAtAnyScale) {
    // A media photon carries spacing³ times the light: a scene scaled by 1e4 (spacing 0.01 -> 100) makes it 1e12
    // times brighter, past what POV-Ray's exponent byte (bias 250) holds; its map's offset keeps it in range.
    const Vec3 c{0.8, 0.5, 0.2};
    for (double spacing : {1e-6, 0.01, 1.0, 100.0, 1e4}) {
        const int offset = flux_exponent_offset(spacing, 3);
        const Vec3 flux = c * (spacing * spacing * spacing);
        const Vec3 back = photon_colour(make_photon({0, 0, 0}, flux, {0, 1, 0}, offset), offset);
        EXPECT_NEAR(back.x, flux.x, flux.x / 128.0) << spacing;
        EXPECT_NEAR(back.z, flux.z, flux.x / 128.0) << spacing;
    }
    // The offset changes only the exponent: the bytes of the mantissas are those without it.
    const Vec3 flux{0.0123, 0.0071, 0.00042};
    const Photon plain = make_photon({0, 0, 0}, flux, {0, 1, 0});
    const Photon shifted = make_photon({0, 0, 0}, flux, {0, 1, 0}, 21);
    EXPECT_EQ(photon_colour(plain), photon_colour(shifted, 21));
    EXPECT_EQ(flux_exponent_offset(0.01, 3), 0);  // at POV-Ray's usual spacings, POV-Ray's bytes
    for (int i = 0; i < 3; ++i) EXPECT_EQ(plain.rgbe[i], shifted.rgbe[i]);
}

TEST(PhotonPacking, DirectionWithinOneStepOfTheTruth) {
    Random rng(7);
    for (int i = 0; i < 200; ++i) {
        const Vec3 d = normalize(Vec3{rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5});
        const Vec3 at{1, 2, 3};
        const Vec3 back = photon_direction(make_photon(at, {1, 1, 1}, at + d * 5.0));
        // Two angles truncated to steps of π/127: the direction is off by less than two steps.
        EXPECT_GT(dot(back, d), std::cos(2.0 * std::numbers::pi / 127.0)) << i;
    }
}

std::vector<Photon> random_photons(int n, std::uint64_t seed) {
    Random rng(seed);
    std::vector<Photon> out;
    for (int i = 0; i < n; ++i)
        out.push_back(make_photon({rng.uniform() * 4, rng.uniform() * 0.2, rng.uniform() * 4}, {1, 1, 1}, {0, 9, 0}));
    return out;
}

TEST(PhotonMap, GatherFindsTheNearestPhotonsLikeBruteForce) {
    scene::PhotonSettings s;
    s.gather_max = 50;
    s.radius = 0.5;
    const std::vector<Photon> photons = random_photons(5000, 11);
    const PhotonMap map(photons, s);
    Random rng(3);
    for (int q = 0; q < 50; ++q) {
        const Vec3 p{rng.uniform() * 4, 0.1, rng.uniform() * 4};
        const Vec3 n{0, 1, 0};
        for (double size : {0.05, 0.3, 2.0}) {
            Gathered g;
            map.gather(p, size, &n, g);
            // Brute force: the flattened distances d² (1 + 16 |n·v|) under size², nearest first.
            std::vector<double> d;
            for (const Photon& ph : photons) {
                const Vec3 v = ph.point() - p;
                const double d2 = dot(v, v) * (1.0 + 16.0 * std::fabs(dot(n, v)));
                if (d2 < size * size) d.push_back(d2);
            }
            std::sort(d.begin(), d.end());
            const std::size_t expect = std::min<std::size_t>(d.size(), 50);
            ASSERT_EQ(g.photons.size(), expect) << q << " " << size;
            // POV-Ray's radius: the search size, or the farthest kept photon when more were in reach.
            const double radius = d.size() > 50 ? std::sqrt(d[49]) : size;
            EXPECT_NEAR(g.radius, radius, 1e-9 * (1 + radius));
        }
    }
}

TEST(PhotonMap, UniformPhotonsGiveTheirFluxDensity) {
    // 160000 photons of flux 0.001 spread uniformly over a 4 x 4 square: 10 per unit area. The mean of the
    // estimates k / (π r²) · flux away from the edges recovers it (the k-nearest estimate is biased by k / (k − 1)).
    Random rng(5);
    std::vector<Photon> photons;
    for (int i = 0; i < 160000; ++i)
        photons.push_back(make_photon({rng.uniform() * 4, 0, rng.uniform() * 4}, {0.001, 0.001, 0.001}, {2, 5, 2}));
    scene::PhotonSettings s;
    const PhotonMap map(photons, s);
    // The estimated radius holds about gather_max (100) photons where the density is even.
    EXPECT_GT(map.min_gather_radius(), std::sqrt(100.0 / (1e4 * std::numbers::pi)) * 0.9);
    double sum = 0.0;
    for (int q = 0; q < 50; ++q) {
        Gathered g;
        map.gather_adaptive({1 + rng.uniform() * 2, 0, 1 + rng.uniform() * 2}, {0, 1, 0}, g);
        double flux = 0.0;
        for (const Photon* p : g.photons) flux += photon_colour(*p).x;
        sum += flux / (std::numbers::pi * g.radius * g.radius);
    }
    EXPECT_NEAR(sum / 50, 10.0, 0.5);
}

TEST(PhotonMap, SparsePlacesGatherWider) {
    // Few photons in reach: POV-Ray gathers once more at three times the radius when the density holds.
    std::vector<Photon> photons;
    for (int i = 0; i < 200; ++i)
        for (int j = 0; j < 200; ++j)
            photons.push_back(make_photon({i * 0.01 + 0.003, 0, j * 0.01 + 0.004}, {0.001, 0.001, 0.001}, {1, 5, 1}));
    scene::PhotonSettings s;
    s.radius = 0.02;
    s.gather_min = 20;
    const PhotonMap map(photons, s);
    Gathered narrow;
    map.gather({1, 0, 1}, 0.02, nullptr, narrow);
    ASSERT_LT(narrow.photons.size(), 20u);
    Gathered g;
    map.gather_adaptive({1, 0, 1}, {0, 1, 0}, g);
    // The wider gather (0.06) finds more than gather_max: the radius is that of the 100th photon.
    EXPECT_EQ(g.photons.size(), 100u);
    EXPECT_GT(g.radius, 0.05);
    EXPECT_LT(g.radius, 0.06);
}

}  // namespace
}  // namespace wardray::photons
