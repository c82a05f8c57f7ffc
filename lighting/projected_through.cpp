// A light's projected_through object (POV-Ray 3.7's Projected_Through_Object in TracePointLightShadowRay).
#include "lighting/projected_through.h"

#include "geometry/scene_geometry.h"

namespace wardray::lighting {

ProjectedThrough::ProjectedThrough(const scene::Object& object) {
    m_scene.objects.push_back(object);
    // The object is only intersected, never shaded or shadowed: nothing of its flags may hide it.
    scene::Object& o = m_scene.objects.back();
    o.no_image = o.no_reflection = o.no_shadow = false;
    m_geometry = std::make_unique<const geometry::SceneGeometry>(m_scene);
}

ProjectedThrough::~ProjectedThrough() = default;

std::vector<std::unique_ptr<const ProjectedThrough>> ProjectedThrough::for_lights(const scene::Scene& scene) {
    std::vector<std::unique_ptr<const ProjectedThrough>> out;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const scene::Light& light = scene.lights[i];
        if (light.projected_through.empty()) continue;
        out.resize(scene.lights.size());
        out[i] = std::make_unique<const ProjectedThrough>(light.projected_through.front());
    }
    return out;
}

bool ProjectedThrough::shine_through(const Vec3& p, const Vec3& dir, double& distance) const {
    // POV-Ray's SMALL_TOLERANCE: shadows stop this far before the object.
    constexpr double kSmallTolerance = 0.001;
    const geometry::Ray ray{p, dir, m_geometry->self_intersection_offset(p), 1e30, geometry::RayKind::Camera};
    const std::optional<geometry::Hit> hit = m_geometry->intersect(ray);
    if (!hit || hit->t >= distance) return false;
    distance = hit->t - kSmallTolerance;
    return true;
}

}  // namespace wardray::lighting
