// Image maps: planar, spherical, cylindrical and torus projections onto the image, then its texels.
#include "texture/image_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wardray::texture {

namespace {

constexpr double k_two_pi = 2.0 * std::numbers::pi;
constexpr double k_epsilon = 1e-10;  // POV-Ray's EPSILON

/// v wrapped into [0, period).
double wrap(double v, double period) {
    v = std::fmod(v, period);
    if (v < 0.0) v += period;
    return v >= period ? 0.0 : v;
}

/// The angle of (x, z) around the y axis, 0 to 2π, as POV-Ray's image maps measure it.
double longitude(double x, double z, double len) {
    if (z == 0.0) return x > 0.0 ? 0.0 : std::numbers::pi;
    const double theta = std::acos(x / len);
    return z < 0.0 ? k_two_pi - theta : theta;
}

/// The image position (u across, v up, in texels) of point p, or false where the map has no image.
bool map_position(const scene::ImageMap& map, int w, int h, const Vec3& p, double& u, double& v) {
    double x = p.x, y = p.y, z = p.z;
    switch (map.map_type) {
    case 1: {  // spherical: longitude across, latitude up
        const double len = std::sqrt(x * x + y * y + z * z);
        if (len == 0.0) return false;
        x /= len, y /= len, z /= len;
        const double phi = 0.5 + std::asin(y) / std::numbers::pi;
        const double ring = std::sqrt(x * x + z * z);
        u = (ring == 0.0 ? 0.0 : longitude(x, z, ring) / k_two_pi) * w;
        v = phi * h;
        return true;
    }
    case 2: {  // cylindrical: longitude across, height up
        if (map.once && (y < 0.0 || y > 1.0)) return false;
        v = std::fmod(y * h, static_cast<double>(h));
        const double len = std::sqrt(x * x + y * y + z * z);
        if (len == 0.0) return false;
        x /= len, z /= len;
        const double ring = std::sqrt(x * x + z * z);
        if (ring == 0.0) return false;
        u = longitude(x, z, ring) / k_two_pi * w;
        return true;
    }
    case 5: {  // torus of major radius 1: around the y axis across, around the tube up
        const double len = std::sqrt(x * x + z * z);
        if (len == 0.0) return false;
        const double theta = -longitude(x, z, len);
        const double dx = len - 1.0;
        double phi = std::acos(-dx / std::sqrt(dx * dx + y * y));
        if (y > 0.0) phi = k_two_pi - phi;
        u = -theta / k_two_pi * w;
        v = phi / k_two_pi * h;
        return true;
    }
    default:  // planar: x across, y up
        if (map.once && (x < 0.0 || x > 1.0 || y < 0.0 || y > 1.0)) return false;
        u = std::fmod(x * w, static_cast<double>(w));
        v = std::fmod(y * h, static_cast<double>(h));
        return true;
    }
}

/// Texel (x, y) (y from the top) with its filter and transmit (POV-Ray's no_interpolation): clamped to the image
/// with `once`, else wrapped; `index` is the palette index of a palette image, else -1.
Color texel(const scene::ImageMap& map, double x, double y, int& index) {
    const scene::ImageData& img = *map.image;
    int ix, iy;
    if (map.once) {
        ix = x < 0.0 ? 0 : (x >= img.width ? img.width - 1 : static_cast<int>(x));
        iy = y < 0.0 ? 0 : (y >= img.height ? img.height - 1 : static_cast<int>(y));
    } else {
        ix = static_cast<int>(wrap(x, img.width));
        iy = static_cast<int>(wrap(y, img.height));
    }
    const std::size_t at = static_cast<std::size_t>(iy) * img.width + ix;
    const float* t = &img.rgb[at * 3];
    if (!img.indexed()) {
        // POV-Ray compat: a true-colour texel's alpha is its transmit, 1 − alpha (straight colours, interpolated
        // as they are); filter all and transmit all add to it.
        index = -1;
        const double transmit = img.alpha.empty() ? 0.0 : 1.0 - img.alpha[at];
        return Color{t[0], t[1], t[2], map.filter_all, transmit + map.transmit_all};
    }
    index = img.index[at];
    if (map.palette_ft.empty()) return Color{t[0], t[1], t[2], 0.0, 0.0};
    const scene::PaletteFT& ft =
        index < static_cast<int>(map.palette_ft.size()) ? map.palette_ft[index] : scene::PaletteFT{};
    return Color{t[0], t[1], t[2], ft.filter, ft.transmit};
}

}  // namespace

