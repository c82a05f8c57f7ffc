// BlobShape: POV-Ray's `blob`, the level set of summed sphere and cylinder densities, in object space.
#pragma once

#include <optional>
#include <vector>

#include "core/transform.h"
#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// A blob as POV-Ray builds it: each sphere component is one element, each cylinder three (the cylinder between
/// its ends and a hemisphere at each end). An element's density is c0 d⁴ + c1 d² + c2 inside its support, with d
/// the distance to its centre (or axis) in the element's own space; along a ray each is a quartic, so the sum is
/// a quartic on every interval between the points where elements start or stop, solved exactly there.
class BlobShape {
public:
    /// Returns nothing without a usable component (zero radius, zero strength, non-finite or singular).
    static std::optional<BlobShape> create(const scene::Blob& blob);

    /// Crossings of the threshold with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Object-space bounding box of the elements of positive strength (POV-Ray's bounds).
    std::optional<Bounds> bounds() const { return m_bounds; }
    /// The inside region's bounds: unbounded when the threshold is not positive.
    std::optional<Bounds> region_bounds() const;
    /// POV-Ray compat (Inside_Blob): inside where the density exceeds the threshold less 1e-6.
    bool inside(const Vec3& p) const { return density(p) > m_threshold - 1e-6; }
    /// The threshold less the density: negative inside.
    double implicit(const Vec3& p) const { return m_threshold - density(p); }
    /// The summed density of all elements at p.
    double density(const Vec3& p) const;
    /// The outward normal at p (minus half the density's gradient), not unit length.
    Vec3 normal(const Vec3& p) const;
    /// POV-Ray's Blob::Determine_Textures weights: each component's absolute density at p (a cylinder's three
    /// elements summed), indexed as scene::Blob::components; `out` is resized to their number.
    void component_densities(const Vec3& p, std::vector<double>& out) const;

private:
    enum class Kind { Sphere, Cylinder, BaseCap, ApexCap };
    struct Element {
        Kind kind = Kind::Sphere;
        Transform to_blob;  ///< element space (centre or base at the origin, axis along z) to blob space
        double rad2 = 1.0;  ///< squared radius of the support
        double len = 0.0;   ///< cylinder length
        double c[3] = {0.0, 0.0, 0.0};
        std::size_t component = 0;  ///< the scene::Blob component it comes from
    };
    /// The element-space point whose distance from the origin (in x and y only for cylinders) gives the density.
    static Vec3 centred(const Element& e, const Vec3& local);
    /// The element's density and outward normal contribution at a blob-space point (zero outside its support).
    static double element_density(const Element& e, const Vec3& p);
    /// The parameter range [s0, s1] where the line o + s d (element space) lies in the element's support.
    static bool support_interval(const Element& e, const Vec3& o, const Vec3& d, double& s0, double& s1);

    std::vector<Element> m_elements;
    std::size_t m_components = 0;
    double m_threshold = 1.0;
    std::optional<Bounds> m_bounds;
};

}  // namespace wardray::geometry
