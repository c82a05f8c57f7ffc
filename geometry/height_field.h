// HeightFieldShape: POV-Ray's `height_field`, two triangles per grid cell over the unit square, in object space.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The height field as POV-Ray 3.7 draws it. Internally in grid units (x and z count pixels, y counts 1/65536 of
/// the height), bounded by POV-Ray's box (no higher or lower than the grid, nor below the water level); rays walk
/// a min/max quadtree of the cells front to back and test each cell's two triangles with POV-Ray's tolerances
/// (over the whole ray, as POV-Ray does, so a cell may add a crossing just past its edge).
class HeightFieldShape {
public:
    /// Nothing for a height field without a grid (an image that is not rendered yet).
    static std::optional<HeightFieldShape> create(const scene::HeightField& hf);

    /// Crossings with t in (t_min, t_max), sorted; normals flat per triangle, or interpolated across the cell
    /// from the grid's vertex normals when smooth.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// POV-Ray's bounding box of the field, in the unit square's space.
    std::optional<Bounds> bounds() const;
    /// POV-Ray's inside test: below the triangle over the point (or below the water level), within the box.
    bool inside(const Vec3& p) const;
    /// Height above the surface over p (unit space, grid clamped): zero on it, negative below.
    double implicit(const Vec3& p) const;

private:
    HeightFieldShape() = default;
    double height(int x, int z) const { return static_cast<double>(m_grid->at(x, z)); }
    void build_tree();
    void build_normals();
    /// A walk of the grid: the grid-space ray, its part [t0, t1] inside the box and the crossings found so far.
    struct Walk {
        LocalRay g;
        double t0 = 0.0;
        double t1 = 0.0;
        SurfaceHits hits;
    };
    /// Tests cell (x, z)'s two triangles over the walk's whole ray; appends grid-space hits.
    void intersect_cell(int x, int z, Walk& walk) const;
    /// Walks node (i, j) of `level` front to back where the ray is over it, t in [t0, t1].
    void visit(int level, int i, int j, double t0, double t1, Walk& walk) const;
    /// The smooth normal at grid point p (bilinear across its cell).
    Vec3 smooth_normal(const Vec3& p) const;

    struct Range {
        float lo = 0.0f;
        float hi = 0.0f;
    };
    std::shared_ptr<const scene::HeightGrid> m_grid;
    bool m_smooth = false;
    Vec3 m_scale;        ///< grid units per unit-square unit: (W - 1, 65536, H - 1)
    double m_y_lo = 0.0;  ///< the box's bottom (the water level or the lowest point), grid units
    double m_y_hi = 0.0;  ///< its top
    std::vector<std::vector<Range>> m_levels;  ///< m_levels[k]: nodes of 2^k x 2^k cells, row-major
    std::vector<int> m_level_width;             ///< nodes per row at each level
    /// smooth: per grid point, POV-Ray's 16-bit normal (32767 * n), taken to world space when a hit needs it
    std::vector<std::array<std::int16_t, 3>> m_normals;
    /// The world-space unit normal of grid point `i` from its stored 16-bit one.
    Vec3 world_normal(std::size_t i) const;
    /// Unit-square space to world (scene::HeightField::placement); on the heap, as every shape instance is as large
    /// as the largest kind of shape.
    std::shared_ptr<const Transform> m_placement;
};

}  // namespace wardray::geometry
