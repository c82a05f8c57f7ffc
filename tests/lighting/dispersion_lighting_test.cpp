// Camera rays through dispersive interiors: split into bands whose hues average to white, the band kept through
// later dispersive surfaces, and nothing split where the relative dispersion is 1.
#include <gtest/gtest.h>

#include <string>

#include "../parser/test_util.h"
#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"

namespace wardray::lighting {
namespace {

struct Seen {
    Vec3 colour;
    std::uint64_t secondary = 0;
};

// What a camera ray from (0, 0, −5) along +z sees of `objects` before a uniform background.
Seen look(const std::string& objects) {
    const scene::Scene scene = parser::test::parse_ok("background { rgb <0.3, 0.6, 0.9> }\n" + objects);
    const geometry::SceneGeometry geometry(scene);
    const Integrator integrator(scene, geometry, {});
    TraceContext ctx;
    const Vec3 c = integrator.trace_camera_ray(geometry::Ray{{0.0, 0.0, -5.0}, {0.0, 0.0, 1.0}}, ctx);
    return {c, ctx.rays.secondary};
}

void expect_background(const Vec3& c) {
    EXPECT_NEAR(c.x, 0.3, 1e-9);
    EXPECT_NEAR(c.y, 0.6, 1e-9);
    EXPECT_NEAR(c.z, 0.9, 1e-9);
}

TEST(DispersiveRefraction, BandsThroughClearGlassAverageToTheBackground) {
    // Through the centre every band goes straight on; off centre the bands part but all see the same background.
    const Seen centre = look("sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 dispersion 1.1 } }");
    expect_background(centre.colour);
    // 7 bands refracted in, each refracted out once, without splitting again.
    EXPECT_EQ(centre.secondary, 14u);
    const Seen off = look("sphere { <0.4, 0.3, 0>, 1 pigment { rgbf 1 } interior { ior 1.3 dispersion 1.2 "
                          "dispersion_samples 11 } }");
    expect_background(off.colour);
    EXPECT_EQ(off.secondary, 22u);
}

TEST(DispersiveRefraction, ASplitRayKeepsItsBandThroughTheNextDispersiveObject) {
    // Two spheres one behind the other, of 7 and 5 samples: the 7 bands of the first cross the second unsplit.
    const Seen two = look("sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 dispersion 1.1 } }\n"
                          "sphere { <0, 0, 3>, 1 pigment { rgbf 1 } interior { ior 1.4 dispersion 1.3 "
                          "dispersion_samples 5 } }");
    expect_background(two.colour);
    EXPECT_EQ(two.secondary, 28u);
}

TEST(DispersiveRefraction, NoDispersionNoSplit) {
    const Seen plain = look("sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 dispersion_samples 9 } }");
    expect_background(plain.colour);
    EXPECT_EQ(plain.secondary, 2u);
}

}  // namespace
}  // namespace wardray::lighting
