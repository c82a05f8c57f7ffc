// The photon pass on small scenes: the flux photons carry through a clear target equals the light they replace,
// the parser's photon blocks, and the same photons for any number of threads.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cstring>
#include <numbers>
#include <string>

#include "../parser/test_util.h"
#include "geometry/scene_geometry.h"
#include "photons/photon_map.h"
#include "photons/photon_shooter.h"
#include "same_map.h"

namespace wardray::photons {
namespace {

// A clear target of index 1 above a floor, the light straight above: photons pass it unbent and land with the
// light's irradiance, POV-Ray's I·cos θ (its lights do not fall off with distance).
constexpr const char* kClearTarget = R"(
global_settings { photons { spacing 0.01 jitter 0 } }
light_source { <0, 10, 0> color rgb <0.8, 0.6, 0.4> photons { refraction on } }
plane { y, 0 pigment { rgb 1 } }
sphere { <0, 2, 0>, 1 pigment { rgbf 1 } interior { ior 1 } photons { target collect off } }
)";

// The photons' flux per unit area on the floor (normal +y) at p, from an adaptive gather.
Vec3 flux_density(const PhotonMap& map, const Vec3& p) {
    Gathered g;
    map.gather_adaptive(p, {0, 1, 0}, g);
    Vec3 flux;
    for (const Photon* ph : g.photons) flux += photon_colour(*ph, g.exponent_offset);
    return flux / (std::numbers::pi * g.radius * g.radius);
}

TEST(PhotonPass, ClearTargetPassesTheLightsIrradiance) {
    const scene::Scene scene = parser::test::parse_ok(kClearTarget);
    ASSERT_TRUE(scene.global.photons);
    const geometry::SceneGeometry geometry(scene);
    PhotonStats stats;
    const auto map = shoot_photons(scene, geometry, stats);
    ASSERT_TRUE(map);
    EXPECT_EQ(stats.units, 1u);
    EXPECT_GT(stats.stored, 10000u);
    // Away from the point under the light, where POV-Ray's polar rows of photons bias any k-nearest estimate.
    for (const Vec3 p : {Vec3{0.5, 0, 0.2}, Vec3{-0.3, 0, 0.6}, Vec3{0.7, 0, -0.5}}) {
        const Vec3 density = flux_density(*map, p);
        const double cos_theta = 10.0 / length(Vec3{0, 10, 0} - p);
        EXPECT_NEAR(density.x, 0.8 * cos_theta, 0.8 * 0.05) << p.x;
        EXPECT_NEAR(density.z / density.x, 0.5, 0.02);
    }
}

// POV-Ray compat (its photons.cpp defines PT_FILTER_BEFORE_TARGET): a pass_through object between the light and the
// target lets photons through unbent but filtered by its pigment at each face, so a filtering slab tints the caustic.
TEST(PhotonPass, PassThroughObjectBeforeTheTargetFiltersThePhotons) {
    const scene::Scene scene = parser::test::parse_ok(std::string(kClearTarget) + R"(
box { <-4, 5, -4>, <4, 5.1, 4> pigment { rgbf <1, 0.5, 0.25, 1> } photons { pass_through } }
)");
    const geometry::SceneGeometry geometry(scene);
    PhotonStats stats;
    const auto map = shoot_photons(scene, geometry, stats);
    ASSERT_TRUE(map);
    EXPECT_GT(stats.stored, 10000u);
    for (const Vec3 p : {Vec3{0.5, 0, 0.2}, Vec3{-0.3, 0, 0.6}}) {
        const Vec3 density = flux_density(*map, p);
        const double cos_theta = 10.0 / length(Vec3{0, 10, 0} - p);
        EXPECT_NEAR(density.x, 0.8 * cos_theta, 0.8 * 0.05) << p.x;  // the red the slab lets through whole
        // Filtered at each of the slab's two faces, as a camera ray through it is: green by 0.5², blue by 0.25².
        EXPECT_NEAR(density.y / density.x, 0.6 / 0.8 * 0.25, 0.01);
        EXPECT_NEAR(density.z / density.x, 0.4 / 0.8 * 0.0625, 0.005);
    }
}

TEST(PhotonPass, SameMapForAnyNumberOfThreads) {
    const scene::Scene scene = parser::test::parse_ok(kClearTarget);
    test::expect_same_map_for_one_and_two_threads(scene);
}

TEST(PhotonPass, NoTargetNoPhotons) {
    const scene::Scene scene = parser::test::parse_ok(R"(
global_settings { photons { spacing 0.01 } }
light_source { <0, 10, 0> color rgb 1 }
plane { y, 0 pigment { rgb 1 } }
sphere { <0, 2, 0>, 1 pigment { rgbf 1 } interior { ior 1.5 } }
)");
    const geometry::SceneGeometry geometry(scene);
    PhotonStats stats;
    EXPECT_FALSE(shoot_photons(scene, geometry, stats));
    EXPECT_EQ(stats.units, 0u);
}

// POV-Ray compat: a target without bounds (an intersection of planes at angles) is aimed at as POV-Ray's largest
// box, 1e10 to each side, so the light inside its sphere shoots all round at the coarse spacing `count` gives. POV-Ray
// 3.7 shoots 5 photons here and stores 2 (its statistics, jitter 0); their flux is far beyond its byte's 2^5.
TEST(PhotonPass, TargetWithoutBoundsIsAimedAtPovRaysLargestBox) {
    const scene::Scene scene = parser::test::parse_ok(R"(
global_settings { photons { count 20000 autostop 0 jitter 0 } }
light_source { <3, 5, -4> color rgb 1 }
plane { y, -1.5 pigment { rgb 1 } }
intersection {
  plane { <1, 1, 1>, 0.8 } plane { <-1, -1, 1>, 0.8 } plane { <1, -1, -1>, 0.8 } plane { <-1, 1, -1>, 0.8 }
  pigment { rgbt <0.8, 0.8, 0.8, 0.4> }
  photons { target refraction on reflection on collect on }
}
)");
    const geometry::SceneGeometry geometry(scene);
    PhotonStats stats;
    const ShotPhotons shot = shoot_photon_sets(scene, geometry, stats);
    EXPECT_EQ(stats.units, 1u);
    EXPECT_EQ(stats.shot, 5u);
    ASSERT_EQ(shot.surface.size(), 2u);
    for (const Photon& p : shot.surface) EXPECT_TRUE(beyond_povray_flux(p, shot.surface_offset));
}

TEST(PhotonPass, FluxWithinPovRaysByteIsNotBeyondIt) {
    const scene::Scene scene = parser::test::parse_ok(kClearTarget);
    const geometry::SceneGeometry geometry(scene);
    PhotonStats stats;
    const ShotPhotons shot = shoot_photon_sets(scene, geometry, stats);
    ASSERT_FALSE(shot.surface.empty());
    for (const Photon& p : shot.surface) EXPECT_FALSE(beyond_povray_flux(p, shot.surface_offset));
    // POV-Ray's byte wraps round past 2^5: a flux of 100 (0.78 · 2^7) comes back as 0.78 · 2^-249, black.
    const Photon wrapped = make_photon({}, {100.0, 20.0, 10.0}, {0, 1, 0});
    EXPECT_FALSE(beyond_povray_flux(wrapped, 0));
    EXPECT_EQ(wrapped.rgbe[3], 1);
    EXPECT_EQ(photon_colour(wrapped).x, 0.0);
    EXPECT_TRUE(beyond_povray_flux(make_photon({}, {40.0, 1.0, 1.0}, {0, 1, 0}, 3), 3));
    EXPECT_FALSE(beyond_povray_flux(make_photon({}, {31.0, 1.0, 1.0}, {0, 1, 0}, 3), 3));
}

// A clear hollow box of scattering medium under the light (a photon target, so every photon crosses it). POV-Ray
// compat: a photon kept at distance D from the light carries the flux of a stretch spaced for the distance D0 at
// which its ray entered the medium, so the photons' fluence is the light's I times D / D0 (POV-Ray's lights do not
// fall off), whether max_steps caps their count or not; an absorbing medium dims the photons on the floor below.
std::string medium_box(const char* media, const char* medium) {
    return std::string("global_settings { photons { spacing 0.03 jitter 0 gather 20, 400 ") + media + R"( } }
light_source { <0, 10, 0> color rgb <0.8, 0.6, 0.4> photons { refraction on } }
plane { y, 0 pigment { rgb 1 } }
box { <-1, 1, -1>, <1, 3, 1> hollow pigment { rgbf 1 }
  interior { media { )" + medium + R"( } } photons { target } }
)";
}

