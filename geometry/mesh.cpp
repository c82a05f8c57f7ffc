// MeshShape: double-precision ray-triangle tests (Möller & Trumbore 1997) with interpolated smooth normals.
#include "geometry/mesh.h"

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <tuple>

namespace wardray::geometry {

namespace {

// Distance from p to the triangle abc (Ericson, Real-Time Collision Detection, 5.1.5: closest point).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return length(ap);
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return length(bp);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return length(p - (a + (d1 / (d1 - d3)) * ab));
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return length(cp);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return length(p - (a + (d2 / (d2 - d6)) * ac));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return length(p - (b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)));
    const double denom = 1.0 / (va + vb + vc);
    return length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

}  // namespace

namespace {

// The shapes already made from a scene mesh, by the address of its vectors: an entry keeps those vectors (so no
// other mesh can take their address while it lives) and the shape made, whose copies share its data.
struct MadeMesh {
    scene::SharedVector<Vec3> vertices, normals;
    scene::SharedVector<scene::Mesh::Face> faces;
    std::optional<MeshShape> shape;
};
using MeshKey = std::tuple<const void*, const void*, const void*, double, double, double>;
std::mutex g_made_mutex;
std::map<MeshKey, std::weak_ptr<const MadeMesh>> g_made;

}  // namespace

std::optional<MeshShape> MeshShape::create(const scene::Mesh& mesh) {
    const MeshKey key{mesh.vertices.data(), mesh.normals.data(), mesh.faces.data(),
                      mesh.inside_vector.x, mesh.inside_vector.y, mesh.inside_vector.z};
    {
        const std::lock_guard lock(g_made_mutex);
        const auto it = g_made.find(key);
        if (it != g_made.end()) {
            if (auto made = it->second.lock()) {
                std::optional<MeshShape> shape = made->shape;
                if (shape) shape->m_source = std::move(made);
                return shape;
            }
        }
    }
    auto made = std::make_shared<MadeMesh>();
    made->vertices = mesh.vertices;
    made->normals = mesh.normals;
    made->faces = mesh.faces;
    made->shape = build(mesh);
    std::optional<MeshShape> shape = made->shape;
    if (shape) shape->m_source = made;
    const std::lock_guard lock(g_made_mutex);
    // Forget the shapes no longer used, then remember this one.
    for (auto it = g_made.begin(); it != g_made.end();) it = it->second.expired() ? g_made.erase(it) : std::next(it);
    g_made[key] = made;
    return shape;
}

std::optional<MeshShape> MeshShape::build(const scene::Mesh& mesh) {
    MeshShape m;
    for (const Vec3& v : mesh.vertices)
        if (!is_finite(v)) return std::nullopt;
    m.m_vertices = mesh.vertices;
    m.m_normals = mesh.normals;
    std::vector<Face> faces;
    const int nv = static_cast<int>(mesh.vertices.size());
    const int nn = static_cast<int>(mesh.normals.size());
    for (std::size_t fi = 0; fi < mesh.faces.size(); ++fi) {
        const scene::Mesh::Face& f = mesh.faces[fi];
        Face face;
        face.source = static_cast<int>(fi);
        bool ok = true;
        for (int k = 0; k < 3; ++k) {
            ok = ok && f.v[k] >= 0 && f.v[k] < nv;
            face.v[k] = f.v[k];
            face.n[k] = f.n[k];
        }
        if (!ok) continue;
        // Smooth only when all three normals exist and are usable.
        for (int k = 0; k < 3; ++k)
            if (face.n[k] < 0 || face.n[k] >= nn || !(length(mesh.normals[face.n[k]]) > 0.0)) face.n = {-1, -1, -1};
        // Degenerate faces (zero area) can never be hit reliably: leave them out.
        const Vec3 e1 = mesh.vertices[face.v[1]] - mesh.vertices[face.v[0]];
        const Vec3 e2 = mesh.vertices[face.v[2]] - mesh.vertices[face.v[0]];
        if (!(length(cross(e1, e2)) > 0.0)) continue;
        faces.push_back(face);
    }
    if (faces.empty()) return std::nullopt;
    m.m_faces = scene::SharedVector<Face>(std::move(faces));
    m.m_inside_vector = mesh.inside_vector;
    m.m_nearest_only = mesh.inside_vector == Vec3{};
    m.finish();
    return m;
}

void MeshShape::finish() {
    // Read through const references: a non-const access to a shared vector would copy it.
    const std::vector<Vec3>& verts = m_vertices.get();
    const std::vector<Face>& all_faces = m_faces.get();
    const Vec3& first = verts[all_faces.front().v[0]];
    m_bounds = {first, first};
    for (const Face& f : all_faces)
        for (int k = 0; k < 3; ++k) m_bounds = m_bounds.merged({verts[f.v[k]], verts[f.v[k]]});
    // The face tree waits for its first use: a plain mesh that Embree traces never needs it.
    m_lazy_tree = std::make_shared<LazyTree>();
}

