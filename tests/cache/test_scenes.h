// Test environments for the cache: a room of planes, a box and a sphere with smoothly varying emitted radiance.
#pragma once

#include <cmath>
#include <limits>
#include <memory>

#include "cache/gather.h"
#include "geometry/scene_geometry.h"
#include "scene/scene.h"

namespace wardray::cache::test {

/// A room of finite slabs, open towards −z and +x: floor y=0, ceiling y=3, back wall z=3, left wall x=−2;
/// a box on the floor and a sphere near the left wall. Every surface emits a smooth pattern, the back wall a
/// bright patch, and rays that leave the room see a uniform sky.
class RoomScene {
public:
    RoomScene() {
        add(scene::Box{{-2.0, -0.1, -3.0}, {4.0, 0.0, 3.0}});  // 0 floor, top face y=0
        add(scene::Box{{-2.0, 3.0, -3.0}, {4.0, 3.1, 3.0}});   // 1 ceiling
        add(scene::Box{{-2.0, 0.0, 3.0}, {4.0, 3.0, 3.1}});    // 2 back wall, face z=3
        add(scene::Box{{-2.1, 0.0, -3.0}, {-2.0, 3.0, 3.0}});  // 3 left wall, face x=−2
        add(scene::Box{{0.5, 0.0, 0.5}, {1.2, 0.8, 1.2}});  // 4 box
        add(scene::Sphere{{-1.2, 0.7, 1.5}, 0.5});           // 5 sphere
        m_geometry = std::make_unique<geometry::SceneGeometry>(m_scene);
    }

    /// The radiance leaving the surface point `q` of object `object`.
    static Vec3 emitted(std::uint32_t object, const Vec3& q) {
        static const Vec3 base[] = {{0.5, 0.4, 0.3}, {0.8, 0.8, 0.8}, {0.3, 0.5, 0.7},
                                    {0.9, 0.2, 0.2}, {0.2, 0.8, 0.3}, {0.6, 0.6, 0.1}};
        const double pattern = 1.0 + 0.5 * std::sin(1.3 * q.x + 0.7 * q.y) * std::cos(0.9 * q.z);
        Vec3 l = base[object % 6] * pattern;
        if (object == 2) {
            // A bright soft patch on the back wall, like a lit area.
            const Vec3 d = q - Vec3{-0.5, 1.0, 3.0};
            l += Vec3{3.0, 2.0, 1.0} * std::exp(-dot(d, d) / 0.18);
        }
        return l;
    }

    /// The gather callback at `origin`: trace, and return the emitted radiance and distance of the hit.
    RadianceFunction radiance_at(const Vec3& origin) const {
        return [this, origin](const Vec3& dir) {
            geometry::Ray ray;
            ray.origin = origin;
            ray.direction = dir;
            ray.t_min = 1e-7;
            ray.kind = geometry::RayKind::Gather;
            const auto hit = m_geometry->intersect(ray);
            if (!hit) return RadianceSample{{0.3, 0.4, 0.5}, std::numeric_limits<double>::infinity()};
            return RadianceSample{emitted(hit->object, hit->position), hit->t};
        };
    }

private:
    void add(const scene::Shape& shape) {
        scene::Object o;
        o.shape = shape;
        m_scene.objects.push_back(o);
    }

    scene::Scene m_scene;
    std::unique_ptr<geometry::SceneGeometry> m_geometry;
};

}  // namespace wardray::cache::test
