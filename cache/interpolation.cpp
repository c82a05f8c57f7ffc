// Interpolation: record validity (error and behind tests), weights, and first-order extrapolation with gradients.
#include "cache/interpolation.h"

#include <algorithm>
#include <cmath>

namespace wardray::cache {
namespace {

/// The behind test's tolerance as a fraction of R_i; records up to this far in front fade out linearly.
constexpr double kFrontLimit = 0.05;
/// Ward's 1/ε weight is bounded at ε = error_bound × this fraction (the singularity at distance zero).
constexpr double kWeightFloor = 1.0 / 32.0;

/// POV-Ray compat: its weighting of a record with t = ε / error_bound in [0, 1) (radiosity.cpp, AverageNearBlock):
/// a smooth pseudo-sigmoid in the final pass at depth 0, linear 1 − t elsewhere.
double coverage_weight(double t, bool smooth) {
    if (!smooth) return 1.0 - t;
    if (t < 0.5) return 1.0 - 2.0 * t * t;
    const double u = 1.0 - t;
    return 2.0 * u * u;
}

/// A fade in [0, 1] for records slightly in front of p, so that the behind test has no hard edge.
double front_fade(double front) {
    if (front >= 0.0) return 1.0;
    return std::clamp(1.0 + front / kFrontLimit, 0.0, 1.0);
}

}  // namespace

LookupParams lookup_params(const scene::RadiositySettings& settings, int depth, bool final_pass, double ray_weight) {
    LookupParams params;
    // POV-Ray compat (radiosity.cpp, RadiosityFunction and ComputeAmbient): pretrace passes use
    // error_bound × low_error_factor; rays of weight below 0.25 get a looser bound; each bounce doubles it.
    double eb = settings.error_bound * (final_pass ? 1.0 : settings.low_error_factor);
    if (ray_weight < 0.25) eb += 0.25 - std::max(ray_weight, 0.0);
    params.error_bound = std::ldexp(eb, std::max(depth, 0));
    // POV-Ray compat: nearest_count at depth 0, at most 2 at depth 1, 1 deeper (GetRecursionSettings).
    const int nc = std::max(settings.nearest_count, 1);
    params.reuse_count = depth == 0 ? nc : (depth == 1 ? std::min(2, nc) : 1);
    params.accept_any = final_pass && !settings.always_sample;
    params.smooth_coverage = final_pass && depth == 0;
    return params;
}

double pretrace_low_error_factor(double low_error_factor) {
    if (!(low_error_factor > 0.0)) return low_error_factor;  // what the scene's block says, left to lookup_params
    return std::min(1.0, low_error_factor / kPovLowErrorFactor);
}

double record_error(const RecordGeometry& record, const Vec3& p, const Vec3& n) {
    // Ward, Rubinstein & Clear 1988, the split-sphere error ε = |p − p_i|/R_i + √(1 − n·n_i);
    // POV-Ray compat: the rotational term is doubled (radiosity.cpp, error_reuse_rotate).
    const double translation = length(p - record.position) / record.radius;
    const double rotation = 2.0 * std::sqrt(std::max(0.0, 1.0 - dot(n, record.normal)));
    return translation + rotation;
}

double record_error(const IrradianceRecord& record, const Vec3& p, const Vec3& n) {
    return record_error(geometry_of(record), p, n);
}

double front_distance(const RecordGeometry& record, const Vec3& p, const Vec3& n) {
    // Ward, Rubinstein & Clear 1988, the "in front" test d_i = (p − p_i)·(n + n_i)/2, here against the unit
    // half vector and divided by R_i so that it does not depend on the scene's scale.
    const Vec3 half = n + record.normal;
    const double len = length(half);
    if (!(len > 1e-12)) return -HUGE_VAL;
    return dot(p - record.position, half) / (len * record.radius);
}

double front_distance(const IrradianceRecord& record, const Vec3& p, const Vec3& n) {
    return front_distance(geometry_of(record), p, n);
}

bool is_valid(const IrradianceRecord& record, const Vec3& p, const Vec3& n, double error_bound) {
    if (!(dot(n, record.normal) > 0.0)) return false;
    if (!(record_error(record, p, n) < error_bound)) return false;
    return front_distance(record, p, n) > -kFrontLimit;
}

namespace {

/// Ward & Heckbert 1992, first-order extrapolation: E_i + (n_i × n)·∇r E_i + (p − p_i)·∇t E_i, with the gradients
/// of channel c given by `rotational(c)` and `translational(c)`.
template <typename Rotational, typename Translational>
Vec3 extrapolate_from(const Vec3& position, const Vec3& normal, const Vec3& irradiance, Rotational&& rotational,
                      Translational&& translational, const Vec3& p, const Vec3& n) {
    const Vec3 axis = cross(normal, n);
    const Vec3 offset = p - position;
    Vec3 out;
    for (int c = 0; c < 3; ++c) {
        const double e = irradiance[c];
        const double v = e + dot(axis, rotational(c)) + dot(offset, translational(c));
        // Never negative; POV-Ray compat: a negative value (negative light) stays on its side of zero.
        out[c] = e >= 0.0 ? std::max(v, 0.0) : std::min(v, 0.0);
    }
    return out;
}

Vec3 channel(const PackedGradients& g, int c) {
    const auto k = 3 * static_cast<std::size_t>(c);
    return {g[k], g[k + 1], g[k + 2]};
}

}  // namespace

Vec3 extrapolate(const IrradianceRecord& record, const Vec3& p, const Vec3& n, bool gradients) {
    if (!gradients) return record.irradiance;
    return extrapolate_from(
        record.position, record.normal, record.irradiance,
        [&](int c) { return record.rotational[static_cast<std::size_t>(c)]; },
        [&](int c) { return record.translational[static_cast<std::size_t>(c)]; }, p, n);
}

Vec3 extrapolate(const RecordGeometry& geometry, const RecordValues& values, const Vec3& p, const Vec3& n,
                 bool gradients) {
    if (!gradients) return values.irradiance;
    return extrapolate_from(
        geometry.position, geometry.normal, values.irradiance,
        [&](int c) { return channel(values.rotational, c); },
        [&](int c) { return channel(values.translational, c); }, p, n);
}

InterpolationAccumulator::InterpolationAccumulator(const Vec3& p, const Vec3& n, const LookupParams& params)
    : m_p(p),
      m_n(normalize(n)),
      m_params(params),
      m_inverse_bound(1.0 / params.error_bound),
      m_weight_floor(kWeightFloor * params.error_bound) {}

bool InterpolationAccumulator::add(const IrradianceRecord& record) {
    RecordWeight w;
    if (!weigh(geometry_of(record), w)) return false;
    add_weighted(record, w);
    return true;
}

bool InterpolationAccumulator::weigh_near(const RecordGeometry& record, RecordWeight& out) const {
    const double eb = m_params.error_bound;
    // Facing away: the cheapest rejection left once the distance test has passed.
    const double cos_normals = dot(m_n, record.normal);
    if (!(cos_normals > 0.0)) return false;
    // is_valid(): ε as record_error() computes it, with the offset shared by the behind test.
    if (!(eb > 0.0)) return false;
    const Vec3 offset = m_p - record.position;
    const double eps = std::sqrt(dot(offset, offset)) / record.radius +
                       2.0 * std::sqrt(std::max(0.0, 1.0 - cos_normals));
    if (!(eps < eb)) return false;
    // front_distance(): a record level with p or behind it (offset·(n + n_i) ≥ 0) has front ≥ 0 and no fade, known
    // without its square root and division; |n + n_i|² > 1 whenever unit normals face the same side.
    const Vec3 half = m_n + record.normal;
    const double half2 = dot(half, half);
    const double along = dot(offset, half);
    double fade = 1.0;
    if (!(along >= 0.0 && half2 > 1.0)) {
        const double len = std::sqrt(half2);
        if (!(len > 1e-12)) return false;
        const double front = along / (len * record.radius);
        if (!(front > -kFrontLimit)) return false;
        fade = front_fade(front);
    }
    // Ward, Rubinstein & Clear 1988's weight 1/ε, bounded at ε → 0 and shifted by 1/error_bound so it reaches
    // zero at the edge of validity (no seams where a record stops being valid).
    out.weight = fade * (1.0 / std::max(eps, m_weight_floor) - m_inverse_bound);
    out.coverage = fade * coverage_weight(eps / eb, m_params.smooth_coverage);
    return out.weight > 0.0;
}

void InterpolationAccumulator::add_weighted(const IrradianceRecord& record, const RecordWeight& w) {
    add_sample(extrapolate(record, m_p, m_n, m_params.gradients), w);
}

void InterpolationAccumulator::add_weighted(const RecordGeometry& geometry, const RecordValues& values,
                                            const RecordWeight& w) {
    add_sample(extrapolate(geometry, values, m_p, m_n, m_params.gradients), w);
}

void InterpolationAccumulator::add_sample(const Vec3& extrapolated, const RecordWeight& w) {
    m_sum += extrapolated * w.weight;
    m_weight_sum += w.weight;
    m_coverage += w.coverage;
    ++m_records;
}

Interpolation InterpolationAccumulator::result() const {
    Interpolation out;
    out.weight_sum = m_weight_sum;
    out.coverage = m_coverage;
    out.records = m_records;
    if (m_weight_sum > 0.0) out.irradiance = m_sum / m_weight_sum;
    // POV-Ray compat (ComputeAmbient): reuse when 4·Σ coverage ≥ nearest_count, or in the final pass when any
    // record is valid.
    out.sufficient = m_records > 0 && (m_params.accept_any || 4.0 * m_coverage >= m_params.reuse_count);
    return out;
}

}  // namespace wardray::cache
