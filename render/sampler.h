// Sampler: one image position traced and shaded, with the per-tile counters and POV-Ray's sample helpers.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "camera/camera.h"
#include "camera/focal_blur.h"
#include "lighting/integrator.h"
#include "render/film.h"
#include "render/renderer.h"

namespace wardray::render {

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
            TileCounters& counters, Film* irradiance = nullptr)
        : m_camera(camera), m_blur(blur), m_integrator(integrator), m_counters(counters), m_irradiance(irradiance) {}

    /// Pixel (x, y)'s centre sample, which also fills the irradiance film when there is one.
    Vec3 centre(int x, int y) const {
        lighting::TraceContext& ctx = m_counters.trace;
        ctx.capture_irradiance = m_irradiance != nullptr;
        ctx.captured = false;
        const Vec3 c = (*this)(x + 0.5, y + 0.5);
        if (m_irradiance)
            m_irradiance->set_pixel(x, y, ctx.captured && is_finite(ctx.irradiance) ? ctx.irradiance : Vec3{});
        ctx.capture_irradiance = false;
        return c;
    }

    Vec3 operator()(double px, double py) const {
        if (m_blur) {
            return m_blur->sample(m_camera, [&](const geometry::Ray& r) { return trace(r); }, px, py);
        }
        if (m_camera.rays_per_pixel() > 1) return several(px, py);
        const std::optional<geometry::Ray> ray = m_camera.ray(px, py);
        return ray ? trace(*ray) : Vec3{};  // POV-Ray compat: where the projection traces no ray, black
    }

private:
    /// POV-Ray compat (TracePixel): a mesh camera's rays of one position averaged over those it traces.
    Vec3 several(double px, double py) const {
        Vec3 sum;
        int traced = 0;
        for (int n = 0; n < m_camera.rays_per_pixel(); ++n) {
            if (const std::optional<geometry::Ray> ray = m_camera.ray(px, py, n)) {
                sum += trace(*ray);
                ++traced;
            }
        }
        return traced > 0 ? sum / static_cast<double>(traced) : Vec3{};
    }

    Vec3 trace(const geometry::Ray& ray) const {
        Vec3 c = m_integrator.trace_camera_ray(ray, m_counters.trace);
        if (!is_finite(c)) {
            ++m_counters.non_finite;
            c = Vec3{};
        }
        return c;
    }

    const camera::CameraModel& m_camera;
    const camera::FocalBlur* m_blur;
    const lighting::Integrator& m_integrator;
    TileCounters& m_counters;
    Film* m_irradiance;
};

/// A jitter offset in [-0.5, 0.5) from a sample position: the same position always jitters the same way,
// so antialiased images are repeatable (POV-Ray's jitter is a fixed function of position too).
inline Vec3 jitter_at(double x, double y) {
    auto hash = [](std::uint64_t v) {
        v ^= v >> 33;
        v *= 0xFF51AFD7ED558CCDull;
        v ^= v >> 33;
        v *= 0xC4CEB9FE1A85EC53ull;
        return v ^ (v >> 33);
    };
    const std::uint64_t h = hash(std::bit_cast<std::uint64_t>(x) ^ hash(std::bit_cast<std::uint64_t>(y)));
    return {static_cast<double>(h >> 40) / double(1 << 24) - 0.5,
            static_cast<double>((h >> 16) & 0xFFFFFF) / double(1 << 24) - 0.5, 0.0};
}

/// POV-Ray's antialiasing distance: summed absolute difference of gamma-encoded channels.
inline double encoded_distance(const Vec3& a, const Vec3& b, double gamma) {
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
        d += std::fabs(std::pow(std::max(a[c], 0.0), 1.0 / gamma) - std::pow(std::max(b[c], 0.0), 1.0 / gamma));
    return d;
}

/// Renders one block with POV-Ray's method 2, adaptive recursive supersampling: the corners of every pixel are
/// traced, and a pixel whose corners differ by the threshold is split into four, down to +R levels.
void render_block_recursive(const Sampler& sample, Film& film, int x0, int y0, int x1, int y1,
                            const AntialiasSettings& aa, TileCounters& counters);

}  // namespace wardray::render
