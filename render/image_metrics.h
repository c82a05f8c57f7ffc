// Image metrics: rRMSE, bad-pixel fraction and non-finite pixels, exactly as docs/metrics.md defines them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "render/film.h"

namespace wardray::render {

struct ImageComparison {
    double rrmse = 0.0;               ///< sqrt(mean (I - R)²) / mean R over pixels and RGB channels
    double bad_pixel_fraction = 0.0;  ///< |Y_I - Y_R| > 0.1 Y_R + 0.01 mean(Y_R)
    std::uint64_t non_finite = 0;     ///< NaN or infinite samples in the image (any channel)
    std::uint64_t pixels = 0;
};

/// Compares `image` against `reference`; nothing when their sizes differ.
std::optional<ImageComparison> compare_images(const Film& image, const Film& reference);

/// A false-colour picture of |Y_I - Y_R| relative to the tolerance of the bad-pixel test:
/// black where they agree, blue to green to red as the difference reaches and passes the tolerance.
Film difference_image(const Film& image, const Film& reference);

}  // namespace wardray::render
