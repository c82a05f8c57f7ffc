// The furnace check shared by the gathers' tests: constant radiance in every direction.
#pragma once

#include <gtest/gtest.h>

#include "cache/gather.h"

namespace wardray::cache {

/// The radiance the furnace sends from every direction, and the distance of its walls.
inline RadianceSample furnace_sample(const Vec3&) { return RadianceSample{{0.25, 0.5, 2.0}, 3.0}; }

/// A gather in the furnace gives E = L in POV-Ray's normalisation, the walls' distance, and no gradient.
inline void expect_furnace(const GatherResult& g) {
    EXPECT_NEAR(g.irradiance.x, 0.25, 1e-12);
    EXPECT_NEAR(g.irradiance.y, 0.5, 1e-12);
    EXPECT_NEAR(g.irradiance.z, 2.0, 1e-12);
    EXPECT_NEAR(g.harmonic_mean_distance, 3.0, 1e-12);
    for (int c = 0; c < 3; ++c) {
        EXPECT_LT(length(g.rotational[c]), 1e-12);
        EXPECT_LT(length(g.translational[c]), 1e-12);
    }
}

}  // namespace wardray::cache
