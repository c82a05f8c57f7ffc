// HeightFieldShape: the grid's triangles, a min/max quadtree walked front to back, POV-Ray's normals and inside test.
#include "geometry/height_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wardray::geometry {

namespace {

// POV-Ray's small offset around the field's box and its least ray distance (HFIELD_OFFSET, HFIELD_TOLERANCE).
constexpr double k_offset = 0.001;
constexpr double k_tolerance = 1.0e-6;
// POV-Ray's EPSILON: rays this close to parallel to a triangle's plane miss it.
constexpr double k_epsilon = 1.0e-10;
// Tolerance of POV-Ray's point-in-triangle test, in cell units.
constexpr double k_edge = 0.0001;
// Node boxes are widened by this (grid units) so a ray along a cell boundary is seen by both sides.
constexpr double k_widen = 1.0e-7;

// The part [t0, t1] of the grid-space ray over the rectangle [x0, x1] x [z0, z1]; false when empty.
bool footprint_interval(const LocalRay& g, double x0, double x1, double z0, double z1, double& t0, double& t1) {
    const double lo[2] = {x0 - k_widen, z0 - k_widen}, hi[2] = {x1 + k_widen, z1 + k_widen};
    const double o[2] = {g.origin.x, g.origin.z}, d[2] = {g.direction.x, g.direction.z};
    for (int k = 0; k < 2; ++k) {
        if (d[k] == 0.0) {
            if (o[k] < lo[k] || o[k] > hi[k]) return false;
            continue;
        }
        double a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
        if (a > b) std::swap(a, b);
        t0 = std::fmax(t0, a);
        t1 = std::fmin(t1, b);
    }
    return t0 <= t1;
}

// POV-Ray's normalize: a vector too short to have a direction becomes +y.
Vec3 direction_or_up(const Vec3& v) {
    const double len = length(v);
    return len > k_epsilon ? v / len : Vec3{0.0, 1.0, 0.0};
}

}  // namespace

std::optional<HeightFieldShape> HeightFieldShape::create(const scene::HeightField& hf) {
    if (!hf.grid || hf.grid->width < 2 || hf.grid->height < 2 || !std::isfinite(hf.water_level)) return std::nullopt;
    HeightFieldShape s;
    s.m_grid = hf.grid;
    s.m_smooth = hf.smooth;
    s.m_placement = std::make_shared<const Transform>(hf.placement);
    s.m_scale = {hf.grid->width - 1.0, 65536.0, hf.grid->height - 1.0};
    const auto [lo, hi] = std::minmax_element(hf.grid->heights.begin(), hf.grid->heights.end());
    // POV-Ray compat: the box runs from the lowest point (or the water level, if higher) to the highest point.
    s.m_y_lo = std::fmax(static_cast<double>(*lo), 65536.0 * hf.water_level) - k_offset;
    s.m_y_hi = static_cast<double>(*hi) + k_offset;
    s.build_tree();
    if (s.m_smooth) s.build_normals();
    return s;
}

void HeightFieldShape::build_tree() {
    const int cx = m_grid->width - 1, cz = m_grid->height - 1;
    std::vector<Range> cells(static_cast<std::size_t>(cx) * cz);
    for (int z = 0; z < cz; ++z)
        for (int x = 0; x < cx; ++x) {
            const double h[4] = {height(x, z), height(x + 1, z), height(x, z + 1), height(x + 1, z + 1)};
            cells[static_cast<std::size_t>(z) * cx + x] = {static_cast<float>(*std::min_element(h, h + 4)),
                                                           static_cast<float>(*std::max_element(h, h + 4))};
        }
    m_levels.push_back(std::move(cells));
    m_level_width.push_back(cx);
    int w = cx, d = cz;
    while (w > 1 || d > 1) {
        const int nw = (w + 1) / 2, nd = (d + 1) / 2;
        const std::vector<Range>& below = m_levels.back();
        std::vector<Range> up(static_cast<std::size_t>(nw) * nd, Range{std::numeric_limits<float>::max(),
                                                                        std::numeric_limits<float>::lowest()});
        for (int j = 0; j < d; ++j)
            for (int i = 0; i < w; ++i) {
                Range& r = up[static_cast<std::size_t>(j / 2) * nw + i / 2];
                const Range& c = below[static_cast<std::size_t>(j) * w + i];
                r.lo = std::min(r.lo, c.lo);
                r.hi = std::max(r.hi, c.hi);
            }
        m_levels.push_back(std::move(up));
        m_level_width.push_back(nw);
        w = nw;
        d = nd;
    }
}

