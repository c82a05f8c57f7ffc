// IrradianceRecord: the reuse radius with its clamps and the gradient limits applied when a record is made.
#include "cache/irradiance_record.h"

#include <algorithm>
#include <cmath>

namespace wardray::cache {
namespace {

/// Replaces a non-finite or non-positive value by `fallback`.
double finite_positive_or(double v, double fallback) { return std::isfinite(v) && v > 0.0 ? v : fallback; }

/// The largest |eigenvalue| of the symmetric 2x2 matrix {a, b; b, c}.
double spectral_radius(double a, double b, double c) {
    return std::fabs(0.5 * (a + c)) + std::sqrt(0.25 * (a - c) * (a - c) + b * b);
}

}  // namespace

double hessian_radius(const GatherResult& gathered, double error_bound) {
    // Schwarzhaupt, Jensen & Jarosz 2012: bound the error of first-order extrapolation by the Hessian. Moving x
    // from the record, E(x) − (E + x·∇E) = ½ xᵀ H x + O(|x|³), so |error| ≤ ½ λ |x|² with λ the largest
    // |eigenvalue| of the tangent Hessian, plus the occlusion bound (GatherResult). A lookup reuses a record up to
    // |x| = eb R (record_error's translational term, eb = error_bound); asking the error there to be at most
    // f · eb · E (f = kHessianErrorFraction, a relative error tied to error_bound as the split sphere's is):
    //   ½ λ (eb R)² = f eb E   ⇒   R = √(2 f E / (eb λ)).
    // The brightest channel sets both E and λ, so that a black channel next to a bright one does not make the
    // radius vanish (their "robust to black occluders").
    double curvature = 0.0, brightest = 0.0;
    for (int c = 0; c < 3; ++c) {
        const auto& h = gathered.hessian[c];
        const double lambda = spectral_radius(h[0], h[1], h[2]) + std::fabs(gathered.occlusion_curvature[c]);
        if (std::isfinite(lambda)) curvature = std::max(curvature, lambda);
        if (std::isfinite(gathered.irradiance[c])) brightest = std::max(brightest, std::fabs(gathered.irradiance[c]));
    }
    const double eb = error_bound > 0.0 && std::isfinite(error_bound) ? error_bound : 1.0;
    if (!(curvature > 0.0)) return HUGE_VAL;
    return std::sqrt(2.0 * kHessianErrorFraction * brightest / (eb * curvature));
}

RadiusLimits radius_limits(const scene::RadiositySettings& settings, int depth, double distance_to_camera,
                           double footprint_min, double footprint_max) {
    // POV-Ray compat: minimum_reuse and maximum_reuse are fractions of the distance to the camera, doubled per
    // bounce (radiosity.cpp, GetRecursionSettings and GatherLight).
    const double scale = std::ldexp(std::isfinite(distance_to_camera) ? std::max(distance_to_camera, 0.0) : 0.0,
                                    std::max(depth, 0));
    const double lo = std::max(settings.minimum_reuse * scale, std::isfinite(footprint_min) ? footprint_min : 0.0);
    const double hi = std::min(settings.maximum_reuse * scale, footprint_max);
    return {std::max(lo, 0.0), std::max(lo, hi), std::isfinite(footprint_min) ? std::max(footprint_min, 0.0) : 0.0};
}

IrradianceRecord make_record(const Vec3& position, const Vec3& normal, const GatherResult& gathered, int depth,
                             const RadiusLimits& limits, const RecordOptions& options) {
    IrradianceRecord rec;
    rec.position = position;
    rec.normal = normalize(normal);
    rec.irradiance = is_finite(gathered.irradiance) ? gathered.irradiance : Vec3{};
    rec.depth = depth;
    if (options.gradients) {
        for (int c = 0; c < 3; ++c) {
            rec.rotational[c] = is_finite(gathered.rotational[c]) ? gathered.rotational[c] : Vec3{};
            rec.translational[c] = is_finite(gathered.translational[c]) ? gathered.translational[c] : Vec3{};
        }
    }

    // The limits themselves must be usable: a positive finite range, else a unit radius.
    const double hi = finite_positive_or(limits.max, finite_positive_or(limits.min, 1.0));
    double lo = std::min(std::isfinite(limits.min) ? std::max(limits.min, 0.0) : 0.0, hi);
    // POV-Ray's minimum_reuse is a fraction of the distance to the camera: next to geometry closer than that (small
    // objects seen from afar, contact, the inside of a frame) it holds records larger than the irradiance's own
    // scale there, and no error_bound removes the blur. The gather's harmonic mean distance measures that scale.
    if (options.geometry_floor && depth == 0 && std::isfinite(gathered.harmonic_mean_distance) &&
        gathered.harmonic_mean_distance >= 0.0) {
        const double footprint = std::isfinite(limits.footprint) ? std::clamp(limits.footprint, 0.0, lo) : 0.0;
        lo = std::max(footprint, std::min(lo, kGeometryFloorFraction * gathered.harmonic_mean_distance));
    }

    // Ward, Rubinstein & Clear 1988: R = harmonic mean distance to the surfaces seen; or from the Hessian, whose
    // error model is that of extrapolation with gradients.
    double r = options.gradients && options.spacing == RadiusSpacing::Hessian && gathered.second_order
                   ? hessian_radius(gathered, options.error_bound)
                   : gathered.harmonic_mean_distance;
    if (std::isnan(r)) r = hi;

    // Křivánek et al. 2006 (gradient-based radius limit): R ≤ E/|∇t E|, taking the channel with the largest
    // relative gradient so that no channel extrapolates by more than its own value over R.
    if (options.gradients && options.gradient_radius_cap) {
        double relative = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double e = std::fabs(rec.irradiance[c]);
            const double g = length(rec.translational[c]);
            if (g > 0.0) relative = std::max(relative, e > 0.0 ? g / e : HUGE_VAL);
        }
        if (relative > 0.0) r = std::min(r, 1.0 / relative);
    }

    // Clamp into the footprint / reuse range; a radius enlarged by the clamp scales the translational gradient by
    // R/R_min (Křivánek et al. 2006), since the gradient was estimated over the smaller neighbourhood.
    if (r < lo) {
        const double shrink = lo > 0.0 ? std::max(r, 0.0) / lo : 1.0;
        for (Vec3& g : rec.translational) g *= shrink;
        r = lo;
    }
    r = std::min(r, hi);
    // A zero radius (a ray hit at distance 0 and no lower limit) becomes the smallest radius the coordinates resolve.
    rec.radius = r > 0.0 ? r : 1e-9 * std::max(1.0, max_abs_component(position));
    // Kept in single precision, as the cache stores them.
    rec.rotational = unpack(pack(rec.rotational));
    rec.translational = unpack(pack(rec.translational));
    return rec;
}

bool neighbour_clamp(IrradianceRecord& a, IrradianceRecord& b) {
    // Křivánek et al. 2006, neighbour clamping: the reuse radius is 1-Lipschitz in position, like the distance to
    // the nearest geometry it estimates.
    const double ra = a.radius, rb = b.radius;
    a.radius = clamped_radius(a, b);
    b.radius = clamped_radius(b, a);
    return a.radius != ra || b.radius != rb;
}

}  // namespace wardray::cache
