// Entry points of the scene-language parser.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "parser/diagnostics.h"
#include "parser/scene.h"

namespace wardray::parser {

struct ParseOptions {
    /// Folders searched by #include after the scene's own folder (POV-Ray's library path, then `+L` paths).
    std::vector<std::filesystem::path> library_paths;
    /// `Declare=NAME=VALUE` floats, defined before the first line is read.
    std::vector<std::pair<std::string, double>> declares;
    /// Image size, for image_width and image_height.
    int image_width = 320;
    int image_height = 240;
    double clock = 0.0;
    std::size_t max_errors = 20;
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
