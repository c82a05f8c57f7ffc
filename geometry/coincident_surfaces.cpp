// Coincident surfaces: finds primitives whose surfaces lie on one another (to rounding), which POV-Ray draws as a
// random speckle of either surface, so that the user hears of it at both places. This half pairs the records that
// coincident_collect.cpp gathers.
#include "geometry/coincident_surfaces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "core/diagnostic_list.h"
#include "core/vec3.h"
#include "geometry/coincident_records.h"
#include "geometry/surface_pieces.h"
#include "scene/scene.h"

namespace wardray::geometry {

namespace {

using detail::Face;
using detail::kInfinity;
using detail::kTolerance;
using detail::Leaf;
using detail::Node;
using detail::Round;

// Pair tests allowed in all: a scene of many equal faces is cut short rather than slowed down.
constexpr std::size_t kPairBudget = 4'000'000;

class Finder {
public:
    explicit Finder(const scene::Scene& scene) { detail::collect_surfaces(scene, m); }

    // Every coincident pair found, in the order of the primitives, each pair of primitives once.
    const std::map<std::pair<std::uint32_t, std::uint32_t>, std::string>& pairs() {
        match_faces();
        match_rounds();
        return m_found;
    }

    const Leaf& leaf(std::uint32_t i) const { return m.leaves[i]; }

    // The nearest CSG node above a primitive written at another place than the primitive, if any.
    const scene::Object* context(std::uint32_t i) const {
        const scene::Object& o = *m.leaves[i].object;
        for (std::int32_t n = m.leaves[i].node; n >= 0; n = m.nodes[static_cast<std::size_t>(n)].parent) {
            const scene::Object* parent = m.nodes[static_cast<std::size_t>(n)].object;
            if (parent->loc != o.loc) return parent;
        }
        return nullptr;
    }

private:
    // The innermost CSG node above both primitives clips them (-1 nodes share none).
    bool clip_each_other(std::uint32_t i, std::uint32_t j) const {
        std::int32_t a = m.leaves[i].node, b = m.leaves[j].node;
        while (a >= 0 && b >= 0 && a != b) {
            const Node& na = m.nodes[static_cast<std::size_t>(a)];
            const Node& nb = m.nodes[static_cast<std::size_t>(b)];
            if (na.depth >= nb.depth) a = na.parent;
            else b = nb.parent;
        }
        return a >= 0 && a == b && m.nodes[static_cast<std::size_t>(a)].clips;
    }

    // Whether the choice between the two surfaces can change the picture.
    bool matters(std::uint32_t i, std::uint32_t j, bool same_facing) const {
        if (clip_each_other(i, j)) return true;
        const Leaf& a = m.leaves[i];
        const Leaf& b = m.leaves[j];
        if (same_facing) return !(a.object->texture == b.object->texture);
        return a.see_through || b.see_through;
    }

    void found(std::uint32_t i, std::uint32_t j, const char* surface) {
        if (i > j) std::swap(i, j);
        m_found.emplace(std::pair{i, j}, surface);
    }

    bool spend() { return m_tests++ < kPairBudget; }

    void match_faces() {
        // Faces grouped by their normal to about 1e-6, in order of the faces within a group; the keys go once the
        // groups are known. A unit normal's components round to -1e6..1e6: 21 bits each, packed in the order of
        // (x, y, z).
        std::vector<std::uint32_t> order(m.faces.size());
        std::vector<std::size_t> ends;  // where each group ends in `order`
        {
            struct Keyed {
                std::uint64_t key;
                std::uint32_t face;
                bool operator<(const Keyed& o) const { return key != o.key ? key < o.key : face < o.face; }
            };
            auto field = [](double c) { return static_cast<std::uint64_t>(std::llround(c * 1e6) + 1'000'000); };
            std::vector<Keyed> keyed(m.faces.size());
            for (std::size_t k = 0; k < m.faces.size(); ++k) {
                const Vec3& n = m.faces[k].normal;
                keyed[k] = {field(n.x) << 42 | field(n.y) << 21 | field(n.z), static_cast<std::uint32_t>(k)};
            }
            std::sort(keyed.begin(), keyed.end());
            for (std::size_t k = 0; k < keyed.size(); ++k) {
                order[k] = keyed[k].face;
                if (k + 1 == keyed.size() || keyed[k + 1].key != keyed[k].key) ends.push_back(k + 1);
            }
        }
        std::size_t begin = 0;
        for (const std::size_t end : ends) {
            match_group(order, begin, end);
            begin = end;
        }
    }

