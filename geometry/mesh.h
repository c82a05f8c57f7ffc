// MeshShape: triangles (`triangle`, `smooth_triangle`, `mesh`, `mesh2`, triangulated `polygon`) in object space.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// A triangle list with optional per-vertex normals. SceneGeometry gives top-level meshes to Embree as native
/// triangles and refines their hits here in double; intersect_all and inside (through a bounding-box tree over the
/// faces, shared by copies) serve CSG and tests.
class MeshShape {
public:
    /// One face: vertex indices and normal indices (-1 when flat).
    struct Face {
        std::array<int, 3> v{};
        std::array<int, 3> n{-1, -1, -1};
        int source = -1;  ///< its index in scene::Mesh::faces (-1 for tessellated shapes)
    };

    /// Drops degenerate faces (zero area, bad indices); returns nothing when no face is left.
    static std::optional<MeshShape> create(const scene::Mesh& mesh);
    /// The polygon triangulated with POV-Ray's even-odd rule for holes (polygon.cpp).
    static std::optional<MeshShape> create(const scene::Polygon& polygon);
    /// A prism as side walls and triangulated caps, faces turned outward (prism.cpp; used for conic sweeps).
    static std::optional<MeshShape> create(const scene::Prism& prism);
    /// A bicubic patch tessellated as POV-Ray does, with its smooth normals (bicubic_patch.cpp).
    static std::optional<MeshShape> create(const scene::BicubicPatch& patch);

    /// All crossings with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// The crossing with one face, if any, with t in (t_min, t_max). With `known_hit` (Embree found this face
    /// in float) only the plane's t is recomputed and the barycentrics are clamped, so no edge crack opens.
    std::optional<SurfaceHit> intersect_face(const LocalRay& ray, std::size_t face, double t_min, double t_max,
                                             bool known_hit = false, double* bary = nullptr) const;
    /// Where a ray crosses a face: its parameter and the barycentric weights of the second and third corners.
    struct FaceCrossing {
        double t = 0.0;
        double u = 0.0;
        double v = 0.0;
    };
    /// intersect_face() up to its crossing, without the normal (inline: Embree's triangle filters call it for every
    /// candidate face); false where intersect_face() finds nothing. intersect_face() is this and face_normal().
    bool face_crossing(const LocalRay& ray, std::size_t index, double t_min, double t_max, bool known_hit,
                       FaceCrossing& out) const {
        const Face& f = m_faces[index];
        const Vec3& a = m_vertices[f.v[0]];
        const Vec3 e1 = m_vertices[f.v[1]] - a;
        const Vec3 e2 = m_vertices[f.v[2]] - a;
        const Vec3 pv = cross(ray.direction, e2);
        const double det = dot(e1, pv);
        if (det == 0.0 || !std::isfinite(det)) return false;
        const Vec3 tv = ray.origin - a;
        double u = dot(tv, pv) / det;
        const Vec3 qv = cross(tv, e1);
        double v = dot(ray.direction, qv) / det;
        if (known_hit) {
            u = std::clamp(u, 0.0, 1.0);
            v = std::clamp(v, 0.0, 1.0 - u);
        } else if (u < 0.0 || u > 1.0 || v < 0.0 || u + v > 1.0) {
            return false;
        }
        const double t = dot(e2, qv) / det;
        if (!(t > t_min && t < t_max)) return false;
        out = {t, u, v};
        return true;
    }
    /// The object-space normal intersect_face() gives at a crossing of face `index` (flat: POV-Ray's side of the
    /// face; smooth: the corners' normals interpolated), and whether `direction` enters against the face's side.
    Vec3 face_normal(std::size_t index, const FaceCrossing& c, const Vec3& direction, bool* entering = nullptr) const;
    /// True when intersect_face() with `known_hit` finds a crossing: the same t, by the same operations in the same
    /// order, without the normal and barycentrics (a shadow ray's test of a face Embree found near its ends).
    /// Change it with face_crossing().
    bool face_crossed(const LocalRay& ray, std::size_t index, double t_min, double t_max) const {
        const Face& f = m_faces[index];
        const Vec3& a = m_vertices[f.v[0]];
        const Vec3 e1 = m_vertices[f.v[1]] - a;
        const Vec3 e2 = m_vertices[f.v[2]] - a;
        const double det = dot(e1, cross(ray.direction, e2));
        if (det == 0.0 || !std::isfinite(det)) return false;
        const double t = dot(e2, cross(ray.origin - a, e1)) / det;
        return t > t_min && t < t_max;
    }
    /// Object-space bounding box of the vertices.
    std::optional<Bounds> bounds() const { return m_bounds; }
    /// With an inside_vector: an odd number of crossings along it; without: never inside.
    bool inside(const Vec3& p) const;
    /// Distance to the nearest face (zero on the surface).
    double implicit(const Vec3& p) const;

