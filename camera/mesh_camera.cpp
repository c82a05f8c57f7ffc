// MeshCamera: the mesh_camera's four distribution methods as POV-Ray 3.7's tracepixel.cpp places their rays.
#include "camera/mesh_camera.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace wardray::camera {

namespace {

int dominant_axis(const Vec3& v) {
    const double x = std::fabs(v.x), y = std::fabs(v.y), z = std::fabs(v.z);
    return x > y ? (x > z ? 0 : 2) : (y > z ? 1 : 2);
}

}  // namespace

MeshCamera::MeshCamera(const scene::MeshCameraSpec& spec)
    : m_rays_per_pixel(spec.rays_per_pixel), m_distribution(spec.distribution), m_smooth(spec.smooth) {
    std::size_t total = 0;
    scene::SharedVector<scene::Mesh::Face> last_faces;
    scene::SharedVector<Vec3> last_vertices;
    for (const scene::MeshCameraSpec::PlacedMesh& pm : *spec.meshes) {
        // A large camera holds millions of faces (a mesh per sample, a face per pixel): only distribution 3 looks
        // at more than each face's centroid and normal, and only in the first mesh.
        const bool whole_faces = m_distribution == 3 && m_meshes.empty();
        PlacedMesh placed;
        placed.transform = pm.transform;
        // Copies of one declared mesh share its faces: their centroids are computed once.
        if (!whole_faces && !m_meshes.empty() && pm.mesh.faces.shares(last_faces) &&
            pm.mesh.vertices.shares(last_vertices)) {
            placed.centroids = m_meshes.back().centroids;
            total += placed.centroids->size();
            m_mesh_end.push_back(total);
            m_meshes.push_back(std::move(placed));
            continue;
        }
        last_faces = pm.mesh.faces;
        last_vertices = pm.mesh.vertices;
        auto centroids = std::make_shared<std::vector<CentroidFace>>();
        centroids->reserve(pm.mesh.faces.size());
        if (whole_faces) placed.faces.reserve(pm.mesh.faces.size());
        const scene::Mesh& m = pm.mesh;
        for (const scene::Mesh::Face& f : m.faces) {
            Face face;
            int vi[3], ni[3], ui[3];
            for (int k = 0; k < 3; ++k) {
                vi[k] = f.v[k];
                ni[k] = f.n[k];
                ui[k] = f.uv[k];
            }
            Vec3 p1 = m.vertices[vi[0]], p2 = m.vertices[vi[1]], p3 = m.vertices[vi[2]];
            // POV-Ray compat (Compute_Mesh_Triangle): the normal is (P3 − P1) × (P2 − P1); degenerate faces are
            // dropped, so they take no pixel.
            Vec3 normal = cross(p3 - p1, p2 - p1);
            const double len = length(normal);
            if (len == 0.0) continue;
            normal = normal / len;
            // POV-Ray compat: the first two corners swap when they wind the wrong way round the dominant axis.
            bool swap = false;
            switch (dominant_axis(normal)) {
                case 0: swap = (p2.y - p3.y) * (p2.z - p1.z) < (p2.z - p3.z) * (p2.y - p1.y); break;
                case 1: swap = (p2.x - p3.x) * (p2.z - p1.z) < (p2.z - p3.z) * (p2.x - p1.x); break;
                default: swap = (p2.x - p3.x) * (p2.y - p1.y) < (p2.y - p3.y) * (p2.x - p1.x); break;
            }
            if (swap) {
                std::swap(p1, p2);
                std::swap(vi[0], vi[1]);
                std::swap(ni[0], ni[1]);
                std::swap(ui[0], ui[1]);
            }
            centroids->push_back({(p1 + p2 + p3) / 3.0, normal});
            if (!whole_faces) continue;
            face.p = {p1, p2, p3};
            face.normal = normal;
            face.smooth = ni[0] >= 0 && ni[1] >= 0 && ni[2] >= 0;
            for (int k = 0; k < 3; ++k) {
                if (face.smooth) face.n[k] = normalize(m.normals[ni[k]]);
                face.uv[k] = ui[k] >= 0 ? m.uvs[ui[k]] : Vec3{};
            }
            // POV-Ray compat (compute_smooth_triangle): the data of its smooth-normal interpolation.
            face.v_axis = dominant_axis(p3 - p2);
            Vec3 t1 = normalize(p2 - p3);
            const Vec3 t2 = p1 - p3;
            t1 = t1 * dot(t2, t1);
            face.perp = normalize(t1 - t2);
            face.perp = face.perp / -dot(t2, face.perp);
            placed.faces.push_back(face);
        }
        placed.centroids = std::move(centroids);
        total += placed.centroids->size();
        m_mesh_end.push_back(total);
        m_meshes.push_back(std::move(placed));
    }
    if (m_distribution == 3 && !m_meshes.empty()) {
        // POV-Ray compat (Parse_Mesh_Camera): the faces filed by the tenths of u and v their uv corners span.
        const std::vector<Face>& faces = m_meshes.front().faces;
        for (std::uint32_t i = 0; i < faces.size(); ++i) {
            int lo_u = 9, hi_u = -10, lo_v = 9, hi_v = -10;
            for (int k = 0; k < 3; ++k) {
                const int cu = static_cast<int>(faces[i].uv[k].x * 10), cv = static_cast<int>(faces[i].uv[k].y * 10);
                lo_u = std::min(lo_u, cu);
                hi_u = std::max(hi_u, cu);
                lo_v = std::min(lo_v, cv);
                hi_v = std::max(hi_v, cv);
            }
            for (int c = std::max(lo_u, 0); c <= std::min(hi_u, 9); ++c) m_u_cells[c].push_back(i);
            for (int c = std::max(lo_v, 0); c <= std::min(hi_v, 9); ++c) m_v_cells[c].push_back(i);
        }
    }
}

