// Sampler: one image position traced and shaded, with the per-tile counters and POV-Ray's sample helpers.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "camera/camera.h"
#include "camera/focal_blur.h"
#include "core/render_seed.h"
#include "lighting/integrator.h"
#include "render/film.h"
#include "render/renderer.h"

namespace wardray::render {

/// A sample's colour and, with Output_Alpha, its transmit (POV-Ray's RGBT with associated alpha: the colour has
/// the transparent background counted as black, and 1 − transmit is the alpha); averaged as one.
struct Rgbt {
    Vec3 c;
    double t = 0.0;

    Rgbt& operator+=(const Rgbt& o) {
        c += o.c;
        t += o.t;
        return *this;
    }
    friend Rgbt operator+(Rgbt a, const Rgbt& b) { return a += b; }
    friend Rgbt operator/(const Rgbt& a, double d) { return {a.c / d, a.t / d}; }
};

/// What one tile adds to the totals, and the trace context its rays carry.
struct TileCounters {
    lighting::TraceContext trace;
    std::uint64_t non_finite = 0;
    std::uint64_t supersampled = 0;
};

/// Traces and shades one image position, keeping NaN and infinity out of the picture.
class Sampler {
public:
    Sampler(const camera::CameraModel& camera, const camera::FocalBlur* blur, const lighting::Integrator& integrator,
            TileCounters& counters, Film* irradiance = nullptr, Film* alpha = nullptr)
        : m_camera(camera),
          m_blur(blur),
          m_integrator(integrator),
          m_counters(counters),
          m_irradiance(irradiance),
          m_alpha(alpha) {}

    /// Pixel (x, y)'s centre sample, which also fills the irradiance film when there is one.
    Rgbt centre(int x, int y) const {
        lighting::TraceContext& ctx = m_counters.trace;
        ctx.capture_irradiance = m_irradiance != nullptr;
        ctx.captured = false;
        const Rgbt c = (*this)(x + 0.5, y + 0.5);
        if (m_irradiance)
            m_irradiance->set_pixel(x, y, ctx.captured && is_finite(ctx.irradiance) ? ctx.irradiance : Vec3{});
        ctx.capture_irradiance = false;
        return c;
    }

    Rgbt operator()(double px, double py) const {
        if (m_blur) {
            // The blur averages its rays' colours; their transmit is averaged alongside.
            double transmit = 0.0;
            int traced = 0;
            const Vec3 c = m_blur->sample(m_camera, [&](const geometry::Ray& r) {
                const Rgbt s = trace(r);
                transmit += s.t;
                ++traced;
                return s.c;
            }, px, py);
            return {c, traced > 0 ? transmit / traced : 0.0};
        }
        if (m_camera.rays_per_pixel() > 1) return several(px, py);
        const std::optional<geometry::Ray> ray = m_camera.ray(px, py);
        // POV-Ray compat: where the projection traces no ray, black (and, with alpha, transparent).
        return ray ? trace(*ray) : Rgbt{{}, m_alpha ? 1.0 : 0.0};
    }

    /// Writes a pixel's colour, and its alpha (1 − transmit) when the render has an alpha channel.
    void store(Film& film, int x, int y, const Rgbt& s) const {
        film.set_pixel(x, y, s.c);
        if (m_alpha) {
            const double a = 1.0 - s.t;
            m_alpha->set_pixel(x, y, {a, a, a});
        }
    }

private:
    /// POV-Ray compat (TracePixel): a mesh camera's rays of one position averaged over those it traces.
    Rgbt several(double px, double py) const {
        Rgbt sum;
        int traced = 0;
        for (int n = 0; n < m_camera.rays_per_pixel(); ++n) {
            if (const std::optional<geometry::Ray> ray = m_camera.ray(px, py, n)) {
                sum += trace(*ray);
                ++traced;
            }
        }
        return traced > 0 ? sum / static_cast<double>(traced) : Rgbt{{}, m_alpha ? 1.0 : 0.0};
    }

    Rgbt trace(const geometry::Ray& ray) const {
        Vec3 c = m_integrator.trace_camera_ray(ray, m_counters.trace);
        double t = m_counters.trace.transmit;
        if (!is_finite(c) || !std::isfinite(t)) {
            ++m_counters.non_finite;
            c = Vec3{};
            t = 0.0;
        }
        return {c, t};
    }

    const camera::CameraModel& m_camera;
    const camera::FocalBlur* m_blur;
    const lighting::Integrator& m_integrator;
    TileCounters& m_counters;
    Film* m_irradiance;
    Film* m_alpha;  ///< Output_Alpha: each pixel's alpha (in all three channels); null without
};

/// A jitter offset in [-0.5, 0.5) from a sample position and the render seed: the same position always jitters the
// same way, so antialiased images are repeatable (POV-Ray's jitter is a fixed function of position too).
inline Vec3 jitter_at(double x, double y, std::uint64_t seed) {
    auto hash = [](std::uint64_t v) {
        v ^= v >> 33;
        v *= 0xFF51AFD7ED558CCDull;
        v ^= v >> 33;
        v *= 0xC4CEB9FE1A85EC53ull;
        return v ^ (v >> 33);
    };
    const std::uint64_t h =
        hash(reseed(std::bit_cast<std::uint64_t>(x) ^ hash(std::bit_cast<std::uint64_t>(y)), seed));
    return {static_cast<double>(h >> 40) / double(1 << 24) - 0.5,
            static_cast<double>((h >> 16) & 0xFFFFFF) / double(1 << 24) - 0.5, 0.0};
}

/// POV-Ray's antialiasing distance (Colour_Distance_RGBT): summed absolute difference of gamma-encoded channels,
/// plus that of the transmit channel (not encoded), which is 0 without an alpha channel.
inline double encoded_distance(const Rgbt& a, const Rgbt& b, double gamma) {
    double d = std::fabs(a.t - b.t);
    for (int c = 0; c < 3; ++c)
        d += std::fabs(std::pow(std::max(a.c[c], 0.0), 1.0 / gamma) - std::pow(std::max(b.c[c], 0.0), 1.0 / gamma));
    return d;
}

/// Renders one block with POV-Ray's method 2, adaptive recursive supersampling: the corners of every pixel are
/// traced, and a pixel whose corners differ by the threshold is split into four, down to +R levels; `seed` is the
/// render seed, which turns the jitter.
void render_block_recursive(const Sampler& sample, Film& film, int x0, int y0, int x1, int y1,
                            const AntialiasSettings& aa, std::uint64_t seed, TileCounters& counters);

}  // namespace wardray::render
