// Shared by the photon tests: the photon map of a scene shot with 1 and with 2 threads, compared byte for byte.
#pragma once

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cstring>
#include <memory>

#include "geometry/scene_geometry.h"
#include "photons/photon_map.h"
#include "photons/photon_shooter.h"
#include "scene/scene.h"

namespace wardray::photons::test {

/// Shoots `scene`'s photons in an arena of 1 and of 2 threads and expects the same photons in the same order.
inline void expect_same_map_for_one_and_two_threads(const scene::Scene& scene) {
    const geometry::SceneGeometry geometry(scene);
    auto shoot = [&](int threads) {
        PhotonStats stats;
        std::unique_ptr<const PhotonMap> map;
        tbb::task_arena(threads).execute([&] { map = shoot_photons(scene, geometry, stats); });
        return map;
    };
    const auto one = shoot(1);
    const auto two = shoot(2);
    ASSERT_TRUE(one && two);
    ASSERT_GT(one->size(), 0u);
    ASSERT_EQ(one->size(), two->size());
    EXPECT_EQ(std::memcmp(one->photons().data(), two->photons().data(), one->size() * sizeof(Photon)), 0);
}

}  // namespace wardray::photons::test
