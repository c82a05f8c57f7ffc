// PhotonMap: POV-Ray 3.7's surface photon map: photons stored as POV-Ray packs them (single-precision position,
// an RGBE colour, the incoming direction in two signed bytes), a balanced kd-tree, and its adaptive gather.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "media/participating_media.h"
#include "scene/settings.h"

namespace wardray::photons {

/// One stored photon, packed as POV-Ray packs it, so its rounding is the same.
struct Photon {
    std::array<float, 3> position{};
    std::array<std::uint8_t, 4> rgbe{};  ///< Ward's RGBE with POV-Ray's exponent bias of 250
    std::int8_t theta = 0;                ///< direction towards the photon's origin, 127 steps per π
    std::int8_t phi = 0;
    std::uint8_t axis = 0;  ///< the kd-tree's split axis at this node

    Vec3 point() const { return {position[0], position[1], position[2]}; }
};

/// The power of two a map's photons are stored divided by, so that their RGBE exponent byte holds them at any
/// scene scale: a photon's flux grows as spacing² on surfaces (`dimensions` 2) and spacing³ in media (3). Zero
/// for spacings below 1/32 (POV-Ray's storage, exactly).
int flux_exponent_offset(double spacing, int dimensions);
/// Packs a photon: its position, its colour (flux) divided by 2^exponent_offset and the point it came from.
Photon make_photon(const Vec3& position, const Vec3& colour, const Vec3& origin, int exponent_offset = 0);
/// The photon's colour as POV-Ray unpacks it, times 2^exponent_offset (its map's).
Vec3 photon_colour(const Photon& p, int exponent_offset = 0);
/// The unit direction from the photon towards where it came from, from its two bytes.
Vec3 photon_direction(const Photon& p);
/// Whether a photon of a map with a power-of-two offset has a flux beyond what POV-Ray's byte holds (2^5 and more,
/// with its fixed bias of 250), where POV-Ray's exponent wraps round and its photon comes out nearly black while
/// wardray's keeps its light. Without an offset wardray's byte wraps as POV-Ray's does: never beyond.
bool beyond_povray_flux(const Photon& p, int exponent_offset);

/// The photons found by a gather and the radius POV-Ray divides their sum by.
struct Gathered {
    std::vector<const Photon*> photons;
    double radius = 0.0;
    int exponent_offset = 0;  ///< the map's: photon_colour(*photon, exponent_offset) is a photon's flux
};

/// The photon map: built once after shooting, then read by every thread.
class PhotonMap {
public:
    /// Builds the kd-tree over `photons` (their order decides nothing but ties) and POV-Ray's gather radius
    /// (setGatherOptions: estimated from the photons' density unless the settings give it), with a fixed seed
    /// turned by the render seed `seed` (--seed). `media`: a map of photons in media, whose radius comes from their
    /// density in volume (POV-Ray's mediaMap).
    /// `exponent_offset`: the one the photons were made with (flux_exponent_offset).
    PhotonMap(std::vector<Photon> photons, const scene::PhotonSettings& settings, bool media = false,
              std::uint64_t seed = 0, int exponent_offset = 0);

    std::size_t size() const { return m_photons.size(); }
    /// The photons in the kd-tree's order.
    const std::vector<Photon>& photons() const { return m_photons; }
    double min_gather_radius() const { return m_min_radius; }

    /// POV-Ray's gatherPhotons: up to gather_max photons nearest `p` within `size`, distances flattened along `n`
    /// (d² grows by 16·|n·v|·d², so photons off the surface's plane count as farther) when `n` is given. The radius
    /// is `size`, or the farthest photon kept when more were in reach.
    void gather(const Vec3& p, double size, const Vec3* n, Gathered& out) const;
    /// POV-Ray's gatherPhotonsAdaptive: gather at the map's radius, and once more at three times it when too few
    /// photons were found and the density does not drop by more than expand_thresholds says.
    void gather_adaptive(const Vec3& p, const Vec3& n, Gathered& out) const { gather_adaptive(p, &n, out); }
    /// The same without a normal (in a medium: a sphere, not a disc).
    void gather_adaptive(const Vec3& p, const Vec3* n, Gathered& out) const;

private:
    /// Builds the subtree of [begin, end), node `id` (the root 1, a node's children 2·id and 2·id + 1).
    void build(int begin, int end, std::size_t id);
    /// The k-nearest walk of gather: the nearest `limit` photons nearer than sqrt(max_d2) into `found` (in no
    /// order), max_d2 shrinking to the farthest kept when more were in reach.
    void search(const Vec3& p, const Vec3* n, double& max_d2, std::size_t limit,
                std::vector<std::pair<double, const Photon*>>& found) const;
    void estimate_radius(const scene::PhotonSettings& settings, bool media, std::uint64_t seed);

    std::vector<Photon> m_photons;
    /// The photons' bounding box per node id, for the nodes of at least 8 photons or so: lo x y z, hi x y z.
    std::vector<std::array<float, 6>> m_boxes;
    int m_gather_max = 100;
    int m_gather_min = 20;
    double m_expand_tolerance = 0.2;
    int m_expand_min = 35;
    double m_min_radius = 0.0;
    double m_radius_step = 0.0;
    int m_exponent_offset = 0;
};

/// The media photon map as the media gather reads it (POV-Ray's ComputeMediaPhotons through its PhotonGatherer).
class MediaPhotonGather final : public media::MediaPhotons {
public:
    explicit MediaPhotonGather(const PhotonMap& map) : m_map(map) {}
    double gather(const Vec3& p, std::vector<Sample>& out) const override;

private:
    const PhotonMap& m_map;
};

}  // namespace wardray::photons