    // One group of faces of one normal (order[first..last)), drawn in one basis (u, v): sorted by offset, compared
    // in runs.
    void match_group(const std::vector<std::uint32_t>& order, std::size_t first, std::size_t last) {
        m_basis = plane_basis(m.faces[order[first]].normal);
        double reach = 0.0;
        for (std::size_t k = first; k < last; ++k)
            reach = std::max(reach, std::abs(m.faces[order[k]].offset) + m.faces[order[k]].size);
        // (offset, face) by offset: std::sort compares the offsets as it did the faces', so the order is the same.
        std::vector<std::pair<double, std::size_t>> members(last - first);
        for (std::size_t k = first; k < last; ++k) members[k - first] = {m.faces[order[k]].offset, order[k]};
        std::sort(members.begin(), members.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        // Runs of faces whose offsets lie within the widest tolerance of one another: only those are compared.
        const double window = kTolerance * reach;
        for (std::size_t begin = 0; begin < members.size();) {
            std::size_t end = begin + 1;
            while (end < members.size() && members[end].first - members[end - 1].first <= window) ++end;
            if (end - begin > 1) {
                // The run's faces (copied, at hand in the sweeps), their bounds and shapes, by their place in the run.
                m_run.clear();
                m_run_faces.clear();
                for (std::size_t k = begin; k < end; ++k) {
                    m_run.push_back(members[k].second);
                    m_run_faces.push_back(m.faces[members[k].second]);
                }
                m_uv.resize(m_run.size());
                m_shape_of.assign(m_run.size(), -1);
                m_shapes.clear();
                for (std::uint32_t x = 0; x < m_run.size(); ++x) m_uv[x] = bound(m_run_faces[x]);
                sweep_run();
            }
            begin = end;
        }
    }

    // A face's bounds in its group's (u, v): u0, u1, v0, v1 of its corners when nothing cuts it, else of its shape.
    std::array<double, 4> bound(const Face& f) const {
        if (!f.bounded) return {-kInfinity, kInfinity, -kInfinity, kInfinity};
        const auto& [u, v] = m_basis;
        std::array<double, 4> uv{kInfinity, -kInfinity, kInfinity, -kInfinity};
        for (std::uint32_t k = f.first; k < f.first + f.count; ++k) {
            const Vec3& p = m.points[m.corners[k]];
            const double a = dot(p, u), b = dot(p, v);
            uv = {std::min(uv[0], a), std::max(uv[1], a), std::min(uv[2], b), std::max(uv[3], b)};
        }
        // Within what a CSG keeps: that box's extent in (u, v) limits it too.
        if (const std::optional<Bounds> kept = m.clip_of(m.leaves[f.leaf])) {
            std::array<double, 4> box{kInfinity, -kInfinity, kInfinity, -kInfinity};
            for (const Vec3& c : corners(*kept)) {
                const double a = dot(c, u), b = dot(c, v);
                box = {std::min(box[0], a), std::max(box[1], a), std::min(box[2], b), std::max(box[3], b)};
            }
            uv = {std::max(uv[0], box[0]), std::min(uv[1], box[1]), std::max(uv[2], box[2]), std::min(uv[3], box[3])};
        }
        return uv;
    }

    // The shape of the run's face x in its group's (u, v), the hull of its corners less its leaf's cuts, made once
    // (its bounds, which the sweeps use, stay); empty when nothing is left.
    const std::vector<Point2>& make_shape(std::uint32_t x) {
        if (m_shape_of[x] >= 0) return m_shapes[static_cast<std::size_t>(m_shape_of[x])];
        m_shape_of[x] = static_cast<std::int32_t>(m_shapes.size());
        const Face& f = m_run_faces[x];
        const Leaf& leaf = m.leaves[f.leaf];
        const auto& [u, v] = m_basis;
        std::vector<Point2> flat;
        for (std::uint32_t k = f.first; k < f.first + f.count; ++k) {
            const Vec3& p = m.points[m.corners[k]];
            flat.push_back({dot(p, u), dot(p, v)});
        }
        std::vector<HalfSpace> cuts;
        for (std::uint32_t k = leaf.first_cut; k < leaf.first_cut + leaf.cut_count; ++k) cuts.push_back(m.cuts[k].space);
        m_shapes.push_back(cut_polygon(hull(std::move(flat)), f.normal * f.offset, {u, v}, cuts, m.clip_of(leaf),
                                       kTolerance * (f.size + std::abs(f.offset))));
        return m_shapes.back();
    }

    const Face& run_face(std::uint32_t x) const { return m_run_faces[x]; }
    const Leaf& run_leaf(std::uint32_t x) const { return m.leaves[run_face(x).leaf]; }

    // The run of faces in one plane: where none lets light through, faces facing opposite ways matter only when a CSG
    // clips one by the other, inside one top-level object (opaque solids touching face to face hide their contact),
    // so each facing is swept alone, and each clipped object's faces together.
    void sweep_run() {
        std::vector<std::uint32_t> all(m_run.size());
        for (std::uint32_t x = 0; x < all.size(); ++x) all[x] = x;
        const bool see_through =
            std::any_of(all.begin(), all.end(), [&](std::uint32_t x) { return run_leaf(x).see_through; });
        if (see_through) return sweep(all);
        std::vector<std::uint32_t> facing[2];
        std::vector<std::array<std::uint32_t, 3>> clipped;  // (top-level object, face, its place in the run)
        for (std::uint32_t x : all) {
            const Face& f = run_face(x);
            if (f.two_sided || f.facing > 0) facing[0].push_back(x);
            if (f.two_sided || f.facing < 0) facing[1].push_back(x);
            const Leaf& leaf = m.leaves[f.leaf];
            if (m.in_clipping(leaf.node)) clipped.push_back({leaf.top, static_cast<std::uint32_t>(m_run[x]), x});
        }
        // Faces facing one way matter only with different textures: one texture shared by all settles the side.
        for (const auto& side : facing) {
            if (side.empty()) continue;
            const scene::Object& first = *run_leaf(side.front()).object;
            const bool one_texture = std::all_of(side.begin(), side.end(), [&](std::uint32_t x) {
                return run_leaf(x).object->texture.shares(first.texture);
            });
            if (side.size() > 1 && !one_texture) sweep(side);
        }
        std::sort(clipped.begin(), clipped.end());
        for (std::size_t begin = 0; begin < clipped.size();) {
            std::size_t end = begin + 1;
            while (end < clipped.size() && clipped[end][0] == clipped[begin][0]) ++end;
            if (end - begin > 1) {
                std::vector<std::uint32_t> same_object;
                for (std::size_t k = begin; k < end; ++k) same_object.push_back(clipped[k][2]);
                sweep(same_object);
            }
            begin = end;
        }
    }

    // Tests the run's faces x and y (offsets within the window): reports them if they coincide over an area.
    void test_faces(std::uint32_t x, std::uint32_t y) {
        const Face& a = run_face(x);
        const Face& b = run_face(y);
        const std::array<double, 4>& ua = m_uv[x];
        const std::array<double, 4>& ub = m_uv[y];
        const double tol = kTolerance * std::max({std::abs(a.offset), std::abs(b.offset), a.size, b.size});
        if (a.leaf == b.leaf) return;
        if (std::min(ua[3], ub[3]) - std::max(ua[2], ub[2]) <= tol) return;
        if (std::min(ua[1], ub[1]) - std::max(ua[0], ub[0]) <= tol) return;
        if (std::abs(a.offset - b.offset) > tol) return;
        if (length(cross(a.normal, b.normal)) > 1e-8) return;
        // The cheap questions first: whether the choice shows, and whether the pair is known already.
        const bool same_facing = a.two_sided || b.two_sided || a.facing == b.facing;
        if (m_found.contains({std::min(a.leaf, b.leaf), std::max(a.leaf, b.leaf)})) return;
        if (!matters(a.leaf, b.leaf, same_facing)) return;
        if (a.bounded && b.bounded) {
            const std::vector<Point2>& shape_a = make_shape(x);
            const std::vector<Point2>& shape_b = make_shape(y);
            if (shape_a.empty() || shape_b.empty() || !overlap(shape_a, shape_b, tol)) return;
        }
        found(a.leaf, b.leaf, "flat faces");
    }

    // The pairs of the run's faces `list` whose bounds overlap: all pairs for a short list; else the faces in a
    // grid of cells about the size of a typical face, each pair tested in the first cell both cover, and faces
    // over many cells (planes) against all.
    void sweep(const std::vector<std::uint32_t>& list) {
        if (list.size() <= 32) {
            for (std::size_t x = 0; x < list.size(); ++x)
                for (std::size_t y = x + 1; y < list.size(); ++y) {
                    if (!spend()) return;
                    test_faces(list[x], list[y]);
                }
            return;
        }
        std::vector<double> sizes;
        for (std::uint32_t x : list)
            if (run_face(x).bounded) sizes.push_back(std::max(m_uv[x][1] - m_uv[x][0], m_uv[x][3] - m_uv[x][2]));
        std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
        const double cell = sizes.empty() ? 0.0 : 2.0 * sizes[sizes.size() / 2];
        std::vector<std::uint32_t> wide, narrow;
        // Each face listed in every cell it covers; sorted by cell (then face), the faces of one cell lie together.
        struct Entry {
            long long i, j;
            std::uint32_t face, x;  // the face, and its place in the run
            bool operator<(const Entry& o) const { return std::tie(i, j, face) < std::tie(o.i, o.j, o.face); }
        };
        std::vector<Entry> grid;
        auto span = [&](std::uint32_t x) {
            const std::array<double, 4>& uv = m_uv[x];
            return std::array<long long, 4>{static_cast<long long>(std::floor(uv[0] / cell)),
                                            static_cast<long long>(std::floor(uv[1] / cell)),
                                            static_cast<long long>(std::floor(uv[2] / cell)),
                                            static_cast<long long>(std::floor(uv[3] / cell))};
        };
        for (std::uint32_t x : list) {
            const std::array<double, 4>& uv = m_uv[x];
            if (!(uv[0] <= uv[1])) continue;  // nothing left of it
            if (!run_face(x).bounded || !(cell > 0.0) || (uv[1] - uv[0]) > 4 * cell || (uv[3] - uv[2]) > 4 * cell) {
                wide.push_back(x);
                continue;
            }
            narrow.push_back(x);
            const auto c = span(x);
            for (long long i = c[0]; i <= c[1]; ++i)
                for (long long j = c[2]; j <= c[3]; ++j) grid.push_back({i, j, static_cast<std::uint32_t>(m_run[x]), x});
        }
        std::sort(grid.begin(), grid.end());
        for (std::size_t x = 0; x < wide.size(); ++x) {
            for (std::size_t y = x + 1; y < wide.size(); ++y)
                if (spend()) test_faces(wide[x], wide[y]);
            for (std::uint32_t k : narrow)
                if (spend()) test_faces(wide[x], k);
        }
        for (std::size_t begin = 0; begin < grid.size();) {
            const long long i = grid[begin].i, j = grid[begin].j;
            std::size_t end = begin + 1;
            while (end < grid.size() && grid[end].i == i && grid[end].j == j) ++end;
            for (std::size_t x = begin; x < end; ++x)
                for (std::size_t y = x + 1; y < end; ++y) {
                    const auto sa = span(grid[x].x), sb = span(grid[y].x);
                    if (i != std::max(sa[0], sb[0]) || j != std::max(sa[2], sb[2])) continue;
                    if (!spend()) return;
                    test_faces(grid[x].x, grid[y].x);
                }
            begin = end;
        }
    }

    void match_rounds() {
        std::vector<Round>& rounds = m.rounds;
        std::sort(rounds.begin(), rounds.end(), [](const Round& a, const Round& b) { return a.radius < b.radius; });
        for (std::size_t x = 0; x < rounds.size(); ++x) {
            const Round& a = rounds[x];
            for (std::size_t y = x + 1; y < rounds.size(); ++y) {
                const Round& b = rounds[y];
                if (!spend()) return;
                const double reach = std::max({a.radius, length(a.center), std::abs(a.from), std::abs(a.to)});
                const double tol = kTolerance * std::max(reach, b.radius);
                if (b.radius - a.radius > tol) break;
                if (a.leaf == b.leaf || a.cylinder != b.cylinder) continue;
                if (length(a.center - b.center) > tol) continue;
                if (a.cylinder && (length(cross(a.axis, b.axis)) > 1e-8 ||
                                   std::min(a.to, b.to) - std::max(a.from, b.from) <= tol))
                    continue;
                if (matters(a.leaf, b.leaf, true)) found(a.leaf, b.leaf, a.cylinder ? "cylinder sides" : "spheres");
            }
        }
    }

    detail::Records m;
    // The run being compared: its faces, their bounds in (u, v) and their shapes, made when a pair needs them
    // (a deque: stable while others are made).
    std::pair<Vec3, Vec3> m_basis;
    std::vector<std::size_t> m_run;
    std::vector<Face> m_run_faces;  // copies, at hand in the sweeps
    std::vector<std::array<double, 4>> m_uv;
    std::vector<std::int32_t> m_shape_of;
    std::deque<std::vector<Point2>> m_shapes;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> m_found;
    std::size_t m_tests = 0;
};

}  // namespace

std::vector<CoincidentPair> find_coincident_surfaces(const scene::Scene& scene, std::size_t limit,
                                                     std::size_t* total) {
    Finder finder(scene);
    std::vector<CoincidentPair> out;
    // One report per pair of places: a declared object used many times shows its pair once.
    std::set<std::tuple<std::uint32_t, std::uint32_t, std::size_t, std::uint32_t, std::uint32_t, std::size_t>> seen;
    const std::hash<std::string> hash;
    std::size_t distinct = 0;
    for (const auto& [pair, surface] : finder.pairs()) {
        const scene::Object& a = *finder.leaf(pair.first).object;
        const scene::Object& b = *finder.leaf(pair.second).object;
        if (!seen.emplace(a.loc.line, a.loc.column, hash(a.loc.path), b.loc.line, b.loc.column, hash(b.loc.path)).second)
            continue;
        ++distinct;
        if (out.size() >= limit) continue;
        auto part_of = [&](std::uint32_t leaf) -> std::string {
            const scene::Object* parent = finder.context(leaf);
            return parent ? std::string("the ") + scene::shape_keyword(parent->shape) + " at " + place(parent->loc) : "";
        };
        out.push_back({a.loc, b.loc, scene::shape_keyword(a.shape), scene::shape_keyword(b.shape), surface,
                       part_of(pair.first), part_of(pair.second)});
    }
    if (total) *total = distinct;
    return out;
}

std::vector<Diagnostic> coincident_surface_warnings(const scene::Scene& scene, std::size_t limit) {
    std::size_t total = 0;
    std::vector<Diagnostic> out;
    for (const CoincidentPair& pair : find_coincident_surfaces(scene, limit, &total)) {
        Diagnostic d;
        d.severity = Severity::Warning;
        d.loc = pair.first;
        const std::string first_part = pair.first_part_of.empty() ? "" : " (part of " + pair.first_part_of + ")";
        const std::string second_part = pair.second_part_of.empty() ? "" : " (part of " + pair.second_part_of + ")";
        d.message = "coincident surfaces: this " + pair.first_kind + first_part + " and the " + pair.second_kind +
                    " at " + place(pair.second) + second_part + " have " + pair.surface +
                    " that lie on one another; POV-Ray shows either surface there at random (a speckle), so this "
                    "picture may differ from POV-Ray's; move or resize one of them by a small amount";
        out.push_back(std::move(d));
    }
    add_count_of_the_rest(out, total, "coincident surfaces", "pairs of objects");
    return out;
}

}  // namespace wardray::geometry
