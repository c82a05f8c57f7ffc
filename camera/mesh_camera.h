// MeshCamera: POV-Ray 3.7's mesh_camera, rays leaving the faces of meshes along their normals.
#pragma once

#include <array>
#include <memory>
#include <cstdint>
#include <vector>

#include "camera/projections.h"
#include "core/transform.h"
#include "scene/camera.h"

namespace wardray::camera {

/// The camera's meshes as POV-Ray holds them (degenerate faces dropped, corners ordered as Compute_Mesh_Triangle
/// leaves them), and the ray of each distribution method.
class MeshCamera {
public:
    explicit MeshCamera(const scene::MeshCameraSpec& spec);

    /// The ray of sample `ray_number` through image position (px, py) (pixel units, origin top-left); false where
    /// POV-Ray traces no ray (no face for the pixel).
    bool ray(const Frame& frame, double px, double py, int ray_number, ProjectedRay& out) const;
    int rays_per_pixel() const { return m_rays_per_pixel; }

private:
    /// One face: its corners, face normal, corner normals (smooth faces) and uv coordinates.
    struct Face {
        std::array<Vec3, 3> p;
        Vec3 normal;             ///< POV-Ray's (P3 − P1) × (P2 − P1), unit
        std::array<Vec3, 3> n;   ///< corner normals (unit), valid when `smooth`
        bool smooth = false;
        std::array<Vec3, 3> uv;  ///< (u, v, 0) of the corners
        Vec3 perp;               ///< POV-Ray's smooth-normal interpolation data
        int v_axis = 0;
    };
    /// What distributions 0-2 need of a face: the ray leaves its centroid along its normal.
    struct CentroidFace {
        Vec3 centroid;
        Vec3 normal;
    };
    struct PlacedMesh {
        /// Every face, for distributions 0-2; shared by the placed copies of one mesh (they differ only in transform).
        std::shared_ptr<const std::vector<CentroidFace>> centroids;
        std::vector<Face> faces;              ///< the whole faces, kept only for distribution 3's first mesh
        Transform transform;
    };

    /// The ray leaving `face` of `mesh` at `origin` (object space) with direction `dir` (object space).
    void leave(const Frame& frame, const PlacedMesh& mesh, Vec3 origin, Vec3 dir, ProjectedRay& out) const;
    bool uv_ray(const Frame& frame, double u, double v, ProjectedRay& out) const;

    std::vector<PlacedMesh> m_meshes;
    std::vector<std::size_t> m_mesh_end;  ///< running face totals (POV-Ray's Mesh_Index)
    int m_rays_per_pixel = 1;
    int m_distribution = 0;
    bool m_smooth = false;
    /// Distribution 3: for each tenth of u and of v, the faces whose uv bounds reach into it (POV-Ray's xrefs).
    std::array<std::vector<std::uint32_t>, 10> m_u_cells, m_v_cells;
};

}  // namespace wardray::camera
