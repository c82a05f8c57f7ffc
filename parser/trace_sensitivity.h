// Whether the objects a scene builds from trace() hang on rounding: a second parse with every trace() result nudged.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "core/diagnostics.h"
#include "core/vec3.h"
#include "parser/parse.h"

namespace wardray::parser {

/// Sees every trace() a parse evaluates, in order (ParseOptions::trace_observer).
class TraceObserver {
public:
    virtual ~TraceObserver() = default;
    /// A trace() at `at` returned `result`; returns whether the parser should describe it (describe()).
    virtual bool seen(const SourceLoc& at, const Vec3& result) = 0;
    /// The trace() just seen, as a diagnostic with its source line and include and macro notes.
    virtual void describe(Diagnostic at) = 0;
};

/// How far trace()'s results move in the second parse: this fraction of the larger of 1 and the distances of the
/// ray's origin and of the hit from the origin of coordinates, along the ray.
inline constexpr double k_trace_nudge = 1e-12;
/// The first parse must take less than this much processor time for the second to run (seconds): processor time,
/// not wall-clock, so that a loaded machine does not change what is checked.
inline constexpr double k_trace_check_parse_limit = 10.0;

/// What the check found.
struct TraceSensitivity {
    std::size_t trace_calls = 0;  ///< trace() calls of the first parse
    bool checked = false;         ///< a second parse ran
    bool diverged = false;        ///< the two parses built different objects
    double second_parse_seconds = 0.0;
    std::string skipped;          ///< why no second parse ran, when trace() was called
};

/// Parses `path` as parse_file does; when the scene calls trace() and parsed in under k_trace_check_parse_limit
/// seconds of processor time, parses it again with every trace() result nudged (k_trace_nudge) and, when the
/// objects the two parses build differ (their number, their bounding boxes, the camera, the lights), adds a
/// warning at the first trace() call whose results diverged. `report`, when given, receives what the check found.
ParseResult parse_file_checking_trace(const std::filesystem::path& path, const ParseOptions& options,
                                      TraceSensitivity* report = nullptr);

}  // namespace wardray::parser
