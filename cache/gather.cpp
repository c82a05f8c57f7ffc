// Gather: stratified hemisphere sampling reduced to irradiance, harmonic mean distance and irradiance gradients.
#include "cache/gather.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/color.h"

namespace wardray::cache {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A radiance that is unusable (NaN, infinite) counts as black, so one bad ray cannot poison a record.
Vec3 sanitize_radiance(const Vec3& l) { return is_finite(l) ? l : Vec3{}; }

/// Distances are non-negative; NaN counts as a miss.
double sanitize_distance(double d) {
    if (std::isnan(d)) return kInf;
    return std::max(d, 0.0);
}

/// Neighbouring hits this close in distance (ratio) are taken as one surface; farther apart, as a depth step.
constexpr double kSameSurface = 2.0;

/// Whether two hit distances lie on one surface (both finite, within kSameSurface of each other).
bool same_surface(double r0, double r1) {
    return std::isfinite(r0) && std::isfinite(r1) && std::max(r0, r1) <= kSameSurface * std::min(r0, r1);
}

/// Whether a wall between cells at distances r0 and r1 is a depth step (an occlusion edge).
bool depth_step(double r0, double r1) { return std::max(r0, r1) > kSameSurface * std::min(r0, r1); }

/// The reciprocal of the distance that sets how fast a cell wall moves, with a floor so that a zero distance gives a
/// large but finite rate.
double inverse_wall_distance(double r0, double r1, double floor) { return 1.0 / std::max(std::min(r0, r1), floor); }

/// The translational Hessian of E in the tangent plane (local frame: x along t, y along b, z along n).
/// Each cell's hit is a planar patch of area A = r² Δω / (p·ω) at q = r ω, facing the point along p = −(its
/// normal), fixed in space while the point moves by x. Its share of E (no π) is
///   g(x) = (L A / π) ((q − x)·n) (p·(q − x)) / |q − x|⁴,
/// and with cosine-weighted strata L Δω cos θ / π = L / (MN). Differentiating g twice at x = 0 (n_i = 0 along
/// the tangent plane) gives, for tangent axes i, j:
///   ∂²g/∂x_i∂x_j = L / (MN r²) · (24 ω_i ω_j − 4 δ_ij − 4 (p_i ω_j + p_j ω_i) / (p·ω)),
/// which sums to zero over a uniformly bright sphere or plane around the point, as it must. The patch's normal
/// comes from differences of its neighbours' hits across θ and φ, central where both lie on the same surface,
/// one-sided where one does; else the patch faces the point (p = ω), as it does for a grazing estimate
/// (p·ω < 0.05). This is the smooth part of Schwarzhaupt, Jensen & Jarosz 2012's Hessian (their per-sample
/// patches), written for the stratified grid.
void tangent_hessian(const std::vector<HemisphereSample>& samples, const std::vector<Vec3>& l,
                     const std::vector<double>& r, const Strata& grid, double distance_floor, GatherResult& out) {
    const int m = grid.polar, cells = grid.azimuthal;
    const auto at = [cells](int j, int k) { return static_cast<std::size_t>(j) * cells + k; };
    const double per_cell = 1.0 / static_cast<double>(samples.size());
    const auto hit = [&](std::size_t i) { return samples[i].direction * r[i]; };
    for (int j = 0; j < m; ++j) {
        for (int k = 0; k < cells; ++k) {
            const std::size_t i = at(j, k);
            if (!std::isfinite(r[i])) continue;  // a miss: light from infinitely far does not change with x
            const Vec3& w = samples[i].direction;
            Vec3 p = w;
            double cos_patch = 1.0;
            // A difference across θ and one across φ, central where both neighbours lie on the same surface, else
            // one-sided toward the one that does.
            const auto across = [&](std::size_t before, std::size_t after, Vec3& edge) {
                const bool b_ok = before != i && same_surface(r[i], r[before]);
                const bool a_ok = after != i && same_surface(r[i], r[after]);
                if (!b_ok && !a_ok) return false;
                edge = (a_ok ? hit(after) : hit(i)) - (b_ok ? hit(before) : hit(i));
                return true;
            };
            Vec3 e_theta, e_phi;
            if (cells >= 3 && across(at(std::max(j - 1, 0), k), at(std::min(j + 1, m - 1), k), e_theta) &&
                across(at(j, (k + cells - 1) % cells), at(j, (k + 1) % cells), e_phi)) {
                Vec3 normal = cross(e_theta, e_phi);
                const double len = length(normal);
                if (len > 0.0) {
                    normal = normal / len;
                    const double c = dot(normal, w);
                    if (std::fabs(c) >= 0.05) {
                        p = c > 0.0 ? normal : -normal;
                        cos_patch = std::fabs(c);
                    }
                }
            }
            const double d = std::max(r[i], distance_floor);
            const double s = per_cell / (d * d);
            const double xx = s * (24.0 * w.x * w.x - 4.0 - 8.0 * p.x * w.x / cos_patch);
            const double xy = s * (24.0 * w.x * w.y - 4.0 * (p.x * w.y + p.y * w.x) / cos_patch);
            const double yy = s * (24.0 * w.y * w.y - 4.0 - 8.0 * p.y * w.y / cos_patch);
            for (int c = 0; c < 3; ++c) {
                out.hessian[c][0] += l[i][c] * xx;
                out.hessian[c][1] += l[i][c] * xy;
                out.hessian[c][2] += l[i][c] * yy;
            }
        }
    }
}

/// The occlusion part: a depth step between two cells is an edge that sweeps over what lies behind it as the point
/// moves. Its first-order effect is the wall's term of the translational gradient, |ΔL| · weight / r_near
/// (Křivánek et al. 2005, as in gather()); the rate r_near changes at is of order one per unit of x, so its second
/// derivative is bounded by |ΔL| · weight / r_near², summed without signs, so that no two edges cancel.
void occlusion_curvature(const std::vector<double>& sin_lo, const std::vector<Vec3>& l, const std::vector<double>& r,
                         const Strata& grid, double distance_floor, GatherResult& out) {
    const int m = grid.polar, cells = grid.azimuthal;
    const auto at = [cells](int j, int k) { return static_cast<std::size_t>(j) * cells + k; };
    const auto add = [&](std::size_t a, std::size_t b, double weight) {
        if (!depth_step(r[a], r[b])) return;
        const double near = std::max(std::min(r[a], r[b]), distance_floor);
        const Vec3 dl = l[a] - l[b];
        const double scale = weight / (near * near);
        for (int c = 0; c < 3; ++c) out.occlusion_curvature[c] += std::fabs(dl[c]) * scale;
    };
    // The gradient's wall weights: polar walls (1/π) sin θ cos² θ |∫u dφ|, azimuthal walls (1/π) ∫ cos θ dθ.
    const double arc = 2.0 * std::sin(std::numbers::pi / cells);
    for (int j = 1; j < m; ++j) {
        const double s = sin_lo[j];
        const double weight = s * (1.0 - s * s) * arc / std::numbers::pi;
        for (int k = 0; k < cells; ++k) add(at(j, k), at(j - 1, k), weight);
    }
    for (int j = 0; j < m; ++j) {
        const double weight = (sin_lo[j + 1] - sin_lo[j]) / std::numbers::pi;
        for (int k = 0; k < cells; ++k) add(at(j, k), at(j, (k + cells - 1) % cells), weight);
    }
}

}  // namespace

