// Coincident surfaces: finds primitives whose surfaces lie on one another (to rounding), which POV-Ray draws as a
// random speckle of either surface, so that the user hears of it at both places.
#include "geometry/coincident_surfaces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <variant>

#include "core/diagnostic_list.h"
#include "core/transform.h"
#include "core/vec3.h"
#include "geometry/surface_pieces.h"
#include "scene/opacity.h"
#include "scene/scene.h"

namespace wardray::geometry {

namespace {

// Surfaces closer than this fraction of their size coincide: rounding decides which one a ray meets first.
constexpr double kTolerance = 1e-9;
// Pair tests allowed in all: a scene of many equal faces is cut short rather than slowed down.
constexpr std::size_t kPairBudget = 4'000'000;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A CSG node above the primitives: its parent (-1 at a top-level object) and whether it clips its children
// (intersection, difference and merge test each child's surface against the others).
struct Node {
    const scene::Object* object = nullptr;
    std::int32_t parent = -1;
    std::uint32_t depth = 0;
    bool clips = false;
};

// A half-space an intersection or difference keeps of its parts, in world space: a plane among an intersection's
// children, or outside a plane a difference takes away.
struct Cut {
    HalfSpace space;
    const scene::Object* plane = nullptr;  ///< the plane it comes from (which it does not cut)
};

struct Leaf {
    const scene::Object* object = nullptr;
    std::int32_t node = -1;   ///< the CSG node it is a child of, -1 for a top-level primitive
    bool see_through = false; ///< its textures may filter or transmit
    std::optional<Bounds> clip; ///< what an intersection or difference above it leaves of space, when bounded
    std::vector<Cut> cuts;
    bool clipped = false;     ///< below an intersection or difference, or clipped_by: its extent is not its own
    std::uint32_t top = 0;    ///< the top-level object it is part of
};

// A planar face in world space: `normal` in a canonical orientation (its first clearly nonzero component
// positive), `facing` saying whether the outward normal is +normal or -normal.
struct Face {
    Vec3 normal;
    double offset = 0.0;                 ///< dot(normal, p) for p on the face
    double size = 0.0;                   ///< the largest extent of its corners
    std::array<double, 4> uv{};          ///< bounds in its group's (u, v): u0, u1, v0, v1
    std::uint32_t leaf = 0;
    std::uint32_t first = 0, count = 0;  ///< its corners in Finder::m_points: world points whose hull covers it
    std::uint32_t group = 0;             ///< its group of faces of one normal, whose basis (u, v) it is drawn in
    std::int32_t shape = -1;             ///< its shape in Finder::m_shapes once a pair needs it
    std::int8_t facing = 1;
    bool two_sided = false;  ///< a disc or polygon: both sides are its surface
    bool bounded = true;     ///< false for a plane
};

// A sphere or a cylinder's side in world space.
struct Round {
    std::uint32_t leaf = 0;
    bool cylinder = false;
    Vec3 center;  ///< the sphere's centre, or the cylinder axis' point nearest the origin
    Vec3 axis;    ///< the cylinder's canonical unit axis
    double radius = 0.0;
    double from = 0.0, to = 0.0;  ///< the cylinder's extent along `axis`
};

class Finder {
public:
    explicit Finder(const scene::Scene& scene) {
        for (const scene::Object& o : scene.objects) {
            collect(o, Transform{}, -1, std::nullopt, {});
            ++m_top;
        }
    }

    // Every coincident pair found, in the order of the primitives, each pair of primitives once.
    const std::map<std::pair<std::uint32_t, std::uint32_t>, std::string>& pairs() {
        match_faces();
        match_rounds();
        return m_found;
    }

    const Leaf& leaf(std::uint32_t i) const { return m_leaves[i]; }