const MeshShape::FaceTree* MeshShape::tree() const {
    std::call_once(m_lazy_tree->once, [&] { m_lazy_tree->tree = build_tree(); });
    return m_lazy_tree->tree.get();
}

std::shared_ptr<const MeshShape::FaceTree> MeshShape::build_tree() const {
    const std::vector<Vec3>& verts = m_vertices.get();
    const std::vector<Face>& all_faces = m_faces.get();
    // A few faces are cheaper to test one by one than through a tree.
    constexpr std::size_t k_min_faces = 16, k_leaf_faces = 4;
    if (all_faces.size() < k_min_faces || all_faces.size() > std::numeric_limits<std::uint32_t>::max()) return nullptr;
    // Boxes are padded by a little more than rounding can move a crossing, so no face a ray meets is left out.
    const double pad = 1e-7 * (m_bounds.magnitude() + 1.0);
    const std::size_t n = all_faces.size();
    std::vector<Bounds> boxes(n);
    std::vector<Vec3> centres(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Face& f = all_faces[i];
        Bounds b{verts[f.v[0]], verts[f.v[0]]};
        for (int k = 1; k < 3; ++k) b = b.merged({verts[f.v[k]], verts[f.v[k]]});
        boxes[i] = {b.lower - Vec3{pad, pad, pad}, b.upper + Vec3{pad, pad, pad}};
        centres[i] = 0.5 * (b.lower + b.upper);
    }
    auto tree = std::make_shared<FaceTree>();
    tree->order.resize(n);
    for (std::size_t i = 0; i < n; ++i) tree->order[i] = static_cast<std::uint32_t>(i);
    tree->nodes.reserve(2 * n / k_leaf_faces + 1);
    // Median split along the widest axis of the centres; a node's left child is the node after it. Median splits
    // keep the recursion depth at log2 of the face count.
    auto build = [&](auto& self, std::size_t begin, std::size_t end) -> void {
        const std::size_t node = tree->nodes.size();
        tree->nodes.emplace_back();
        Bounds box = boxes[tree->order[begin]];
        Bounds cb{centres[tree->order[begin]], centres[tree->order[begin]]};
        for (std::size_t i = begin + 1; i < end; ++i) {
            box = box.merged(boxes[tree->order[i]]);
            cb = cb.merged({centres[tree->order[i]], centres[tree->order[i]]});
        }
        tree->nodes[node].box = box;
        const Vec3 extent = cb.upper - cb.lower;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        if (end - begin <= k_leaf_faces || !(extent[axis] > 0.0)) {
            tree->nodes[node].first = static_cast<std::uint32_t>(begin);
            tree->nodes[node].count = static_cast<std::uint32_t>(end - begin);
            return;
        }
        const std::size_t mid = begin + (end - begin) / 2;
        std::nth_element(tree->order.begin() + static_cast<std::ptrdiff_t>(begin),
                         tree->order.begin() + static_cast<std::ptrdiff_t>(mid),
                         tree->order.begin() + static_cast<std::ptrdiff_t>(end),
                         [&](std::uint32_t x, std::uint32_t y) { return centres[x][axis] < centres[y][axis]; });
        self(self, begin, mid);
        tree->nodes[node].first = static_cast<std::uint32_t>(tree->nodes.size());
        self(self, mid, end);
    };
    build(build, 0, n);
    return tree;
}

std::optional<Vec3> MeshShape::params_at(std::size_t face, double bary_u, double bary_v) const {
    if (m_params.empty() || face >= m_faces.size()) return std::nullopt;
    const Face& f = m_faces[face];
    return (1.0 - bary_u - bary_v) * m_params[f.v[0]] + bary_u * m_params[f.v[1]] + bary_v * m_params[f.v[2]];
}

std::optional<SurfaceHit> MeshShape::intersect_face(const LocalRay& ray, std::size_t index, double t_min,
                                                    double t_max, bool known_hit, double* bary) const {
    FaceCrossing c;
    if (!face_crossing(ray, index, t_min, t_max, known_hit, c)) return std::nullopt;
    if (bary) {
        bary[0] = c.u;
        bary[1] = c.v;
    }
    bool entering = true;
    const Vec3 normal = face_normal(index, c, ray.direction, &entering);
    return SurfaceHit{c.t, normal, entering};
}

Vec3 MeshShape::face_normal(std::size_t index, const FaceCrossing& c, const Vec3& direction, bool* entering) const {
    const Face& f = m_faces[index];
    const Vec3& a = m_vertices[f.v[0]];
    const Vec3 e1 = m_vertices[f.v[1]] - a;
    const Vec3 e2 = m_vertices[f.v[2]] - a;
    // POV-Ray compat: a triangle's normal is (p3 - p1) x (p2 - p1), so the side a face's normal is on follows its
    // vertex order as in POV-Ray (trace() returns it, interior_texture shows on the other side, a closed mesh is
    // entered against it). Smooth triangles interpolate their vertex normals as given, whichever side they face.
    const Vec3 ng = cross(e2, e1);
    if (entering) *entering = dot(ng, direction) < 0.0;
    if (f.n[0] < 0) return ng;
    const Vec3 ns = (1.0 - c.u - c.v) * normalize(m_normals[f.n[0]]) + c.u * normalize(m_normals[f.n[1]]) +
                    c.v * normalize(m_normals[f.n[2]]);
    if (!(length(ns) > 0.0)) return ng;
    return m_normals_outward && dot(ns, ng) < 0.0 ? -ns : ns;
}