bool image_position(const scene::ImageMap& map, const Vec3& p, double& x, double& y) {
    const scene::ImageData& img = *map.image;
    double u = 0.0, v = 0.0;
    const bool inside = map_position(map, img.width, img.height, p, u, v);
    u += k_epsilon;
    v += k_epsilon;
    if (!inside || (map.once && (u >= img.width || v >= img.height || u < 0.0 || v < 0.0))) return false;
    // POV-Ray compat: image rows run from the top, so v is flipped.
    x = wrap(u, img.width);
    y = wrap(-v, img.height);
    return true;
}

Color image_color_at(const scene::ImageMap& map, double x, double y, int& index) {
    if (map.interpolate != 2 && map.interpolate != 4) return texel(map, x, y, index);
    // The four texels around the position, weighted bilinearly or by normalized inverse squared distance.
    const double xs = x + 0.5, ys = y + 0.5;
    const int ix = static_cast<int>(xs), iy = static_cast<int>(ys);
    const double fx = xs - ix, fy = ys - iy;
    int corner_index[4];
    const Color c[4] = {texel(map, ix, iy, corner_index[0]), texel(map, ix - 1.0, iy, corner_index[1]),
                        texel(map, ix, iy - 1.0, corner_index[2]), texel(map, ix - 1.0, iy - 1.0, corner_index[3])};
    double f[4];
    if (map.interpolate == 2) {
        f[0] = fx * fy, f[1] = (1 - fx) * fy, f[2] = fx * (1 - fy), f[3] = (1 - fx) * (1 - fy);
    } else {
        const double d2[4] = {(1 - fx) * (1 - fx) + (1 - fy) * (1 - fy), fx * fx + (1 - fy) * (1 - fy),
                              (1 - fx) * (1 - fx) + fy * fy, fx * fx + fy * fy};
        double sum = 0.0;
        for (int i = 0; i < 4; ++i) sum += 1.0 / d2[i];
        // On a texel's centre its own weight is the whole (POV-Ray divides by zero there).
        for (int i = 0; i < 4; ++i) f[i] = std::isfinite(sum) ? (1.0 / d2[i]) / sum : (d2[i] == 0.0 ? 1.0 : 0.0);
    }
    Vec3 rgb;
    double filter = 0.0, transmit = 0.0, idx = 0.0;
    for (int i = 0; i < 4; ++i) {
        rgb += c[i].rgb() * f[i];
        filter += c[i].filter * f[i];
        transmit += c[i].transmit * f[i];
        idx += corner_index[i] * f[i];
    }
    // POV-Ray compat: the interpolated index is truncated.
    index = static_cast<int>(idx);
    return Color{rgb.x, rgb.y, rgb.z, filter, transmit};
}

Color image_map_color(const scene::ImageMap& map, const Vec3& p) {
    double x = 0.0, y = 0.0;
    if (!image_position(map, p, x, y)) return Color{1.0, 1.0, 1.0, 0.0, 1.0};
    int index = -1;
    return image_color_at(map, x, y, index);
}

int material_map_index(const scene::ImageMap& map, const Vec3& p, int count) {
    // POV-Ray's material_map: the texel's palette index, else its red channel times 255 (0 off the image).
    int number = 0;
    double x = 0.0, y = 0.0;
    if (image_position(map, p, x, y)) {
        int index = -1;
        const Color c = image_color_at(map, x, y, index);
        number = index == -1 ? static_cast<int>(c.r * 255.0) : index;
    }
    // POV-Ray compat: a number past the count wraps; one equal to it, or a negative one, takes the last or first.
    if (number > count) number %= count;
    return std::clamp(number, 0, count - 1);
}

}  // namespace wardray::texture