Vec3 media_fluence(const PhotonMap& map, const Vec3& p) {
    const MediaPhotonGather gather(map);
    std::vector<media::MediaPhotons::Sample> found;
    const double r = gather.gather(p, found);
    Vec3 flux;
    for (const auto& ph : found) {
        flux += ph.colour;
        EXPECT_GT(ph.to_origin.y, 0.9);  // towards the light above
    }
    return flux / (4.0 / 3.0 * std::numbers::pi * r * r * r);
}

TEST(MediaPhotons, KeptPhotonsCarryTheLightsFluence) {
    for (const char* media : {"media 400", "media 60"}) {
        const scene::Scene scene = parser::test::parse_ok(medium_box(media, "scattering { 1, rgb 0.5 extinction 0 }"));
        const geometry::SceneGeometry geometry(scene);
        PhotonStats stats;
        std::unique_ptr<const PhotonMap> media_map;
        shoot_photons(scene, geometry, stats, &media_map);
        ASSERT_TRUE(media_map) << media;
        EXPECT_EQ(stats.media_stored, media_map->size());
        EXPECT_GT(stats.media_stored, 100000u);
        for (const Vec3 p : {Vec3{0.3, 2.0, 0.2}, Vec3{-0.4, 1.6, 0.3}, Vec3{0.2, 2.5, -0.4}}) {
            const Vec3 f = media_fluence(*media_map, p);
            const double expected = 0.8 * (10.0 - p.y) / 7.0;  // D / D0 along the ray from the light to p
            EXPECT_NEAR(f.x, expected, expected * 0.08) << media << " at " << p.y;
            EXPECT_NEAR(f.z / f.x, 0.5, 0.02);
        }
    }
}

