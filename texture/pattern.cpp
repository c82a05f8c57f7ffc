// Pattern: POV-Ray 3.7's pattern functions (pattern.cpp there), re-derived from its documented behaviour and
// checked against its renders; constants marked "POV-Ray compat" are POV-Ray's own.
#include "texture/pattern.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <type_traits>

#include "core/constants.h"
#include "texture/density_file.h"
#include "texture/facets.h"
#include "texture/fractal.h"
#include "texture/function_pattern.h"
#include "texture/image_map.h"
#include "texture/noise.h"
#include "texture/object_pattern.h"
#include "texture/pattern_blocks.h"
#include "texture/pavement.h"
#include "texture/slope.h"
#include "texture/tiling.h"

namespace wardray::texture {

namespace {

using Type = scene::Pattern::Type;

constexpr double kEpsilon = kPovEpsilon;  // POV-Ray's EPSILON
constexpr double kTwoPi = 2.0 * std::numbers::pi;

TurbulenceParams turb_params(const scene::Turbulence& t) { return {t.octaves, t.omega, t.lambda}; }

// POV-Ray's FLOOR: floor that mirrors the positive side for negative values.
double pov_floor(double x) { return x >= 0.0 ? std::floor(x) : (0.0 - std::floor(0.0 - x) - 1.0); }

// POV-Ray compat: density-style patterns map distance d to 1 − d inside [0, 1], 1 below, 0 above.
double clip_density(double d) {
    if (d < 0.0) return 1.0;
    if (d > 1.0) return 0.0;
    return 1.0 - d;
}

double triangle_wave(double v) {
    const double offset = v >= 0.0 ? v - std::floor(v) : v + 1.0 + std::floor(std::fabs(v));
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

// The fractional position inside a repeating cell, truncating like C's (int) cast and wrapping negatives.
double cell_fraction(double x) {
    double f = x - static_cast<double>(static_cast<int>(x));
    if (f < 0.0) f += 1.0;
    return f;
}

double brick(const scene::Pattern& pat, const Vec3& p) {
    // POV-Ray compat: the mortar is stored 2·EPSILON thinner, in single precision (so 0.5 stays 0.5), and the
    // point is shifted by EPSILON + mortar.
    const double mortar = static_cast<float>(pat.params->mortar - 2.0 * kEpsilon);
    const double fudge = kEpsilon + mortar;
    const double x = p.x + fudge, y = p.y + fudge, z = p.z + fudge;
    const Vec3& size = pat.params->brick_size;
    // Horizontal mortar layers.
    if (cell_fraction(y / size.y) <= mortar / size.y) return 0.0;
    // Odd and even courses are offset by half a brick along x and z.
    const bool odd_course = cell_fraction(y / size.y * 0.5) <= 0.5;
    const double mx = mortar / size.x, mz = mortar / size.z;
    if (odd_course ? cell_fraction(x / size.x) <= mx : cell_fraction(x / size.x + 0.5) <= mx) return 0.0;
    if (odd_course ? cell_fraction(z / size.z + 0.5) <= mz : cell_fraction(z / size.z) <= mz) return 0.0;
    return 1.0;
}

double hexagon(const Vec3& p) {
    // Three colours on a grid of half-triangles 0.5 wide and √3/2 tall, six cells per period.
    constexpr double kXFactor = 0.5;
    constexpr double kZFactor = 0.866025404;
    const double x = std::fabs(p.x);
    const double z = p.z < 0.0 ? 5.196152424 - std::fabs(p.z) : p.z;
    double xs = x / kXFactor;
    double zs = z / kZFactor;
    xs -= std::floor(xs / 6.0) * 6.0;
    zs -= std::floor(zs / 6.0) * 6.0;
    const int xm = static_cast<int>(pov_floor(xs)) % 6;
    const int zm = static_cast<int>(pov_floor(zs)) % 6;
    static constexpr int kStraightA[6] = {0, 1, 1, 2, 2, 0};  // xm 0 or 5, by zm
    static constexpr int kStraightB[6] = {2, 2, 0, 0, 1, 1};  // xm 2 or 3
    static constexpr int kBelow[6] = {0, 2, 1, 0, 2, 1};      // diagonal cells, below the edge
    static constexpr int kAbove[6] = {2, 1, 0, 2, 1, 0};      // diagonal cells, above the edge
    if (xm == 0 || xm == 5) return kStraightA[zm];
    if (xm == 2 || xm == 3) return kStraightB[zm];
    double xl = xs - xm;
    const double zl = zs - zm;
    if ((xm + zm) % 2 == 1) xl = 1.0 - xl;
    if (xl == 0.0) xl = 0.0001;
    return (zl / xl) < 1.0 ? kBelow[zm] : kAbove[zm];
}

// The random points of the 81 unit cubes within a "3D knight move" of cube (x, y, z), in crackle's order.
struct CrackleCube {
    int x = 0, y = 0, z = 0;
    bool valid = false;
    Vec3 points[81];
};

// The points of the cubes around (fx, fy, fz), from a small per-thread cache: neighbouring rays, and the layers
// of a texture, mostly ask for the same cubes, and each entry saves 81 hashes and 243 random numbers. The points
// depend only on the cube, so the cache changes no value and no thread sees another's. The slot comes from the
// high bits of a mixed hash: with the low bits of a plain one, cubes 16 apart (two densities of one medium
// translated by 24 at scale 0.5) took the same slot and evicted each other on every sample.
const CrackleCube& crackle_cube(int fx, int fy, int fz) {
    constexpr int kSlotBits = 6;
    thread_local CrackleCube cache[1 << kSlotBits];
    std::uint64_t h = static_cast<std::uint32_t>(fx) * 0x9E3779B97F4A7C15ull ^
                      static_cast<std::uint32_t>(fy) * 0xC2B2AE3D27D4EB4Full ^
                      static_cast<std::uint32_t>(fz) * 0x165667B19E3779F9ull;
    h ^= h >> 29;
    const std::size_t slot = static_cast<std::size_t>((h * 0xBF58476D1CE4E5B9ull) >> (64 - kSlotBits));
    CrackleCube& c = cache[slot];
    if (c.valid && c.x == fx && c.y == fy && c.z == fz) return c;
    int k = 0;
    for (int ax = -2; ax <= 2; ++ax) {
        for (int ay = -2; ay <= 2; ++ay) {
            for (int az = -2; az <= 2; ++az) {
                if ((std::abs(ax) == 2) + (std::abs(ay) == 2) + (std::abs(az) == 2) > 1) continue;
                const int cx = fx + ax, cy = fy + ay, cz = fz + az;
                const std::size_t seed = static_cast<std::size_t>(hash3d(cx & 0xFFF, cy & 0xFFF, cz & 0xFFF));
                c.points[k++] = {cx + pattern_rand(seed), cy + pattern_rand(seed + 1), cz + pattern_rand(seed + 2)};
            }
        }
    }
    c.x = fx;
    c.y = fy;
    c.z = fz;
    c.valid = true;
    return c;
}

double crackle(const scene::Pattern& pat, const Vec3& p, int generator) {
    // Voronoi distances to one random point per unit cube in the 81 cubes within a "3D knight move".
    const int fx = static_cast<int>(std::floor(p.x - kEpsilon));
    const int fy = static_cast<int>(std::floor(p.y - kEpsilon));
    const int fz = static_cast<int>(std::floor(p.z - kEpsilon));
    const CrackleCube& cube = crackle_cube(fx, fy, fz);
    const double metric = pat.params->crackle_metric;
    // The three smallest distances, kept in registers (an array here stayed in memory through the loop), one loop
    // per metric.
    double d0 = INFINITY, d1 = INFINITY, d2 = INFINITY;
    const Vec3* nearest = nullptr;
    auto scan = [&](auto distance) {
        for (const Vec3& point : cube.points) {
            const double s = distance(point - p);
            if (s < d0) {
                d2 = d1;
                d1 = d0;
                d0 = s;
                nearest = &point;
            } else if (s < d1) {
                d2 = d1;
                d1 = s;
            } else if (s < d2) {
                d2 = s;
            }
        }
    };
    if (metric == 2.0) {
        scan([](const Vec3& v) { return dot(v, v); });
    } else if (metric == 1.0) {
        scan([](const Vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); });
    } else {
        scan([metric](const Vec3& v) {
            return std::pow(std::fabs(v.x), metric) + std::pow(std::fabs(v.y), metric) + std::pow(std::fabs(v.z), metric);
        });
    }
    double d[3] = {d0, d1, d2};
    if (pat.params->crackle_offset != 0.0) {
        const double o = metric == 2.0 ? pat.params->crackle_offset * pat.params->crackle_offset
                         : metric == 1.0 ? pat.params->crackle_offset
                                         : std::pow(pat.params->crackle_offset, metric);
        for (double& v : d) v += o;
    }
    double value = 0.0;
    if (pat.params->crackle_solid) {
        value = noise(nearest ? *nearest : Vec3{}, generator);
    } else {
        const Vec3& form = pat.params->crackle_form;
        for (int i = 0; i < 3; ++i) {
            const double r = metric == 2.0 ? std::sqrt(d[i]) : metric == 1.0 ? d[i] : std::pow(d[i], 1.0 / metric);
            value += form[i] * r;
        }
    }
    return std::clamp(value, 0.0, 1.0);
}

double waves_sum(const scene::Pattern& pat, const Vec3& p, bool ripples) {
    const std::vector<WaveSource>& sources = wave_sources();
    double sum = 0.0;
    for (const WaveSource& s : sources) {
        double len = length(p - s.center);
        if (len == 0.0) len = 1.0;
        if (ripples) {
            sum += cycloidal(len * pat.params->frequency + pat.params->phase);
        } else {
            sum += cycloidal(len * pat.params->frequency * s.frequency + pat.params->phase) / s.frequency;
        }
    }
    const double n = static_cast<double>(sources.size());
    return ripples ? 0.5 * (1.0 + sum / n) : 0.2 * (2.5 + sum / n);
}

double wrinkles(const Vec3& p, int generator) {
    // Nine extra octaves of noise with lambda 2 and omega 0.5, each clipped for generators 2 and 3; the ten noises
    // are evaluated together, then added in order.
    constexpr int kOctaves = 10;
    Vec3 q[kOctaves];
    double lambda = 1.0;
    for (int i = 0; i < kOctaves; ++i, lambda *= 2.0) q[i] = i == 0 ? p : p * lambda;
    double n[kOctaves];
    noise_batch(q, kOctaves, generator, n);
    auto octave = [&](double v) { return generator > 1 ? std::clamp(v * 2.0 - 0.5, 0.0, 1.0) : v; };
    double value = octave(n[0]);
    double omega = 0.5;
    for (int i = 1; i < kOctaves; ++i, omega *= 0.5) value += omega * octave(n[i]);
    return value / 2.0;
}

double granite(const Vec3& p, int generator) {
    // Six octaves of |1 − 2n| (capped at 0.5) at 4·p, each halved.
    constexpr int kOctaves = 6;
    const Vec3 base = p * 4.0;
    Vec3 q[kOctaves];
    double freq = 1.0;
    for (int i = 0; i < kOctaves; ++i, freq *= 2.0) q[i] = base * freq;
    double n[kOctaves];
    noise_batch(q, kOctaves, generator, n);
    double value = 0.0;
    freq = 1.0;
    for (int i = 0; i < kOctaves; ++i, freq *= 2.0) {
        const double t = generator == 1 ? std::fabs(0.5 - n[i]) : std::min(std::fabs(1.0 - 2.0 * n[i]), 0.5);
        value += t / freq;
    }
    return value;
}

// The pattern functions of WARDRAY_PATTERNS, one each, at a point of pattern space.

double checker_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    const int v = static_cast<int>(std::floor(p.x + kEpsilon) + std::floor(p.y + kEpsilon) +
                                   std::floor(p.z + kEpsilon));
    return (v & 1) ? 1.0 : 0.0;
}

double gradient_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    const double v = dot(p, pat.params->gradient);
    return v > 1.0 ? std::fmod(v, 1.0) : v;
}