    // The nearest CSG node above a primitive written at another place than the primitive, if any.
    const scene::Object* context(std::uint32_t i) const {
        const scene::Object& o = *m_leaves[i].object;
        for (std::int32_t n = m_leaves[i].node; n >= 0; n = m_nodes[static_cast<std::size_t>(n)].parent) {
            const scene::Object* parent = m_nodes[static_cast<std::size_t>(n)].object;
            if (parent->loc != o.loc) return parent;
        }
        return nullptr;
    }

private:
    void collect(const scene::Object& o, const Transform& outer, std::int32_t node, std::optional<Bounds> clip,
                 const std::vector<Cut>& cuts) {
        if (o.no_image) return;  // never seen by the camera
        const Transform world = o.transform.then(outer);
        // clipped_by keeps what lies inside its objects, as an intersection does.
        std::vector<Cut> clipped = cuts;
        for (const scene::Object& c : o.clipped_by) {
            if (const std::optional<Bounds> kept = world_bounds(c, world)) clip = intersect_bounds(clip, kept);
            if (const std::optional<Cut> cut = plane_cut(c, world)) clipped.push_back(*cut);
        }
        if (const auto* csg = std::get_if<scene::Csg>(&o.shape)) {
            // Only what an intersection or difference keeps of space holds its parts' surfaces (planes included).
            if (csg->op == scene::Csg::Op::Intersection || csg->op == scene::Csg::Op::Difference)
                if (const std::optional<Bounds> kept = world_bounds(o, outer)) clip = intersect_bounds(clip, kept);
            Node n;
            n.object = &o;
            n.parent = node;
            n.depth = node < 0 ? 0 : m_nodes[static_cast<std::size_t>(node)].depth + 1;
            n.clips = csg->op != scene::Csg::Op::Union;
            m_nodes.push_back(n);
            const auto id = static_cast<std::int32_t>(m_nodes.size() - 1);
            // The planes among an intersection's children cut every other child; those a difference takes away
            // cut its first.
            std::vector<Cut> inner = clipped;
            std::vector<Cut> first = clipped;
            for (std::size_t k = 0; k < csg->children.size(); ++k) {
                const std::optional<Cut> cut = plane_cut(csg->children[k], world);
                if (!cut) continue;
                if (csg->op == scene::Csg::Op::Intersection) inner.push_back(*cut);
                if (csg->op == scene::Csg::Op::Difference && k > 0)
                    first.push_back({{-cut->space.normal, -cut->space.distance}, cut->plane});
            }
            for (std::size_t k = 0; k < csg->children.size(); ++k)
                collect(csg->children[k], world, id, clip,
                        csg->op == scene::Csg::Op::Difference && k == 0 ? first : inner);
            return;
        }
        bool see_through = scene::texture_may_show_through(o.texture);
        for (const scene::Texture& inside : o.interior_texture) see_through = see_through || scene::texture_may_show_through(inside);
        const auto index = static_cast<std::uint32_t>(m_leaves.size());
        std::vector<Cut> own;
        for (const Cut& c : clipped)
            if (c.plane != &o) own.push_back(c);
        const bool clipped_somewhere = clip.has_value() || !clipped.empty() || !o.clipped_by.empty() || in_clipping(node);
        m_leaves.push_back({&o, node, see_through, clip, std::move(own), clipped_somewhere, m_top});
        add_surfaces(o.shape, world, index);
    }

    // The half-space inside a plane child (dot(n, p) <= d in world space), if the child is a plane.
    static std::optional<Cut> plane_cut(const scene::Object& child, const Transform& parent_world) {
        const auto* plane = std::get_if<scene::Plane>(&child.shape);
        if (!plane) return std::nullopt;
        const double len = length(plane->normal);
        if (!(len > 0.0)) return std::nullopt;
        const Transform world = child.transform.then(parent_world);
        Vec3 n = world.normal(plane->normal / len);
        const double n_len = length(n);
        if (!(n_len > 0.0) || !std::isfinite(n_len)) return std::nullopt;
        n = n / n_len;
        double d = dot(n, world.point(plane->normal * (plane->distance / len)));
        if (child.inverse) {
            n = -n;
            d = -d;
        }
        return Cut{{n, d}, &child};
    }

