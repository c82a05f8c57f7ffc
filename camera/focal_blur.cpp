// FocalBlur: batches of rays over the aperture with POV-Ray's confidence test (tracepixel.cpp's focal blur).
#include "camera/focal_blur.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/render_seed.h"

namespace wardray::camera {

namespace {

// The regularized upper incomplete gamma function Q(a, x), by its series below a + 1 and its continued fraction
// above (Abramowitz & Stegun 6.5.29 and 6.5.31).
double upper_gamma_q(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double log_prefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 1000 && std::fabs(term) > 1e-16 * std::fabs(sum); ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return 1.0 - sum * std::exp(log_prefix);
    }
    // Lentz's method for the continued fraction.
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 1000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-16) break;
    }
    return std::exp(log_prefix) * h;
}

std::uint64_t mix(std::uint64_t v) {
    v ^= v >> 33;
    v *= 0xFF51AFD7ED558CCDull;
    v ^= v >> 33;
    v *= 0xC4CEB9FE1A85EC53ull;
    return v ^ (v >> 33);
}

double unit_from(std::uint64_t h) { return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0); }

/// The radical inverse of `i` in base `b` (Halton's sequence).
double radical_inverse(int i, int b) {
    double f = 1.0, r = 0.0;
    for (; i > 0; i /= b) {
        f /= b;
        r += f * (i % b);
    }
    return r;
}

/// A point of [0,1)² mapped to the disc of radius 0.5 keeping strata (Shirley & Chiu 1997, concentric map).
void square_to_disc(double u, double v, double& x, double& y) {
    const double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
    if (a == 0.0 && b == 0.0) {
        x = y = 0.0;
        return;
    }
    const double quarter = std::numbers::pi / 4.0;
    double r, phi;
    if (std::fabs(a) > std::fabs(b)) {
        r = a;
        phi = quarter * (b / a);
    } else {
        r = b;
        phi = 2.0 * quarter - quarter * (a / b);
    }
    x = 0.5 * r * std::cos(phi);
    y = 0.5 * r * std::sin(phi);
}

}  // namespace

double inverse_chi_square_complement(double df, double y) {
    // Q(df / 2, x / 2) falls from 1 to 0 as x grows: bisect for y.
    double lo = 0.0, hi = std::max(1.0, df);
    while (upper_gamma_q(0.5 * df, 0.5 * hi) > y && hi < 1e12) hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (upper_gamma_q(0.5 * df, 0.5 * mid) > y) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

FocalBlur::FocalBlur(const scene::Camera& camera, std::uint64_t seed)
    : m_samples(camera.blur_samples), m_seed(seed), m_min_samples(camera.blur_samples_min) {
    // POV-Ray compat (FocalBlurData): the thresholds of the confidence test, and the batch sizes of its hexagonal
    // grids of 7, 19 and 37 samples.
    m_threshold.assign(static_cast<std::size_t>(std::max(m_samples, 1)), 0.0);
    if (m_samples > 1) {
        const double t1 = camera.variance / inverse_chi_square_complement(m_samples - 1.0, camera.confidence);
        for (int i = 0; i < m_samples; ++i)
            m_threshold[i] = t1 * inverse_chi_square_complement(i + 1.0, camera.confidence);
    }
    if (m_samples >= 37) m_batches = {7, 6, 6, 4, 4, 4, 4, 2};
    else if (m_samples >= 19) m_batches = {7, 6, 6};
    else if (m_samples >= 7) m_batches = {7};
    m_halton.reserve(4 * static_cast<std::size_t>(std::max(m_samples, 0)));
    for (int n = 1; n <= m_samples; ++n)
        for (const int base : {2, 3, 5, 7}) m_halton.push_back(radical_inverse(n, base));
}

Vec3 FocalBlur::sample(const CameraModel& camera, const std::function<Vec3(const geometry::Ray&)>& trace,
                       double px, double py) const {
    // One random shift of a Halton sequence per position (Cranley-Patterson rotation): bases 2 and 3 place the
    // rays within the pixel, 5 and 7 on the aperture.
    const std::uint64_t seed =
        reseed(mix(std::bit_cast<std::uint64_t>(px) ^ mix(std::bit_cast<std::uint64_t>(py))), m_seed);
    double shift[4];
    for (int k = 0; k < 4; ++k) shift[k] = unit_from(mix(seed + 0x9E3779B97F4A7C15ull * (k + 1)));
    auto wrap = [](double v) { return v - std::floor(v); };
    Vec3 sum, sum_sq;
    int n = 0;
    std::size_t level = 0;
    do {
        const int batch = level < m_batches.size() ? m_batches[level++] : 4;
        for (int i = 0; i < batch && n < m_samples; ++i, ++n) {
            const double* h = &m_halton[4 * static_cast<std::size_t>(n)];
            // POV-Ray compat: its jitter runs from -1 to 0 cells of a 16 x 16 grid, so the rays cover the pixel
            // shifted by 1/32 of a pixel to the left and up.
            const double dx = wrap(h[0] + shift[0]) - 0.5 - 1.0 / 32.0;
            const double dy = wrap(h[1] + shift[1]) - 0.5 - 1.0 / 32.0;
            double lens_x, lens_y;
            square_to_disc(wrap(h[2] + shift[2]), wrap(h[3] + shift[3]), lens_x, lens_y);
            const std::optional<geometry::Ray> ray = camera.ray(px + dx, py + dy, lens_x, lens_y);
            const Vec3 c = ray ? trace(*ray) : Vec3{};
            sum += c;
            sum_sq += c * c;
        }
        // The variance of the mean, per channel, against the threshold for this many samples.
        const Vec3 mean = sum / n;
        const Vec3 variance = (sum_sq / n - mean * mean) / n;
        const double limit = m_threshold[n - 1];
        if (n >= m_min_samples && variance.x < limit && variance.y < limit && variance.z < limit) break;
    } while (n < m_samples);
    return sum / n;
}

}  // namespace wardray::camera
