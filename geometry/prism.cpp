// Prism meshes: POV-Ray's conic sweeps as side walls plus triangulated caps, of linear outlines (flat walls) and of
// spline outlines, which are sampled finely with the spline's own normals at every sample so shading follows the
// curve rather than the facets (linear sweeps are LinearPrismShape and SplinePrismShape).
#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "geometry/mesh.h"
#include "geometry/prism_outline.h"

namespace wardray::geometry {

namespace {

// Samples per spline piece: enough that the outline turns at most half a degree between two samples (POV-Ray
// parity needs far finer steps than the eye: the walls' interpolated normals and the caps' edges both follow them).
constexpr double kMaxTurnPerSample = 0.5 * 3.14159265358979323846 / 180.0;
constexpr int kMinSamples = 4;
constexpr int kMaxSamples = 128;

// One edge of the outline in (u, v, 0), with the outline's tangent at both ends (zero: a flat wall).
struct Edge {
    Vec3 a, b;
    Vec3 ta, tb;
};

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

// The outline as loops of edges: the sub-polygons of a linear outline, or the sampled spline pieces chained into
// loops wherever one piece starts where the last one ended.
std::vector<std::vector<Edge>> outline_edges(const scene::Prism& prism) {
    std::vector<std::vector<Edge>> loops;
    if (prism.spline == scene::Prism::Spline::Linear) {
        for (const auto& loop : polygon_loops(prism.points)) {
            std::vector<Edge> edges;
            for (std::size_t i = 0; i < loop.size(); ++i) edges.push_back({loop[i], loop[(i + 1) % loop.size()], {}, {}});
            loops.push_back(std::move(edges));
        }
        return loops;
    }
    std::vector<Edge> current;
    auto close = [&] {
        if (current.size() >= 2) loops.push_back(std::move(current));
        current.clear();
    };
    for (const PrismPiece& piece : prism_spline_pieces(prism)) {
        const Vec3 start = piece.at(0.0);
        if (!current.empty() && length(current.back().b - start) > 1e-9) close();
        // The piece's total turn, from its tangent at 64 places.
        double turn = 0.0;
        Vec3 last = piece.tangent(0.0);
        for (int k = 1; k <= 64; ++k) {
            const Vec3 t = piece.tangent(k / 64.0);
            if (length(t) > 0.0 && length(last) > 0.0)
                turn += std::atan2(std::fabs(cross(last, t).z), dot(last, t));
            if (length(t) > 0.0) last = t;
        }
        const int samples = std::clamp(static_cast<int>(std::ceil(turn / kMaxTurnPerSample)), kMinSamples, kMaxSamples);
        for (int k = 0; k < samples; ++k) {
            const double w0 = double(k) / samples, w1 = double(k + 1) / samples;
            const Edge e{piece.at(w0), piece.at(w1), piece.tangent(w0), piece.tangent(w1)};
            if (length(e.b - e.a) > 0.0) current.push_back(e);
        }
    }
    close();
    return loops;
}

}  // namespace

std::optional<MeshShape> MeshShape::create(const scene::Prism& prism) {
    for (const Vec3& p : prism.points)
        if (!is_finite(p)) return std::nullopt;
    if (!std::isfinite(prism.height1) || !std::isfinite(prism.height2) || prism.height1 == prism.height2)
        return std::nullopt;
    const double h1 = std::fmin(prism.height1, prism.height2);
    const double h2 = std::fmax(prism.height1, prism.height2);
    // POV-Ray compat: a conic sweep needs heights on one side of its apex (the origin).
    if (prism.conic && h1 < 0.0 && h2 > 0.0) return std::nullopt;
    const auto edge_loops = outline_edges(prism);
    std::vector<std::vector<Vec3>> loops;
    for (const auto& edges : edge_loops) {
        std::vector<Vec3> loop;
        for (const Edge& e : edges) loop.push_back(e.a);
        if (loop.size() >= 3) loops.push_back(std::move(loop));
    }
    if (loops.empty()) return std::nullopt;
    // Outline point (u, v) at height y: (u, y, v), scaled by y for a conic sweep.
    auto place = [&](const Vec3& uv, double y) {
        const double s = prism.conic ? y : 1.0;
        return Vec3{uv.x * s, y, uv.y * s};
    };
    // The wall's normal at an outline point with tangent (du, dv): across the tangent and the sweep direction.
    auto wall_normal = [&](const Vec3& uv, const Vec3& t) {
        if (!prism.conic) return Vec3{t.y, 0.0, -t.x};
        return Vec3{-t.y, t.y * uv.x - t.x * uv.y, t.x};
    };

    // Which side of each loop is inside, from one test beside its longest edge: every edge of the loop faces the
    // same way (a per-triangle test would cost the outline's size for each of its triangles).
    std::vector<double> loop_sign(edge_loops.size(), 1.0);
    for (std::size_t l = 0; l < edge_loops.size(); ++l) {
        const Edge* longest = nullptr;
        for (const Edge& e : edge_loops[l])
            if (longest == nullptr || length(e.b - e.a) > length(longest->b - longest->a)) longest = &e;
        if (longest == nullptr) continue;
        const Vec3 d = longest->b - longest->a;
        const double len = length(d);
        const Vec3 mid = 0.5 * (longest->a + longest->b);
        const double eps = 1e-7 * (max_abs_component(mid) + len);
        if (inside_outline(loops, mid.x + eps * d.y / len, mid.y - eps * d.x / len)) loop_sign[l] = -1.0;
    }
    // A conic sweep below its apex turns the outline half round.
    const double sweep_sign = prism.conic && h1 + h2 < 0.0 ? -1.0 : 1.0;

    scene::Mesh mesh;
    // A triangle turned to face `outward`, with vertex normals when given.
    auto add_triangle = [&](const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& outward,
                            const Vec3* normals = nullptr) {
        const int base = static_cast<int>(mesh.vertices.size());
        mesh.vertices.mut().insert(mesh.vertices.mut().end(), {a, b, c});
        scene::Mesh::Face f;
        f.v = {base, base + 1, base + 2};
        if (normals != nullptr) {
            const int nb = static_cast<int>(mesh.normals.size());
            mesh.normals.mut().insert(mesh.normals.mut().end(), {normals[0], normals[1], normals[2]});
            f.n = {nb, nb + 1, nb + 2};
        }
        if (dot(cross(c - a, b - a), outward) < 0.0) {
            std::swap(f.v[1], f.v[2]);
            std::swap(f.n[1], f.n[2]);
        }
        mesh.faces.push_back(f);
    };
    for (std::size_t l = 0; l < edge_loops.size(); ++l)
        for (const Edge& e : edge_loops[l]) {
            const Vec3 a1 = place(e.a, h1), b1 = place(e.b, h1), a2 = place(e.a, h2), b2 = place(e.b, h2);
            // The edge's outward side in the outline's plane, placed in x-z.
            const double k = loop_sign[l] * sweep_sign;
            const Vec3 outward{k * (e.b.y - e.a.y), 0.0, -k * (e.b.x - e.a.x)};
            if (e.ta == Vec3{} || e.tb == Vec3{}) {
                add_triangle(a1, b1, b2, outward);
                add_triangle(a1, b2, a2, outward);
                continue;
            }
            // Smooth walls: the mesh keeps interpolated normals on the geometric side, so their sign is free.
            const Vec3 na = wall_normal(e.a, e.ta), nb = wall_normal(e.b, e.tb);
            const Vec3 n1[3] = {na, nb, nb};
            const Vec3 n2[3] = {na, nb, na};
            add_triangle(a1, b1, b2, outward, n1);
            add_triangle(a1, b2, a2, outward, n2);
        }
    if (!prism.open) {
        for (double h : {h1, h2}) {
            scene::Polygon cap;
            for (const auto& loop : loops) {
                for (const Vec3& p : loop) cap.points.push_back(place(p, h));
                cap.points.push_back(place(loop.front(), h));
            }
            const auto caps = create(cap);
            if (!caps) continue;
            const Vec3 outward{0.0, h == h1 ? -1.0 : 1.0, 0.0};
            for (const Face& f : caps->faces())
                add_triangle(caps->vertices()[f.v[0]], caps->vertices()[f.v[1]], caps->vertices()[f.v[2]], outward);
        }
    }
    // Crossings along a direction in no special position decide the inside, as for a closed mesh.
    mesh.inside_vector = prism.open ? Vec3{1.0, 0.0123, 0.0371} : Vec3{0.0123, 1.0, 0.0371};
    auto shape = create(mesh);
    // The walls' vertex normals are the outline's, which near a kink can face away from a wall's face; a prism is
    // solid, so its normal stays on the outside.
    if (shape) shape->m_normals_outward = true;
    return shape;
}

std::vector<PrismPiece> prism_spline_pieces(const scene::Prism& prism) {
    using Spline = scene::Prism::Spline;
    const auto& P = prism.points;
    const int n = static_cast<int>(P.size());
    std::vector<PrismPiece> pieces;
    Vec3 first = P.size() > 1 ? P[1] : Vec3{};
    auto same = [](const Vec3& a, const Vec3& b) {
        return std::fabs(a.x - b.x) < kPovEpsilon && std::fabs(a.y - b.y) < kPovEpsilon;
    };
    for (int i = 0; i < n - 1; ++i) {
        PrismPiece piece;
        for (int axis = 0; axis < 2; ++axis) {
            double* c = axis == 0 ? piece.cu : piece.cv;
            auto p = [&](int k) { return axis == 0 ? P[k].x : P[k].y; };
            switch (prism.spline) {
                case Spline::Quadratic:
                    if (i + 2 >= n) return pieces;
                    c[0] = p(i + 1);
                    c[1] = -0.5 * p(i) + 0.5 * p(i + 2);
                    c[2] = 0.5 * p(i) - p(i + 1) + 0.5 * p(i + 2);
                    c[3] = 0.0;
                    break;
                case Spline::Cubic:
                    if (i + 3 >= n) return pieces;
                    c[0] = p(i + 1);
                    c[1] = -0.5 * p(i) + 0.5 * p(i + 2);
                    c[2] = p(i) - 2.5 * p(i + 1) + 2.0 * p(i + 2) - 0.5 * p(i + 3);
                    c[3] = -0.5 * p(i) + 1.5 * p(i + 1) - 1.5 * p(i + 2) + 0.5 * p(i + 3);
                    break;
                default:  // Bézier
                    if (i + 3 >= n) return pieces;
                    c[0] = p(i);
                    c[1] = 3.0 * (p(i + 1) - p(i));
                    c[2] = 3.0 * p(i + 2) - 6.0 * p(i + 1) + 3.0 * p(i);
                    c[3] = p(i + 3) - 3.0 * p(i + 2) + 3.0 * p(i + 1) - p(i);
                    break;
            }
        }
        piece.end = prism.spline == Spline::Bezier ? P[i + 3] : P[i + 2];
        piece.end.z = 0.0;
        pieces.push_back(piece);
        switch (prism.spline) {
            case Spline::Quadratic:
                if (same(P[i + 2], first)) {
                    i += 2;
                    if (i + 2 < n) first = P[i + 2];
                }
                break;
            case Spline::Cubic:
                if (same(P[i + 2], first)) {
                    i += 3;
                    if (i + 2 < n) first = P[i + 2];
                }
                break;
            default:
                i += 3;
                break;
        }
    }
    return pieces;
}

}  // namespace wardray::geometry