void MeshCamera::leave(const Frame& frame, const PlacedMesh& mesh, Vec3 origin, Vec3 dir, ProjectedRay& out) const {
    // POV-Ray compat: location's z moves the origin along the (object-space) normal, direction's z < 0 reverses
    // the ray; then the mesh's transform places both.
    origin = origin + dir * frame.camera->location.z;
    if (frame.camera->direction.z < -kPovEpsilon) dir = -dir;
    out.origin = mesh.transform.point(origin);
    out.direction = mesh.transform.normal(dir);
}

bool MeshCamera::uv_ray(const Frame& frame, double u, double v, ProjectedRay& out) const {
    const PlacedMesh& mesh = m_meshes.front();
    // POV-Ray compat: the candidate faces are those filed under both cells, tried in face order; the first
    // whose uv triangle holds (u, v) is the one.
    const int cu = u * 10 >= 9.0 ? 9 : std::max(0, static_cast<int>(u * 10));
    const int cv = v * 10 >= 9.0 ? 9 : std::max(0, static_cast<int>(v * 10));
    const std::vector<std::uint32_t>& us = m_u_cells[cu];
    const std::vector<std::uint32_t>& vs = m_v_cells[cv];
    std::size_t a = 0, b = 0;
    while (a < us.size() && b < vs.size()) {
        if (us[a] < vs[b]) {
            ++a;
            continue;
        }
        if (vs[b] < us[a]) {
            ++b;
            continue;
        }
        const Face& f = mesh.faces[us[a]];
        ++a;
        ++b;
        const double p1u = f.uv[0].x, p2u = f.uv[1].x, p3u = f.uv[2].x;
        const double p1v = f.uv[0].y, p2v = f.uv[1].y, p3v = f.uv[2].y;
        const double scale = (p2u - p1u) * (p3v - p1v) - (p3u - p1u) * (p2v - p1v);
        const double b1 = ((p2u - u) * (p3v - v) - (p3u - u) * (p2v - v)) / scale;
        const double b2 = ((p3u - u) * (p1v - v) - (p1u - u) * (p3v - v)) / scale;
        const double b3 = ((p1u - u) * (p2v - v) - (p2u - u) * (p1v - v)) / scale;
        if (b1 < 0 || b2 < 0 || b3 < 0) continue;
        const Vec3 origin = f.p[0] * b1 + f.p[1] * b2 + f.p[2] * b3;
        Vec3 dir = f.normal;
        if (m_smooth && f.smooth) {
            // POV-Ray compat (Smooth_Mesh_Normal): its own interpolation of the corner normals.
            const Vec3 d = origin - f.p[0];
            const double su = dot(d, f.perp);
            if (su < kPovEpsilon) {
                dir = f.n[0];
            } else {
                const int ax = f.v_axis;
                const double sv = (d[ax] / su + f.p[0][ax] - f.p[1][ax]) / (f.p[2][ax] - f.p[1][ax]);
                dir = f.n[0] + su * (f.n[1] - f.n[0] + sv * (f.n[2] - f.n[1]));
            }
        }
        leave(frame, mesh, origin, dir, out);
        return true;
    }
    return false;
}

