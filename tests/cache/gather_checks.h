// Checks shared by the gathers' tests: the furnace (constant radiance everywhere), and a gather's gradients against
// central finite differences of a much larger gather in the test room.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

#include "cache/gather.h"
#include "cache/hemisphere_sampler.h"
#include "test_scenes.h"

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

/// The irradiance gradients at p (unit normal n, tangent axes t and b) by central differences of a 131072-ray
/// stratified irradiance in the test room, one seed for both sides of each difference (the difference of the same
/// stratified estimator): turned by ±0.03 rad about each tangent axis, moved by ±0.02 along it ((step / distance to
/// the nearest wall)² stays below 1 %).
class FiniteDifferenceGradients {
public:
    FiniteDifferenceGradients(const test::RoomScene& room, const Vec3& p, const Vec3& n, const Vec3& t, const Vec3& b)
        : m_t(t), m_b(b) {
        constexpr double kAngle = 0.03, kStep = 0.02;
        const Strata strata = strata_for_count(131072);
        const auto irradiance = [&](const Vec3& q, const Vec3& nn) {
            return gather_seeded(q, nn, strata, room.radiance_at(q), 0x5EED).irradiance;
        };
        const Vec3 axes[2] = {t, b};
        for (int a = 0; a < 2; ++a) {
            // Rotation by ±α about the tangent axis: n(α) = n cos α + (axis × n) sin α.
            const Vec3 turn = cross(axes[a], n);
            m_rotational[a] = (irradiance(p, n * std::cos(kAngle) + turn * std::sin(kAngle)) -
                               irradiance(p, n * std::cos(kAngle) - turn * std::sin(kAngle))) / (2.0 * kAngle);
            m_translational[a] =
                (irradiance(p + axes[a] * kStep, n) - irradiance(p - axes[a] * kStep, n)) / (2.0 * kStep);
        }
    }
    /// The size of channel c's reference rotational (translational) gradient in the tangent plane.
    double rotational_size(int c) const { return std::hypot(m_rotational[0][c], m_rotational[1][c]); }
    double translational_size(int c) const { return std::hypot(m_translational[0][c], m_translational[1][c]); }
    /// The error of channel c of a gather's rotational (translational) gradient in the tangent plane, relative to the
    /// reference's size.
    double rotational_error(const GatherResult& g, int c) const { return error(g.rotational[c], m_rotational, c); }
    double translational_error(const GatherResult& g, int c) const {
        return error(g.translational[c], m_translational, c);
    }

private:
    double error(const Vec3& estimate, const std::array<Vec3, 2>& reference, int c) const {
        const double e0 = dot(estimate, m_t) - reference[0][c], e1 = dot(estimate, m_b) - reference[1][c];
        return std::hypot(e0, e1) / std::hypot(reference[0][c], reference[1][c]);
    }
    Vec3 m_t, m_b;
    std::array<Vec3, 2> m_rotational, m_translational;
};

}  // namespace wardray::cache
