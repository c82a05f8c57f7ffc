// Entry points of the scene-language parser.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/diagnostics.h"
#include "parser/namespaces.h"
#include "scene/scene_query.h"

namespace wardray::parser {

class TraceObserver;

/// How to parse: search paths, predefined values, file-access rules and guard-rail limits.
struct ParseOptions {
    /// Folders searched by #include after the scene's own folder (POV-Ray's library path, then `+L` paths).
    std::vector<std::filesystem::path> library_paths;
    /// `Declare=NAME=VALUE` floats, defined before the first line is read.
    std::vector<std::pair<std::string, double>> declares;
    /// Image size, for image_width and image_height.
    int image_width = 320;
    int image_height = 240;
    /// The animation values the front end declares (POV-Ray's names); all 0 for a still image.
    struct FrameClock {
        double clock = 0.0;
        double clock_delta = 0.0;
        bool clock_on = false;  ///< an animation, or a clock given for a still (+K)
        double frame_number = 0.0;
        double initial_frame = 0.0;
        double final_frame = 0.0;
        double initial_clock = 0.0;
        double final_clock = 0.0;
    };
    FrameClock animation;
    std::size_t max_errors = 20;
    /// Receives the text of #debug (and #render, #statistics) as POV-Ray prints it on its console; null
    /// discards it.
    std::function<void(const std::string&)> debug_output;

    /// Folders besides the scene's own folder and `library_paths` that #fopen may read from.
    std::vector<std::filesystem::path> read_paths;
    /// Folders a configuration permits reading from (POV-Ray's povray.conf `read*` and `read` entries): judged by
    /// the file's real location (links and '..' resolved), inside the folder or, without `subfolders`, directly in it.
    struct PermittedFolder {
        std::filesystem::path folder;
        bool subfolders = true;
    };
    std::vector<PermittedFolder> permitted_reads;
    /// Folders besides the scene's own folder that #fopen may write or append to.
    std::vector<std::filesystem::path> write_paths;
    /// What `#fopen ... write/append` does: refuse (an error), discard (check the rules, parse the #write
    /// directives, write nothing; one warning) or allow (write inside the permitted folders).
    enum class FileWrites { Refuse, Discard, Allow };
    /// Safe by default: a parse has no side effects unless the user asks (--allow-file-writes).
    FileWrites file_writes = FileWrites::Discard;

    // Guard rails: each limit, when exceeded, is an error at its location naming the limit and its switch.
    /// #while/#for iterations in the whole parse (--max-loop-iterations).
    std::uint64_t max_loop_iterations = 10'000'000;
    /// Macros being expanded at once, i.e. macro recursion depth (--max-macro-depth).
    std::size_t max_macro_depth = 200;
    /// Nested #include files (--max-include-depth).
    std::size_t max_include_depth = 64;
    /// Elements of one array, all dimensions multiplied (--max-array-size).
    std::size_t max_array_elements = 100'000'000;
    /// Characters of one string value (--max-string-length).
    std::size_t max_string_length = 10'000'000;
    /// Bytes of a file #write keeps in memory while file writes are off (--max-memory-file); the mesh-camera
    /// examples write about 20 MB and read it back.
    std::size_t max_memory_file_bytes = std::size_t{64} << 20;
    /// Objects the parse creates, counting every shape a statement makes and every one an `object { Name }`
    /// copies (--max-objects).
    std::size_t max_objects = 2'000'000;
    /// Memory the parse may take, the growth of the process's resident memory since it began (--max-memory, in
    /// MB on the command line); checked every few thousand tokens.
    std::size_t max_memory_bytes = std::size_t{2048} << 20;

    /// Pay for what is used: a `#declare` of a pigment, finish, texture or colour map in a file found through
    /// `library_paths` is read when the scene first uses the identifier, not where it stands. Off, every
    /// declaration is evaluated in place (so `--check` reports mistakes in declarations nothing uses).
    bool defer_library_declarations = true;

    /// The geometry layer, for trace(), inside(), min_extent() and max_extent() at parse time; when null those
    /// functions are an error. Not owned.
    const SceneQuery* query = nullptr;
    /// Sees every trace() (parser/trace_sensitivity.h); null: none. Not owned.
    TraceObserver* trace_observer = nullptr;
    /// Receives each object as it is placed at the top level, instead of the scene keeping it, so that a parse
    /// that needs only a summary of its objects (the trace() check's second parse) holds one at a time; empty: the
    /// scene keeps them. The scene's light sources are kept either way.
    std::function<void(const Object&)> object_sink;
    /// Moves every trace() hit along its ray by this fraction of the larger of 1 and the distances of the ray's
    /// origin and of the hit from the origin (parser/trace_sensitivity.h); 0: trace() as it is.
    double trace_nudge = 0.0;
    /// The lighting layer's vector turbulence (POV-Ray's DTurbulence) of point p with octaves, omega and lambda,
    /// for vturbulence(); when empty that function is an error.
    std::function<Vec3(const Vec3& p, int octaves, double omega, double lambda)> vector_turbulence;
    /// The render layer's image reader, for image_map: RGB texels as the file stores them (8- and 16-bit values
    /// scaled to [0, 1], `encoded` then set) or nothing with `error` set; when empty image_map is an error. The
    /// image is a new one the parser keeps and changes (its gamma), not a copy of it.
    std::function<std::shared_ptr<ImageData>(const std::filesystem::path& file, bool& encoded,
                                                   std::string& error)>
        read_image;
    /// The render layer's height field image reader: the 16-bit heights POV-Ray takes from each pixel (palette
    /// index, grey value, or red and green bytes), or nothing with `error` set (or `unsupported`, naming a kind of
    /// file not read as POV-Ray reads it); when empty height_field images are an error.
    std::function<std::shared_ptr<const HeightGrid>(const std::filesystem::path& file, std::string& error,
                                                    std::string& unsupported)>
        read_height_grid;
    /// The texture layer's pattern value at p (POV-Ray's Evaluate_TPat after the pattern's warps and transform),
    /// for `function { pattern { ... } }`; when empty such functions evaluate to 0 with a warning.
    std::function<double(const Pattern& pattern, const Vec3& p, int noise_generator)> pattern_value;
    /// The texture layer's wave sources for waves and ripples evaluated while parsing: called with 10 when a parse
    /// starts. POV-Ray compat: parse-time evaluations (eval_pigment) use the default 10 sources whatever the
    /// scene's number_of_waves, which applies only to the render; may be empty.
    std::function<void(int count)> set_number_of_waves;
    /// The texture layer's pigment colour at p, for `function { pigment { ... } }`; when empty it is black.
    std::function<Color(const Pigment& pigment, const Vec3& p, int noise_generator)> pigment_value;
};

/// The outcome of a parse: a scene when there was no error, and every diagnostic in source order.
struct ParseResult {
    std::optional<Scene> scene;
    std::vector<Diagnostic> diagnostics;

    bool ok() const { return scene.has_value(); }
};

/// Parses a scene file; a missing or unreadable file is an error diagnostic, never an exception.
ParseResult parse_file(const std::filesystem::path& path, const ParseOptions& options);

/// Parses scene text held in memory; `path` names it in diagnostics and anchors relative #includes.
ParseResult parse_string(std::string_view text, const std::string& path, const ParseOptions& options);

}  // namespace wardray::parser
