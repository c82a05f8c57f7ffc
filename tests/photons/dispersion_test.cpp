// Dispersion: the band hues average to white, the index of the middle band is the interior's, the ends are spread
// by dispersion^±½, and photons split by a dispersive target keep the light's flux and are the same for any thread
// count.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "../parser/test_util.h"
#include "geometry/scene_geometry.h"
#include "photons/dispersion.h"
#include "photons/photon_map.h"
#include "photons/photon_shooter.h"
#include "same_map.h"

namespace wardray::photons {
namespace {

TEST(Dispersion, BandHuesAverageToWhite) {
    for (const int n : {2, 3, 7, 12, 50}) {
        Vec3 sum;
        for (int i = 0; i < n; ++i) {
            const Vec3 h = band_hue({i, n});
            EXPECT_GE(std::min(h.x, std::min(h.y, h.z)), -1e-12) << i << " of " << n;  // none negative
            sum += h;
        }
        EXPECT_NEAR(sum.x / n, 1.0, 1e-12) << n;
        EXPECT_NEAR(sum.y / n, 1.0, 1e-12) << n;
        EXPECT_NEAR(sum.z / n, 1.0, 1e-12) << n;
    }
    // White light is its own band.
    const Vec3 white = band_hue({});
    EXPECT_NEAR(white.x, 1.0, 1e-12);
    EXPECT_NEAR(white.y, 1.0, 1e-12);
    EXPECT_NEAR(white.z, 1.0, 1e-12);
}

TEST(Dispersion, BandHuesRunFromVioletThroughGreenToRed) {
    const Vec3 violet = band_hue({0, 7}), green = band_hue({3, 7}), red = band_hue({6, 7});
    EXPECT_GT(violet.z, violet.y);
    EXPECT_GT(violet.x, violet.y);  // the violet end has a little red in it
    EXPECT_GT(green.y, green.x);
    EXPECT_GT(green.y, green.z);
    EXPECT_GT(red.x, 3.0 * red.y);
    EXPECT_NEAR(red.z, 0.0, 1e-12);
    EXPECT_NEAR(hue_integral(kSpectrumViolet).y, 0.0, 1e-15);
    EXPECT_NEAR(hue_integral(kSpectrumRed).y, 1.0, 1e-15);
}

TEST(Dispersion, MiddleBandKeepsTheIndexAndTheEndsSpreadBySquareRoots) {
    const double ior = 1.0 / 1.5, d = 1.0 / 1.1;  // entering glass of ior 1.5, dispersion 1.1
    EXPECT_DOUBLE_EQ(dispersion_ior(ior, d, {3, 7}), ior);
    EXPECT_DOUBLE_EQ(dispersion_ior(ior, d, {}), ior);
    // Violet is bent more than red: its relative index (outside over inside) is the smaller.
    EXPECT_LT(dispersion_ior(ior, d, {0, 7}), dispersion_ior(ior, d, {6, 7}));
    // Band i of n sits at (i + ½)/n of the spectrum: the glass's index there is 1.5 · 1.1^(½ − (i + ½)/n).
    for (const int i : {0, 2, 5, 6}) {
        const double glass = 1.0 / dispersion_ior(ior, d, {i, 7});
        EXPECT_NEAR(glass, 1.5 * std::pow(1.1, 0.5 - (i + 0.5) / 7.0), 1e-12) << i;
    }
    EXPECT_NEAR(1.0 / dispersion_ior(ior, d, {0, 1000}), 1.5 * std::sqrt(1.1), 1e-3);
    EXPECT_NEAR(1.0 / dispersion_ior(ior, d, {999, 1000}), 1.5 / std::sqrt(1.1), 1e-3);
}

// A dispersive target of index 1 above a floor: each photon splits into 7 bands that pass it unbent, so the floor
// still receives the light's irradiance and colour (the band hues sum to white).
constexpr const char* kDispersiveTarget = R"(
global_settings { photons { spacing 0.015 jitter 0 gather 140, 700 } }
light_source { <0, 10, 0> color rgb <0.8, 0.6, 0.4> photons { refraction on } }
plane { y, 0 pigment { rgb 1 } }
sphere { <0, 2, 0>, 1 pigment { rgbf 1 } interior { ior 1 dispersion 1.001 } photons { target collect off } }
)";

TEST(DispersionPhotons, SplitPhotonsKeepTheLightsIrradiance) {
    const scene::Scene scene = parser::test::parse_ok(kDispersiveTarget);
    const geometry::SceneGeometry geometry(scene);
    PhotonStats stats;
    const auto map = shoot_photons(scene, geometry, stats);
    ASSERT_TRUE(map);
    EXPECT_GT(stats.stored, 5u * stats.shot / 2u);  // most photons are split in 7 at the sphere
    for (const Vec3 p : {Vec3{0.5, 0, 0.2}, Vec3{-0.3, 0, 0.6}}) {
        Gathered g;
        map->gather_adaptive(p, {0, 1, 0}, g);
        Vec3 flux;
        for (const Photon* ph : g.photons) flux += photon_colour(*ph, g.exponent_offset);
        const Vec3 density = flux / (std::numbers::pi * g.radius * g.radius);
        const double cos_theta = 10.0 / length(Vec3{0, 10, 0} - p);
        EXPECT_NEAR(density.x, 0.8 * cos_theta, 0.8 * 0.06) << p.x;
        EXPECT_NEAR(density.z / density.x, 0.5, 0.03);
    }
}

TEST(DispersionPhotons, SameMapForAnyNumberOfThreads) {
    const scene::Scene scene = parser::test::parse_ok(R"(
global_settings { photons { spacing 0.03 } }
light_source { <0, 10, 0> color rgb 1 photons { refraction on } }
plane { y, 0 pigment { rgb 1 } }
sphere { <0, 2, 0>, 1 pigment { rgbf 1 } interior { ior 1.5 dispersion 1.2 dispersion_samples 5 }
         photons { target } }
)");
    test::expect_same_map_for_one_and_two_threads(scene);
}

}  // namespace
}  // namespace wardray::photons
