// FocalBlur: POV-Ray 3.7's focal blur, a pixel's rays spread over the aperture until their colours settle.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "camera/camera.h"

namespace wardray::camera {

/// The samples of focal blur for one camera: how many rays per batch, and when a pixel has enough.
class FocalBlur {
public:
    /// `seed` is the render seed (--seed), which turns every pixel's sample positions.
    explicit FocalBlur(const scene::Camera& camera, std::uint64_t seed = 0);

    /// The colour at image position (px, py): rays through jittered positions within the pixel and points of
    /// the aperture, traced by `trace`, in POV-Ray's batches until the confidence test passes or blur_samples
    /// are spent. The positions depend only on (px, py) and the seed, so the image is the same for any thread count.
    Vec3 sample(const CameraModel& camera, const std::function<Vec3(const geometry::Ray&)>& trace, double px,
                double py) const;

private:
    int m_samples;
    std::uint64_t m_seed;
    int m_min_samples;
    std::vector<double> m_threshold;  ///< the variance below which n + 1 samples are enough
    std::vector<int> m_batches;       ///< the batch sizes before the default of 4
    /// Sample n's unshifted Halton point (bases 2, 3, 5, 7), computed once: 4 values per sample.
    std::vector<double> m_halton;
};

/// The inverse of the complemented chi-square distribution: the x with P(χ²(df) > x) = y (Cephes' chdtri).
double inverse_chi_square_complement(double df, double y);

}  // namespace wardray::camera
