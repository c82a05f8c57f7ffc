// Coincident surfaces: surfaces of two objects that lie on one another, where POV-Ray shows either at random.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/diagnostics.h"

namespace wardray::scene {
struct Scene;
}

namespace wardray::geometry {

/// Two primitives whose surfaces coincide over an area: a plane face on a plane face (box faces, planes, discs,
/// polygons, cylinder and cone caps), a sphere on a sphere, a cylinder's side on a cylinder's side.
struct CoincidentPair {
    SourceLoc first;    ///< the primitive written first
    SourceLoc second;
    std::string first_kind;  ///< "box", "plane", ...
    std::string second_kind;
    std::string surface;     ///< what coincides: "flat faces", "spheres", "cylinder sides"
    /// The nearest CSG written elsewhere that each primitive is part of ("the union at path:line:col"), or empty.
    std::string first_part_of;
    std::string second_part_of;
};

/// Where the scene's primitives have coincident surfaces whose choice can change the picture: the two carry
/// different textures, or one of them may let light through (a ray crosses both at one distance, in either order),
/// or one clips the other (both below one intersection, difference or merge). Planar faces count in either
/// orientation only in the last two cases; two opaque solids that touch face to face hide the contact. Surfaces
/// count as coincident when they agree to about 1e-9 of their size, the rounding that decides which one a ray sees.
/// At most `limit` pairs are returned; `total` receives how many were found (capped by the work done).
std::vector<CoincidentPair> find_coincident_surfaces(const scene::Scene& scene, std::size_t limit, std::size_t* total);

/// The warnings for find_coincident_surfaces: one per pair up to `limit`, at the first primitive with a note at
/// the second, and a last one that counts the rest.
std::vector<Diagnostic> coincident_surface_warnings(const scene::Scene& scene, std::size_t limit = 3);

}  // namespace wardray::geometry