void MeshShape::candidate_faces(const FaceTree& tree, const LocalRay& ray, double t_min, double t_max,
                                std::vector<std::uint32_t>& out) {
    out.clear();
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const TreeNode& node = tree.nodes[stack[--top]];
        double s0 = 0.0, s1 = 0.0;
        if (!slab_interval(node.box.lower, node.box.upper, ray.origin, ray.direction, s0, s1)) continue;
        if (!(s1 >= t_min && s0 <= t_max)) continue;
        if (node.count > 0) {
            out.insert(out.end(), tree.order.begin() + node.first, tree.order.begin() + node.first + node.count);
            continue;
        }
        const auto self = static_cast<std::uint32_t>(&node - tree.nodes.data());
        stack[top++] = node.first;
        stack[top++] = self + 1;
    }
    std::sort(out.begin(), out.end());
}

SurfaceHits MeshShape::nearest_crossings(const LocalRay& ray, double t_min, double t_max) const {
    constexpr double far = std::numeric_limits<double>::infinity();
    thread_local std::vector<std::uint32_t> faces;
    if (const FaceTree* tree = this->tree()) {
        candidate_faces(*tree, ray, t_min, far, faces);
    } else {
        faces.resize(m_faces.size());
        for (std::size_t i = 0; i < m_faces.size(); ++i) faces[i] = static_cast<std::uint32_t>(i);
    }
    // Each face's box: where the ray enters it, nearest first (faces whose box it never meets are left out).
    thread_local std::vector<std::pair<double, std::uint32_t>> entries;
    entries.clear();
    for (const std::uint32_t i : faces) {
        const Face& f = m_faces[i];
        Bounds b{m_vertices[f.v[0]], m_vertices[f.v[0]]};
        for (int k = 1; k < 3; ++k) b = b.merged({m_vertices[f.v[k]], m_vertices[f.v[k]]});
        double s0 = 0.0, s1 = 0.0;
        if (slab_interval(b.lower, b.upper, ray.origin, ray.direction, s0, s1) && s1 >= t_min)
            entries.emplace_back(s0, i);
    }
    std::stable_sort(entries.begin(), entries.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    SurfaceHits hits;
    double best = far;
    for (const auto& [entry, i] : entries) {
        if (entry > best) break;
        const auto h = intersect_face(ray, i, t_min, far);
        if (!h) continue;
        // POV-Ray compat: the walk's bound is the crossing found last, not the nearest one.
        best = h->t;
        if (h->t < t_max) hits.push(*h);
    }
    hits.sort_by_t();
    return hits;
}

SurfaceHits MeshShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    // POV-Ray compat: a mesh without an inside_vector gives only the crossings its box walk meets before it stops
    // (mesh.cpp, intersect_bbox_tree), so a CSG sees its far side only where its boxes overlap the near crossing.
    if (m_nearest_only) return nearest_crossings(ray, t_min, t_max);
    SurfaceHits hits;
    if (const FaceTree* tree = this->tree()) {
        thread_local std::vector<std::uint32_t> faces;
        candidate_faces(*tree, ray, t_min, t_max, faces);
        for (const std::uint32_t i : faces)
            if (const auto h = intersect_face(ray, i, t_min, t_max)) hits.push(*h);
    } else {
        for (std::size_t i = 0; i < m_faces.size(); ++i)
            if (const auto h = intersect_face(ray, i, t_min, t_max)) hits.push(*h);
    }
    hits.sort_by_t();
    return hits;
}

bool MeshShape::inside(const Vec3& p) const {
    if (m_inside_vector == Vec3{}) return false;
    // POV-Ray compat: a point is inside a mesh when a ray along inside_vector crosses it an odd number of times.
    const LocalRay ray{p, m_inside_vector};
    constexpr double far = std::numeric_limits<double>::infinity();
    std::size_t crossings = 0;
    if (const FaceTree* tree = this->tree()) {
        thread_local std::vector<std::uint32_t> faces;
        candidate_faces(*tree, ray, 0.0, far, faces);
        for (const std::uint32_t i : faces)
            if (intersect_face(ray, i, 0.0, far)) ++crossings;
    } else {
        for (std::size_t i = 0; i < m_faces.size(); ++i)
            if (intersect_face(ray, i, 0.0, far)) ++crossings;
    }
    return crossings % 2 == 1;
}

double MeshShape::implicit(const Vec3& p) const {
    double best = std::numeric_limits<double>::infinity();
    for (const Face& f : m_faces)
        best = std::fmin(best, point_triangle_distance(p, m_vertices[f.v[0]], m_vertices[f.v[1]], m_vertices[f.v[2]]));
    return best;
}

}  // namespace wardray::geometry
