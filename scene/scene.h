// Scene description: the renderer-independent plain data the parser produces, with a source location on each entity.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/color.h"
#include "core/diagnostics.h"
#include "scene/atmosphere.h"
#include "scene/camera.h"
#include "scene/interior.h"
#include "scene/light.h"
#include "scene/media.h"
#include "scene/object.h"
#include "scene/settings.h"
#include "scene/shapes.h"
#include "scene/texture.h"

namespace wardray::scene {

/// Everything the renderer needs from a scene file.
struct Scene {
    std::string path;  ///< the main scene file
    double version = 3.7;  ///< the language version in force at the end of the file
    /// POV-Ray compat: the effective version at the end is below 3.7 (no #version anywhere counts as 3.62).
    bool legacy_version = false;
    Camera camera;
    std::vector<Light> lights;
    std::vector<Object> objects;
    GlobalSettings global;
    Color background{0.0, 0.0, 0.0};
    bool background_given = false;   ///< a `background` statement was read
    /// POV-Ray compat: the background was read under an effective #version below 3.7 (none given counts as 3.62),
    /// so with Output_Alpha it is fully transparent whatever its transmit says.
    bool background_legacy = false;
    std::optional<SkySphere> sky_sphere;
    std::vector<Fog> fogs;
    std::vector<Rainbow> rainbows;
    /// Scene-level `media { }` blocks: POV-Ray's atmosphere, filling everything outside non-hollow objects.
    std::vector<Media> media;
    /// Features parsed but not rendered yet, and other warnings found while parsing.
    std::vector<Diagnostic> warnings;
};

}  // namespace wardray::scene
