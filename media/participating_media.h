// ParticipatingMedia: POV-Ray 3.7's media (absorption, emission, scattering) along a ray segment.
#pragma once

#include <array>
#include <cstddef>
#include <unordered_map>
#include <vector>

#include "media/medium.h"
#include "scene/scene.h"

namespace wardray::media {

/// The media one ray segment passes through together: those of the interiors the ray is in, or the atmosphere's.
struct MediaList {
    static constexpr int kMax = 32;
    std::array<const scene::Media*, kMax> items{};
    int size = 0;
    /// Adds an interior's (or the scene's) media blocks, in their order (beyond kMax they are ignored).
    void add(const std::vector<scene::Media>& media) {
        for (const scene::Media& m : media)
            if (size < kMax) items[size++] = &m;
    }
    bool empty() const { return size == 0; }
};

/// What a medium scatters towards the eye needs from the integrator: the light reaching a point inside it.
class LightQuery {
public:
    virtual ~LightQuery() = default;
    /// The light from `scene.lights[light]` arriving at `p` as POV-Ray's TestShadow sees it (attenuated, shadowed,
    /// dimmed by media on the way); `to_light` receives the unit direction towards the light. Zero when none.
    virtual Vec3 arriving(std::size_t light, const Vec3& p, Vec3& to_light) const = 0;
};

/// POV-Ray 3.7's MediaFunction::ComputeMedia: lit intervals, sampling intervals, sampling methods 1 to 3, and the
/// scattering phase functions. Refers to the scene, which must outlive it; stateless, so threads share it.
class ParticipatingMedia {
public:
    explicit ParticipatingMedia(const scene::Scene& scene);

    /// True when the scene has a media block anywhere; without one no ParticipatingMedia is built.
    static bool in_scene(const scene::Scene& scene);

    /// The colour arriving at the segment's origin when `colour` leaves its far end through `media` (an infinite
    /// segment ends at POV-Ray's BOUND_HUGE); in-scattered light comes through `lights`.
    Vec3 along(const MediaList& media, const Segment& segment, const Vec3& colour, const LightQuery& lights) const;
    /// What passes along the segment (extinction only): POV-Ray's ComputeMedia on a shadow ray.
    Vec3 transmittance(const MediaList& media, const Segment& segment) const;

    /// The scene-level media (the atmosphere); empty when the scene has none.
    const MediaList& atmosphere() const { return m_atmosphere; }

    /// Per media of method 1 or 2 with more max than min samples: the variance threshold for each sample count.
    using Thresholds = std::unordered_map<const scene::Media*, std::vector<double>>;

private:
    const scene::Scene& m_scene;
    MediaList m_atmosphere;
    Thresholds m_thresholds;
    int m_noise_generator = 2;
};

/// POV-Ray's chdtri (Cephes): the x at which the upper tail of the chi-square distribution with `df` degrees of
/// freedom is `y`. Media methods 1 and 2 derive their sample thresholds from it.
double inverse_chi_square_tail(double df, double y);

}  // namespace wardray::media