void HeightFieldShape::build_normals() {
    const int xs = m_grid->width - 1, zs = m_grid->height - 1;
    // The normal of the triangle (x0, z0), (x1, z1), (x2, z2) turned upward, or nothing past the grid's edge.
    auto corner = [&](int x0, int z0, int x1, int z1, int x2, int z2, Vec3& sum) {
        if (std::min({x0, z0, x1, z1, x2, z2}) < 0 || std::max({x0, x1, x2}) > xs || std::max({z0, z1, z2}) > zs)
            return 0;
        const Vec3 v0{double(x0), height(x0, z0), double(z0)}, v1{double(x1), height(x1, z1), double(z1)},
            v2{double(x2), height(x2, z2), double(z2)};
        Vec3 n = direction_or_up(cross(v2 - v0, v1 - v0));
        if (n.y < 0.0) n = -n;
        sum = sum + n;
        return 1;
    };
    m_normals.resize(static_cast<std::size_t>(m_grid->width) * m_grid->height);
    for (int i = 0; i <= zs; ++i)
        for (int j = 0; j <= xs; ++j) {
            Vec3 sum;
            corner(j, i, j + 1, i, j, i + 1, sum);
            corner(j, i, j, i + 1, j - 1, i, sum);
            corner(j, i, j - 1, i, j, i - 1, sum);
            corner(j, i, j, i - 1, j + 1, i, sum);
            const Vec3 n = direction_or_up(sum);
            // POV-Ray compat: vertex normals are stored as 16-bit integers (6 bytes a point, as POV-Ray keeps
            // them), then taken to the object's space where a hit needs them (world_normal).
            m_normals[static_cast<std::size_t>(i) * m_grid->width + j] = {
                static_cast<std::int16_t>(static_cast<short>(32767 * n.x)),
                static_cast<std::int16_t>(static_cast<short>(32767 * n.y)),
                static_cast<std::int16_t>(static_cast<short>(32767 * n.z))};
        }
}

Vec3 HeightFieldShape::world_normal(std::size_t i) const {
    const auto& q = m_normals[i];
    const Vec3 world = m_placement->normal({double(q[0]) * m_scale.x, double(q[1]) * m_scale.y, double(q[2]) * m_scale.z});
    return direction_or_up(world);
}

std::optional<Bounds> HeightFieldShape::bounds() const {
    return Bounds{{0.0, m_y_lo / m_scale.y, 0.0}, {1.0, m_y_hi / m_scale.y, 1.0}};
}

void HeightFieldShape::intersect_cell(int x, int z, Walk& walk) const {
    const LocalRay& g = walk.g;
    const double y1 = height(x, z), y2 = height(x + 1, z), y3 = height(x, z + 1), y4 = height(x + 1, z + 1);
    // The two triangles: (x, z), (x+1, z), (x, z+1) and (x+1, z+1), (x, z+1), (x+1, z), normals up.
    const Vec3 corners[2] = {{double(x), y1, double(z)}, {double(x + 1), y4, double(z + 1)}};
    const Vec3 normals[2] = {{y1 - y2, 1.0, y1 - y3}, {y3 - y4, 1.0, y2 - y4}};
    for (int k = 0; k < 2; ++k) {
        const double dn = dot(normals[k], g.direction);
        if (!(std::fabs(dn) > k_epsilon)) continue;
        // POV-Ray compat: the plane is met anywhere in the box, not only over this cell; the in-triangle test
        // below, with its tolerance, decides, so a crossing up to k_edge past the cell's edge counts.
        const double t = dot(normals[k], corners[k] - g.origin) / dn;
        if (!(t >= walk.t0 && t <= walk.t1)) continue;
        const double s = g.origin.x + t * g.direction.x - x, u = g.origin.z + t * g.direction.z - z;
        const bool in = k == 0 ? (s >= -k_edge && u >= -k_edge && s + u <= 1.0 + k_edge)
                               : (s <= 1.0 + k_edge && u <= 1.0 + k_edge && s + u >= 1.0 - k_edge);
        if (!in) continue;
        const Vec3 n = m_smooth ? smooth_normal(g.origin + t * g.direction)
                                : Vec3{normals[k].x * m_scale.x, normals[k].y * m_scale.y, normals[k].z * m_scale.z};
        walk.hits.push({t, n, dn < 0.0});
    }
}

Vec3 HeightFieldShape::smooth_normal(const Vec3& p) const {
    const int px = std::clamp(static_cast<int>(p.x), 0, m_grid->width - 2);
    const int pz = std::clamp(static_cast<int>(p.z), 0, m_grid->height - 2);
    const double x = p.x - px, z = p.z - pz;
    const std::size_t w = static_cast<std::size_t>(m_grid->width), i = static_cast<std::size_t>(pz) * w + px;
    const Vec3 n0 = world_normal(i), n1 = world_normal(i + 1), n2 = world_normal(i + w), n3 = world_normal(i + w + 1);
    // POV-Ray compat: the world-space vertex normals are interpolated; the result goes back to object space
    // through the transpose of the placement, which the instance's inverse transpose undoes.
    const Vec3 n_world = (1.0 - z) * ((1.0 - x) * n0 + x * n1) + z * ((1.0 - x) * n2 + x * n3);
    const auto& m = m_placement->matrix();
    Vec3 n;
    for (int k = 0; k < 3; ++k) n[k] = m[0][k] * n_world.x + m[1][k] * n_world.y + m[2][k] * n_world.z;
    return n;
}

