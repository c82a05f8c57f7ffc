// Participating media against closed forms: transmittance and in-scattering of a homogeneous medium with isotropic
// scattering, emission, the chi-square thresholds of methods 1 and 2, and the media block as parsed.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "media/media_density.h"
#include "media/participating_media.h"
#include "texture/pigment.h"
#include "parser/parse.h"

namespace wardray::media {
namespace {

// Light of a fixed colour arriving everywhere from +y: what a point light far above an open medium delivers.
class ConstantLight final : public LightQuery {
public:
    explicit ConstantLight(const Vec3& c) : m_colour(c) {}
    Vec3 arriving(std::size_t, const Vec3&, Vec3& to_light) const override {
        to_light = {0.0, 1.0, 0.0};
        ++calls;
        return m_colour;
    }
    mutable int calls = 0;

private:
    Vec3 m_colour;
};

scene::Scene scene_with(const scene::Media& m) {
    scene::Scene s;
    s.media.push_back(m);
    scene::Light light;
    light.position = {0.0, 1e6, 0.0};
    s.lights.push_back(light);
    return s;
}

const Segment kRay{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 4.0};

TEST(ParticipatingMedia, HomogeneousAbsorptionTransmitsExpOfMinusSigmaTimesLength) {
    scene::Media m;
    m.absorption = {0.1, 0.2, 0.4};
    const scene::Scene s = scene_with(m);
    const ParticipatingMedia media(s);
    const Vec3 t = media.transmittance(media.atmosphere(), kRay);
    EXPECT_NEAR(t.x, std::exp(-0.4), 1e-12);
    EXPECT_NEAR(t.y, std::exp(-0.8), 1e-12);
    EXPECT_NEAR(t.z, std::exp(-1.6), 1e-12);
}

TEST(ParticipatingMedia, ExtinctionScalesHowMuchScatteringDims) {
    scene::Media m;
    m.scattering = {0.5, 0.5, 0.5};
    m.extinction = 0.25;
    const scene::Scene s = scene_with(m);
    const ParticipatingMedia media(s);
    EXPECT_NEAR(media.transmittance(media.atmosphere(), kRay).x, std::exp(-0.5 * 0.25 * 4.0), 1e-12);
}

// The single-scattering integral of a homogeneous medium lit by a constant light L with isotropic phase (POV-Ray's
// normalisation: phase 1), over a segment of length d ending at a surface of radiance C:
// C·exp(−σt d) + σs·L/σt·(1 − exp(−σt d)).
double single_scattering(double sigma_s, double sigma_t, double light, double behind, double d) {
    const double t = std::exp(-sigma_t * d);
    return behind * t + sigma_s * light / sigma_t * (1.0 - t);
}

TEST(ParticipatingMedia, IsotropicScatteringConvergesToTheSingleScatteringIntegral) {
    for (int method : {2, 3}) {
        scene::Media m;
        m.method = method;
        m.scattering = {0.3, 0.3, 0.3};
        m.absorption = {0.2, 0.2, 0.2};
        m.intervals = 400;
        m.min_samples = m.max_samples = 3;
        const scene::Scene s = scene_with(m);
        const ParticipatingMedia media(s);
        const ConstantLight light({2.0, 2.0, 2.0});
        const Vec3 c = media.along(media.atmosphere(), kRay, {0.5, 0.5, 0.5}, light);
        const double expected = single_scattering(0.3, 0.5, 2.0, 0.5, 4.0);
        EXPECT_NEAR(c.x, expected, 0.005 * expected) << "method " << method;
        EXPECT_GT(light.calls, 400);
    }
}

TEST(ParticipatingMedia, EmissionAloneAddsEmissionTimesLengthAndLightsAreNotAsked) {
    scene::Media m;
    m.emission = {0.25, 0.5, 1.0};
    const scene::Scene s = scene_with(m);
    const ParticipatingMedia media(s);
    const ConstantLight light({1.0, 1.0, 1.0});
    const Vec3 c = media.along(media.atmosphere(), kRay, {0.1, 0.1, 0.1}, light);
    EXPECT_NEAR(c.x, 0.1 + 0.25 * 4.0, 1e-12);
    EXPECT_NEAR(c.z, 0.1 + 1.0 * 4.0, 1e-12);
    EXPECT_EQ(light.calls, 0);
    // Without extinction a shadow ray passes unchanged.
    EXPECT_EQ(media.transmittance(media.atmosphere(), kRay), (Vec3{1.0, 1.0, 1.0}));
}

TEST(ParticipatingMedia, ADensityScalesTheMediumWhereItIsEvaluated) {
    // A density of 0.5 everywhere halves the optical depth.
    scene::Media m;
    m.absorption = {1.0, 1.0, 1.0};
    scene::Pigment half;
    half.color = {0.5, 0.5, 0.5};
    m.densities.push_back(half);
    m.densities.push_back(half);  // several densities multiply
    const scene::Scene s = scene_with(m);
    const ParticipatingMedia media(s);
    EXPECT_NEAR(media.transmittance(media.atmosphere(), kRay).x, std::exp(-0.25 * 4.0), 1e-12);
}

TEST(ParticipatingMedia, OnlyASceneWithMediaHasAny) {
    scene::Scene s;
    EXPECT_FALSE(ParticipatingMedia::in_scene(s));
    scene::Object o;
    o.interior.media.emplace_back();
    s.objects.push_back(o);
    EXPECT_TRUE(ParticipatingMedia::in_scene(s));
}

// What a medium lit by one spot or cylinder light scatters along `ray` with the whole scene scaled by `scale`:
// positions, lengths and the cylinder's falloff times scale, the scattering coefficient divided by it.
Vec3 scattered_at_scale(scene::Light::Type type, Segment ray, double scale) {
    scene::Media m;
    m.method = 3;
    m.jitter = 0.0;
    m.scattering = {0.3 / scale, 0.3 / scale, 0.3 / scale};
    scene::Scene s = scene_with(m);
    scene::Light& light = s.lights.front();
    light.type = type;
    light.position = Vec3{0.0, 10.0, 0.0} * scale;
    light.point_at = {0.0, 0.0, 0.0};
    if (type == scene::Light::Type::Cylinder) {
        light.radius = 1.0 * scale;
        light.falloff = 1.82 * scale;
    } else {
        light.radius = 15.0;
        light.falloff = 20.0;  // degrees: 1.82 from the axis at y = 5
    }
    ray.origin = ray.origin * scale;
    ray.length *= scale;
    const ParticipatingMedia media(s);
    const ConstantLight lit({2.0, 2.0, 2.0});
    return media.along(media.atmosphere(), ray, {0.5, 0.5, 0.5}, lit);
}

TEST(ParticipatingMedia, ASpotlightsConeScattersTheSameAtAnyScale) {
    // A segment inside the cone, shorter than POV-Ray's SMALL_TOLERANCE (0.001) once scaled by 1e-4: the cone is
    // dropped there if the tolerance is absolute.
    const Segment inside{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.0};
    const Vec3 unit = scattered_at_scale(scene::Light::Type::Spot, inside, 1.0);
    ASSERT_GT(unit.x, 0.6);  // more than the 0.5·exp(−0.3) behind: the cone lights it
    for (double scale : {1e-4, 1e4})
        EXPECT_NEAR(scattered_at_scale(scene::Light::Type::Spot, inside, scale).x, unit.x, 1e-9 * unit.x) << scale;
}

TEST(ParticipatingMedia, ARayGrazingALightsBeamScattersTheSameAtAnyScale) {
    // A ray to the sky grazing the beam 0.08 inside its edge: the discriminant (0.08² at unit size, a squared
    // length) falls below EPSILON at 1e-4 if compared with it as it is, and the ray counts as lit to MAX_DISTANCE.
    const Segment grazing{{-20.0, 5.0, std::sqrt(1.82 * 1.82 - 0.08 * 0.08)}, {1.0, 0.0, 0.0}, HUGE_VAL};
    for (scene::Light::Type type : {scene::Light::Type::Spot, scene::Light::Type::Cylinder}) {
        const Vec3 unit = scattered_at_scale(type, grazing, 1.0);
        ASSERT_GT(unit.x, 0.0);
        for (double scale : {1e-4, 1e4})
            EXPECT_NEAR(scattered_at_scale(type, grazing, scale).x, unit.x, 1e-6 * unit.x) << scale;
    }
}

TEST(ChiSquare, InverseTailMatchesTabulatedQuantiles) {
    // Upper-tail quantiles of the chi-square distribution (standard tables).
    EXPECT_NEAR(inverse_chi_square_tail(1.0, 0.95), 0.00393214, 1e-7);
    EXPECT_NEAR(inverse_chi_square_tail(2.0, 0.9), 0.210721, 1e-6);
    EXPECT_NEAR(inverse_chi_square_tail(10.0, 0.05), 18.307, 1e-3);
    EXPECT_NEAR(inverse_chi_square_tail(100.0, 0.9), 82.3581, 1e-3);
}

TEST(MediaBlock, ParsesWithPovRaysDefaultsAndItsItems) {
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(
        "#version 3.7;\n"
        "#declare D = density { spherical }\n"
        "#declare M = media { emission 0.5 }\n"
        "media { M scattering { 5, rgb 0.1 eccentricity 0.3 extinction 0.5 } }\n"
        "sphere { 0, 1 hollow interior { media { method 2 intervals 4 samples 2, 8 density { D } density { rgb 0.5 } }"
        " media { absorption 1 } } translate x }\n",
        "media.pov", options);
    ASSERT_TRUE(r.ok());
    const scene::Scene& s = *r.scene;
    ASSERT_EQ(s.media.size(), 1u);
    const scene::Media& a = s.media[0];
    EXPECT_EQ(a.method, 3);
    EXPECT_EQ(a.intervals, 1);
    EXPECT_EQ(a.min_samples, 10);
    EXPECT_EQ(a.emission.r, 0.5);
    EXPECT_EQ(a.scattering_type, 5);
    EXPECT_EQ(a.eccentricity, 0.3);
    EXPECT_EQ(a.extinction, 0.5);
    ASSERT_EQ(s.objects.size(), 1u);
    const scene::Interior& in = s.objects[0].interior;
    EXPECT_TRUE(in.hollow);
    ASSERT_EQ(in.media.size(), 2u);
    EXPECT_EQ(in.media[0].method, 2);
    EXPECT_EQ(in.media[0].max_samples, 8);
    ASSERT_EQ(in.media[0].densities.size(), 2u);
    // The object's translate moved the densities with it.
    EXPECT_FALSE(in.media[0].densities[1].pattern.transform.is_identity());
}

TEST(MediaBlock, BadValuesAreErrorsAtTheirItem) {
    parser::ParseOptions options;
    for (const char* bad : {"media { method 4 }", "media { intervals 0 }", "media { samples 3, 2 }",
                            "media { scattering { 1, rgb 1 eccentricity 0.5 } }", "media { aa_level 0 }"}) {
        const parser::ParseResult r = parser::parse_string(bad, "bad.pov", options);
        EXPECT_FALSE(r.ok()) << bad;
    }
}

// A photon's ray through a medium leaves one photon every step · factor (POV-Ray's DepositMediaPhotons), evenly
// spread with jitter 0; past max_steps it leaves max_steps, each standing for a longer stretch.
TEST(MediaPhotonDeposit, OnePhotonPerStepUpToMaxSteps) {
    scene::Media m;
    m.scattering = {0.3, 0.3, 0.3};
    m.extinction = 0.0;
    m.absorption = {0.1, 0.0, 0.0};
    const scene::Scene s = scene_with(m);
    const ParticipatingMedia media(s);
    PhotonDeposit d;
    d.step = 0.1;
    d.factor = 2.0;
    d.max_steps = 100;
    d.jitter = 0.0;
    std::vector<DepositPoint> out;
    const Vec3 c = media.deposit_photons(media.atmosphere(), kRay, {1.0, 1.0, 1.0}, d, out);
    ASSERT_EQ(out.size(), 20u);  // 4 / (0.1 · 2)
    for (std::size_t i = 0; i < out.size(); ++i) {
        EXPECT_NEAR(out[i].t, (i + 0.5) * 0.2, 1e-12);
        EXPECT_EQ(out[i].factor, 2.0);
    }
    // The photon leaves dimmed by the absorption along the way.
    EXPECT_NEAR(c.x, std::exp(-0.4), 1e-12);
    EXPECT_NEAR(c.y, 1.0, 1e-12);
    out.clear();
    d.max_steps = 8;
    media.deposit_photons(media.atmosphere(), kRay, {1.0, 1.0, 1.0}, d, out);
    ASSERT_EQ(out.size(), 8u);
    EXPECT_NEAR(out[0].factor, 4.0 / (0.1 * 8), 1e-12);
    EXPECT_NEAR(out[7].t, 7.5 * 0.5, 1e-12);
}

// POV-Ray compat: a stretch shorter than one step keeps no photon and makes the photon's colour NaN (0/0 optical
// depth), so everything it stores later is black; a medium without extinction keeps nothing and dims nothing.
TEST(MediaPhotonDeposit, TooShortAStretchKillsThePhoton) {
    scene::Media m;
    m.scattering = {0.3, 0.3, 0.3};
    const scene::Scene s = scene_with(m);
    const ParticipatingMedia media(s);
    PhotonDeposit d;
    d.step = 0.1;
    d.max_steps = 100;
    std::vector<DepositPoint> out;
    const Vec3 c = media.deposit_photons(media.atmosphere(), Segment{{}, {0.0, 0.0, 1.0}, 0.05}, {1, 1, 1}, d, out);
    EXPECT_TRUE(out.empty());
    EXPECT_TRUE(std::isnan(c.x));
    scene::Media clear;
    clear.emission = {0.5, 0.5, 0.5};
    const scene::Scene s2 = scene_with(clear);
    const ParticipatingMedia none(s2);
    const Vec3 c2 = none.deposit_photons(none.atmosphere(), kRay, {1, 1, 1}, d, out);
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(c2, (Vec3{1, 1, 1}));
}

// Photons in the medium light it like a light would (POV-Ray's ComputeMediaPhotons): photons of flux density F
// (flux per volume) stand for a light of F arriving from their direction; here a uniform cloud of them, all from +y.
class UniformPhotons final : public MediaPhotons {
public:
    double gather(const Vec3&, std::vector<Sample>& out) const override {
        // 100 photons of flux 0.01 within radius 1: flux density 1 / (4/3 π).
        out.assign(100, Sample{{0.01, 0.01, 0.01}, {0.0, 1.0, 0.0}});
        return 1.0;
    }
};

class PhotonsOnly final : public LightQuery {
public:
    Vec3 arriving(std::size_t, const Vec3&, Vec3& to_light) const override {
        to_light = {0.0, 1.0, 0.0};
        return {};
    }
    const MediaPhotons* photons() const override { return &m_photons; }

private:
    UniformPhotons m_photons;
};

TEST(MediaPhotonGather, PhotonsScatterLikeALightOfTheirFluxDensity) {
    scene::Media m;
    m.scattering = {0.2, 0.2, 0.2};
    m.extinction = 0.0;
    m.method = 2;
    m.min_samples = m.max_samples = 4;
    const scene::Scene s = scene_with(m);
    const ParticipatingMedia media(s);
    const double light = 1.0 / (4.0 / 3.0 * std::numbers::pi);
    const Vec3 c = media.along(media.atmosphere(), kRay, {}, PhotonsOnly{});
    EXPECT_NEAR(c.x, 0.2 * light * 4.0, 1e-9);
}


TEST(MediaDensity, IsTheProductInOrderAndBlackWhereACheapDensityIsBlack) {
    // Crackle first, then a spherical fall-off that is black beyond radius 1: inside, the product in the blocks'
    // order, bit for bit; outside, black without the crackle mattering.
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(
        "#version 3.7;\n"
        "media { emission 1 density { crackle scale 0.5 color_map { [0 rgb 0.2] [1 rgb <1, 0.5, 0.25>] } }"
        " density { spherical color_map { [0 rgb 0] [1 rgb 1] } } density { rgb <1, 0.5, 2> } }\n",
        "density.pov", options);
    ASSERT_TRUE(r.ok());
    const scene::Media& m = r.scene->media.at(0);
    ASSERT_EQ(m.densities.size(), 3u);
    for (const Vec3 p : {Vec3{0.1, 0.2, 0.3}, Vec3{-0.4, 0.5, 0.1}, Vec3{0.9, 0.0, 0.2}, Vec3{2.0, 1.0, 0.0}}) {
        Vec3 expected{1.0, 1.0, 1.0};
        for (const scene::Pigment& d : m.densities) expected = expected * texture::evaluate_pigment(d, p, 2).rgb();
        const Vec3 got = media_density(m, p, 2);
        EXPECT_EQ(got, expected) << p.x << " " << p.y << " " << p.z;
    }
    EXPECT_EQ(media_density(m, {2.0, 1.0, 0.0}, 2), Vec3{});
    scene::Media none;
    EXPECT_EQ(media_density(none, {0.3, 0.3, 0.3}, 2), (Vec3{1.0, 1.0, 1.0}));
}

}  // namespace
}  // namespace wardray::media
