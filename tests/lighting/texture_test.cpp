// Textures against POV-Ray 3.7: noise and pattern values printed by POV-Ray itself (f_noise3d, eval_pigment),
// map lookup rules, texture transforms, and reflection/transparency against analytic answers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"
#include "texture/noise.h"
#include "texture/pattern.h"
#include "texture/pigment.h"
#include "parser/parse.h"

namespace wardray::lighting {
namespace {

scene::Scene parse(const std::string& text) {
    parser::ParseOptions options;
    const parser::ParseResult r =
        parser::parse_string("global_settings { assumed_gamma 1 }\n" + text, "test.pov", options);
    EXPECT_TRUE(r.ok());
    for (const auto& d : r.diagnostics) ADD_FAILURE() << d.message;
    return r.scene.value_or(scene::Scene{});
}

// A pigment mapping the raw pattern value onto grey levels 0..1.
scene::Pigment grey_ramp(scene::Pattern::Type type) {
    scene::Pigment p;
    p.pattern.type = type;
    p.color_map = {{0.0, {0, 0, 0}}, {1.0, {1, 1, 1}}};
    return p;
}

TEST(Noise, MatchesPovRaysNoiseFunction) {
    // POV-Ray 3.7.0.10: #debug str(f_noise3d(x, y, z), 0, 12), noise_generator 2 (the default).
    struct Sample {
        Vec3 p;
        double expected;
    };
    const Sample samples[] = {{{0.3, 0.7, 1.1}, 0.689585217264},   {{-2.25, 5.5, 0.125}, 0.408067910158},
                              {{10.5, -3.75, 7.2}, 0.669307813391}, {{0.01, 0.02, 0.03}, 0.307115252171},
                              {{123.4, -56.7, 8.9}, 0.320953256784}, {{-0.5, -0.5, -0.5}, 0.560727982465}};
    for (const Sample& s : samples) EXPECT_NEAR(texture::noise(s.p, 2), s.expected, 1e-11) << s.p.x;
}

TEST(Noise, VturbulenceMatchesPovRay) {
    // POV-Ray 3.7.0.10: #debug vstr(3, vturbulence(Lambda, Omega, Octaves, V), ",", 0, 12), through the parser
    // with the lighting layer's turbulence plugged in as the CLI does (octaves 2.7 truncate to 2, 20 clamp to 10).
    parser::ParseOptions options;
    options.vector_turbulence = [](const Vec3& p, int octaves, double omega, double lambda) {
        return texture::dturbulence(p, texture::TurbulenceParams{octaves, omega, lambda});
    };
    const parser::ParseResult r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\n"
        "sphere { vturbulence(2, 0.5, 6, <0.3, 0.7, 1.1>), 1 }\n"
        "sphere { vturbulence(3, 0.25, 2.7, <-1.25, 2.5, 0.125>), 1 }\n"
        "sphere { vturbulence(2, 0.5, 20, <10.5, -3.25, 7>), 1 }\n",
        "test.pov", options);
    ASSERT_TRUE(r.ok());
    const Vec3 expected[] = {{0.344564479963, -0.261186792178, -0.078804351206},
                             {0.174196423096, -0.134849620652, 0.177083016186},
                             {0.104562092773, -0.022230415234, -0.312172768945}};
    ASSERT_EQ(r.scene->objects.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        const Vec3 c = std::get<scene::Sphere>(r.scene->objects[i].shape).center;
        EXPECT_NEAR(c.x, expected[i].x, 1e-11) << i;
        EXPECT_NEAR(c.y, expected[i].y, 1e-11) << i;
        EXPECT_NEAR(c.z, expected[i].z, 1e-11) << i;
    }
}

TEST(Patterns, MatchPovRaysEvalPigment) {
    // POV-Ray 3.7.0.10: eval_pigment(pigment { P color_map { [0 rgb 0] [1 rgb 1] } }, point).red (float colours).
    using T = scene::Pattern::Type;
    const Vec3 points[] = {{0.3, 0.7, 1.1}, {-2.25, 5.5, 0.125}, {10.5, -3.75, 7.2}, {-0.5, -0.5, -0.5}};
    struct Row {
        T type;
        double expected[4];
    };
    const Row rows[] = {
        {T::Granite, {0.244587064, 0.374362886, 0.693381965, 0.275481880}},
        {T::Crackle, {0.124382854, 0.051822271, 0.070177607, 0.572031081}},
        {T::Wrinkles, {0.696829081, 0.336533368, 0.650689900, 0.659337223}},
        {T::Cells, {0.992742598, 0.502220988, 0.834779084, 0.206389710}},
        {T::Marble, {0.536339879, 0.407481164, 0.841214001, 0.817570210}},
        {T::Waves, {0.602790296, 0.399426669, 0.608640313, 0.737113416}},
    };
    for (const Row& row : rows) {
        scene::Pigment pig = grey_ramp(row.type);
        if (row.type == T::Marble) {
            pig.pattern.params->wave = scene::WaveType::Triangle;
            pig.pattern.params->turbulence = scene::Turbulence{{0.7, 0.7, 0.7}};
        }
        for (int i = 0; i < 4; ++i)
            EXPECT_NEAR(texture::evaluate_pigment(pig, points[i], 2).r, row.expected[i], 2e-6)
                << static_cast<int>(row.type) << " at point " << i;
    }
}

TEST(Patterns, MapLookupFollowsPovRaysRules) {
    scene::Pigment p = grey_ramp(scene::Pattern::Type::Gradient);
    p.color_map = {{0.2, {1, 0, 0}}, {0.5, {0, 1, 0}}, {0.5, {0, 0, 1}}, {0.8, {1, 1, 1}}};
    // Below the first entry: the first colour; above the last: the last; a repeated value is a sharp edge.
    EXPECT_DOUBLE_EQ(texture::evaluate_pigment(p, {0.1, 0, 0}, 2).r, 1.0);
    EXPECT_DOUBLE_EQ(texture::evaluate_pigment(p, {0.9, 0, 0}, 2).g, 1.0);
    EXPECT_NEAR(texture::evaluate_pigment(p, {0.35, 0, 0}, 2).r, 0.5, 1e-6);
    EXPECT_NEAR(texture::evaluate_pigment(p, {0.35, 0, 0}, 2).g, 0.5, 1e-6);
    EXPECT_NEAR(texture::evaluate_pigment(p, {0.65, 0, 0}, 2).b, 1.0, 1e-6);
    EXPECT_NEAR(texture::evaluate_pigment(p, {0.65, 0, 0}, 2).r, 0.5, 1e-6);
}

TEST(Patterns, WaveTypesShapeTheValue) {
    scene::Pattern pat;
    pat.type = scene::Pattern::Type::Gradient;
    pat.params->wave = scene::WaveType::Triangle;
    EXPECT_NEAR(texture::pattern_value(pat, {0.25, 0, 0}, 2), 0.5, 1e-12);
    EXPECT_NEAR(texture::pattern_value(pat, {0.75, 0, 0}, 2), 0.5, 1e-12);
    pat.params->wave = scene::WaveType::Sine;
    EXPECT_NEAR(texture::pattern_value(pat, {0.25, 0, 0}, 2), 1.0, 1e-12);
    pat.params->wave = scene::WaveType::Poly;
    pat.params->exponent = 2.0;
    EXPECT_NEAR(texture::pattern_value(pat, {0.5, 0, 0}, 2), 0.25, 1e-12);
    pat.params->wave = scene::WaveType::Ramp;
    pat.params->frequency = 2.0;
    pat.params->phase = 0.1;
    EXPECT_NEAR(texture::pattern_value(pat, {0.3, 0, 0}, 2), std::fmod(0.7, 1.00001), 1e-12);
}

TEST(Textures, ObjectTransformsAfterTheTextureMoveIt) {
    const scene::Scene scene = parse(
        "sphere { 0, 1 pigment { checker rgb 1, rgb 0 scale 0.5 } translate <0.5, 0, 0> }\n"
        "sphere { 0, 1 translate <0.5, 0, 0> pigment { checker rgb 1, rgb 0 scale 0.5 } }\n");
    ASSERT_EQ(scene.objects.size(), 2u);
    // The first pigment moved with the sphere by half a checker; the second did not.
    const Vec3 p{0.1, 0.1, 0.1};
    EXPECT_DOUBLE_EQ(texture::evaluate_pigment(scene.objects[0].texture->pigment, p, 2).r, 0.0);
    EXPECT_DOUBLE_EQ(texture::evaluate_pigment(scene.objects[1].texture->pigment, p, 2).r, 1.0);
}

TEST(Textures, ParsesMapsOldColorMapFormAndPigmentMaps) {
    const scene::Scene scene = parse(
        "plane { y, 0 pigment { gradient x color_map { [0, 0.5 color rgb 0 color rgb 1] [0.5 rgb <1, 0, 0>] } } }\n"
        "plane { y, 0 pigment { bozo pigment_map { [0.3 rgb 1] [0.7 checker rgb 0, rgb 1] } turbulence 0.5 } }\n"
        "plane { y, 0 pigment { marble } normal { bumps 0.4 scale 0.2 } finish { reflection { 0.1, 0.9 fresnel } } }\n");
    ASSERT_EQ(scene.objects.size(), 3u);
    const auto& map = scene.objects[0].texture->pigment.color_map;
    ASSERT_EQ(map.size(), 3u);
    EXPECT_DOUBLE_EQ(map[1].value, 0.5);
    EXPECT_DOUBLE_EQ(map[1].color.g, 1.0);
    const scene::Pigment& bozo = scene.objects[1].texture->pigment;
    ASSERT_EQ(bozo.pigment_map.size(), 2u);
    EXPECT_EQ(bozo.pigment_map[1].pigment.pattern.type, scene::Pattern::Type::Checker);
    ASSERT_TRUE(bozo.pattern.params->turbulence.has_value());
    const scene::Texture& t = scene.objects[2].texture;
    EXPECT_EQ(t.pigment.pattern.params->wave, scene::WaveType::Triangle);
    EXPECT_EQ(t.pigment.color_map.size(), 3u);  // marble's default map
    EXPECT_EQ(t.normal.pattern.type, scene::Pattern::Type::Bumps);
    EXPECT_DOUBLE_EQ(t.normal.amount, static_cast<double>(0.4f));  // POV-Ray keeps bump sizes in single precision
    EXPECT_TRUE(t.finish.reflection_fresnel);
}

// A camera ray straight down onto a plane at y = 0 with the given texture, over a background colour.
Vec3 look_down(const std::string& object, const std::string& extra = "") {
    const scene::Scene scene = parse("background { rgb <0.2, 0.4, 0.6> }\n" + extra + object);
    EXPECT_FALSE(scene.objects.empty());
    const geometry::SceneGeometry geometry(scene);
    const Integrator integrator(scene, geometry, {});
    TraceContext counters;
    return integrator.trace_camera_ray({{0.3, 1.0, 0.3}, {0, -1, 0}}, counters);
}

TEST(Transparency, TransmitShowsWhatIsBehind) {
    // Fully transmitting, no light of its own: the background shows through unchanged.
    const Vec3 c = look_down("plane { y, 0 pigment { rgbt <1, 0, 0, 1> } finish { ambient 0 diffuse 0 } }\n");
    EXPECT_NEAR(c.x, 0.2, 1e-12);
    EXPECT_NEAR(c.z, 0.6, 1e-12);
    // Filter tints it by the pigment: rgb·filter.
    const Vec3 f = look_down("plane { y, 0 pigment { rgbf <1, 0.5, 0, 1> } finish { ambient 0 diffuse 0 } }\n");
    EXPECT_NEAR(f.x, 0.2, 1e-12);
    EXPECT_NEAR(f.y, 0.2, 1e-12);
    EXPECT_NEAR(f.z, 0.0, 1e-12);
}

TEST(Reflection, MirrorReflectsTheBackgroundByItsReflectivity) {
    const Vec3 c = look_down("plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 0.5 } }\n");
    EXPECT_NEAR(c.y, 0.2, 1e-12);
    // Fresnel at normal incidence for ior 1.5: ((1.5 − 1)/(1.5 + 1))² = 0.04 of the maximum.
    const Vec3 f = look_down(
        "plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection { 1 fresnel } }"
        " interior { ior 1.5 } }\n");
    EXPECT_NEAR(f.z, 0.6 * 0.04, 1e-9);
}

TEST(Reflection, MaxTraceLevelStopsTheRecursion) {
    // A black half-mirror floor under a glowing half-mirror ceiling: each level adds the ceiling's glow, halved
    // per bounce, until max_trace_level ends the recursion.
    const std::string mirrors =
        "plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 0.5 } }\n"
        "plane { y, 2 pigment { rgb 1 } finish { ambient 0 emission 1 diffuse 0 reflection 0.5 } }\n";
    EXPECT_NEAR(look_down(mirrors, "global_settings { max_trace_level 3 }\n").x, 0.5, 1e-12);
    EXPECT_NEAR(look_down(mirrors, "global_settings { max_trace_level 5 }\n").x, 0.625, 1e-12);
}

TEST(Noise, CoordinatesBeyondIntRangeAreFiniteAsInPovRay) {
    // POV-Ray 3.7.0.10 printed these (f_noise3d, generator 2): its (int) cast of an out-of-range coordinate gives
    // x86's INT_MIN, which wardray reproduces without the undefined behaviour (a render-fuzz finding).
    EXPECT_NEAR(texture::noise({1e10, -1e10, 3e9}, 2), 0.0, 1e-11);
    EXPECT_NEAR(texture::noise({0.3, 5e9, -0.7}, 2), 1.0, 1e-11);
    for (int generator = 1; generator <= 3; ++generator) {
        for (const Vec3& p : {Vec3{-3e9, 2.2e9, 1e18}, Vec3{2147483647.5, -2147483648.5, 0}})
            EXPECT_TRUE(std::isfinite(texture::noise(p, generator))) << generator << " " << p.x;
    }
}


// A double's bits, so that a comparison tells 0.0 from -0.0 and catches a difference in the last bit.
std::uint64_t bits(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

TEST(Noise, BatchesAndBothBuildsGiveTheSameBits) {
    // noise_batch evaluates several points side by side, and the noise functions have an AVX2 and an SSE2 build:
    // each must give exactly the bits of noise() one point at a time, and dturbulence those of its dnoise sum,
    // or an image would change with the batch size or the processor.
    std::mt19937 rng(14);
    std::uniform_real_distribution<double> coord(-400.0, 400.0);
    std::vector<Vec3> points;
    for (int i = 0; i < 3000; ++i) points.push_back({coord(rng), coord(rng), coord(rng)});
    points.push_back({0.0, -0.0, 0.5});
    points.push_back({-1e10, 3e9, 0.25});
    points.push_back({2147483647.5, -2147483648.5, 1e-300});
    const texture::TurbulenceParams params[] = {{6, 0.5, 2.0}, {1, 0.5, 2.0}, {3, 0.7, 2.3}, {10, 0.45, 1.9}};
    int mismatches = 0;
    auto evaluate = [&] {
        std::vector<std::uint64_t> out;
        for (int generator = 1; generator <= 3; ++generator) {
            for (std::size_t count = 1; count <= 9; ++count) {
                for (std::size_t i = 0; i + count <= points.size(); i += count * 7) {
                    double n[9];
                    texture::noise_batch(&points[i], count, generator, n);
                    for (std::size_t j = 0; j < count; ++j) {
                        mismatches += bits(n[j]) != bits(texture::noise(points[i + j], generator));
                        out.push_back(bits(n[j]));
                    }
                }
            }
            for (const Vec3& p : points) {
                for (const texture::TurbulenceParams& t : params)
                    out.push_back(bits(texture::turbulence(p, t, generator)));
            }
        }
        for (const Vec3& p : points) {
            for (const texture::TurbulenceParams& t : params) {
                Vec3 sum = texture::dnoise(p);
                double l = t.lambda, o = t.omega;
                for (int i = 2; i <= t.octaves; ++i, l *= t.lambda, o *= t.omega) sum += o * texture::dnoise(p * l);
                const Vec3 d = texture::dturbulence(p, t);
                for (int c = 0; c < 3; ++c) {
                    mismatches += bits(d[c]) != bits(sum[c]);
                    out.push_back(bits(d[c]));
                }
            }
        }
        return out;
    };
    function::use_avx2_noise(false);
    const std::vector<std::uint64_t> portable = evaluate();
    function::use_avx2_noise(true);
    const std::vector<std::uint64_t> fast = evaluate();
    EXPECT_EQ(mismatches, 0);
    ASSERT_EQ(portable.size(), fast.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < fast.size(); ++i) differ += portable[i] != fast[i];
    EXPECT_EQ(differ, 0u) << "of " << fast.size() << " values";
}

}  // namespace
}  // namespace wardray::lighting