    const std::vector<Vec3>& vertices() const { return m_vertices.get(); }
    const std::vector<Face>& faces() const { return m_faces.get(); }
    /// The surface parameters at a face's point of barycentric weights (bary_u, bary_v) for its second and third
    /// corners, interpolated from the vertices' (a tessellated bicubic patch's (u, v)); nothing without them.
    std::optional<Vec3> params_at(std::size_t face, double bary_u, double bary_v) const;

    /// A node of the face tree: a leaf holds `count` faces from `first` in the tree's face order; an inner node's
    /// children are the next node and node `first`.
    struct TreeNode {
        Bounds box;
        std::uint32_t first = 0;
        std::uint32_t count = 0;
    };
    /// The face tree: nodes (root first) and the faces' indices in leaf order.
    struct FaceTree {
        std::vector<TreeNode> nodes;
        std::vector<std::uint32_t> order;
    };

private:
    MeshShape() = default;
    /// create() without the memo: the faces kept and the bounds (the face tree waits for its first use).
    static std::optional<MeshShape> build(const scene::Mesh& mesh);
    void finish();
    /// The face tree, made on first use (once, whichever thread asks first); null for a few faces.
    const FaceTree* tree() const;
    std::shared_ptr<const FaceTree> build_tree() const;
    /// The faces whose (padded) box the ray meets within [t_min, t_max], in increasing index order, so the hits
    /// come in the same order as a test of every face.
    static void candidate_faces(const FaceTree& tree, const LocalRay& ray, double t_min, double t_max,
                                std::vector<std::uint32_t>& out);
    /// POV-Ray's crossings of a mesh without an inside_vector: its faces nearest box first, up to the first box
    /// that starts beyond the last crossing found.
    SurfaceHits nearest_crossings(const LocalRay& ray, double t_min, double t_max) const;

    // Shared by copies, and by the shapes made from one scene mesh (a declared mesh used many times).
    scene::SharedVector<Vec3> m_vertices;
    scene::SharedVector<Vec3> m_normals;
    scene::SharedVector<Face> m_faces;
    scene::SharedVector<Vec3> m_params;  ///< per vertex, or empty
    std::shared_ptr<const void> m_source;  ///< keeps the scene mesh's vectors, the key of the shapes made from it
    Vec3 m_inside_vector;
    bool m_nearest_only = false;  ///< a mesh or mesh2 without an inside_vector (see nearest_crossings)
    bool m_normals_outward = false;  ///< smooth normals turned to the face's side (wardray's own prism walls)
    Bounds m_bounds;
    /// The face tree once made (null for a few faces), shared by copies like the faces it indexes.
    struct LazyTree {
        std::once_flag once;
        std::shared_ptr<const FaceTree> tree;
    };
    std::shared_ptr<LazyTree> m_lazy_tree;
};

/// POV-Ray's texture coordinates of a bicubic patch at its parameters (u, v): the uv_vectors blended bilinearly,
/// the first pair of corners along v (POV-Ray's Compute_Texture_UV with the point (v, u)).
Vec3 bicubic_patch_uv(const scene::BicubicPatch& patch, const Vec3& params);

/// POV-Ray's sub-polygons of a point list: each closes when its first point repeats; an unclosed rest is closed.
std::vector<std::vector<Vec3>> polygon_loops(const std::vector<Vec3>& points);
/// The plane normal of a polygon's loops (Newell's, not unit length; zero for a degenerate polygon).
Vec3 polygon_normal(const std::vector<std::vector<Vec3>>& loops);

}  // namespace wardray::geometry