double hexagon_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return hexagon(p); }

double brick_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return brick(pat, p); }

double bozo_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return noise(p, generator); }

double spotted_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return noise(p, generator); }

double bumps_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return noise(p, generator); }

double dents_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    const double n = noise(p, generator);
    return n * n * n;
}

double granite_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return granite(p, generator); }

double marble_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    double turb = 0.0;
    if (pat.params->turbulence) turb = pat.params->turbulence->amount.x * turbulence(p, turb_params(*pat.params->turbulence), generator);
    return p.x + turb;
}

double wood_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    Vec3 q{p.x, p.y, 0.0};
    if (pat.params->turbulence) {
        const scene::Turbulence& t = *pat.params->turbulence;
        const Vec3 w = dturbulence(p, turb_params(t));
        q.x += cycloidal((p.x + w.x) * t.amount.x);
        q.y += cycloidal((p.y + w.y) * t.amount.y);
    }
    return length(q);
}

double agate_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    const scene::Turbulence t = pat.params->turbulence.value_or(scene::Turbulence{});
    const double turb = pat.params->agate_turb * turbulence(p, turb_params(t), generator);
    const double v = 0.5 * (cycloidal(1.3 * turb + 1.1 * p.z) + 1.0);
    return v < 0.0 ? 0.0 : std::pow(std::min(1.0, v), 0.77);
}

