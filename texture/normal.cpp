// Normal perturbation: slope patterns sampled on a tetrahedron and the five noise-based normal-only patterns,
// as POV-Ray 3.7 computes them (normal.cpp there).
#include "texture/normal.h"

#include <cmath>

#include "texture/facets.h"
#include "texture/image_map.h"
#include "texture/noise.h"
#include "texture/pattern.h"

namespace wardray::texture {

namespace {

using Type = scene::Pattern::Type;

// POV-Ray's sampling directions: the vertices of a regular tetrahedron around the point.
constexpr Vec3 kPyramid[4] = {{0.942809041, -0.333333333, 0.0},
                              {-0.471404521, -0.333333333, 0.816496581},
                              {-0.471404521, -0.333333333, -0.816496581},
                              {0.0, 1.0, 0.0}};

bool is_normal_only(Type t) {
    return t == Type::Bumps || t == Type::Dents || t == Type::Ripples || t == Type::Waves || t == Type::Wrinkles ||
           t == Type::Quilted;
}

// The special normal patterns add a vector to the (pattern-space) normal directly.
Vec3 normal_only_offset(const scene::Normal& normal, const Vec3& p, int generator) {
    const scene::Pattern& pat = normal.pattern;
    switch (pat.type) {
        case Type::Bumps:
            return dnoise(p) * normal.amount;
        case Type::Dents: {
            const double n = noise(p, generator);
            return dnoise(p) * (n * n * n * normal.amount);
        }
        case Type::Wrinkles: {
            Vec3 sum;
            double scale = 1.0;
            for (int i = 0; i < 10; ++i, scale *= 2.0) {
                const Vec3 d = dnoise(p * scale);
                sum += Vec3{std::fabs(d.x / scale), std::fabs(d.y / scale), std::fabs(d.z / scale)};
            }
            return sum * normal.amount;
        }
        case Type::Quilted:
            return quilted_offset(pat, p) * normal.amount;
        case Type::Ripples:
        case Type::Waves: {
            const std::vector<WaveSource>& sources = wave_sources();
            const double count = static_cast<double>(sources.size());
            Vec3 sum;
            for (const WaveSource& s : sources) {
                const Vec3 d = p - s.center;
                double len = length(d);
                if (len == 0.0) len = 1.0;
                double scalar = 0.0;
                if (pat.type == Type::Ripples) {
                    scalar = cycloidal(len * pat.params->frequency + pat.params->phase) * normal.amount;
                } else {
                    scalar = cycloidal(len * pat.params->frequency * s.frequency + pat.params->phase) * normal.amount / s.frequency;
                }
                sum += d * (scalar / (len * count));
            }
            return sum;
        }
        default:
            return {};
    }
}

// POV-Ray's Do_Slope_Map: the height at `value`, a Hermite cubic between the entries' heights and slopes.
double slope_map_value(const std::vector<scene::SlopeMapEntry>& map, double value) {
    const MapLookup m = search_map(value, static_cast<int>(map.size()), [&](int i) { return map[i].value; });
    const scene::SlopeMapEntry& cur = map[m.cur];
    if (m.prev == m.cur) return cur.height;
    const scene::SlopeMapEntry& prev = map[m.prev];
    const double t = (value - prev.value) / (cur.value - prev.value);
    const double tt = t * t, ttt = tt * t;
    double rv = ttt * (prev.slope + cur.slope + 2.0 * (prev.height - cur.height));
    rv += -tt * (2.0 * prev.slope + cur.slope + 3.0 * (prev.height - cur.height));
    rv += t * prev.slope + prev.height;
    return rv;
}

}  // namespace

namespace {

// Perturb_Normal with `keep` true when the normal goes into and out of pattern space unnormalized (no_bump_scale on
// this normal, or inherited from the normal_map holding it, as POV-Ray's Post_Tnormal passes it down).
Vec3 perturb(const scene::Normal& normal, const Vec3& n, const Vec3& p, int noise_generator,
             const SurfacePoint* surface, bool keep) {
    const scene::Pattern& pat = normal.pattern;
    keep = keep || pat.no_bump_scale;
    if (normal.bump_map) {
        // POV-Ray's bump_map: the image's normal in pattern space, carried back out.
        const Vec3 local =
            bump_map_normal(*normal.bump_map, normal.amount, warp_point(pat, p), warp_normal(pat, n, keep));
        return unwarp_normal(pat, local, keep);
    }
    if (pat.type == Type::None) return n;
    const int generator = pat.params->noise_generator != 0 ? pat.params->noise_generator : noise_generator;
    const Vec3 tp = warp_point(pat, p);
    if (pat.type == Type::Average && !normal.normal_map.empty()) {
        // POV-Ray's Do_Average_Normals: each entry perturbs the pattern-space normal; the results are weighted by
        // their map values (summed in single precision).
        const Vec3 local = warp_normal(pat, n, keep);
        Vec3 sum;
        float total = 0.0f;
        for (const scene::NormalMapEntry& e : normal.normal_map) {
            sum += perturb(e.normal, local, tp, noise_generator, surface, keep) * e.value;
            total += static_cast<float>(e.value);
        }
        return unwarp_normal(pat, sum / static_cast<double>(total), keep);
    }
    if (!normal.normal_map.empty()) {
        // normal_map: the entries perturb the normal in this pattern's space and the results are blended.
        const double value = pattern_value(pat, tp, noise_generator, surface);
        const auto& map = normal.normal_map;
        const MapLookup m = search_map(value, static_cast<int>(map.size()), [&](int i) { return map[i].value; });
        const Vec3 local = warp_normal(pat, n, keep);
        Vec3 result = perturb(map[m.cur].normal, local, tp, noise_generator, surface, keep);
        if (m.prev != m.cur) {
            const Vec3 other = perturb(map[m.prev].normal, local, tp, noise_generator, surface, keep);
            result = other * (1.0 - m.fraction) + result * m.fraction;
        }
        // POV-Ray normalizes a normal_map's result whatever its flags.
        const Vec3 out = unwarp_normal(pat, result, keep);
        return keep ? normalize(out) : out;
    }
    Vec3 local = warp_normal(pat, n, keep);
    if (pat.type == Type::Facets) {
        local = facets_normal(pat, tp, local);
    } else if (is_normal_only(pat.type)) {
        local += normal_only_offset(normal, tp, generator);
    } else {
        // POV-Ray compat: the slope of any other pattern from four samples, scaled by −5 (its fudge factor).
        const double amount = normal.amount * -5.0 * (0.02 / normal.delta);
        for (const Vec3& dir : kPyramid) {
            double v = pattern_value(pat, tp + dir * normal.delta, noise_generator, surface);
            if (!normal.slope_map.empty()) v = slope_map_value(normal.slope_map, v);
            local += dir * (v * amount);
        }
    }
    return unwarp_normal(pat, local, keep);
}

}  // namespace

Vec3 perturb_normal(const scene::Normal& normal, const Vec3& n, const Vec3& p, int noise_generator,
                    const SurfacePoint* surface) {
    // POV-Ray compat: a normal kept unnormalized through pattern space is normalized once perturbed.
    const Vec3 r = perturb(normal, n, p, noise_generator, surface, false);
    return normal.pattern.no_bump_scale ? normalize(r) : r;
}

}  // namespace wardray::texture
