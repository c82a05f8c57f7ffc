// Integrator: the colour seen along a ray, from POV-Ray 3.7's direct-lighting model.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "parser/scene.h"
#include "parser/vec3.h"

namespace wardray::geometry {
class SceneGeometry;
struct Ray;
struct Hit;
}  // namespace wardray::geometry

namespace wardray::lighting {

/// How indirect light is computed (`--gi`).
enum class GiMode { Off, Cache, Reference };

/// Rays traced, by kind, for --stats. Each thread keeps its own and the totals are summed.
struct RayCounters {
    std::uint64_t camera = 0;
    std::uint64_t shadow = 0;

    RayCounters& operator+=(const RayCounters& o) {
        camera += o.camera;
        shadow += o.shadow;
        return *this;
    }
};

struct IntegratorOptions {
    GiMode gi = GiMode::Off;
};

/// Shades rays against a built scene. Stateless after construction, so one instance serves every thread.
class Integrator {
public:
    Integrator(const parser::Scene& scene, const geometry::SceneGeometry& geometry, IntegratorOptions options);

    /// Linear RGB radiance arriving along a camera ray (the background where it hits nothing).
    Vec3 trace_camera_ray(const geometry::Ray& ray, RayCounters& counters) const;

    /// Warnings about what this integrator leaves out of the picture (reported once per render).
    const std::vector<std::string>& limitations() const { return m_limitations; }

private:
    /// Colour of the surface at `hit` seen from direction `-view_dir`.
    Vec3 shade(const geometry::Hit& hit, const Vec3& view_dir, RayCounters& counters) const;
    /// The light arriving at `p` from `light` unblocked, as colour times attenuation; zero when in shadow.
    Vec3 light_arriving(const parser::Light& light, const Vec3& p, const Vec3& n, Vec3& to_light,
                        RayCounters& counters) const;

    const parser::Scene& m_scene;
    const geometry::SceneGeometry& m_geometry;
    IntegratorOptions m_options;
    bool m_ambient_is_light = true;
    std::vector<std::string> m_limitations;
};

}  // namespace wardray::lighting
