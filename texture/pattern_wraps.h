// Pattern wraps on surfaces: a texture that changes abruptly exactly on a primitive's surface (an onion's sphere,
// a gradient's plane), where POV-Ray shows either side of the jump at random.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/diagnostics.h"

namespace wardray::scene {
struct Scene;
}

namespace wardray::texture {

/// A primitive's surface on which its texture jumps from one look to another.
struct PatternWrap {
    SourceLoc where;          ///< the pigment or normal that jumps, or the object for a texture_map
    SourceLoc object;         ///< the primitive
    std::string object_kind;  ///< "sphere", "box", ...
    std::string surface;      ///< "sphere", "flat face", "cylinder side"
    std::string part;         ///< "pigment", "normal" or "texture_map"
    std::string pattern;      ///< the keyword of the pattern whose value jumps, or empty when it is nested deeper
};

/// Where a primitive's flat face, sphere or cylinder side lies on a jump of its own texture: the look (pigment
/// colour, perturbed normal, texture_map entry) just inside the surface differs from the look just outside at
/// most of the points sampled on it. "Just" is 1e-13 of the point's distance from the origin: well above the
/// rounding of a hit point, well below POV-Ray's 1e-10 guard of checker-like patterns, so only jumps that rounding
/// decides count. A map whose two ends agree shows nothing and is not reported. At most `limit` surfaces are
/// returned; `total` receives how many places were found (capped by the work done).
std::vector<PatternWrap> find_pattern_wraps(const scene::Scene& scene, std::size_t limit, std::size_t* total);

/// The warnings for find_pattern_wraps: one per surface up to `limit`, at the pigment, normal or object, and a last
/// one that counts the rest.
std::vector<Diagnostic> pattern_wrap_warnings(const scene::Scene& scene, std::size_t limit = 3);

}  // namespace wardray::texture
