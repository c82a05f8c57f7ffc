// Scene description, objects: a shape with its placement, appearance and flags; CSG over objects.
#pragma once

#include <variant>
#include <vector>

#include "core/diagnostics.h"
#include "core/transform.h"
#include "scene/interior.h"
#include "scene/shapes.h"
#include "scene/texture.h"

namespace wardray::scene {

struct Object;

/// Constructive solid geometry over child objects (each with its own transform relative to this node).
struct Csg {
    enum class Op { Union, Intersection, Difference, Merge };
    Op op = Op::Union;
    std::vector<Object> children;
    bool operator==(const Csg&) const = default;
};

/// The shapes the renderer draws.
using Shape = std::variant<Sphere, Box, Plane, Cylinder, Cone, Disc, Torus, Mesh, Polygon, Quadric, Superellipsoid,
                           Quartic, Prism, Lathe, Sor, Text, Csg>;

/// One object of the scene: a shape, its placement, its appearance and its flags.
struct Object {
    Shape shape;
    Transform transform;  ///< object space to world space, in the order the keywords appeared
    Texture texture;
    Interior interior;
    bool inverse = false;
    bool no_shadow = false;
    bool no_image = false;
    bool no_reflection = false;
    bool no_radiosity = false;
    bool has_texture = false;  ///< the statement gave its own texture (else it takes its CSG parent's)
    std::vector<Object> clipped_by;  ///< clipping objects, placed relative to this object's transform
    /// `bounded_by` objects, placed as clipped_by: POV-Ray tests the object only on rays that meet them all.
    std::vector<Object> bounded_by;
    SourceLoc loc;
    bool operator==(const Object&) const = default;
};

}  // namespace wardray::scene
