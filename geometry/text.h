// TextShape: POV-Ray's `text`, TrueType glyph outlines extruded from z = 0 to z = thickness, intersected analytically.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The union of the glyphs of a text object. Each glyph's outline is walked into lines and quadratic Bézier arcs as
/// POV-Ray walks TrueType contours; a point is inside a glyph when a ray from it in +x crosses the outline an odd
/// number of times and 0 <= z <= thickness. Walls are found by solving the arcs against the ray's projection on
/// the x-y plane, caps by the inside test where the ray meets z = 0 and z = thickness.
class TextShape {
public:
    /// Returns nothing for a text without any outline or with non-finite numbers.
    static std::optional<TextShape> create(const scene::Text& text);

    /// Crossings with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Object-space bounds of the glyphs.
    std::optional<Bounds> bounds() const { return m_bounds; }
    /// True inside some glyph (POV-Ray's union of glyphs).
    bool inside(const Vec3& p) const;
    /// Distance to the nearest glyph surface, negative inside.
    double implicit(const Vec3& p) const;

    /// One piece of outline in text space: a line (p1 unused) or a quadratic Bézier arc p0, p1, p2.
    struct Segment {
        double x0, y0, x1, y1, x2, y2;
        bool quadratic;
    };
    struct Glyph {
        std::vector<Segment> segments;
        double x_min, y_min, x_max, y_max;
    };

private:
    TextShape() = default;
    bool inside_outline(const Glyph& g, double x, double y) const;
    double outline_distance(const Glyph& g, double x, double y) const;

    std::shared_ptr<const std::vector<Glyph>> m_glyphs;
    double m_z_low = 0.0;
    double m_z_high = 1.0;
    std::optional<Bounds> m_bounds;
};

}  // namespace wardray::geometry