GatherResult gather(const Vec3& position, const Vec3& normal, const Strata& strata, const RadianceFunction& radiance,
                    std::uint64_t salt) {
    return gather_seeded(position, normal, strata, radiance, seed_from(position, normal, salt));
}

GatherResult gather_seeded(const Vec3& position, const Vec3& normal, const Strata& strata,
                           const RadianceFunction& radiance, std::uint64_t seed, bool second_order, int extra_rays) {
    GatherResult out;
    const Vec3 n = normalize(normal);
    const int m = std::max(strata.polar, 1);
    const int cells_azimuthal = std::max(strata.azimuthal, 1);
    if (!(dot(n, n) > 0.0) || !is_finite(n)) {
        out.harmonic_mean_distance = kInf;
        out.nearest_distance = kInf;
        return out;
    }
    Vec3 t, b;
    orthonormal_basis(n, t, b);

    // Trace one jittered ray per cell (Ward & Heckbert 1992: θ_j = asin√((j+ξ)/M), φ_k = 2π(k+ξ')/N).
    SplitMix64 rng(seed);
    const std::vector<HemisphereSample> samples = stratified_cosine_samples({m, cells_azimuthal}, rng);
    const std::size_t count = samples.size();
    std::vector<Vec3> l(count);
    std::vector<double> r(count);
    double nearest = kInf;
    const auto trace = [&](const Vec3& d, Vec3& l_out, double& r_out) {
        const RadianceSample s = radiance(t * d.x + b * d.y + n * d.z);
        l_out = sanitize_radiance(s.radiance);
        r_out = sanitize_distance(s.distance);
        nearest = std::min(nearest, r_out);
    };
    for (std::size_t i = 0; i < count; ++i) trace(samples[i].direction, l[i], r[i]);
    out.ray_count = static_cast<int>(count);
    if (extra_rays > 0) {
        // Adaptive hemisphere sampling: the extras go to the cells whose neighbours differ most in luminance, and
        // each such cell keeps the mean radiance and the harmonic mean distance of its rays, so that every
        // estimator below still sees one value per cell of the grid.
        std::vector<double> luminance(count);
        for (std::size_t i = 0; i < count; ++i) luminance[i] = wardray::luminance(l[i]);
        const std::vector<int> extra = adaptive_extra_rays(luminance, {m, cells_azimuthal}, extra_rays);
        // Each cell draws its extras from its own stream, so a cell that gets one ray more or less (two nearly equal
        // variances in a scaled scene) changes no other cell's directions.
        const std::uint64_t extra_seed = rng.next();
        for (std::size_t i = 0; i < count; ++i) {
            if (extra[i] == 0) continue;
            SplitMix64 cell_rng(SplitMix64(extra_seed ^ (0xD1B54A32D192ED03ull * (i + 1))).next());
            Vec3 l_sum = l[i];
            double inverse_sum = r[i] > 0.0 ? 1.0 / r[i] : kInf;
            for (int e = 0; e < extra[i]; ++e) {
                Vec3 l_e;
                double r_e = 0.0;
                trace(sample_in_cell({m, cells_azimuthal}, samples[i].polar, samples[i].azimuth, cell_rng).direction,
                      l_e, r_e);
                l_sum += l_e;
                inverse_sum += r_e > 0.0 ? 1.0 / r_e : kInf;
            }
            const double rays = 1.0 + extra[i];
            l[i] = l_sum / rays;
            r[i] = inverse_sum > 0.0 ? rays / inverse_sum : kInf;
            out.ray_count += extra[i];
        }
    }
    double inverse_distance_sum = 0.0;
    Vec3 sum;
    for (std::size_t i = 0; i < count; ++i) {
        sum += l[i];
        inverse_distance_sum += r[i] > 0.0 ? 1.0 / r[i] : kInf;
    }

    // Irradiance without π: E = (1/MN) Σ L_jk, each cell covering π/(MN) of projected solid angle.
    out.irradiance = sum / static_cast<double>(count);
    // Harmonic mean distance (Ward, Rubinstein & Clear 1988, the record's reuse radius).
    out.harmonic_mean_distance = inverse_distance_sum > 0.0 ? count / inverse_distance_sum : kInf;
    out.nearest_distance = nearest;

    // The floor on wall distances is relative to the coordinates, so the gradients stay finite and scale-free.
    const double distance_floor = 1e-9 * std::max(1.0, max_abs_component(position));

    // Cell boundaries: sin²θ_j− = j/M, φ_k− = 2πk/N.
    std::vector<double> sin_lo(m + 1), theta_lo(m + 1);
    for (int j = 0; j <= m; ++j) {
        sin_lo[j] = std::sqrt(static_cast<double>(j) / m);
        theta_lo[j] = std::asin(std::min(1.0, sin_lo[j]));
    }
    const double dphi = 2.0 * std::numbers::pi / cells_azimuthal;
    std::vector<Vec3> u_integral(cells_azimuthal), wall_tangent(cells_azimuthal);
    for (int k = 0; k < cells_azimuthal; ++k) {
        const double p0 = k * dphi, p1 = (k + 1) * dphi;
        // ∫ u(φ) dφ over cell k, with u(φ) = cos φ t + sin φ b.
        u_integral[k] = t * (std::sin(p1) - std::sin(p0)) + b * (std::cos(p0) - std::cos(p1));
        // The direction in which the azimuthal wall at φ_k− moves its contents: v = −sin φ t + cos φ b.
        wall_tangent[k] = t * (-std::sin(p0)) + b * std::cos(p0);
    }
    const auto at = [cells_azimuthal](int j, int k) { return static_cast<std::size_t>(j) * cells_azimuthal + k; };

    // Rotational gradient (Ward & Heckbert 1992, rotation gradient: ∇r E = Σ_k v_k Σ_j tan θ_j L_jk · π/(MN)), with the
    // per-cell weight integrated exactly for radiance constant over the cell:
    // dE/dα = (1/π) Σ_jk L_jk a·(n × ∫u dφ) ∫ sin²θ dθ, the sign fixed by n × u (tested against finite differences).
    for (int j = 0; j < m; ++j) {
        const auto antiderivative = [](double th) { return 0.5 * th - 0.25 * std::sin(2.0 * th); };
        const double w = (antiderivative(theta_lo[j + 1]) - antiderivative(theta_lo[j])) / std::numbers::pi;
        for (int k = 0; k < cells_azimuthal; ++k) {
            const Vec3 v = cross(n, u_integral[k]) * w;
            const Vec3& lk = l[at(j, k)];
            for (int c = 0; c < 3; ++c) out.rotational[c] += v * lk[c];
        }
    }

    // Translational gradient (Ward & Heckbert 1992, translation gradient, in the occlusion-robust form of
    // Křivánek, Gautron, Bouatouch & Pattanaik 2005, docs/design.md's formula divided by π):
    // each wall between neighbouring cells moves at a rate set by the nearer of its two hit distances.
    for (int j = 1; j < m; ++j) {
        // Polar wall θ_j−: (1/π) sin θ cos² θ / min(r) · (L_j − L_{j−1}) · ∫u dφ.
        const double s = sin_lo[j];
        const double rate = s * (1.0 - s * s) / std::numbers::pi;
        for (int k = 0; k < cells_azimuthal; ++k) {
            const std::size_t hi = at(j, k), lo = at(j - 1, k);
            const Vec3 dir = u_integral[k] * (rate * inverse_wall_distance(r[hi], r[lo], distance_floor));
            const Vec3 dl = l[hi] - l[lo];
            for (int c = 0; c < 3; ++c) out.translational[c] += dir * dl[c];
        }
    }
    for (int j = 0; j < m; ++j) {
        // Azimuthal wall φ_k−: (1/π) (sin θ_j+ − sin θ_j−) / min(r) · (L_k − L_{k−1}) · v_k−, the exact ∫ cos θ dθ
        // over the cell in place of Křivánek's cos θ_j (cos θ_j− − cos θ_j+) / sin θ_j.
        const double rate = (sin_lo[j + 1] - sin_lo[j]) / std::numbers::pi;
        for (int k = 0; k < cells_azimuthal; ++k) {
            const int k_prev = (k + cells_azimuthal - 1) % cells_azimuthal;
            const std::size_t cur = at(j, k), prev = at(j, k_prev);
            const Vec3 dir = wall_tangent[k] * (rate * inverse_wall_distance(r[cur], r[prev], distance_floor));
            const Vec3 dl = l[cur] - l[prev];
            for (int c = 0; c < 3; ++c) out.translational[c] += dir * dl[c];
        }
    }
    if (second_order) {
        out.second_order = true;
        tangent_hessian(samples, l, r, {m, cells_azimuthal}, distance_floor, out);
        occlusion_curvature(sin_lo, l, r, {m, cells_azimuthal}, distance_floor, out);
    }
    return out;
}

}  // namespace wardray::cache