bool MeshCamera::ray(const Frame& frame, double px, double py, int ray_number, ProjectedRay& out) const {
    // POV-Ray compat: its pixel position is (px, py − 1) here (CreateCameraRay's x + 0.5, y − 0.5), clipped to
    // the image; distributions 0-2 then truncate it to a pixel index.
    const double x = std::max(0.0, std::min(px, frame.width - 1.0));
    const double y = std::max(0.0, std::min(py - 1.0, frame.height - 1.0));
    const unsigned width = static_cast<unsigned>(frame.width);
    const unsigned index = static_cast<unsigned>(y) * width + static_cast<unsigned>(x);
    auto centroid_ray = [&](const PlacedMesh& mesh, std::size_t face) {
        const CentroidFace& f = (*mesh.centroids)[face];
        leave(frame, mesh, f.centroid, f.normal, out);
        return true;
    };
    out.x0 = 0.0;
    out.y0 = 0.0;
    switch (m_distribution) {
        case 0: {
            // One mesh per sample, one face per pixel in row order.
            const PlacedMesh& mesh = m_meshes[static_cast<std::size_t>(ray_number)];
            if (index >= mesh.centroids->size()) return false;
            return centroid_ray(mesh, index);
        }
        case 1: {
            // POV-Ray compat: the meshes' faces in one sequence; sample n looks n whole sequences further on,
            // so only the first sample of a pixel finds a face.
            const std::size_t total = m_mesh_end.back();
            const std::size_t face = index + static_cast<std::size_t>(ray_number) * total;
            if (face >= total) return false;
            std::size_t first = 0;
            for (std::size_t m = 0; m < m_meshes.size(); ++m) {
                if (m_mesh_end[m] > face) return centroid_ray(m_meshes[m], face - first);
                first = m_mesh_end[m];
            }
            return false;
        }
        case 2: {
            // Side-by-side cameras, one mesh each; POV-Ray compat: the face index counts from the image's left.
            const std::size_t n = m_meshes.size();
            const std::size_t m = static_cast<std::size_t>(x / (frame.width / static_cast<double>(n)));
            if (m >= n) return false;
            const unsigned face = static_cast<unsigned>(y) * static_cast<unsigned>(width / n) +
                                  static_cast<unsigned>(x);
            if (face >= m_meshes[m].centroids->size()) return false;
            return centroid_ray(m_meshes[m], face);
        }
        default: {
            // Texture baking: the image is the unit square of uv space.
            const double u = (x - 0.5) / frame.width;
            const double v = 1.0 - (y + 0.5) / frame.height;
            return uv_ray(frame, u, v, out);
        }
    }
}

}  // namespace wardray::camera