double radial_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
    return 0.25 + (std::atan2(p.x, p.z) + std::numbers::pi) / kTwoPi;
}

double onion_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return std::fmod(length(p), 1.0); }

double leopard_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    const double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
    return s * s;
}

double ripples_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return waves_sum(pat, p, true); }

double waves_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return waves_sum(pat, p, false); }

double wrinkles_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return wrinkles(p, generator); }

double crackle_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    return crackle(pat, p, generator);
}

double cells_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    const int h = hash3d(static_cast<int>(std::floor(p.x + kEpsilon)), static_cast<int>(std::floor(p.y + kEpsilon)),
                         static_cast<int>(std::floor(p.z + kEpsilon)));
    return std::min(pattern_rand(static_cast<std::size_t>(h)), 1.0);
}

double boxed_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    return clip_density(std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))));
}

double spherical_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return clip_density(length(p)); }

double planar_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    return clip_density(std::fabs(p.y));
}

double cylindrical_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    return clip_density(std::sqrt(p.x * p.x + p.z * p.z));
}

// `average` has no value of its own: the pigment, normal or texture averages its map's entries.
double average_pattern(const scene::Pattern& pat, const Vec3& p, int generator) { return 0.0; }

double quilted_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    return quilted_value(pat, p);
}

// POV-Ray's spiral angle in the x-y plane, 0..2π, through asin as it computes it.
double spiral_value(const scene::Pattern& pat, const Vec3& p, int generator) {
    const double turb =
        pat.params->turbulence ? pat.params->turbulence->amount.x * turbulence(p, turb_params(*pat.params->turbulence), generator) : 0.0;
    const double rad = std::sqrt(p.x * p.x + p.y * p.y);
    double phi = 0.0;
    if (rad != 0.0)
        phi = p.x < 0.0 ? 3.0 * std::numbers::pi / 2 - std::asin(p.y / rad) : std::numbers::pi / 2 + std::asin(p.y / rad);
    return p.z + rad + static_cast<double>(pat.params->arms) * phi / kTwoPi + turb;
}

