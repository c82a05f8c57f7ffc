// The coincident-surface check's first half: every primitive's flat faces and round surfaces placed in world space,
// with what the CSG above it keeps of space, as the compact records of coincident_records.h.
#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>
#include <vector>

#include "core/transform.h"
#include "geometry/coincident_records.h"
#include "geometry/surface_pieces.h"
#include "scene/opacity.h"
#include "scene/scene.h"

namespace wardray::geometry::detail {

namespace {

// A primitive's corners shared by its faces are looked up among at most this many (a box has 24, 8 of them
// different); beyond, each corner is placed on its own.
constexpr std::size_t kSharedCornerLimit = 64;

class Collector {
public:
    explicit Collector(Records& out) : m(out) {}

    void top_level(const scene::Object& o) {
        collect(o, Transform{}, -1, std::nullopt, {});
        ++m_top;
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
            n.depth = node < 0 ? 0 : m.nodes[static_cast<std::size_t>(node)].depth + 1;
            n.clips = csg->op != scene::Csg::Op::Union;
            m.nodes.push_back(n);
            const auto id = static_cast<std::int32_t>(m.nodes.size() - 1);
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
        const auto index = static_cast<std::uint32_t>(m.leaves.size());
        Leaf leaf;
        leaf.object = &o;
        leaf.node = node;
        leaf.clip = clip ? m.clip_index(*clip) : -1;
        leaf.top = m_top;
        leaf.first_cut = static_cast<std::uint32_t>(m.cuts.size());
        for (const Cut& c : clipped)
            if (c.plane != &o) m.cuts.push_back(c);
        leaf.cut_count = static_cast<std::uint32_t>(m.cuts.size() - leaf.first_cut);
        leaf.see_through = see_through;
        leaf.clipped = clip.has_value() || !clipped.empty() || !o.clipped_by.empty() || m.in_clipping(node);
        m.leaves.push_back(leaf);
        const std::size_t faces = m.faces.size(), rounds = m.rounds.size(), points = m.points.size();
        add_surfaces(o.shape, world, index);
        // A primitive with nothing to compare (a torus, or faces all outside what its CSG keeps) never pairs.
        if (m.faces.size() == faces && m.rounds.size() == rounds) {
            m.points.resize(points);
            m.cuts.resize(leaf.first_cut);
            m.leaves.pop_back();
        }
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

    // A face from its corners, given as indices into m.points (none for a plane).
    void add_face(std::uint32_t leaf, const Transform& world, const Vec3& n_object, const Vec3& p_object,
                  const std::vector<std::uint32_t>& corners, bool two_sided) {
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
        const std::size_t mark = m.corners.size(), points = m.points.size();
        for (std::uint32_t c : corners) m.corners.push_back(c);
        // A plane below an intersection or difference is bounded by what that keeps: its section of that box.
        const std::optional<Bounds> clip = m.clip_of(m.leaves[leaf]);
        if (corners.empty() && clip) {
            for (const Vec3& c : section(*clip, n, dot(n, world.point(p_object)))) {
                m.corners.push_back(static_cast<std::uint32_t>(m.points.size()));
                m.points.push_back(c);
            }
            if (m.corners.size() == mark) return;  // the plane misses what is kept
        }
        auto reject = [&] {
            m.corners.resize(mark);
            m.points.resize(points);
        };
        f.first = static_cast<std::uint32_t>(mark);
        f.count = static_cast<std::uint32_t>(m.corners.size() - mark);
        f.bounded = f.count > 0;
        Vec3 lo{kInfinity, kInfinity, kInfinity}, hi = -lo;
        for (std::size_t k = mark; k < m.corners.size(); ++k) {
            const Vec3& p = m.points[m.corners[k]];
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], p[a]);
                hi[a] = std::max(hi[a], p[a]);
            }
        }
        f.size = f.bounded ? std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) : 0.0;
        // A face wholly outside what a CSG keeps never shows (a cylinder's caps beyond the box it is cut to).
        if (clip && f.bounded) {
            const double slack = kTolerance * std::max(f.size, std::abs(f.offset));
            for (int a = 0; a < 3; ++a)
                if (lo[a] > clip->upper[a] + slack || hi[a] < clip->lower[a] - slack) return reject();
        }
        // A plane clipped by shapes of unknown extent (quadrics, ...) is left alone rather than taken as infinite.
        if ((!f.bounded && m.leaves[leaf].clipped) || (f.bounded && !(f.size > 0.0)) || !std::isfinite(f.offset) ||
            !std::isfinite(f.size))
            return reject();
        m.faces.push_back(f);
    }

    // The primitive's flat faces and round surfaces, placed in world space; a corner its faces share placed once.
    void add_surfaces(const scene::Shape& shape, const Transform& world, std::uint32_t leaf) {
        const std::vector<FlatPiece> pieces = flat_pieces(shape);
        std::size_t total = 0;
        for (const FlatPiece& piece : pieces) total += piece.corners.size();
        std::vector<Vec3> seen;  // object-space corners placed so far, when looked up
        std::vector<std::uint32_t> placed, corners;
        for (const FlatPiece& piece : pieces) {
            corners.clear();
            for (const Vec3& c : piece.corners) {
                std::size_t k = seen.size();
                if (total <= kSharedCornerLimit)
                    k = static_cast<std::size_t>(
                        std::find_if(seen.begin(), seen.end(),
                                     [&](const Vec3& s) { return same_bits(s, c); }) -
                        seen.begin());
                if (total > kSharedCornerLimit || k == seen.size()) {
                    if (total <= kSharedCornerLimit) seen.push_back(c);
                    placed.push_back(static_cast<std::uint32_t>(m.points.size()));
                    m.points.push_back(world.point(c));
                    k = placed.size() - 1;
                }
                corners.push_back(placed[k]);
            }
            add_face(leaf, world, piece.normal, piece.point, corners, piece.two_sided);
        }
        for (const RoundPiece& piece : round_pieces(shape)) {
            if (piece.cylinder) {
                add_cylinder_side(leaf, world, piece.base, piece.cap, piece.radius);
                continue;
            }
            const double s = similarity_scale(world);
            if (s > 0.0) m.rounds.push_back({leaf, false, world.point(piece.base), {}, piece.radius * s, 0.0, 0.0});
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
        if (const std::optional<Bounds> kept = m.clip_of(m.leaves[leaf])) {
            double lo = kInfinity, hi = -kInfinity;
            for (const Vec3& c : geometry::corners(*kept)) {
                lo = std::min(lo, dot(c, r.axis));
                hi = std::max(hi, dot(c, r.axis));
            }
            r.from = std::max(r.from, lo);
            r.to = std::min(r.to, hi);
            if (!(r.from < r.to)) return;
        }
        m.rounds.push_back(r);
    }

    Records& m;
    std::uint32_t m_top = 0;  // the top-level object being collected
};

}  // namespace

void collect_surfaces(const scene::Scene& scene, Records& out) {
    Collector collector(out);
    for (const scene::Object& o : scene.objects) collector.top_level(o);
}

}  // namespace wardray::geometry::detail
