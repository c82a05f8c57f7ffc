// Tests of the trace() sensitivity check: a scene whose objects hang on trace()'s rounding is warned about at the
// trace() call; one that uses trace() stably is not.
#include "parser/trace_sensitivity.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <vector>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

/// Answers trace() and extents for untransformed spheres only, which is all these tests place.
class SphereQuery : public SceneQuery {
public:
    std::optional<QueryHit> trace(const Object& object, const Vec3& origin, const Vec3& direction) const override {
        const auto* s = std::get_if<Sphere>(&object.shape);
        if (s == nullptr) return std::nullopt;
        const Vec3 d = normalize(direction);
        const Vec3 oc = origin - s->center;
        const double b = dot(oc, d);
        const double disc = b * b - (dot(oc, oc) - s->radius * s->radius);
        if (disc < 0) return std::nullopt;
        const double t = -b - std::sqrt(disc);
        if (t <= 0) return std::nullopt;
        const Vec3 p = origin + d * t;
        return QueryHit{p, normalize(p - s->center)};
    }
    bool inside(const Object&, const Vec3&) const override { return false; }
    std::optional<std::pair<Vec3, Vec3>> extent(const Object& object) const override {
        const auto* s = std::get_if<Sphere>(&object.shape);
        if (s == nullptr) return std::nullopt;
        const Vec3 r{s->radius, s->radius, s->radius};
        return std::make_pair(object.transform.point(s->center) - r, object.transform.point(s->center) + r);
    }
};

/// Writes `text` to a scene file of its own and parses it with the check.
ParseResult parse_checked(const std::string& text, TraceSensitivity& report) {
    const auto path = std::filesystem::temp_directory_path() /
                      ("wardray_trace_sensitivity_" + std::to_string(::getpid()) + ".pov");
    std::ofstream(path) << text;
    static const SphereQuery query;
    ParseOptions options = test::default_options();
    options.query = &query;
    ParseResult r = parse_file_checking_trace(path, options, &report);
    std::filesystem::remove(path);
    return r;
}

std::size_t count_trace_warnings(const ParseResult& r, std::uint32_t* line = nullptr) {
    std::size_t n = 0;
    for (const Diagnostic& d : r.diagnostics)
        if (d.severity == Severity::Warning && d.message.find("hang on rounding") != std::string::npos) {
            ++n;
            if (line) *line = d.loc.line;
        }
    return n;
}

TEST(TraceSensitivity, AnIfOnAnExactHitIsWarnedAtTheTrace) {
    // The ray meets the ball exactly at z = 4: whether P.z > 4 is rounding, and the nudge flips it.
    TraceSensitivity report;
    const ParseResult r = parse_checked("#declare Ball = sphere { <0, 0, 5>, 1 }\n"
                                        "#declare P = trace(Ball, <0, 0, 0>, z);\n"
                                        "#if (P.z > 4) sphere { <0, 3, 0>, 1 } #end\n"
                                        "sphere { P, 0.5 }\n",
                                        report);
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(report.trace_calls, 1u);
    EXPECT_TRUE(report.checked);
    EXPECT_TRUE(report.diverged);
    std::uint32_t line = 0;
    EXPECT_EQ(count_trace_warnings(r, &line), 1u) << test::all_diagnostics(r);
    EXPECT_EQ(line, 2u);
    EXPECT_EQ(r.scene->objects.size(), 1u);  // the first parse's objects are the scene
}

TEST(TraceSensitivity, ObjectsPlacedOnASphereAreStable) {
    TraceSensitivity report;
    const ParseResult r = parse_checked("#declare Ball = sphere { <0, 0, 0>, 2 }\n"
                                        "#for (I, 0, 35)\n"
                                        "  #declare D = vrotate(<1, 0.3, 0>, <0, I * 10, 0>);\n"
                                        "  #declare P = trace(Ball, D * 10, -D);\n"
                                        "  sphere { P, 0.1 }\n"
                                        "#end\n",
                                        report);
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(report.trace_calls, 36u);
    EXPECT_TRUE(report.checked);
    EXPECT_FALSE(report.diverged);
    EXPECT_EQ(count_trace_warnings(r), 0u) << test::all_diagnostics(r);
}

TEST(TraceSensitivity, AChainOfTracesThatDivergesIsWarnedWhereItDiverges) {
    // Each hit decides by a comparison whether the next ray goes left or right: the walk differs after the tie.
    TraceSensitivity report;
    const ParseResult r = parse_checked("#declare Ball = sphere { <0, 0, 5>, 1 }\n"
                                        "#declare A = trace(Ball, <0, 0, 0>, z);\n"
                                        "#declare X = (A.z > 4 ? 0.5 : -0.5);\n"
                                        "#declare B = trace(Ball, <X, 0, 0>, z);\n"
                                        "sphere { B, 0.1 }\n",
                                        report);
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_TRUE(report.diverged);
    std::uint32_t line = 0;
    EXPECT_EQ(count_trace_warnings(r, &line), 1u) << test::all_diagnostics(r);
    EXPECT_EQ(line, 4u);  // the second call is the first whose result diverged
}

TEST(TraceSensitivity, ASceneWithoutTraceIsParsedOnce) {
    TraceSensitivity report;
    const ParseResult r = parse_checked("sphere { <0, 0, 5>, 1 }\n", report);
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(report.trace_calls, 0u);
    EXPECT_FALSE(report.checked);
}

TEST(TraceSensitivity, AnObjectSinkReceivesEveryObjectAndTheSceneKeepsNone) {
    // The check's second parse keeps only each object's box: the sink sees the objects the scene would hold, in
    // order, and the scene holds none of them (its lights it keeps).
    const std::string text = "#for (I, 1, 3) sphere { <I, 0, 0>, I / 10 } #end\n"
                             "union { sphere { 0, 0.5 } box { -1, 1 } }\n"
                             "light_source { <0, 5, 0>, 1 }\n";
    auto radius = [](const Object& o) {
        const auto* s = std::get_if<Sphere>(&o.shape);
        return s ? s->radius : -1.0;
    };
    const ParseResult kept = parse_string(text, "sink.pov", test::default_options());
    ASSERT_TRUE(kept.ok()) << test::all_diagnostics(kept);
    ParseOptions options = test::default_options();
    std::vector<double> radii;
    options.object_sink = [&](const Object& o) { radii.push_back(radius(o)); };
    const ParseResult sunk = parse_string(text, "sink.pov", options);
    ASSERT_TRUE(sunk.ok()) << test::all_diagnostics(sunk);
    EXPECT_TRUE(sunk.scene->objects.empty());
    EXPECT_EQ(sunk.scene->lights.size(), 1u);
    ASSERT_EQ(radii.size(), kept.scene->objects.size());
    ASSERT_GE(radii.size(), 4u);
    for (std::size_t i = 0; i < radii.size(); ++i) EXPECT_EQ(radii[i], radius(kept.scene->objects[i])) << i;
    EXPECT_DOUBLE_EQ(radii[0], 0.1);
    EXPECT_DOUBLE_EQ(radii[2], 0.3);
}

}  // namespace
}  // namespace wardray::parser
