// Image metrics: the project's one definition of image error (docs/metrics.md).
#include "render/image_metrics.h"

#include <algorithm>
#include <cmath>

#include "core/color.h"

namespace wardray::render {

namespace {

double mean_luminance(const Film& f) {
    double sum = 0.0;
    for (int y = 0; y < f.height(); ++y)
        for (int x = 0; x < f.width(); ++x) sum += luminance(f.pixel(x, y));
    return f.width() * f.height() > 0 ? sum / (static_cast<double>(f.width()) * f.height()) : 0.0;
}

}  // namespace

std::optional<ImageComparison> compare_images(const Film& image, const Film& reference) {
    if (image.width() != reference.width() || image.height() != reference.height()) return std::nullopt;
    ImageComparison out;
    out.pixels = static_cast<std::uint64_t>(image.width()) * image.height();
    const double mean_y_ref = mean_luminance(reference);
    double sum_sq = 0.0, sum_ref = 0.0;
    std::uint64_t bad = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const Vec3 i = image.pixel(x, y);
            const Vec3 r = reference.pixel(x, y);
            if (!is_finite(i)) {
                ++out.non_finite;
                ++bad;
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                sum_sq += (i[c] - r[c]) * (i[c] - r[c]);
                sum_ref += r[c];
            }
            const double y_ref = luminance(r);
            if (std::fabs(luminance(i) - y_ref) > 0.1 * y_ref + 0.01 * mean_y_ref) ++bad;
        }
    }
    const double n = 3.0 * static_cast<double>(out.pixels);
    out.rrmse = sum_ref > 0.0 ? std::sqrt(sum_sq / n) / (sum_ref / n) : (sum_sq > 0.0 ? INFINITY : 0.0);
    out.bad_pixel_fraction = out.pixels > 0 ? static_cast<double>(bad) / out.pixels : 0.0;
    return out;
}

Film difference_image(const Film& image, const Film& reference) {
    const int w = std::min(image.width(), reference.width());
    const int h = std::min(image.height(), reference.height());
    Film out(w, h);
    const double mean_y_ref = mean_luminance(reference);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const Vec3 i = image.pixel(x, y);
            if (!is_finite(i)) {
                out.set_pixel(x, y, {1.0, 0.0, 1.0});  // magenta: not a number
                continue;
            }
            const double y_ref = luminance(reference.pixel(x, y));
            const double tolerance = 0.1 * y_ref + 0.01 * mean_y_ref;
            // s = 1 at the bad-pixel threshold; the colour runs blue (0) → green (1) → red (≥ 2).
            const double s = tolerance > 0.0 ? std::fabs(luminance(i) - y_ref) / tolerance : 0.0;
            const double t = std::clamp(s / 2.0, 0.0, 1.0);
            const Vec3 c = t < 0.5 ? Vec3{0.0, 2.0 * t, 1.0 - 2.0 * t} : Vec3{2.0 * t - 1.0, 2.0 - 2.0 * t, 0.0};
            out.set_pixel(x, y, c * std::min(1.0, s));
        }
    }
    return out;
}

}  // namespace wardray::render
