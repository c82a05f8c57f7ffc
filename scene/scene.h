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
    Camera camera;
    std::vector<Light> lights;
    std::vector<Object> objects;
    GlobalSettings global;
    Color background{0.0, 0.0, 0.0};
    std::optional<SkySphere> sky_sphere;
    std::vector<Fog> fogs;
    std::vector<Rainbow> rainbows;
    /// Scene-level `media { }` blocks: POV-Ray's atmosphere, filling everything outside non-hollow objects.
    std::vector<Media> media;
    /// Features parsed but not rendered yet, and other warnings found while parsing.
    std::vector<Diagnostic> warnings;
};

}  // namespace wardray::scene
