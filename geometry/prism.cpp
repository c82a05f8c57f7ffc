// Prism meshes: POV-Ray's linear-spline prism (linear or conic sweep) as side walls plus triangulated caps.
#include <cmath>

#include "geometry/mesh.h"

namespace wardray::geometry {

namespace {

// POV-Ray compat: a 2-D point is inside the outline when it is inside an odd number of sub-polygons.
bool inside_outline(const std::vector<std::vector<Vec3>>& loops, double u, double v) {
    bool in = false;
    for (const auto& loop : loops)
        for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
            const Vec3& a = loop[i];
            const Vec3& b = loop[j];
            if ((a.y > v) != (b.y > v) && u < a.x + (v - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
        }
    return in;
}

}  // namespace

std::optional<MeshShape> MeshShape::create(const parser::Prism& prism) {
    for (const Vec3& p : prism.points)
        if (!is_finite(p)) return std::nullopt;
    if (!std::isfinite(prism.height1) || !std::isfinite(prism.height2) || prism.height1 == prism.height2)
        return std::nullopt;
    const double h1 = std::fmin(prism.height1, prism.height2);
    const double h2 = std::fmax(prism.height1, prism.height2);
    // POV-Ray compat: a conic sweep needs heights on one side of its apex (the origin).
    if (prism.conic && h1 < 0.0 && h2 > 0.0) return std::nullopt;
    const auto loops = polygon_loops(prism.points);
    if (loops.empty()) return std::nullopt;
    // Outline point (u, v) at height y: (u, y, v), scaled by y for a conic sweep.
    auto place = [&](const Vec3& uv, double y) {
        const double s = prism.conic ? y : 1.0;
        return Vec3{uv.x * s, y, uv.y * s};
    };
    auto inside = [&](const Vec3& p) {
        if (!(p.y > h1 && p.y < h2)) return false;
        const double s = prism.conic ? p.y : 1.0;
        return inside_outline(loops, p.x / s, p.z / s);
    };

    parser::Mesh mesh;
    auto add_triangle = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        const int base = static_cast<int>(mesh.vertices.size());
        mesh.vertices.insert(mesh.vertices.end(), {a, b, c});
        parser::Mesh::Face f;
        f.v = {base, base + 1, base + 2};
        // Turn the face outward: just in front of its centre must be outside the prism.
        const Vec3 n = cross(b - a, c - a);
        const double len = length(n);
        if (len > 0.0) {
            const Vec3 centre = (a + b + c) / 3.0;
            const double eps = 1e-7 * (1.0 + max_abs_component(centre) + std::sqrt(len));
            if (inside(centre + eps * (n / len))) std::swap(f.v[1], f.v[2]);
        }
        mesh.faces.push_back(f);
    };
    for (const auto& loop : loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Vec3& a = loop[i];
            const Vec3& b = loop[(i + 1) % loop.size()];
            add_triangle(place(a, h1), place(b, h1), place(b, h2));
            add_triangle(place(a, h1), place(b, h2), place(a, h2));
        }
    if (!prism.open) {
        for (double h : {h1, h2}) {
            parser::Polygon cap;
            for (const auto& loop : loops) {
                for (const Vec3& p : loop) cap.points.push_back(place(p, h));
                cap.points.push_back(place(loop.front(), h));
            }
            const auto caps = create(cap);
            if (!caps) continue;
            for (const Face& f : caps->faces())
                add_triangle(caps->vertices()[f.v[0]], caps->vertices()[f.v[1]], caps->vertices()[f.v[2]]);
        }
    }
    // Crossings along a direction in no special position decide the inside, as for a closed mesh.
    mesh.inside_vector = prism.open ? Vec3{1.0, 0.0123, 0.0371} : Vec3{0.0123, 1.0, 0.0371};
    return create(mesh);
}

}  // namespace wardray::geometry
