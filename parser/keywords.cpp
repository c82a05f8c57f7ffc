// Keyword tables (with the kind lists of scene/) and the edit distance used for "did you mean" notes.
#include "parser/keywords.h"

#include <algorithm>
#include <unordered_set>

#include "parser/namespaces.h"

namespace wardray::parser {

namespace {

// The rest of POV-Ray 3.7's reserved words (its documentation's list): directive names, file formats, spline
// and wave types, and items parsed where they stand. Reserved, so never declared and never taken for a name.
const std::vector<std::string_view> k_reserved = {
    "aa_level", "aa_threshold", "absorption", "accuracy", "agate_turb", "all", "all_intersections", "alpha",
    "altitude", "append", "arc_angle", "asc", "ascii", "autostop", "b_spline", "bezier_spline",
    "black_hole", "bokeh", "break", "brick_size", "bump_size", "case", "caustics", "collect", "component",
    "composite", "conic_sweep", "contained_by", "control0", "control1", "coords", "cube", "cubic_spline",
    "cubic_wave", "debug", "df3", "dispersion", "dispersion_samples", "dist_exp", "distance", "eccentricity", "else",
    "elseif", "end", "error", "evaluate", "expand_thresholds", "exterior", "extinction", "face_indices",
    "fade_color", "fade_colour", "falloff_angle", "fclose", "flatness", "flip", "fog_alt", "fog_offset", "fog_type",
    "fopen", "for", "form", "gamma", "gather", "gif", "global_lights", "gray", "hierarchy", "hypercomplex", "if",
    "ifdef", "iff", "ifndef", "include", "input_file_name", "inside_vector", "internal", "interpolate", "intervals",
    "ior", "jpeg", "linear_spline", "linear_sweep", "local", "macro", "major_radius", "map_type", "max_gradient",
    "max_iteration", "max_trace", "method", "metric", "mortar", "natural_spline", "no_bump_scale", "normal_indices",
    "normal_vectors", "number_of_sides", "number_of_tiles", "offset", "once", "orientation", "pass_through",
    "pattern", "pgm", "png", "poly_wave", "pot",
    "ppm", "precision", "precompute", "premultiplied", "pwr", "quadratic_spline", "quaternion", "ramp_wave", "range",
    "ratio", "read", "reciprocal", "refraction", "render", "repeat", "samples", "scallop_wave", "scattering",
    "sine_wave", "sint16be", "sint16le", "sint32be", "sint32le", "sint8", "size", "slice", "smooth", "solid",
    "spacing", "sqr", "statistics", "strength", "switch", "sys", "target", "texture_list", "tga", "thickness",
    "threshold", "tiff", "tile2", "tolerance", "toroidal", "translucency", "triangle_wave", "ttf", "turb_depth",
    "type", "u_steps", "uint16be", "uint16le", "uint8", "undef", "use_alpha", "use_color", "use_colour", "use_index",
    "utf8", "uv_indices", "uv_vectors", "v_steps", "vertex_vectors", "warning", "water_level", "while", "width",
    "write"};

// Object kinds that are valid POV-Ray but not drawn yet (the drawn ones are WARDRAY_SHAPES, scene/shapes.h).
const std::vector<std::string_view> k_unsupported_objects = {
    "blob", "sphere_sweep", "bicubic_patch", "intersection", "difference", "merge", "light_group"};

const std::vector<std::string_view> k_unsupported_blocks = {
    "media", "normal", "interior", "material",
    "interior_texture", "photons", "color_map", "colour_map", "pigment_map", "normal_map", "texture_map",
    "slope_map", "density", "density_map", "function", "looks_like", "projected_through",
    "clipped_by", "bounded_by", "irid", "subsurface", "warp", "image_map", "bump_map", "material_map"};

// Pattern keywords and pattern items not rendered yet (the rendered patterns are WARDRAY_PATTERNS, scene/texture.h).
const std::vector<std::string_view> k_patterns = {
    "turbulence", "octaves", "omega", "lambda", "frequency", "phase", "color_map", "colour_map", "pigment_map",
    "image_map", "tiles", "texture_map", "material_map", "warp"};

const std::vector<std::string_view> k_handled = {
    "abs", "ceil", "acos", "acosh", "adaptive", "adc_bailout", "albedo", "always_sample", "ambient", "ambient_light",
    "angle", "aperture", "area_illumination", "area_light", "asin", "asinh", "assumed_gamma", "atan", "atan2",
    "atanh", "background", "blue", "blur_samples", "brightness", "brilliance", "camera", "charset",
    "chr", "circular", "clock", "clock_delta", "clock_on", "color", "colour", "concat", "confidence",
    "fog", "rainbow", "sky_sphere",
    "conserve_energy", "cos", "cosh", "count", "crand", "declare", "defined", "degrees", "diffuse",
    "direction", "div", "double_illuminate", "emission", "error_bound", "exp", "exponent", "fade_distance",
    "fade_power", "falloff", "false", "file_exists", "filter", "final_clock", "final_frame", "finish",
    "fisheye", "floor", "focal_point", "frame_number", "fresnel", "global_settings", "gray_threshold", "green",
    "hf_gray_16", "hollow", "image_height", "image_width", "importance", "initial_clock", "initial_frame",
    "int", "inverse", "irid_wavelength", "jitter", "light_source", "ln", "load_file", "location", "log",
    "look_at", "low_error_factor", "matrix", "max", "max_intersections", "max_sample", "max_trace_level",
    "maximum_reuse", "media_attenuation", "media_interaction", "metallic", "min", "minimum_reuse",
    "mm_per_unit", "mod", "nearest_count", "no", "no_image", "no_radiosity", "no_reflection", "no_shadow",
    "noise_generator", "number_of_waves", "off", "omnimax", "on", "orient", "panoramic",
    "parallel", "phong", "phong_size", "pi", "pigment", "point_at", "pow",
    "pretrace_end", "pretrace_start", "quick_color", "quick_colour", "radians", "radiosity", "radius",
    "recursion_limit", "red", "reflection", "reflection_exponent", "rgb", "rgbf", "rgbft", "rgbt", "right",
    "rotate", "roughness", "save_file", "scale", "select", "shadowless", "sin", "sinh", "sky", "specular",
    "spherical", "split_union", "spotlight", "sqrt", "srgb", "srgbf", "srgbft", "srgbt", "str",
    "strcmp", "strlen", "strlwr", "strupr", "sturm", "substr", "tan", "tanh", "texture", "tightness",
    "transform", "translate", "transmit", "true", "ultra_wide_angle", "union", "up", "val", "variance",
    "vaxis_rotate", "vcross", "vdot", "version", "vlength", "vnormalize", "vrotate", "x", "y", "yes", "z",
    "object", "open", "cutaway_textures", "u", "v", "t", "seed", "rand", "optional", "array", "split_union", "vstr",
    "trace", "vturbulence", "max_extent", "min_extent", "inside", "eval_pigment", "dimension_size", "dimensions",
    "bitwise_and", "bitwise_or", "bitwise_xor", "prod", "sum", "datetime", "now", "deprecated", "default",
    "mesh_camera", "spline", "uv_mapping"};

std::unordered_set<std::string_view> make_set(std::initializer_list<const std::vector<std::string_view>*> lists) {
    std::unordered_set<std::string_view> s;
    for (const auto* l : lists) s.insert(l->begin(), l->end());
    return s;
}

// Every reserved word: the tables above and the keywords of the kind lists of scene/.
std::unordered_set<std::string_view> reserved_words() {
    auto s = make_set({&k_unsupported_objects, &k_unsupported_blocks, &k_patterns, &k_handled, &k_reserved});
    s.insert(k_shape_keywords.begin(), k_shape_keywords.end());
    for (const auto& p : k_pattern_keywords) s.insert(p.keyword);
    for (const auto& c : k_camera_keywords) s.insert(c.keyword);
    return s;
}

}  // namespace

const std::vector<std::string_view>& all_keywords() {
    static const std::vector<std::string_view> all = [] {
        const auto s = reserved_words();
        std::vector<std::string_view> v(s.begin(), s.end());
        std::sort(v.begin(), v.end());
        return v;
    }();
    return all;
}

bool is_keyword(std::string_view word) {
    static const auto set = reserved_words();
    return set.count(word) > 0;
}

bool is_predeclared_identifier(std::string_view word) {
    // POV-Ray compat: these come from the front end as declarations (simplefrontend.h, animationprocessing.cpp),
    // not from the reserved word table; clock and clock_on are reserved words.
    static const std::unordered_set<std::string_view> set = {"image_width",   "image_height",  "clock_delta",
                                                             "initial_clock", "final_clock",   "initial_frame",
                                                             "final_frame",   "frame_number"};
    return set.count(word) > 0;
}

bool is_unsupported_object(std::string_view word) {
    static const auto set = make_set({&k_unsupported_objects});
    return set.count(word) > 0;
}

bool is_unsupported_block(std::string_view word) {
    static const auto set = make_set({&k_unsupported_blocks});
    return set.count(word) > 0;
}

bool is_pattern_keyword(std::string_view word) {
    static const auto set = make_set({&k_patterns});
    return set.count(word) > 0;
}

std::size_t edit_distance(std::string_view a, std::string_view b, std::size_t limit) {
    const std::size_t diff = a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
    if (diff > limit) return limit + 1;
    std::vector<std::size_t> prev(b.size() + 1);
    std::vector<std::size_t> cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        std::size_t row_min = cur[0];
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
            row_min = std::min(row_min, cur[j]);
        }
        if (row_min > limit) return limit + 1;
        std::swap(prev, cur);
    }
    return std::min(prev[b.size()], limit + 1);
}

}  // namespace wardray::parser