void HeightFieldShape::visit(int level, int i, int j, double t0, double t1, Walk& walk) const {
    const LocalRay& g = walk.g;
    const int span = 1 << level;
    const int cx = m_grid->width - 1, cz = m_grid->height - 1;
    if (!footprint_interval(g, double(i * span), double(std::min((i + 1) * span, cx)), double(j * span),
                            double(std::min((j + 1) * span, cz)), t0, t1))
        return;
    // Skip the node when the ray stays above or below all its heights over it.
    const Range& r = m_levels[static_cast<std::size_t>(level)][static_cast<std::size_t>(j) * m_level_width[level] + i];
    const double ya = g.origin.y + t0 * g.direction.y, yb = g.origin.y + t1 * g.direction.y;
    const double slack = 1e-9 * (std::fabs(ya) + std::fabs(yb)) + k_offset;
    if (std::fmin(ya, yb) > r.hi + slack || std::fmax(ya, yb) < r.lo - slack) return;
    if (level == 0) {
        intersect_cell(i, j, walk);
        return;
    }
    // Children front to back: along x in the ray's x direction, along z in its z direction; the order of the
    // two diagonal neighbours does not matter (the ray meets at most one of them between the others).
    const int below = level - 1, w = m_level_width[below];
    const int nd = static_cast<int>(m_levels[below].size()) / w;
    const int first_x = g.direction.x < 0.0 ? 1 : 0, first_z = g.direction.z < 0.0 ? 1 : 0;
    const int order[4][2] = {{first_x, first_z}, {1 - first_x, first_z}, {first_x, 1 - first_z},
                             {1 - first_x, 1 - first_z}};
    for (const auto& o : order) {
        const int ci = 2 * i + o[0], cj = 2 * j + o[1];
        if (ci >= w || cj >= nd) continue;
        visit(below, ci, cj, t0, t1, walk);
    }
}

SurfaceHits HeightFieldShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    Walk walk;
    walk.g = {{ray.origin.x * m_scale.x, ray.origin.y * m_scale.y, ray.origin.z * m_scale.z},
              {ray.direction.x * m_scale.x, ray.direction.y * m_scale.y, ray.direction.z * m_scale.z}};
    // POV-Ray compat: only the part of the ray inside the field's box counts, and nothing nearer than 1e-6.
    double s0 = 0.0, s1 = 0.0;
    if (!slab_interval({0.0, m_y_lo, 0.0}, {m_scale.x, m_y_hi, m_scale.z}, walk.g.origin, walk.g.direction, s0, s1))
        return {};
    walk.t0 = std::max({s0, t_min, k_tolerance});
    walk.t1 = std::fmin(s1, t_max);
    if (!(walk.t0 <= walk.t1)) return {};
    const int top = static_cast<int>(m_levels.size()) - 1;
    visit(top, 0, 0, walk.t0, walk.t1, walk);
    walk.hits.sort_by_t();
    return without_repeated_crossings(walk.hits);
}

bool HeightFieldShape::inside(const Vec3& p_unit) const {
    const Vec3 p{p_unit.x * m_scale.x, p_unit.y * m_scale.y, p_unit.z * m_scale.z};
    if (p.x < 0.0 || p.x >= m_scale.x || p.z < 0.0 || p.z >= m_scale.z || p.y >= m_y_hi) return false;
    const double water = m_y_lo;
    if (p.y < water) return true;
    int px = static_cast<int>(p.x), pz = static_cast<int>(p.z);
    Vec3 origin, n;
    if ((p.x - px) + (p.z - pz) < 1.0) {
        const double y1 = std::fmax(height(px, pz), water), y2 = std::fmax(height(px + 1, pz), water),
                     y3 = std::fmax(height(px, pz + 1), water);
        origin = {double(px), y1, double(pz)};
        n = {y1 - y2, 1.0, y1 - y3};
    } else {
        px = static_cast<int>(std::ceil(p.x));
        pz = static_cast<int>(std::ceil(p.z));
        const double y1 = std::fmax(height(px, pz), water), y2 = std::fmax(height(px - 1, pz), water),
                     y3 = std::fmax(height(px, pz - 1), water);
        origin = {double(px), y1, double(pz)};
        n = {y2 - y1, 1.0, y3 - y1};
    }
    return dot(p, n) < dot(origin, n);
}

double HeightFieldShape::implicit(const Vec3& p_unit) const {
    const double gx = std::clamp(p_unit.x * m_scale.x, 0.0, m_scale.x);
    const double gz = std::clamp(p_unit.z * m_scale.z, 0.0, m_scale.z);
    const int px = std::clamp(static_cast<int>(gx), 0, m_grid->width - 2);
    const int pz = std::clamp(static_cast<int>(gz), 0, m_grid->height - 2);
    const double x = gx - px, z = gz - pz;
    const double h = x + z <= 1.0
                         ? height(px, pz) + x * (height(px + 1, pz) - height(px, pz)) +
                               z * (height(px, pz + 1) - height(px, pz))
                         : height(px + 1, pz + 1) + (1.0 - x) * (height(px, pz + 1) - height(px + 1, pz + 1)) +
                               (1.0 - z) * (height(px + 1, pz) - height(px + 1, pz + 1));
    return p_unit.y - h / m_scale.y;
}

}  // namespace wardray::geometry