    void add_face(std::uint32_t leaf, const Transform& world, const Vec3& n_object, const Vec3& p_object,
                  const std::vector<Vec3>& corners_object, bool two_sided) {
        Vec3 n = world.normal(n_object);
        const double len = length(n);
        if (!(len > 0.0) || !std::isfinite(len)) return;
        n = n / len;
        Face f;
        f.leaf = leaf;
        f.facing = static_cast<std::int8_t>(canonical_sign(n));
        f.normal = n * static_cast<double>(f.facing);
        f.offset = dot(f.normal, world.point(p_object));
        f.two_sided = two_sided;
        const std::size_t mark = m_points.size();
        for (const Vec3& c : corners_object) m_points.push_back(world.point(c));
        // A plane below an intersection or difference is bounded by what that keeps: its section of that box.
        const std::optional<Bounds>& clip = m_leaves[leaf].clip;
        if (corners_object.empty() && clip) {
            for (const Vec3& c : section(*clip, n, dot(n, world.point(p_object)))) m_points.push_back(c);
            if (m_points.size() == mark) return;  // the plane misses what is kept
        }
        f.first = static_cast<std::uint32_t>(mark);
        f.count = static_cast<std::uint32_t>(m_points.size() - mark);
        f.bounded = f.count > 0;
        Vec3 lo{kInfinity, kInfinity, kInfinity}, hi = -lo;
        for (std::size_t k = mark; k < m_points.size(); ++k)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], m_points[k][a]);
                hi[a] = std::max(hi[a], m_points[k][a]);
            }
        f.size = f.bounded ? std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) : 0.0;
        // A face wholly outside what a CSG keeps never shows (a cylinder's caps beyond the box it is cut to).
        if (clip && f.bounded) {
            const double slack = kTolerance * std::max(f.size, std::abs(f.offset));
            for (int a = 0; a < 3; ++a)
                if (lo[a] > clip->upper[a] + slack || hi[a] < clip->lower[a] - slack) {
                    m_points.resize(mark);
                    return;
                }
        }
        // A plane clipped by shapes of unknown extent (quadrics, ...) is left alone rather than taken as infinite.
        if ((!f.bounded && m_leaves[leaf].clipped) || (f.bounded && !(f.size > 0.0)) || !std::isfinite(f.offset) ||
            !std::isfinite(f.size)) {
            m_points.resize(mark);
            return;
        }
        m_faces.push_back(std::move(f));
    }

    // The primitive's flat faces and round surfaces, placed in world space.
    void add_surfaces(const scene::Shape& shape, const Transform& world, std::uint32_t leaf) {
        for (const FlatPiece& piece : flat_pieces(shape))
            add_face(leaf, world, piece.normal, piece.point, piece.corners, piece.two_sided);
        for (const RoundPiece& piece : round_pieces(shape)) {
            if (piece.cylinder) {
                add_cylinder_side(leaf, world, piece.base, piece.cap, piece.radius);
                continue;
            }
            const double s = similarity_scale(world);
            if (s > 0.0) m_rounds.push_back({leaf, false, world.point(piece.base), {}, piece.radius * s, 0.0, 0.0});
        }
    }

    void add_cylinder_side(std::uint32_t leaf, const Transform& world, const Vec3& base, const Vec3& cap,
                           double radius) {
        const double s = similarity_scale(world);
        if (!(s > 0.0) || !(radius > 0.0)) return;
        const Vec3 a = world.point(base), b = world.point(cap);
        const double len = length(b - a);
        if (!(len > 0.0) || !std::isfinite(len)) return;
        Round r;
        r.leaf = leaf;
        r.cylinder = true;
        r.axis = (b - a) / len;
        r.axis = r.axis * static_cast<double>(canonical_sign(r.axis));
        r.center = a - r.axis * dot(a, r.axis);
        r.radius = radius * s;
        r.from = std::min(dot(a, r.axis), dot(b, r.axis));
        r.to = std::max(dot(a, r.axis), dot(b, r.axis));
        // Below an intersection or difference only the part within what it keeps can show.
        if (const std::optional<Bounds>& kept = m_leaves[leaf].clip) {
            double lo = kInfinity, hi = -kInfinity;
            for (const Vec3& c : corners(*kept)) {
                lo = std::min(lo, dot(c, r.axis));
                hi = std::max(hi, dot(c, r.axis));
            }
            r.from = std::max(r.from, lo);
            r.to = std::min(r.to, hi);
            if (!(r.from < r.to)) return;
        }
        m_rounds.push_back(r);
    }

    bool in_clipping(std::int32_t node) const {
        for (; node >= 0; node = m_nodes[static_cast<std::size_t>(node)].parent)
            if (m_nodes[static_cast<std::size_t>(node)].clips) return true;
        return false;
    }

    // The innermost CSG node above both primitives clips them (-1 nodes share none).
    bool clip_each_other(std::uint32_t i, std::uint32_t j) const {
        std::int32_t a = m_leaves[i].node, b = m_leaves[j].node;
        while (a >= 0 && b >= 0 && a != b) {
            const Node& na = m_nodes[static_cast<std::size_t>(a)];
            const Node& nb = m_nodes[static_cast<std::size_t>(b)];
            if (na.depth >= nb.depth) a = na.parent;
            else b = nb.parent;
        }
        return a >= 0 && a == b && m_nodes[static_cast<std::size_t>(a)].clips;
    }

    // Whether the choice between the two surfaces can change the picture.
    bool matters(std::uint32_t i, std::uint32_t j, bool same_facing) const {
        if (clip_each_other(i, j)) return true;
        const Leaf& a = m_leaves[i];
        const Leaf& b = m_leaves[j];
        if (same_facing) return !(a.object->texture == b.object->texture);
        return a.see_through || b.see_through;
    }

    void found(std::uint32_t i, std::uint32_t j, const char* surface) {
        if (i > j) std::swap(i, j);
        m_found.emplace(std::pair{i, j}, surface);
    }

    bool spend() { return m_tests++ < kPairBudget; }

    void match_faces() {
        // Faces grouped by their normal to about 1e-6, each group sorted by offset.
        std::vector<std::pair<std::array<long long, 3>, std::size_t>> keyed(m_faces.size());
        for (std::size_t k = 0; k < m_faces.size(); ++k) {
            const Vec3& n = m_faces[k].normal;
            keyed[k] = {{std::llround(n.x * 1e6), std::llround(n.y * 1e6), std::llround(n.z * 1e6)}, k};
        }
        std::sort(keyed.begin(), keyed.end());
        std::vector<std::vector<std::size_t>> groups;
        for (std::size_t k = 0; k < keyed.size(); ++k) {
            if (k == 0 || keyed[k].first != keyed[k - 1].first) groups.emplace_back();
            groups.back().push_back(keyed[k].second);
        }
        for (auto& members : groups) {
            const auto group = static_cast<std::uint32_t>(m_bases.size());
            m_bases.push_back(plane_basis(m_faces[members.front()].normal));
            double reach = 0.0;
            for (std::size_t k : members) {
                m_faces[k].group = group;
                reach = std::max(reach, std::abs(m_faces[k].offset) + m_faces[k].size);
            }
            std::sort(members.begin(), members.end(),
                      [&](std::size_t a, std::size_t b) { return m_faces[a].offset < m_faces[b].offset; });
            // Runs of faces whose offsets lie within the widest tolerance of one another: only those are compared.
            const double window = kTolerance * reach;
            for (std::size_t begin = 0; begin < members.size();) {
                std::size_t end = begin + 1;
                while (end < members.size() &&
                       m_faces[members[end]].offset - m_faces[members[end - 1]].offset <= window)
                    ++end;
                if (end - begin > 1) {
                    const std::vector<std::size_t> run(members.begin() + begin, members.begin() + end);
                    for (std::size_t k : run) bound(m_faces[k]);
                    sweep_run(run);
                }
                begin = end;
            }
        }
    }

    // A face's bounds in its group's (u, v): its corners' when nothing cuts it, else those of its shape.
    void bound(Face& f) {
        if (!f.bounded) {
            f.uv = {-kInfinity, kInfinity, -kInfinity, kInfinity};
            return;
        }
        const auto& [u, v] = m_bases[f.group];
        f.uv = {kInfinity, -kInfinity, kInfinity, -kInfinity};
        for (std::uint32_t k = f.first; k < f.first + f.count; ++k) {
            const double a = dot(m_points[k], u), b = dot(m_points[k], v);
            f.uv = {std::min(f.uv[0], a), std::max(f.uv[1], a), std::min(f.uv[2], b), std::max(f.uv[3], b)};
        }
        // Within what a CSG keeps: that box's extent in (u, v) limits it too.
        if (const std::optional<Bounds>& kept = m_leaves[f.leaf].clip) {
            std::array<double, 4> box{kInfinity, -kInfinity, kInfinity, -kInfinity};
            for (const Vec3& c : corners(*kept)) {
                const double a = dot(c, u), b = dot(c, v);
                box = {std::min(box[0], a), std::max(box[1], a), std::min(box[2], b), std::max(box[3], b)};
            }
            f.uv = {std::max(f.uv[0], box[0]), std::min(f.uv[1], box[1]), std::max(f.uv[2], box[2]),
                    std::min(f.uv[3], box[3])};
        }
    }

    // The face's convex shape in its group's (u, v), the hull of its corners less its leaf's cuts, made once (its
    // bounds, which the sweeps use, stay); empty when nothing is left.
    const std::vector<Point2>& make_shape(Face& f) {
        if (f.shape >= 0) return m_shapes[static_cast<std::size_t>(f.shape)];
        f.shape = static_cast<std::int32_t>(m_shapes.size());
        const auto& [u, v] = m_bases[f.group];
        std::vector<Point2> flat;
        for (std::uint32_t k = f.first; k < f.first + f.count; ++k)
            flat.push_back({dot(m_points[k], u), dot(m_points[k], v)});
        std::vector<HalfSpace> cuts;
        for (const Cut& cut : m_leaves[f.leaf].cuts) cuts.push_back(cut.space);
        m_shapes.push_back(cut_polygon(hull(std::move(flat)), f.normal * f.offset, {u, v}, cuts,
                                       m_leaves[f.leaf].clip, kTolerance * (f.size + std::abs(f.offset))));
        return m_shapes.back();
    }

    // A run of faces in one plane: where none lets light through, faces facing opposite ways matter only when a CSG
    // clips one by the other, inside one top-level object (opaque solids touching face to face hide their contact),
    // so each facing is swept alone, and each clipped object's faces together.
    void sweep_run(const std::vector<std::size_t>& run) {
        const bool see_through = std::any_of(run.begin(), run.end(),
                                             [&](std::size_t k) { return m_leaves[m_faces[k].leaf].see_through; });
        if (see_through) return sweep(run);
        std::vector<std::size_t> facing[2];
        std::vector<std::pair<std::uint32_t, std::size_t>> clipped;  // (top-level object, face)
        for (std::size_t k : run) {
            const Face& f = m_faces[k];
            if (f.two_sided || f.facing > 0) facing[0].push_back(k);
            if (f.two_sided || f.facing < 0) facing[1].push_back(k);
            const Leaf& leaf = m_leaves[f.leaf];
            if (in_clipping(leaf.node)) clipped.emplace_back(leaf.top, k);
        }
        // Faces facing one way matter only with different textures: one texture shared by all settles the side.
        for (const auto& side : facing) {
            if (side.empty()) continue;
            const scene::Object& first = *m_leaves[m_faces[side.front()].leaf].object;
            const bool one_texture = std::all_of(side.begin(), side.end(), [&](std::size_t k) {
                return m_leaves[m_faces[k].leaf].object->texture.shares(first.texture);
            });
            if (side.size() > 1 && !one_texture) sweep(side);
        }
        std::sort(clipped.begin(), clipped.end());
        for (std::size_t begin = 0; begin < clipped.size();) {
            std::size_t end = begin + 1;
            while (end < clipped.size() && clipped[end].first == clipped[begin].first) ++end;
            if (end - begin > 1) {
                std::vector<std::size_t> same_object;
                for (std::size_t k = begin; k < end; ++k) same_object.push_back(clipped[k].second);
                sweep(same_object);
            }
            begin = end;
        }
    }

    // Tests one pair of faces of a run (offsets within the window): reports them if they coincide over an area.
    void test_faces(Face& a, Face& b) {
        const double tol = kTolerance * std::max({std::abs(a.offset), std::abs(b.offset), a.size, b.size});
        if (a.leaf == b.leaf) return;
        if (std::min(a.uv[3], b.uv[3]) - std::max(a.uv[2], b.uv[2]) <= tol) return;
        if (std::min(a.uv[1], b.uv[1]) - std::max(a.uv[0], b.uv[0]) <= tol) return;
        if (std::abs(a.offset - b.offset) > tol) return;
        if (length(cross(a.normal, b.normal)) > 1e-8) return;
        // The cheap questions first: whether the choice shows, and whether the pair is known already.
        const bool same_facing = a.two_sided || b.two_sided || a.facing == b.facing;
        if (m_found.contains({std::min(a.leaf, b.leaf), std::max(a.leaf, b.leaf)})) return;
        if (!matters(a.leaf, b.leaf, same_facing)) return;
        if (a.bounded && b.bounded) {
            const std::vector<Point2>& shape_a = make_shape(a);
            const std::vector<Point2>& shape_b = make_shape(b);
            if (shape_a.empty() || shape_b.empty() || !overlap(shape_a, shape_b, tol)) return;
        }
        found(a.leaf, b.leaf, "flat faces");
    }

    // The pairs of a run of faces in one plane whose bounds overlap: all pairs for a short run; else the faces in a
    // grid of cells about the size of a typical face, each pair tested in the first cell both cover, and faces
    // over many cells (planes) against all.
    void sweep(const std::vector<std::size_t>& run) {
        if (run.size() <= 32) {
            for (std::size_t x = 0; x < run.size(); ++x)
                for (std::size_t y = x + 1; y < run.size(); ++y) {
                    if (!spend()) return;
                    test_faces(m_faces[run[x]], m_faces[run[y]]);
                }
            return;
        }
        std::vector<double> sizes;
        for (std::size_t k : run)
            if (m_faces[k].bounded) sizes.push_back(std::max(m_faces[k].uv[1] - m_faces[k].uv[0], m_faces[k].uv[3] - m_faces[k].uv[2]));
        std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
        const double cell = sizes.empty() ? 0.0 : 2.0 * sizes[sizes.size() / 2];
        std::vector<std::size_t> wide, narrow;
        // Each face listed in every cell it covers; sorted by cell, the faces of one cell lie together.
        std::vector<std::tuple<long long, long long, std::size_t>> grid;
        auto span = [&](const Face& f) {
            return std::array<long long, 4>{static_cast<long long>(std::floor(f.uv[0] / cell)),
                                            static_cast<long long>(std::floor(f.uv[1] / cell)),
                                            static_cast<long long>(std::floor(f.uv[2] / cell)),
                                            static_cast<long long>(std::floor(f.uv[3] / cell))};
        };
        for (std::size_t k : run) {
            const Face& f = m_faces[k];
            if (!(f.uv[0] <= f.uv[1])) continue;  // nothing left of it
            if (!f.bounded || !(cell > 0.0) || (f.uv[1] - f.uv[0]) > 4 * cell || (f.uv[3] - f.uv[2]) > 4 * cell) {
                wide.push_back(k);
                continue;
            }
            narrow.push_back(k);
            const auto c = span(f);
            for (long long i = c[0]; i <= c[1]; ++i)
                for (long long j = c[2]; j <= c[3]; ++j) grid.emplace_back(i, j, k);
        }
        std::sort(grid.begin(), grid.end());
        for (std::size_t x = 0; x < wide.size(); ++x) {
            for (std::size_t y = x + 1; y < wide.size(); ++y)
                if (spend()) test_faces(m_faces[wide[x]], m_faces[wide[y]]);
            for (std::size_t k : narrow)
                if (spend()) test_faces(m_faces[wide[x]], m_faces[k]);
        }
        for (std::size_t begin = 0; begin < grid.size();) {
            const auto [i, j, first] = grid[begin];
            std::size_t end = begin + 1;
            while (end < grid.size() && std::get<0>(grid[end]) == i && std::get<1>(grid[end]) == j) ++end;
            for (std::size_t x = begin; x < end; ++x)
                for (std::size_t y = x + 1; y < end; ++y) {
                    Face& a = m_faces[std::get<2>(grid[x])];
                    Face& b = m_faces[std::get<2>(grid[y])];
                    const auto sa = span(a), sb = span(b);
                    if (i != std::max(sa[0], sb[0]) || j != std::max(sa[2], sb[2])) continue;
                    if (!spend()) return;
                    test_faces(a, b);
                }
            begin = end;
        }
    }

    void match_rounds() {
        std::sort(m_rounds.begin(), m_rounds.end(), [](const Round& a, const Round& b) { return a.radius < b.radius; });
        for (std::size_t x = 0; x < m_rounds.size(); ++x) {
            const Round& a = m_rounds[x];
            for (std::size_t y = x + 1; y < m_rounds.size(); ++y) {
                const Round& b = m_rounds[y];
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

    std::vector<Node> m_nodes;
    std::vector<Leaf> m_leaves;
    std::vector<Face> m_faces;
    std::vector<Vec3> m_points;                // the faces' corners
    std::deque<std::vector<Point2>> m_shapes;  // the faces' shapes, made when needed (stable while others are made)
    std::vector<std::pair<Vec3, Vec3>> m_bases;  // each group's (u, v)
    std::vector<Round> m_rounds;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> m_found;
    std::size_t m_tests = 0;
    std::uint32_t m_top = 0;  // the top-level object being collected
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
