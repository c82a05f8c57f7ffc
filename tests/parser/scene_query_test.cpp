// Tests of trace(), inside(), min_extent() and max_extent() through a fake geometry layer.
#include <cmath>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

/// Answers for untransformed spheres only, which is all these tests place.
class FakeQuery : public SceneQuery {
public:
    std::optional<QueryHit> trace(const Object& object, const Vec3& origin, const Vec3& direction) const override {
        const auto* s = std::get_if<Sphere>(&object.shape);
        if (s == nullptr) return std::nullopt;
        const Vec3 c = object.transform.point(s->center);
        const Vec3 d = normalize(direction);
        const Vec3 oc = origin - c;
        const double b = dot(oc, d);
        const double disc = b * b - (dot(oc, oc) - s->radius * s->radius);
        if (disc < 0) return std::nullopt;
        double t = -b - std::sqrt(disc);
        if (t <= 0) t = -b + std::sqrt(disc);
        if (t <= 0) return std::nullopt;
        const Vec3 p = origin + d * t;
        return QueryHit{p, normalize(p - c)};
    }
    bool inside(const Object& object, const Vec3& point) const override {
        const auto* s = std::get_if<Sphere>(&object.shape);
        return s != nullptr && length(point - object.transform.point(s->center)) < s->radius;
    }
    std::optional<std::pair<Vec3, Vec3>> extent(const Object& object) const override {
        const auto* s = std::get_if<Sphere>(&object.shape);
        if (s == nullptr) return std::nullopt;
        const Vec3 c = object.transform.point(s->center);
        const Vec3 r{s->radius, s->radius, s->radius};
        return std::make_pair(c - r, c + r);
    }
};

ParseOptions with_query(const SceneQuery& q) {
    ParseOptions o = test::default_options();
    o.query = &q;
    return o;
}

/// The x, y and z of the centre of the first sphere the scene places.
Vec3 first_center(const Scene& s) {
    if (s.objects.empty()) return {NAN, NAN, NAN};
    const auto* sp = std::get_if<Sphere>(&s.objects[0].shape);
    return sp ? s.objects[0].transform.point(sp->center) : Vec3{NAN, NAN, NAN};
}

TEST(SceneQuery, TraceReturnsPointAndNormal) {
    const FakeQuery q;
    const Scene s = test::parse_ok("#declare Ball = sphere { <0, 0, 5>, 1 }\n"
                                   "#declare N = <9, 9, 9>;\n"
                                   "#declare P = trace(Ball, <0, 0, 0>, z, N);\n"
                                   "sphere { P + N * 10, 0.1 }\n",
                                   with_query(q));
    const Vec3 c = first_center(s);
    EXPECT_NEAR(c.z, 4.0 - 10.0, 1e-9);
    EXPECT_NEAR(c.x, 0.0, 1e-9);
}

TEST(SceneQuery, TraceMissGivesZeroVectors) {
    const FakeQuery q;
    const Scene s = test::parse_ok("#declare P = trace(sphere { <0, 0, 5>, 1 }, <0, 0, 0>, -z, Normal);\n"
                                   "sphere { P + Normal + <1, 2, 3>, 1 }\n",
                                   with_query(q));
    const Vec3 c = first_center(s);
    EXPECT_EQ(c.x, 1.0);
    EXPECT_EQ(c.y, 2.0);
    EXPECT_EQ(c.z, 3.0);
}

TEST(SceneQuery, TraceWithAZeroDirectionMisses) {
    // POV-Ray normalises the direction to NaN and finds nothing: the point and the normal are <0,0,0>, no error.
    const FakeQuery q;
    const Scene s = test::parse_ok("#declare Ball = sphere { <0, 0, 0>, 1 }\n"
                                   "#declare Normal = <7, 7, 7>;\n"
                                   "#declare P = trace(Ball, <0.5, 0, 0>, <0, 0, 0>, Normal);\n"
                                   "sphere { P + Normal + <1, 2, 3>, 1 }\n",
                                   with_query(q));
    const Vec3 c = first_center(s);
    EXPECT_EQ(c.x, 1.0);
    EXPECT_EQ(c.y, 2.0);
    EXPECT_EQ(c.z, 3.0);
}

/// Answers every trace with origin + direction: the point shows which direction the geometry layer was given.
class DirectionEcho : public FakeQuery {
public:
    std::optional<QueryHit> trace(const Object&, const Vec3& origin, const Vec3& direction) const override {
        return QueryHit{origin + direction, direction};
    }
};

TEST(SceneQuery, TraceNormalisesItsDirection) {
    // POV-Ray's Parse_Trace normalises the direction before intersecting; an isosurface's solver steps by the ray's
    // length, so isocacti.pov's trace(Body, Orig, -Orig) found a deeper root when the length 50 was passed on.
    const DirectionEcho q;
    const Scene s = test::parse_ok("#declare Ball = sphere { <0, 0, 0>, 1 }\n"
                                   "sphere { trace(Ball, <1, 2, 3>, <0, 0, -50>), 1 }\n",
                                   with_query(q));
    const Vec3 c = first_center(s);
    EXPECT_NEAR(c.x, 1.0, 1e-12);
    EXPECT_NEAR(c.y, 2.0, 1e-12);
    EXPECT_NEAR(c.z, 2.0, 1e-12);
}

TEST(SceneQuery, TraceTakesTheNearestPartOfAUnion) {
    const FakeQuery q;
    const Scene s = test::parse_ok("#declare U = union { sphere { <0, 0, 9>, 1 } sphere { <0, 0, 4>, 1 } }\n"
                                   "sphere { trace(U, 0, z), 1 }\n",
                                   with_query(q));
    EXPECT_NEAR(first_center(s).z, 3.0, 1e-9);
}

TEST(SceneQuery, InsideAndExtents) {
    const FakeQuery q;
    const Scene s = test::parse_ok("#declare B = sphere { <1, 2, 3>, 2 }\n"
                                   "sphere { <inside(B, <1, 2, 4>), inside(B, 0), 0>, 1 }\n"
                                   "sphere { min_extent(B), 1 }\nsphere { max_extent(B), 1 }\n",
                                   with_query(q));
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(first_center(s).x, 1.0);
    EXPECT_EQ(first_center(s).y, 0.0);
    const auto* lo = std::get_if<Sphere>(&s.objects[1].shape);
    const auto* hi = std::get_if<Sphere>(&s.objects[2].shape);
    ASSERT_TRUE(lo && hi);
    EXPECT_EQ(s.objects[1].transform.point(lo->center).x, -1.0);
    EXPECT_EQ(s.objects[2].transform.point(hi->center).z, 5.0);
}

TEST(SceneQuery, WithoutGeometryLayerIsAnError) {
    const ParseResult r = test::parse_fail("#declare P = trace(sphere { 0, 1 }, <0, 0, -5>, z);\n");
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(format_diagnostic(r.diagnostics[0]),
              "test.pov:1:14: error: trace() needs the geometry layer, which this program did not provide\n"
              "    1 | #declare P = trace(sphere { 0, 1 }, <0, 0, -5>, z);\n"
              "      |              ^~~~~\n");
}

TEST(SceneQuery, FirstArgumentMustBeAnObject) {
    const FakeQuery q;
    const ParseResult r = test::parse_fail("#declare P = inside(3, <0, 0, 0>);\n", with_query(q));
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].message, "the first argument of 'inside' must be an object");
}

}  // namespace
}  // namespace wardray::parser