TEST(MediaPhotons, AbsorbingMediumDimsThePhotonsBeyond) {
    // Absorption 0.5 over the box's height 2: the floor's photons carry exp(−1/cos θ) of the light, with or without
    // photons kept in the medium (an absorbing medium keeps none: it scatters nothing).
    for (const char* media : {"media 100", ""}) {
        const scene::Scene scene = parser::test::parse_ok(medium_box(media, "absorption 0.5"));
        const geometry::SceneGeometry geometry(scene);
        PhotonStats stats;
        std::unique_ptr<const PhotonMap> media_map;
        const auto map = shoot_photons(scene, geometry, stats, &media_map);
        ASSERT_TRUE(map);
        EXPECT_FALSE(media_map);
        Gathered g;
        map->gather_adaptive(Vec3{0.3, 0.0, -0.2}, {0, 1, 0}, g);
        Vec3 flux;
        for (const Photon* ph : g.photons) flux += photon_colour(*ph, g.exponent_offset);
        const double cos_theta = 10.0 / length(Vec3{0.3, -10.0, -0.2});
        const double expected = 0.8 * cos_theta * std::exp(-0.5 * 2.0 / cos_theta);
        EXPECT_NEAR(flux.x / (std::numbers::pi * g.radius * g.radius), expected, expected * 0.03) << media;
    }
}

