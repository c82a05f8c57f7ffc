// Block patterns and pigment_pattern, as POV-Ray 3.7 computes them (square_pattern, triangular_pattern,
// cubic_pattern and pigment_pattern there).
#include "texture/pattern_blocks.h"

#include <cmath>

#include "texture/pigment.h"

namespace wardray::texture {

namespace {

constexpr double kSqrt3 = 1.7320508075688772935274463415059;
constexpr double kSqrt3Half = 0.86602540378443864676372317075294;

}  // namespace

double square_pattern(const scene::Pattern&, const Vec3& p, int) {
    const int x = static_cast<int>(std::floor(p.x));
    const int z = static_cast<int>(std::floor(p.z));
    if (x & 1) return (z & 1) ? 2.0 : 3.0;
    return (z & 1) ? 1.0 : 0.0;
}

double triangular_pattern(const scene::Pattern&, const Vec3& p, int) {
    // Fold the plane onto a 3 × √3 rectangle, then onto its lower half by symmetry.
    double xs = p.x - 3.0 * std::floor(p.x / 3.0);
    double zs = p.z - kSqrt3 * std::floor(p.z / kSqrt3);
    const int a = static_cast<int>(std::floor(xs));
    xs -= a;
    const bool mirrored = zs >= kSqrt3Half;
    if (mirrored) zs = kSqrt3 - zs;
    const double k = 1.0 - xs;
    double answer = 1.0;
    if (xs != 0.0 && k != 0.0) {
        const int side = (zs / xs < kSqrt3 ? 1 : 0) + (zs / k < kSqrt3 ? 2 : 0);
        // POV-Ray leaves the (measure-zero) case 0 undefined; 0 is taken here.
        static constexpr double kBySide[4] = {0.0, 3.0, 1.0, 0.0};
        answer = kBySide[side];
    }
    const int mask = static_cast<int>(answer);
    answer = (mask & 1) ? std::fmod(answer + 2.0 * a, 6.0) : std::fmod(6.0 + answer - 2.0 * a, 6.0);
    return mirrored ? 5.0 - answer : answer;
}

double cubic_pattern(const scene::Pattern&, const Vec3& p, int) {
    const double x = p.x, y = p.y, z = p.z;
    const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
    if (x >= 0 && x >= ay && x >= az) return 0.0;
    if (y >= 0 && y >= ax && y >= az) return 1.0;
    if (z >= 0 && z >= ax && z >= ay) return 2.0;
    if (x < 0 && x <= -ay && x <= -az) return 3.0;
    if (y < 0 && y <= -ax && y <= -az) return 4.0;
    return 5.0;
}

double pigment_pattern_pattern(const scene::Pattern& pat, const Vec3& p, int generator, const SurfacePoint* surface) {
    if (!pat.params->pigment.pigment) return 0.0;
    const Color c = evaluate_pigment(*pat.params->pigment.pigment, p, generator, surface);
    return grey(c.rgb());
}

}  // namespace wardray::texture
