// Polygon triangulation: POV-Ray's sub-polygons with holes by the even-odd rule, via a CGAL constrained
// Delaunay triangulation (one of the two files that include CGAL).
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <cmath>
#include <deque>
#include <map>
#include <utility>

#include "geometry/mesh.h"

namespace wardray::geometry {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_2<Kernel>;
using FaceInfoBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;  // nesting level, -1 unvisited
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, FaceInfoBase>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;


// Levels by flood fill from the outside: crossing a constrained edge adds one nesting level.
void mark_levels(Cdt& cdt) {
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
    std::deque<std::pair<Cdt::Face_handle, int>> border{{cdt.infinite_face(), 0}};
    while (!border.empty()) {
        auto [start, level] = border.front();
        border.pop_front();
        if (start->info() != -1) continue;
        std::deque<Cdt::Face_handle> queue{start};
        start->info() = level;
        while (!queue.empty()) {
            const Cdt::Face_handle f = queue.front();
            queue.pop_front();
            for (int i = 0; i < 3; ++i) {
                const Cdt::Face_handle n = f->neighbor(i);
                if (n->info() != -1) continue;
                if (cdt.is_constrained({f, i})) {
                    border.push_back({n, level + 1});
                } else {
                    n->info() = level;
                    queue.push_back(n);
                }
            }
        }
    }
}

}  // namespace

Vec3 polygon_normal(const std::vector<std::vector<Vec3>>& loops) {
    Vec3 normal;
    for (const auto& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i) normal += cross(loop[i], loop[(i + 1) % loop.size()]);
    return normal;
}

std::vector<std::vector<Vec3>> polygon_loops(const std::vector<Vec3>& points) {
    std::vector<std::vector<Vec3>> loops;
    std::vector<Vec3> current;
    for (const Vec3& p : points) {
        if (!current.empty() && current.size() >= 3 && p == current.front()) {
            loops.push_back(std::move(current));
            current.clear();
            continue;
        }
        current.push_back(p);
    }
    // POV-Ray compat: an unclosed last sub-polygon is closed (POV-Ray warns about it).
    if (current.size() >= 3) loops.push_back(std::move(current));
    return loops;
}

std::optional<MeshShape> MeshShape::create(const scene::Polygon& polygon) {
    for (const Vec3& p : polygon.points)
        if (!is_finite(p)) return std::nullopt;
    const auto loops = polygon_loops(polygon.points);
    if (loops.empty()) return std::nullopt;
    // The plane of the polygon (Newell's normal of all loops), then 2-D coordinates in it.
    Vec3 normal = polygon_normal(loops);
    if (!(length(normal) > 0.0)) return std::nullopt;
    normal = normalize(normal);
    const Vec3 origin = loops.front().front();
    const Vec3 helper = std::fabs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 e1 = normalize(cross(helper, normal));
    const Vec3 e2 = cross(normal, e1);

    Cdt cdt;
    for (const auto& loop : loops) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Vec3 a = loop[i] - origin;
            const Vec3 b = loop[(i + 1) % loop.size()] - origin;
            const Kernel::Point_2 pa(dot(a, e1), dot(a, e2));
            const Kernel::Point_2 pb(dot(b, e1), dot(b, e2));
            if (pa != pb) cdt.insert_constraint(pa, pb);
        }
    }
    mark_levels(cdt);

    scene::Mesh mesh;
    std::map<Cdt::Vertex_handle, int> index;
    auto vertex = [&](Cdt::Vertex_handle v) {
        auto [it, fresh] = index.try_emplace(v, static_cast<int>(mesh.vertices.size()));
        if (fresh) mesh.vertices.push_back(origin + v->point().x() * e1 + v->point().y() * e2);
        return it->second;
    };
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        // POV-Ray compat: a point inside an odd number of sub-polygons is inside the polygon.
        if (f->info() % 2 != 1) continue;
        scene::Mesh::Face face;
        // POV-Ray compat: the polygon's normal is its points' Newell normal; a face (a, b, c) counter-clockwise
        // about it is stored as (a, c, b), since a mesh face's normal is (p3 - p1) x (p2 - p1).
        for (int k = 0; k < 3; ++k) face.v[k] = vertex(f->vertex(k));
        std::swap(face.v[1], face.v[2]);
        mesh.faces.push_back(face);
    }
    auto shape = create(mesh);
    // A polygon is POV-Ray's own shape, whose crossings are all given (one plane: at most one).
    if (shape) shape->m_nearest_only = false;
    return shape;
}

}  // namespace wardray::geometry
