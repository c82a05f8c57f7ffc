// A light's `projected_through` object: the light reaches only the points that see it through that object.
#pragma once

#include <memory>
#include <vector>

#include "core/vec3.h"
#include "scene/scene.h"

namespace wardray::geometry {
class SceneGeometry;
}  // namespace wardray::geometry

namespace wardray::lighting {

/// The geometry of one light's projected_through object, built on its own (the object is not part of the scene).
class ProjectedThrough {
public:
    explicit ProjectedThrough(const scene::Object& object);
    ~ProjectedThrough();
    ProjectedThrough(const ProjectedThrough&) = delete;
    ProjectedThrough& operator=(const ProjectedThrough&) = delete;

    /// One per light of `scene`, null for the lights without projected_through; empty when no light has one.
    static std::vector<std::unique_ptr<const ProjectedThrough>> for_lights(const scene::Scene& scene);

    /// POV-Ray's TracePointLightShadowRay: true when the ray from `p` along the unit `dir` meets the object before
    /// the light, `distance` away; `distance` then becomes how far shadows are tested (up to the object, less
    /// POV-Ray's SMALL_TOLERANCE, so the object and what lies beyond it cast none).
    bool shine_through(const Vec3& p, const Vec3& dir, double& distance) const;

private:
    scene::Scene m_scene;  ///< the object alone, which m_geometry refers to
    std::unique_ptr<const geometry::SceneGeometry> m_geometry;
};

}  // namespace wardray::lighting