double spiral1_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    return spiral_value(pat, p, generator);
}

double spiral2_pattern(const scene::Pattern& pat, const Vec3& p, int generator) {
    const double rad = std::sqrt(p.x * p.x + p.y * p.y);
    return triangle_wave(rad) + triangle_wave(spiral_value(pat, p, generator));
}

}  // namespace

Vec3 quilted_offset(const scene::Pattern& pat, const Vec3& p) {
    Vec3 v{p.x - pov_floor(p.x) - 0.5, p.y - pov_floor(p.y) - 0.5, p.z - pov_floor(p.z) - 0.5};
    const double t = length(v);
    // POV-Ray's quilt_cubic: a Bezier-like cubic through the controls, scaled by 1/sqrt(3/4).
    const double it = 1.0 - t;
    const double it2 = it * it, t2 = t * t;
    const double c = (t * t2 + 3.0 * t * it2 * pat.params->control0 + 3.0 * t2 * it * pat.params->control1) * 1.154700538;
    return v * c;
}

double quilted_value(const scene::Pattern& pat, const Vec3& p) {
    const Vec3 v = quilted_offset(pat, p);
    return (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z)) / 3.0;
}

double cycloidal(double v) {
    if (v >= 0.0) return std::sin((v - std::floor(v)) * kTwoPi);
    return 0.0 - std::sin((0.0 - (v + std::floor(0.0 - v))) * kTwoPi);
}

