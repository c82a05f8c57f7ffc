// ParticipatingMedia: POV-Ray 3.7's media (absorption, emission, scattering) along a ray segment.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
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

/// The photons the photon pass left in media, as the media gather reads them (photons/ implements it).
class MediaPhotons {
public:
    /// One gathered photon: its flux and the unit direction towards where it came from.
    struct Sample {
        Vec3 colour;
        Vec3 to_origin;
    };
    virtual ~MediaPhotons() = default;
    /// POV-Ray's gatherPhotonsAdaptive in a medium (no normal): the photons around `p` into `out`, and the radius
    /// of the sphere they were gathered from.
    virtual double gather(const Vec3& p, std::vector<Sample>& out) const = 0;
};

/// What a medium scatters towards the eye needs from the integrator: the light reaching a point inside it.
class LightQuery {
public:
    virtual ~LightQuery() = default;
    /// The light from `scene.lights[light]` arriving at `p` as POV-Ray's TestShadow sees it (attenuated, shadowed,
    /// dimmed by media on the way); `to_light` receives the unit direction towards the light. Zero when none.
    virtual Vec3 arriving(std::size_t light, const Vec3& p, Vec3& to_light) const = 0;
    /// The media photon map, or null (no photons in media).
    virtual const MediaPhotons* photons() const { return nullptr; }
};

/// How a photon's ray deposits photons in media (POV-Ray's DepositMediaPhotons): one photon every
/// `step · factor` along the ray, at most `max_steps` per sampling interval.
struct PhotonDeposit {
    double step = 0.0;  ///< the photon spacing at the segment's start: spread · distance (spread when parallel)
    double factor = 1.0;  ///< `media max_steps, factor`: the spacing factor
    int max_steps = 0;
    double jitter = 0.4;  ///< the photons block's jitter
};

/// One photon deposited along a segment: its distance from the segment's origin and its interval's spacing factor
/// (larger than PhotonDeposit::factor where max_steps capped the count).
struct DepositPoint {
    double t = 0.0;
    double factor = 1.0;
};

/// POV-Ray 3.7's MediaFunction::ComputeMedia: lit intervals, sampling intervals, sampling methods 1 to 3, and the
/// scattering phase functions. Refers to the scene, which must outlive it; stateless, so threads share it.
class ParticipatingMedia {
public:
    /// `seed` is the render seed (--seed), which turns the sampling's jitter.
    explicit ParticipatingMedia(const scene::Scene& scene, std::uint64_t seed = 0);

    /// True when the scene has a media block anywhere; without one no ParticipatingMedia is built.
    static bool in_scene(const scene::Scene& scene);

    /// The colour arriving at the segment's origin when `colour` leaves its far end through `media` (an infinite
    /// segment ends at POV-Ray's BOUND_HUGE); in-scattered light comes through `lights`.
    Vec3 along(const MediaList& media, const Segment& segment, const Vec3& colour, const LightQuery& lights) const;
    /// What passes along the segment (extinction only): POV-Ray's ComputeMedia on a shadow ray.
    Vec3 transmittance(const MediaList& media, const Segment& segment) const;
    /// A photon's ray through `media` (POV-Ray's ComputeMediaAndDepositPhotons): where it leaves photons, into
    /// `out`, and the photon's colour at the far end. POV-Ray compat: a sampling interval too short for one photon
    /// makes the colour NaN (its 0/0 optical depth), so the photon carries nothing further.
    Vec3 deposit_photons(const MediaList& media, const Segment& segment, const Vec3& colour,
                         const PhotonDeposit& deposit, std::vector<DepositPoint>& out) const;

    /// The scene-level media (the atmosphere); empty when the scene has none.
    const MediaList& atmosphere() const { return m_atmosphere; }

    /// Per media of method 1 or 2 with more max than min samples: the variance threshold for each sample count.
    using Thresholds = std::unordered_map<const scene::Media*, std::vector<double>>;

private:
    const scene::Scene& m_scene;
    MediaList m_atmosphere;
    Thresholds m_thresholds;
    int m_noise_generator = 2;
    std::uint64_t m_seed = 0;
};

/// POV-Ray's chdtri (Cephes): the x at which the upper tail of the chi-square distribution with `df` degrees of
/// freedom is `y`. Media methods 1 and 2 derive their sample thresholds from it.
double inverse_chi_square_tail(double df, double y);

}  // namespace wardray::media
