// Gamma in the scene language: assumed_gamma, the 3.6 no-gamma mode and srgb colours, as POV-Ray 3.7 reads them.
#include <gtest/gtest.h>

#include <cmath>

#include "test_util.h"

namespace wardray::parser {
namespace {

ParseResult parse(const std::string& text) { return parse_string(text, "test.pov", test::default_options()); }

const GlobalSettings& global_of(const ParseResult& r) {
    static const GlobalSettings none;
    return r.scene ? r.scene->global : none;
}

TEST(AssumedGamma, AnyValueOrSrgbIsTheWorkingGamma) {
    const ParseResult r = parse("#version 3.7;\nglobal_settings { assumed_gamma 2.2 }\n");
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(global_of(r).assumed_gamma, GammaCurve::power_law(2.2));
    EXPECT_TRUE(global_of(r).gamma_handling);
    const ParseResult s = parse("#version 3.7;\nglobal_settings { assumed_gamma srgb }\n");
    ASSERT_TRUE(s.ok()) << test::all_diagnostics(s);
    EXPECT_EQ(global_of(s).assumed_gamma.kind, GammaCurve::Kind::Srgb);
    EXPECT_FALSE(parse("global_settings { assumed_gamma 0 }\n").ok());
}

TEST(AssumedGamma, TheFirstOneStays) {
    const ParseResult r =
        parse("#version 3.7;\nglobal_settings { assumed_gamma 1.5 }\nglobal_settings { assumed_gamma 2.2 }\n");
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(global_of(r).assumed_gamma, GammaCurve::power_law(1.5));
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_NE(r.diagnostics[0].message.find("second assumed_gamma"), std::string::npos);
    EXPECT_EQ(r.diagnostics[0].loc.line, 3u);
}

TEST(AssumedGamma, WithoutItOnlyAThreeSevenScenePutsGammaHandlingOn) {
    // POV-Ray 3.7 takes a scene without any #version for 3.62.
    struct Case {
        const char* text;
        bool on;
    };
    for (const Case& c : {Case{"#version 3.7;\n", true}, Case{"#version 3.6;\n", false}, Case{"", false},
                          Case{"#version 3.5;\nglobal_settings { assumed_gamma 1 }\n", true},
                          Case{"#version 3.6;\nglobal_settings { assumed_gamma 2.2 }\n", true},
                          Case{"#version 3.6;\n#version 3.7;\n", true},
                          // An include file's own #version (colors.inc says 3.5, then restores) sets one too.
                          Case{"#include \"colors.inc\"\n", true}}) {
        const ParseResult r = parse(c.text);
        ASSERT_TRUE(r.ok()) << c.text << test::all_diagnostics(r);
        EXPECT_EQ(global_of(r).gamma_handling, c.on) << c.text;
    }
    const ParseResult off = parse("#version 3.6;\n");
    ASSERT_EQ(off.diagnostics.size(), 1u);
    EXPECT_NE(off.diagnostics[0].message.find("gamma handling is off"), std::string::npos);
}

TEST(SrgbColours, AreDecodedThenEncodedWithTheWorkingGamma) {
    const double half = std::pow((0.5 + 0.055) / 1.055, 2.4);
    const ParseResult r = parse("#version 3.7;\nglobal_settings { assumed_gamma 2.2 }\n"
                                "background { srgbft <0.5, 1, 0, 0.25, 0.5> }\n");
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    const Color& c = r.scene->background;
    EXPECT_NEAR(c.r, std::pow(half, 1 / 2.2), 1e-6);
    EXPECT_NEAR(c.g, 1.0, 1e-9);
    EXPECT_EQ(c.b, 0.0);
    EXPECT_DOUBLE_EQ(c.filter, 0.25);
    EXPECT_DOUBLE_EQ(c.transmit, 0.5);
    // With assumed_gamma srgb, sRGB values are the working values themselves.
    const ParseResult s = parse("#version 3.7;\nglobal_settings { assumed_gamma srgb }\n"
                                "background { srgbt <0.5, 0.2, 0.1, 0.3> }\n");
    ASSERT_TRUE(s.ok()) << test::all_diagnostics(s);
    EXPECT_DOUBLE_EQ(s.scene->background.r, 0.5);
    EXPECT_DOUBLE_EQ(s.scene->background.transmit, 0.3);
}

TEST(SrgbColours, BeforeAssumedGammaAreAnError) {
    // POV-Ray 3.7 stops with "Cannot parse sRGB colors before assumed_gamma has been set."
    const ParseResult r = parse("#version 3.7;\nbackground { srgb 0.5 }\nglobal_settings { assumed_gamma 1 }\n");
    EXPECT_FALSE(r.ok());
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_NE(r.diagnostics[0].message.find("before assumed_gamma"), std::string::npos);
    EXPECT_EQ(r.diagnostics[0].loc.line, 2u);
}

}  // namespace
}  // namespace wardray::parser