namespace {

// A `<keyword>_pattern` function, given the surface when it takes one (slope, aoi, pigment_pattern).
template <typename F>
double call_pattern(F f, const scene::Pattern& pat, const Vec3& p, int generator, const SurfacePoint* surface) {
    if constexpr (std::is_invocable_v<F, const scene::Pattern&, const Vec3&, int, const SurfacePoint*>)
        return f(pat, p, generator, surface);
    else
        return f(pat, p, generator);
}

}  // namespace

double raw_pattern_value(const scene::Pattern& pat, const Vec3& p, int generator, const SurfacePoint* surface) {
    // One case per pattern of WARDRAY_PATTERNS, each calling its `<keyword>_pattern`: a listed pattern without
    // its evaluation fails to compile here.
#define WARDRAY_PATTERN_CASE(keyword, Enumerator) \
    case Type::Enumerator:                        \
        return call_pattern(keyword##_pattern, pat, p, generator, surface);
    switch (pat.type) {
        case Type::None:
            return 0.0;
        WARDRAY_PATTERNS(WARDRAY_PATTERN_CASE)
    }
#undef WARDRAY_PATTERN_CASE
    return 0.0;
}

double pattern_value(const scene::Pattern& pat, const Vec3& p, int noise_generator, const SurfacePoint* surface) {
    const int generator = pat.params->noise_generator != 0 ? pat.params->noise_generator : noise_generator;
    double value = raw_pattern_value(pat, p, generator, surface);
    // POV-Ray compat: frequency and phase wrap with fmod(…, 1.00001); negative results fold into [0, 1).
    if (pat.params->frequency != 0.0) value = std::fmod(value * pat.params->frequency + pat.params->phase, 1.00001);
    if (value < 0.0) value -= std::floor(value);
    switch (pat.params->wave) {
        case scene::WaveType::Ramp:
            break;
        case scene::WaveType::Sine:
            value = (1.0 + cycloidal(value)) * 0.5;
            break;
        case scene::WaveType::Triangle:
            value = triangle_wave(value);
            break;
        case scene::WaveType::Scallop:
            value = std::fabs(cycloidal(value * 0.5));
            break;
        case scene::WaveType::Cubic:
            value = value * value * (3.0 - 2.0 * value);
            break;
        case scene::WaveType::Poly:
            value = std::pow(value, pat.params->exponent);
            break;
    }
    return value;
}

}  // namespace wardray::texture
