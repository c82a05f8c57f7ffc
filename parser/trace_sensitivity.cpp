// The trace() sensitivity check: a scene parsed twice, the second time with trace()'s results nudged, and the
// objects the two parses built compared.
#include "parser/trace_sensitivity.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

namespace wardray::parser {
namespace {

using Clock = std::chrono::steady_clock;

/// One trace() call: where (the path interned) and what it returned.
struct TraceCall {
    std::uint32_t path = 0;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
    Vec3 result;
};

/// Interns the paths of trace() calls (a scene calls trace() from a handful of places, many times).
class PathTable {
public:
    std::uint32_t id(const std::string& path) {
        if (m_last < m_paths.size() && m_paths[m_last] == path) return static_cast<std::uint32_t>(m_last);
        for (m_last = 0; m_last < m_paths.size(); ++m_last)
            if (m_paths[m_last] == path) return static_cast<std::uint32_t>(m_last);
        m_paths.push_back(path);
        return static_cast<std::uint32_t>(m_last);
    }

private:
    std::vector<std::string> m_paths;
    std::size_t m_last = 0;
};

/// The first parse: records every call; describes the first, where a warning falls back to.
class Recorder final : public TraceObserver {
public:
    bool seen(const SourceLoc& at, const Vec3& result) override {
        calls.push_back({paths.id(at.path), at.line, at.column, result});
        return calls.size() == 1;
    }
    void describe(Diagnostic at) override { first = std::move(at); }

    PathTable paths;
    std::vector<TraceCall> calls;
    std::optional<Diagnostic> first;
};

/// The second parse: compares each call with the first parse's, and describes the first that diverged (another
/// place, or a result that moved by far more than the nudge).
class Comparer final : public TraceObserver {
public:
    explicit Comparer(Recorder& first) : m_first(first) {}

    bool seen(const SourceLoc& at, const Vec3& result) override {
        const std::size_t i = m_index++;
        if (diverged) return false;
        const std::uint32_t path = m_first.paths.id(at.path);
        bool same = i < m_first.calls.size();
        if (same) {
            const TraceCall& c = m_first.calls[i];
            const double scale = std::max({1.0, length(c.result), length(result)});
            same = c.path == path && c.line == at.line && c.column == at.column &&
                   length(result - c.result) <= 1e3 * k_trace_nudge * scale;
        }
        diverged = !same;
        return diverged;
    }
    void describe(Diagnostic at) override { first_diverged = std::move(at); }

    bool diverged = false;
    std::optional<Diagnostic> first_diverged;

private:
    Recorder& m_first;
    std::size_t m_index = 0;
};

/// What the second parse keeps of each object it places: its bounding box (none when unbounded or without a
/// geometry layer), so that the second parse never holds the objects themselves.
using Extent = std::optional<std::pair<Vec3, Vec3>>;

/// How the objects of the first parse (`a`) differ from the second's (`b`, whose objects are `b_extents`), or
/// nothing when they agree within a millionth of the scene's size.
std::optional<std::string> build_difference(const Scene& a, const Scene& b, const std::vector<Extent>& b_extents,
                                            const SceneQuery* query) {
    char text[200];
    if (a.objects.size() != b_extents.size()) {
        std::snprintf(text, sizeof text, "%zu objects against %zu", a.objects.size(), b_extents.size());
        return std::string(text);
    }
    if (a.lights.size() != b.lights.size()) {
        std::snprintf(text, sizeof text, "%zu light sources against %zu", a.lights.size(), b.lights.size());
        return std::string(text);
    }
    if (query == nullptr) return std::nullopt;
    std::vector<Extent> boxes;
    boxes.reserve(a.objects.size());
    double size = 1.0;
    auto grow = [&size](const Vec3& p) {
        for (double v : {p.x, p.y, p.z})
            if (std::isfinite(v)) size = std::max(size, std::abs(v));
    };
    for (const Object& o : a.objects) {
        boxes.push_back(query->extent(o));
        if (boxes.back()) {
            grow(boxes.back()->first);
            grow(boxes.back()->second);
        }
    }
    grow(a.camera.location);
    const double tolerance = 1e-6 * size;
    auto apart = [tolerance](const Vec3& p, const Vec3& q) {
        const Vec3 d = p - q;
        return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) > tolerance;  // NaN compares false
    };
    if (apart(a.camera.location, b.camera.location)) return std::string("the camera moves");
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        const Extent& other = b_extents[i];
        if (boxes[i].has_value() != other.has_value() ||
            (other && (apart(boxes[i]->first, other->first) || apart(boxes[i]->second, other->second)))) {
            const SourceLoc& at = a.objects[i].loc;
            std::snprintf(text, sizeof text, "the bounding box of object %zu (%s:%u) moves", i + 1, at.path.c_str(),
                          at.line);
            return std::string(text);
        }
    }
    for (std::size_t i = 0; i < a.lights.size(); ++i)
        if (apart(a.lights[i].position, b.lights[i].position)) return std::string("a light source moves");
    return std::nullopt;
}

}  // namespace

