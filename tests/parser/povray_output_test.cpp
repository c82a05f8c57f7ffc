// Scene files whose #debug output is compared line by line with what POV-Ray 3.7 prints for them: the files and
// POV-Ray's output are in tests/parser/data, with the command that produced the output in each file's header.
#include <sstream>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

// Parses data/NAME.pov and compares its #debug lines with data/NAME_povray37.txt; returns how many matched.
std::size_t compare_with_povray(const std::string& name) {
    const std::filesystem::path data = std::filesystem::path(WARDRAY_SOURCE_DIR) / "tests/parser/data";
    ParseOptions o = test::default_options();
    std::string printed;
    o.debug_output = [&](const std::string& text) { printed += text; };
    const ParseResult r = parse_file(data / (name + ".pov"), o);
    EXPECT_TRUE(r.ok()) << test::all_diagnostics(r);
    std::ifstream expected(data / (name + "_povray37.txt"));
    std::istringstream got(printed);
    std::string want;
    std::string line;
    std::size_t matched = 0;
    while (std::getline(expected, want)) {
        if (!std::getline(got, line)) {
            ADD_FAILURE() << "wardray printed nothing for: " << want;
            break;
        }
        EXPECT_EQ(line, want);
        matched += line == want ? 1 : 0;
    }
    return matched;
}

TEST(PovRayOutput, BuiltinFunctionsConstantsAndFormats) {
    // 88 functions, constants, operators and str()/vstr() formats.
    EXPECT_EQ(compare_with_povray("builtins"), 88u);
}

TEST(PovRayOutput, DirectivesMacrosColoursAndIncludeMacros) {
    // Arrays, loops, recursion, by-reference arguments, #local, #switch/#range, colour promotion, strings, rand(),
    // user functions, math.inc, strings.inc and transforms.inc.
    EXPECT_EQ(compare_with_povray("directives"), 22u);
}

TEST(PovRayOutput, InternalFunctionsOfFunctionsInc) {
    // All 76 evaluated internal functions (the "_2d" ones with and without their sweep), also inside a user
    // function; the noise functions with POV-Ray's default generator.
    EXPECT_EQ(compare_with_povray("internal"), 146u);
}

}  // namespace
}  // namespace wardray::parser
