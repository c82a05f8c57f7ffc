// Spline outlines of POV-Ray's prism: the pieces its Compute_Prism makes from the points (prism.cpp).
#pragma once

#include <vector>

#include "scene/scene.h"
#include "core/vec3.h"

namespace wardray::geometry {

/// One piece of a prism outline: u(w) = Σ cu[i] wⁱ, v(w) = Σ cv[i] wⁱ for w in [0, 1], as (u, v, 0).
struct PrismPiece {
    double cu[4] = {};
    double cv[4] = {};
    Vec3 end;  ///< the point the piece ends on, exactly (the polynomial at 1 may round differently)

    Vec3 at(double w) const {
        if (w == 1.0) return end;
        return {((cu[3] * w + cu[2]) * w + cu[1]) * w + cu[0], ((cv[3] * w + cv[2]) * w + cv[1]) * w + cv[0], 0.0};
    }
    Vec3 tangent(double w) const {
        return {(3.0 * cu[3] * w + 2.0 * cu[2]) * w + cu[1], (3.0 * cv[3] * w + 2.0 * cv[2]) * w + cv[1], 0.0};
    }
};

/// POV-Ray's pieces of a quadratic, cubic or Bézier outline, in order: quadratic and cubic sub-polygons run from
/// their second point and close when a point two ahead repeats that first curve point; Bézier pieces take four
/// points each.
std::vector<PrismPiece> prism_spline_pieces(const scene::Prism& prism);

}  // namespace wardray::geometry
