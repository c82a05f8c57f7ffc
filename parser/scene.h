// Scene description: the renderer-independent plain data the parser produces, with a source location on each entity.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "parser/diagnostics.h"
#include "parser/transform.h"
#include "parser/vec3.h"

namespace wardray::parser {

/// POV-Ray's five-component colour: linear RGB plus filter and transmit.
struct Color {
    double r = 0.0;
    double g = 0.0;
    double b = 0.0;
    double filter = 0.0;
    double transmit = 0.0;

    Vec3 rgb() const { return {r, g, b}; }
};

/// A pigment. Only solid colours so far; patterns and maps extend this struct.
struct Pigment {
    Color color;  // POV-Ray compat: the default pigment is black.
    SourceLoc loc;
};

/// Surface finish with POV-Ray 3.7's defaults.
struct Finish {
    Color ambient{0.1, 0.1, 0.1};
    Color emission{0.0, 0.0, 0.0};
    double diffuse = 0.6;
    double brilliance = 1.0;
    double phong = 0.0;
    double phong_size = 40.0;
    double specular = 0.0;
    double roughness = 0.05;
    SourceLoc loc;
};

struct Texture {
    Pigment pigment;
    Finish finish;
};

struct Sphere {
    Vec3 center;
    double radius = 1.0;
};

struct Box {
    Vec3 corner1;
    Vec3 corner2;
};

/// POV-Ray's `plane { normal, distance }`: the surface {p : dot(n̂, p) = distance} with n̂ the unit normal;
/// the inside is where dot(n̂, p) < distance. The parser stores the normal as written.
struct Plane {
    Vec3 normal{0.0, 1.0, 0.0};
    double distance = 0.0;
};

/// The shapes the renderer draws so far; the geometry issue extends this list.
using Shape = std::variant<Sphere, Box, Plane>;

/// One object of the scene: a shape, its placement, its appearance and its flags.
struct Object {
    Shape shape;
    Transform transform;  ///< object space to world space, in the order the keywords appeared
    Texture texture;
    bool inverse = false;
    bool no_shadow = false;
    bool no_image = false;
    bool no_reflection = false;
    bool no_radiosity = false;
    SourceLoc loc;
};

/// The camera, resolved by the parser to POV-Ray's final vectors (after look_at, angle, sky and transforms).
struct Camera {
    enum class Type { Perspective, Orthographic };
    Type type = Type::Perspective;
    Vec3 location{0.0, 0.0, 0.0};
    Vec3 direction{0.0, 0.0, 1.0};  ///< from location to the centre of the image plane
    Vec3 right{1.33, 0.0, 0.0};     ///< full width of the image plane
    Vec3 up{0.0, 1.0, 0.0};         ///< full height of the image plane
    SourceLoc loc;
};

struct Light {
    enum class Type { Point, Spot, Parallel, Cylinder };
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
    SourceLoc loc;
};

/// The `radiosity { ... }` block of global_settings with POV-Ray 3.7's defaults.
struct RadiositySettings {
    int count = 35;
    int count_directions = 1600;
    double error_bound = 1.8;
    double low_error_factor = 0.5;
    double minimum_reuse = 0.015;
    double maximum_reuse = 0.2;
    int nearest_count = 5;
    int nearest_count_pretrace = 0;  ///< 0: not given
    int recursion_limit = 2;
    double pretrace_start = 0.08;
    double pretrace_end = 0.04;
    double brightness = 1.0;
    double gray_threshold = 0.0;
    double adc_bailout = 0.01;
    bool always_sample = false;
    bool normal = false;
    bool media = false;
    SourceLoc loc;
};

struct GlobalSettings {
    double assumed_gamma = 1.0;
    bool assumed_gamma_given = false;
    Color ambient_light{1.0, 1.0, 1.0};
    int max_trace_level = 5;
    double adc_bailout = 1.0 / 255.0;
    std::optional<RadiositySettings> radiosity;
};

/// Everything the renderer needs from a scene file.
struct Scene {
    std::string path;  ///< the main scene file
    double version = 3.7;  ///< the language version in force at the end of the file
    Camera camera;
    std::vector<Light> lights;
    std::vector<Object> objects;
    GlobalSettings global;
    Color background{0.0, 0.0, 0.0};
    /// Features parsed but not rendered yet, and other warnings found while parsing.
    std::vector<Diagnostic> warnings;
};

}  // namespace wardray::parser
