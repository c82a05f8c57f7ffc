// The photon pass: POV-Ray 3.7's photon shooting from every light at every target object, traced on Embree
// through the targets' reflection and refraction, and the photon map built from what lands on surfaces.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "photons/photon_file.h"
#include "photons/photon_map.h"
#include "scene/scene.h"

namespace wardray::geometry {
class SceneGeometry;
}  // namespace wardray::geometry

namespace wardray::photons {

/// What the photon pass did, for --stats.
struct PhotonStats {
    std::uint64_t shot = 0;
    std::uint64_t stored = 0;
    std::uint64_t media_stored = 0;  ///< photons kept in media (`media` in the photons block)
    std::size_t units = 0;       ///< light-and-target pairs shot
    double spacing = 0.0;        ///< the surface spacing used (after `count`'s estimate)
    double gather_radius = 0.0;  ///< the map's gather radius
    double media_gather_radius = 0.0;  ///< the media map's
    double shoot_seconds = 0.0;
    double build_seconds = 0.0;
};

/// POV-Ray's photon pass for a scene whose global_settings enable photons: the units (each light but fill lights
/// with each target, in scene order), `count`'s spacing estimate, the shooting (rows of each unit in parallel, each
/// row seeded by its unit and index, so the photons are the same for any number of threads), and the map. Null
/// when no photon was stored on a surface. `media_map`, when given, receives the map of the photons kept in media
/// (null when none). `progress`, when set, is called now and then with the photons stored so far. `seed` is the
/// render seed (--seed), which turns every row's jitter, the media deposits and the maps' radius estimates.
std::unique_ptr<const PhotonMap> shoot_photons(const scene::Scene& scene, const geometry::SceneGeometry& geometry,
                                               PhotonStats& stats,
                                               std::unique_ptr<const PhotonMap>* media_map = nullptr,
                                               void (*progress)(std::uint64_t) = nullptr, std::uint64_t seed = 0);

/// The shooting part of shoot_photons: the photons stored on surfaces and in media, in the order stored.
ShotPhotons shoot_photon_sets(const scene::Scene& scene, const geometry::SceneGeometry& geometry, PhotonStats& stats,
                              void (*progress)(std::uint64_t) = nullptr, std::uint64_t seed = 0);
/// The maps part: the surface map (null when `shot` has no surface photon) and, into `media_map` when given, the
/// media map, from photons shot now or read from a file (`load_file`), the same maps either way.
std::unique_ptr<const PhotonMap> build_photon_maps(ShotPhotons shot, const scene::PhotonSettings& settings,
                                                   PhotonStats& stats,
                                                   std::unique_ptr<const PhotonMap>* media_map = nullptr,
                                                   std::uint64_t seed = 0);

/// POV-Ray's ComputeShadowColour test: with a photon map, a shadow ray through `blocker` (a target that refracts
/// photons of `light`) is black, since the photons carry that light.
bool photons_replace_shadow(const scene::Object& blocker, const scene::Light& light);

}  // namespace wardray::photons
