// POV-Ray's metallic tint: the pigment's colour at normal incidence, white at grazing angles, nothing without it.
#include "lighting/metallic.h"

#include <gtest/gtest.h>

namespace wardray::lighting {
namespace {

const Vec3 kGold{1.0, 0.8, 0.2};

TEST(MetallicTint, PigmentAtNormalIncidenceWhiteAtGrazing) {
    // F(0) = 0.014567225/1.2544 − 0.011612903 ≈ 0 and F(1) = 0.014567225/0.0144 − 0.011612903 ≈ 1.
    const Vec3 normal = metallic_tint(kGold, 1.0, 1.0);
    EXPECT_NEAR(normal.y, 0.8, 1e-6);
    EXPECT_NEAR(normal.z, 0.2, 1e-6);
    const Vec3 grazing = metallic_tint(kGold, 1.0, 0.0);
    EXPECT_NEAR(grazing.y, 1.0, 1e-6);
    EXPECT_NEAR(grazing.z, 1.0, 1e-6);
    // In between the tint lies between the two, and half the metallic amount halves the tint's departure from 1.
    const Vec3 mid = metallic_tint(kGold, 1.0, 0.5);
    EXPECT_GT(mid.z, 0.2);
    EXPECT_LT(mid.z, 1.0);
    EXPECT_NEAR(1.0 - metallic_tint(kGold, 0.5, 0.5).z, 0.5 * (1.0 - mid.z), 1e-12);
}

TEST(MetallicTint, NoMetallicLeavesWhite) {
    EXPECT_EQ(metallic_tint(kGold, 0.0, 0.3), (Vec3{1.0, 1.0, 1.0}));
}

}  // namespace
}  // namespace wardray::lighting