TEST(MediaPhotons, SameMediaMapForAnyNumberOfThreads) {
    const scene::Scene scene = parser::test::parse_ok(medium_box("media 50", "scattering { 1, rgb 0.5 }"));
    const geometry::SceneGeometry geometry(scene);
    auto shoot = [&](int threads) {
        PhotonStats stats;
        std::unique_ptr<const PhotonMap> media_map;
        tbb::task_arena(threads).execute([&] { shoot_photons(scene, geometry, stats, &media_map); });
        return media_map;
    };
    const auto one = shoot(1);
    const auto two = shoot(2);
    ASSERT_TRUE(one && two);
    ASSERT_EQ(one->size(), two->size());
    EXPECT_EQ(one->min_gather_radius(), two->min_gather_radius());
    EXPECT_EQ(std::memcmp(one->photons().data(), two->photons().data(), one->size() * sizeof(Photon)), 0);
}

TEST(PhotonBlocks, ReadAsPovRayReadsThem) {
    const scene::Scene s = parser::test::parse_ok(R"(
global_settings { photons { count 20000 gather 10, 50 media 100, 2 jitter 0.2 max_trace_level 7 adc_bailout 0.02
                            expand_thresholds 0.3, 25 radius 0.5, 2 autostop 0.3 } }
light_source { <0, 10, 0> color rgb 1 photons { refraction on reflection off area_light } }
union {
  sphere { 0, 1 photons { reflection on collect off } }
  sphere { x, 1 }
  photons { target 0.5 refraction on pass_through }
}
)");
    ASSERT_TRUE(s.global.photons);
    const scene::PhotonSettings& p = *s.global.photons;
    EXPECT_EQ(p.count, 20000);
    EXPECT_EQ(p.gather_min, 10);
    EXPECT_EQ(p.gather_max, 50);
    EXPECT_EQ(p.media_steps, 100);
    EXPECT_EQ(p.media_factor, 2.0);
    EXPECT_EQ(p.max_trace_level, 7);
    EXPECT_EQ(p.expand_min, 25);
    EXPECT_EQ(p.radius, 0.5);
    EXPECT_EQ(p.radius_multiplier, 2.0);
    EXPECT_EQ(p.autostop, 0.3);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].photon_refraction, scene::PhotonSwitch::On);
    EXPECT_EQ(s.lights[0].photon_reflection, scene::PhotonSwitch::Off);
    EXPECT_TRUE(s.lights[0].photon_area_light);
    // A union of plain shapes is split into its parts, each keeping its own flags but those the union sets.
    ASSERT_EQ(s.objects.size(), 2u);
    // CheckPassThru: pass_through given after target and refraction on turns refraction off, with its warning.
    const scene::ObjectPhotons& u = s.objects[0].photons;
    EXPECT_TRUE(u.target);
    EXPECT_EQ(u.spacing_multiplier, 0.5);
    EXPECT_TRUE(u.pass_through);
    EXPECT_EQ(u.refraction, scene::PhotonSwitch::Off);
    // The union's set flags override its children's; what it leaves unset the children keep.
    const scene::Object* kids = s.objects.data();
    EXPECT_TRUE(kids[0].photons.target);
    EXPECT_EQ(kids[0].photons.reflection, scene::PhotonSwitch::On);
    EXPECT_FALSE(kids[0].photons.collect);
    EXPECT_EQ(kids[1].photons.refraction, scene::PhotonSwitch::Off);
    EXPECT_TRUE(kids[1].photons.pass_through);
    bool warned = false;
    for (const Diagnostic& d : s.warnings) warned = warned || d.message.find("Turning off refraction") != std::string::npos;
    EXPECT_TRUE(warned);
    // `gather` with a maximum of 0 turns photons off.
    EXPECT_FALSE(parser::test::parse_ok("global_settings { photons { gather 0, 0 } }").global.photons);
}

}  // namespace
}  // namespace wardray::photons
