// Mesh surfaces: uv coordinates and per-triangle textures as POV-Ray 3.7's mesh.cpp gives them.
#include "lighting/mesh_texture.h"

#include "core/constants.h"

namespace wardray::lighting {

Vec3 mesh_uv(const scene::Mesh& mesh, const geometry::Hit& hit) {
    if (hit.face < 0 || static_cast<std::size_t>(hit.face) >= mesh.faces.size()) return {};
    const scene::Mesh::Face& f = mesh.faces[hit.face];
    const double w[3] = {1.0 - hit.bary_u - hit.bary_v, hit.bary_u, hit.bary_v};
    Vec3 uv;
    for (int k = 0; k < 3; ++k)
        if (f.uv[k] >= 0) uv += mesh.uvs[f.uv[k]] * w[k];
    return {uv.x, uv.y, 0.0};
}

double smooth_t(const Vec3& m, const Vec3& a, const Vec3& b, const Vec3& c) {
    // Solve r (M - A) + s (B - C) = B - A on the best-conditioned pair of axes; Q = B + s (C - B).
    const Vec3 am = m - a, cb = b - c, ab = b - a;
    const double dm1 = am.x * cb.y - am.y * cb.x;
    const double dm2 = am.x * cb.z - am.z * cb.x;
    const double dm3 = am.y * cb.z - am.z * cb.y;
    double s = 0.0;
    if (dm1 * dm1 >= kPovEpsilon) s = (am.x * ab.y - am.y * ab.x) / dm1;
    else if (dm2 * dm2 >= kPovEpsilon) s = (am.x * ab.z - am.z * ab.x) / dm2;
    else if (dm3 * dm3 >= kPovEpsilon) s = (am.y * ab.z - am.z * ab.y) / dm3;
    else return 0.0;
    const Vec3 q = b + s * (c - b);
    // t = (M - A) / (Q - A) on the first axis where Q - A is not tiny.
    const Vec3 aq = q - a;
    if (aq.x * aq.x >= kPovEpsilon) return am.x / aq.x;
    if (aq.y * aq.y >= kPovEpsilon) return am.y / aq.y;
    if (aq.z * aq.z >= kPovEpsilon) return am.z / aq.z;
    return 0.0;
}

int mesh_face_textures(const scene::Mesh& mesh, const scene::Object& object, const geometry::Hit& hit,
                       std::array<const scene::Texture*, 3>& textures, std::array<double, 3>& weights) {
    if (mesh.textures.empty() || hit.face < 0 || static_cast<std::size_t>(hit.face) >= mesh.faces.size()) return 0;
    const scene::Mesh::Face& f = mesh.faces[hit.face];
    if (f.tex[0] < 0) return 0;
    if (f.tex[1] < 0 || f.tex[2] < 0) {
        textures[0] = &mesh.textures[f.tex[0]];
        return 1;
    }
    // POV-Ray compat: each corner weighs 1 − t, t measured from it towards the opposite side, in object space.
    const Vec3 p = object.transform.inverse_point(hit.position);
    const Vec3& p1 = mesh.vertices[f.v[0]];
    const Vec3& p2 = mesh.vertices[f.v[1]];
    const Vec3& p3 = mesh.vertices[f.v[2]];
    // POV-Ray compat: the weights are single precision (COLC).
    const float w1 = 1.0f - static_cast<float>(smooth_t(p, p1, p2, p3));
    const float w2 = 1.0f - static_cast<float>(smooth_t(p, p2, p3, p1));
    const float w3 = 1.0f - static_cast<float>(smooth_t(p, p3, p1, p2));
    const float inv = 1.0f / (w1 + w2 + w3);
    weights = {w1 * inv, w2 * inv, w3 * inv};
    for (int k = 0; k < 3; ++k) textures[k] = &mesh.textures[f.tex[k]];
    return 3;
}

}  // namespace wardray::lighting
