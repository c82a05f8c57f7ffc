// bump_map: a normal from an image's heights, as POV-Ray 3.7's bump_map (imageutil.cpp) computes it: the plane
// through the texel's height and those of the texels one step left-down and right-down, turned into the frame of
// the surface normal.
#include <cmath>

#include "core/constants.h"
#include "texture/image_map.h"
#include "texture/pigment.h"

namespace wardray::texture {

namespace {

/// A height sample: the grey level (or, with use_index on a palette image, the index) times `amount`.
double height_of(const scene::ImageMap& map, double amount, const Color& c, int index, bool by_index) {
    return by_index ? amount * index : amount * grey(c.rgb());
}

/// x wrapped once into [0, size), as POV-Ray steps to the neighbouring texels.
double wrap_once(double x, int size) {
    if (x < 0.0) return x + size;
    if (x >= size) return x - size;
    return x;
}

}  // namespace

Vec3 bump_map_normal(const scene::ImageMap& map, double amount, const Vec3& p, const Vec3& n) {
    const scene::ImageData& img = *map.image;
    double x = 0.0, y = 0.0;
    if (!image_position(map, p, x, y)) return n;
    int i1 = -1, i2 = -1, i3 = -1;
    const Color c1 = image_color_at(map, x, y, i1);
    x = wrap_once(x - 1.0, img.width);
    y = wrap_once(y + 1.0, img.height);
    const Color c2 = image_color_at(map, x, y, i2);
    x = wrap_once(x + 2.0, img.width);
    const Color c3 = image_color_at(map, x, y, i3);
    // POV-Ray compat: the indices are used only with use_index and when all three texels have one.
    const bool by_index = map.use_index && i1 != -1 && i2 != -1 && i3 != -1;
    const Vec3 p1{0.0, height_of(map, amount, c1, i1, by_index), 0.0};
    const Vec3 p2{-1.0, height_of(map, amount, c2, i2, by_index), 1.0};
    const Vec3 p3{1.0, height_of(map, amount, c3, i3, by_index), 1.0};
    const Vec3 bump = normalize(cross(p3 - p2, p1 - p2));
    // A frame around the surface normal: x' perpendicular to it and to y, z' completing it.
    Vec3 yp = n;
    Vec3 xp = cross(yp, Vec3{0.0, 1.0, 0.0});
    double len = length(xp);
    if (len < kPovEpsilon) {
        yp = std::fabs(n.y - 1.0) < kPovEpsilon ? Vec3{0.0, 1.0, 0.0} : Vec3{0.0, -1.0, 0.0};
        xp = {1.0, 0.0, 0.0};
        len = 1.0;
    }
    xp = xp * (1.0 / len);
    const Vec3 zp = normalize(cross(xp, yp));
    return xp * bump.x + yp * bump.y - zp * bump.z;
}

}  // namespace wardray::texture
