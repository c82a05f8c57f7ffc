// The pavement pattern against POV-Ray 3.7: every paving of squares, triangles and hexagons, with exterior,
// interior and form varied, at points whose values POV-Ray printed (data/pavement_values.pov), and the parser's
// checks of its numbers.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "parser/parse.h"
#include "texture/pigment.h"

namespace wardray::lighting {
namespace {

parser::ParseResult parse(const std::string& text) {
    parser::ParseOptions options;
    return parser::parse_string("global_settings { assumed_gamma 1 }\n" + text, "test.pov", options);
}

TEST(Pavement, MatchesPovRaysValuesForEveryPaving) {
    std::ifstream in(std::string(WARDRAY_SOURCE_DIR) + "/tests/lighting/data/pavement_values.txt");
    ASSERT_TRUE(in) << "no data/pavement_values.txt";
    std::map<std::string, scene::Pigment> pigments;
    std::string line;
    int count = 0;
    while (std::getline(in, line)) {
        std::istringstream row(line);
        std::string word;
        int sides = 0, tiles = 0, number = 0, exterior = 0, interior = 0, form = 0;
        double x = 0.0, z = 0.0, expected = 0.0;
        row >> word >> sides >> tiles >> number >> exterior >> interior >> form >> x >> z >> expected;
        ASSERT_TRUE(row) << line;
        std::ostringstream text;
        text << "pavement number_of_sides " << sides << " number_of_tiles " << tiles << " pattern " << number
             << " exterior " << exterior << " interior " << interior << " form " << form;
        auto it = pigments.find(text.str());
        if (it == pigments.end()) {
            const parser::ParseResult r =
                parse("sphere { 0, 1 pigment { " + text.str() + " color_map { [0 rgb 0] [1 rgb 1] } } }\n");
            ASSERT_TRUE(r.ok() && r.scene) << text.str();
            it = pigments.emplace(text.str(), r.scene->objects[0].texture->pigment).first;
        }
        EXPECT_NEAR(texture::evaluate_pigment(it->second, {x, 0.0, z}, 2).r, expected, 2e-6) << line;
        ++count;
    }
    EXPECT_EQ(count, 1344);
    EXPECT_EQ(pigments.size(), 112u);  // 56 pavings of squares, 22 of triangles, 34 of hexagons
}

TEST(Pavement, ParsesItsModifiersAsPovRayKeepsThem) {
    const parser::ParseResult r = parse(
        "sphere { 0, 1 pigment { pavement number_of_sides 4.7 number_of_tiles 6 pattern 35 exterior 4 interior 5 "
        "form 6 } }\n");
    ASSERT_TRUE(r.ok() && r.scene);
    const scene::Pattern& pat = r.scene->objects[0].texture->pigment.pattern;
    ASSERT_EQ(pat.type, scene::Pattern::Type::Pavement);
    // POV-Ray compat: integers; exterior and interior modulo 3, form modulo 4 for squares.
    EXPECT_EQ(pat.params->pavement, (scene::PavementParams{4, 6, 35, 1, 2, 2}));
    const parser::ParseResult defaults = parse("sphere { 0, 1 normal { pavement } }\n");
    ASSERT_TRUE(defaults.ok() && defaults.scene);
    EXPECT_EQ(defaults.scene->objects[0].texture->normal.pattern.params->pavement, scene::PavementParams{});
}

TEST(Pavement, RefusesWhatPovRayRefuses) {
    const std::pair<const char*, const char*> cases[] = {
        {"pavement number_of_sides 5", "number_of_sides of pavement must be 3, 4 or 6."},
        {"pavement number_of_sides 6 number_of_tiles 6", "number_of_tiles of pavement must be between 1 and 5."},
        {"pavement number_of_tiles 0", "number_of_tiles of pavement must be between 1 and 6."},
        {"pavement number_of_sides 4 number_of_tiles 6 pattern 36", "max per tile:(1,1,2,5,12,35)"},
        {"pavement number_of_tiles 4 pattern 4", "max per tile:(1,1,1,3,4,12)"},
        {"bozo number_of_tiles 2", "'number_of_tiles' can only be used in a pavement pattern"}};
    for (const auto& [pigment, message] : cases) {
        const parser::ParseResult r = parse(std::string("sphere { 0, 1 pigment { ") + pigment + " } }\n");
        EXPECT_FALSE(r.ok()) << pigment;
        std::string all;
        for (const auto& d : r.diagnostics) all += d.message + "\n";
        EXPECT_NE(all.find(message), std::string::npos) << pigment << ":\n" << all;
    }
}

}  // namespace
}  // namespace wardray::lighting
