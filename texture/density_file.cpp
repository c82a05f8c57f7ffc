// density_file: the value of a df3 voxel grid over the unit cube, without or with trilinear interpolation.
#include "texture/density_file.h"

#include <cmath>
#include <cstddef>

namespace wardray::texture {

double density_file_pattern(const scene::Pattern& pat, const Vec3& p, int) {
    if (!pat.params->density_file) return 0.0;
    const scene::DensityFile& d = *pat.params->density_file;
    if (d.nx == 0 || d.ny == 0 || d.nz == 0) return 0.0;
    if (!(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0 && p.z >= 0.0 && p.z < 1.0)) return 0.0;
    const std::size_t sx = static_cast<std::size_t>(d.nx), sy = static_cast<std::size_t>(d.ny),
                      sz = static_cast<std::size_t>(d.nz);
    double xx = p.x * static_cast<double>(sx), yy = p.y * static_cast<double>(sy), zz = p.z * static_cast<double>(sz);
    const std::size_t x1 = static_cast<std::size_t>(xx), y1 = static_cast<std::size_t>(yy),
                      z1 = static_cast<std::size_t>(zz);
    // POV-Ray compat: the interpolation type counts modulo 10; tricubic (2) is read as trilinear (the parser
    // warns).
    if (pat.params->density_interpolation % 10 == 0) {
        if (x1 >= sx || y1 >= sy || z1 >= sz) return 0.0;
        return d.at(x1, y1, z1);
    }
    // Trilinear between the voxel and its neighbours, the far ones wrapping round to the first.
    const std::size_t x2 = (x1 + 1) % sx, y2 = (y1 + 1) % sy, z2 = (z1 + 1) % sz;
    xx -= std::floor(xx);
    yy -= std::floor(yy);
    zz -= std::floor(zz);
    const double xi = 1.0 - xx, yi = 1.0 - yy;
    const double f111 = d.at(x1, y1, z1), f112 = d.at(x2, y1, z1), f121 = d.at(x1, y2, z1), f122 = d.at(x2, y2, z1);
    const double f211 = d.at(x1, y1, z2), f212 = d.at(x2, y1, z2), f221 = d.at(x1, y2, z2), f222 = d.at(x2, y2, z2);
    return ((f111 * xi + f112 * xx) * yi + (f121 * xi + f122 * xx) * yy) * (1.0 - zz) +
           ((f211 * xi + f212 * xx) * yi + (f221 * xi + f222 * xx) * yy) * zz;
}

}  // namespace wardray::texture
