// Scene description, light sources.
#pragma once

#include <string_view>
#include <vector>

#include "core/color.h"
#include "core/diagnostics.h"
#include "core/vec3.h"
#include "scene/interior.h"
#include "scene/kind_list.h"

namespace wardray::scene {

struct Object;

/// The light kinds, listed once: X(name, Enumerator). A point light is the default and has no keyword; each other
/// name is the keyword that makes a light one. Light::Type and the names of light_type_name come from this list.
#define WARDRAY_LIGHTS(X) \
    X(point, Point)       \
    X(spotlight, Spot)    \
    X(parallel, Parallel) \
    X(cylinder, Cylinder)

/// A light source with POV-Ray's defaults.
struct Light {
#define WARDRAY_LIGHT_ENUMERATOR(name, Enumerator) Enumerator,
    /// The kinds of WARDRAY_LIGHTS, in its order.
    enum class Type { WARDRAY_LIGHTS(WARDRAY_LIGHT_ENUMERATOR) };
#undef WARDRAY_LIGHT_ENUMERATOR
    Type type = Type::Point;
    Vec3 position;
    Color color{1.0, 1.0, 1.0};
    double fade_distance = 0.0;  ///< 0: no fading
    double fade_power = 0.0;
    bool shadowless = false;
    // Spotlight and cylinder parameters (degrees), POV-Ray's defaults.
    Vec3 point_at{0.0, 0.0, 1.0};
    double radius = 30.0;
    double falloff = 45.0;
    double tightness = 0.0;
    // `area_light axis1, axis2, size1, size2` with its options, POV-Ray's defaults.
    bool area = false;
    Vec3 area_axis1;
    Vec3 area_axis2;
    int area_size1 = 1;
    int area_size2 = 1;
    int adaptive = 100;  ///< POV-Ray's default: subdivide to the full grid
    bool jitter = false;
    bool circular = false;
    bool orient = false;
    /// `media_attenuation`: fog dims the light on its way (POV-Ray's default: off); `media_interaction` (on).
    bool media_attenuation = false;
    bool media_interaction = true;
    /// 0: a global light, lighting every object but those of light groups without `global_lights`; else the
    /// `light_group` it belongs to, and it lights only that group's objects (Object::light_groups).
    int group = 0;
    /// `projected_through { object }`, at most one: the light reaches only points that see it through this object
    /// (placed in world space); shadows count only between the point and the object. Empty for most lights.
    std::vector<Object> projected_through;
    /// The light's `photons { refraction reflection area_light }` block.
    PhotonSwitch photon_refraction = PhotonSwitch::Unset;
    PhotonSwitch photon_reflection = PhotonSwitch::Unset;
    bool photon_area_light = false;
    SourceLoc loc;
    bool operator==(const Light&) const = default;
};

#define WARDRAY_LIGHT_NAME(name, Enumerator) {#name, Light::Type::Enumerator},
/// The name of each light kind of WARDRAY_LIGHTS, in its order.
inline constexpr KindKeyword<Light::Type> k_light_names[] = {WARDRAY_LIGHTS(WARDRAY_LIGHT_NAME)};
#undef WARDRAY_LIGHT_NAME

/// The name of a light kind: "point", "spotlight", "parallel" or "cylinder".
constexpr std::string_view light_type_name(Light::Type type) { return kind_keyword(k_light_names, type); }

}  // namespace wardray::scene
