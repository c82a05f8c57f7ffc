// Tests of POV-Ray's File_Gamma= and Display_Gamma= settings on the command line.
#include <gtest/gtest.h>

#include "app/options.h"

namespace wardray::app {
namespace {

Options parse_ok(const std::vector<std::string>& args) {
    auto r = parse_command_line(args);
    EXPECT_TRUE(std::holds_alternative<Options>(r));
    return std::holds_alternative<Options>(r) ? std::get<Options>(r) : Options{};
}

TEST(GammaOptions, FileAndDisplayGammaTakeANumberOrSrgb) {
    EXPECT_EQ(parse_ok({}).file_gamma, GammaCurve::srgb());
    EXPECT_EQ(parse_ok({}).display_gamma, GammaCurve::srgb());
    EXPECT_TRUE(parse_ok({"File_Gamma=1.0"}).file_gamma.is_neutral());
    EXPECT_EQ(parse_ok({"file_gamma=2.2"}).file_gamma, GammaCurve::power_law(2.2));
    EXPECT_EQ(parse_ok({"File_Gamma=1.8", "File_Gamma=sRGB"}).file_gamma, GammaCurve::srgb());
    const Options o = parse_ok({"Display_Gamma=1.8"});
    EXPECT_EQ(o.display_gamma, GammaCurve::power_law(1.8));
    EXPECT_EQ(o.file_gamma, GammaCurve::srgb());
    for (const char* bad : {"File_Gamma=0", "File_Gamma=-2", "Display_Gamma=abc", "File_Gamma="}) {
        auto r = parse_command_line({bad});
        ASSERT_TRUE(std::holds_alternative<UsageError>(r)) << bad;
        EXPECT_NE(std::get<UsageError>(r).message.find("positive gamma or sRGB"), std::string::npos);
    }
}

}  // namespace
}  // namespace wardray::app
