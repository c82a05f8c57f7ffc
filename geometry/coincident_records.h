// The coincident-surface check's records: the scene's primitives as world-space flat faces and round surfaces, in
// compact form (a scene of 50,000 boxes makes 300,000 faces). coincident_collect.cpp gathers them from the scene,
// coincident_surfaces.cpp pairs them; included by those two files only.
#pragma once

#include <bit>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <vector>

#include "core/vec3.h"
#include "geometry/csg_bounds.h"
#include "geometry/shape.h"

namespace wardray::scene {
struct Object;
struct Scene;
}  // namespace wardray::scene

namespace wardray::geometry::detail {

// Surfaces closer than this fraction of their size coincide: rounding decides which one a ray meets first.
inline constexpr double kTolerance = 1e-9;
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// A CSG node above the primitives: its parent (-1 at a top-level object) and whether it clips its children
/// (intersection, difference and merge test each child's surface against the others).
struct Node {
    const scene::Object* object = nullptr;
    std::int32_t parent = -1;
    std::uint32_t depth = 0;
    bool clips = false;
};

/// A half-space an intersection or difference keeps of its parts, in world space: a plane among an intersection's
/// children, or outside a plane a difference takes away.
struct Cut {
    HalfSpace space;
    const scene::Object* plane = nullptr;  ///< the plane it comes from (which it does not cut)
};

/// A primitive that has a face or round surface the check compares.
struct Leaf {
    const scene::Object* object = nullptr;
    std::int32_t node = -1;      ///< the CSG node it is a child of, -1 for a top-level primitive
    std::int32_t clip = -1;      ///< what an intersection or difference above it leaves of space, in Records::clips
    std::uint32_t top = 0;       ///< the top-level object it is part of
    std::uint32_t first_cut = 0, cut_count = 0;  ///< its cuts in Records::cuts
    bool see_through = false;    ///< its textures may filter or transmit
    bool clipped = false;        ///< below an intersection or difference, or clipped_by: its extent is not its own
};

/// A planar face in world space: `normal` in a canonical orientation (its first clearly nonzero component
/// positive), `facing` saying whether the outward normal is +normal or -normal.
struct Face {
    Vec3 normal;
    double offset = 0.0;                 ///< dot(normal, p) for p on the face
    double size = 0.0;                   ///< the largest extent of its corners
    std::uint32_t leaf = 0;
    std::uint32_t first = 0, count = 0;  ///< its corners in Records::corners: world points whose hull covers it
    std::int8_t facing = 1;
    bool two_sided = false;  ///< a disc or polygon: both sides are its surface
    bool bounded = true;     ///< false for a plane
};

/// A sphere or a cylinder's side in world space.
struct Round {
    std::uint32_t leaf = 0;
    bool cylinder = false;
    Vec3 center;  ///< the sphere's centre, or the cylinder axis' point nearest the origin
    Vec3 axis;    ///< the cylinder's canonical unit axis
    double radius = 0.0;
    double from = 0.0, to = 0.0;  ///< the cylinder's extent along `axis`
};

/// Whether two points are the same to the bit (-0 differs from 0, as it may in what follows).
inline bool same_bits(const Vec3& a, const Vec3& b) {
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
           std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

/// Everything the check compares. The long lists are deques: they grow without a moment holding two copies.
struct Records {
    std::vector<Node> nodes;
    std::deque<Leaf> leaves;
    std::deque<Face> faces;
    std::deque<Vec3> points;            ///< world points, each corner shared by a primitive's faces once
    std::deque<std::uint32_t> corners;  ///< the faces' corners: indices into points
    std::vector<Bounds> clips;          ///< the boxes CSG keeps, shared by the leaves below one node
    std::vector<Cut> cuts;
    std::vector<Round> rounds;

    /// A leaf's clip box, or nothing when what is kept is unbounded.
    std::optional<Bounds> clip_of(const Leaf& leaf) const {
        if (leaf.clip < 0) return std::nullopt;
        return clips[static_cast<std::size_t>(leaf.clip)];
    }
    /// The index of `box` in clips, added unless it is (bit for bit) the last one added.
    std::int32_t clip_index(const Bounds& box) {
        if (clips.empty() || !same_bits(clips.back().lower, box.lower) || !same_bits(clips.back().upper, box.upper))
            clips.push_back(box);
        return static_cast<std::int32_t>(clips.size() - 1);
    }
    /// Whether some CSG node at or above `node` clips its children.
    bool in_clipping(std::int32_t node) const {
        for (; node >= 0; node = nodes[static_cast<std::size_t>(node)].parent)
            if (nodes[static_cast<std::size_t>(node)].clips) return true;
        return false;
    }
};

/// The faces and round surfaces of every primitive of the scene that the camera sees.
void collect_surfaces(const scene::Scene& scene, Records& out);

}  // namespace wardray::geometry::detail