ParseResult parse_file_checking_trace(const std::filesystem::path& path, const ParseOptions& options,
                                      TraceSensitivity* report) {
    TraceSensitivity found;
    Recorder recorder;
    ParseOptions first_options = options;
    first_options.trace_observer = &recorder;
    const std::clock_t start = std::clock();
    ParseResult first = parse_file(path, first_options);
    const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    found.trace_calls = recorder.calls.size();
    if (!first.ok() || recorder.calls.empty()) {
        if (report) *report = found;
        return first;
    }
    if (seconds >= k_trace_check_parse_limit) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "trace() sensitivity not checked: the parse took %.1f s of processor time, and the second "
                      "parse with trace()'s results nudged runs only under %.0f s", seconds, k_trace_check_parse_limit);
        found.skipped = text;
        Diagnostic note = recorder.first.value_or(Diagnostic{});
        note.severity = Severity::Note;
        note.message = found.skipped;
        first.diagnostics.push_back(std::move(note));
        if (report) *report = found;
        return first;
    }
    // The second parse prints nothing (#debug) and writes no file; only its objects and trace() calls count.
    Comparer comparer(recorder);
    ParseOptions second_options = options;
    second_options.trace_observer = &comparer;
    second_options.trace_nudge = k_trace_nudge;
    second_options.debug_output = nullptr;
    second_options.file_writes = ParseOptions::FileWrites::Discard;
    // Only each object's box is kept: the two parses' objects are never held at once (a scene placing thousands
    // of textured objects would otherwise take twice its memory).
    std::vector<Extent> second_extents;
    second_options.object_sink = [&second_extents, query = options.query](const Object& o) {
        second_extents.push_back(query ? query->extent(o) : Extent{});
    };
    const auto second_start = Clock::now();
    const ParseResult second = parse_file(path, second_options);
    found.second_parse_seconds = std::chrono::duration<double>(Clock::now() - second_start).count();
    found.checked = true;
    std::optional<std::string> difference;
    if (!second.ok())
        difference = "the parse fails";
    else
        difference = build_difference(*first.scene, *second.scene, second_extents, options.query);
    if (difference) {
        found.diverged = true;
        Diagnostic d = comparer.first_diverged ? std::move(*comparer.first_diverged)
                                               : recorder.first.value_or(Diagnostic{});
        d.severity = Severity::Warning;
        char nudge[32];
        std::snprintf(nudge, sizeof nudge, "%g", k_trace_nudge);
        d.message = std::string("the objects this scene builds from trace() change when trace()'s results move by ") +
                    nudge + " of their distance (" + *difference +
                    "): they hang on rounding, and POV-Ray's picture will differ from this one";
        d.notes.insert(d.notes.begin(), comparer.first_diverged
                                            ? "the first trace() call whose results diverged"
                                            : "no trace() result diverged by itself; this is the first trace() call");
        first.diagnostics.push_back(d);
        if (first.scene) first.scene->warnings.push_back(std::move(d));
    }
    if (report) *report = found;
    return first;
}

}  // namespace wardray::parser
