// The slope pattern's parameters: `slope <slope>` or `slope { [point_at] <slope> [, lo, hi] [altitude <altitude>
// [, lo, hi]] }`, kept as POV-Ray 3.7's Parse_Pattern keeps them (unit vectors, weights summing to 1, ranges).
#include <cmath>

#include "parser/parser.h"

namespace wardray::parser {

void Parser::parse_slope_range(double& lo, double& range, const char* what) {
    accept(",");
    lo = starts_value(peek()) ? parse_float() : 0.0;
    accept(",");
    const Token at = peek();
    const double hi = starts_value(at) ? parse_float() : 0.0;
    // POV-Ray compat: a range from lo to lo is ignored with a warning; else it is kept as its start and width.
    if (hi != 0.0 && hi == lo) {
        lo = range = 0.0;
        warn(at, std::string("Zero ") + what + " range, ignoring.");
    } else {
        range = hi - lo;
    }
}

void Parser::parse_slope_parameters(const Token& kw, Pattern& pat) {
    SlopeParams s;
    const Token& first = peek();
    // The vector may start with x, y or z, which starts_value leaves to the keyword readers.
    if (starts_value(first) || is_word(first, "x") || is_word(first, "y") || is_word(first, "z")) {
        s.slope_vector = parse_vector();
    } else if (is_punct(peek(), "{")) {
        expect("{");
        s.point_at = accept_keyword("point_at");
        s.slope_vector = parse_vector();
        parse_slope_range(s.slope_lo, s.slope_range, "slope");
        if (is_word(peek(), "altitude")) {
            const Token alt = next();
            if (s.point_at) fail(alt, "Keyword 'altitude' cannot be used with 'point_at' in slope pattern.");
            s.altitude_vector = parse_vector();
            parse_slope_range(s.altitude_lo, s.altitude_range, "gradient");
        }
        expect("}");
    }
    if (s.point_at) {
        s.slope_len = 1.0;
        s.altitude_len = 0.0;
    } else {
        // Each part weighs its vector's length; the vectors are made unit.
        double slope_len = length(s.slope_vector);
        const double altitude_len = length(s.altitude_vector);
        if (slope_len != 0.0) s.slope_vector = s.slope_vector / slope_len;
        if (altitude_len != 0.0) s.altitude_vector = s.altitude_vector / altitude_len;
        const double total = slope_len + altitude_len;
        if (total == 0.0) fail(kw, "Zero length for both slope and gradient.");
        s.slope_len = slope_len / total;
        s.altitude_len = 1.0 - s.slope_len;
    }
    pat.params->slope = s;
}

}  // namespace wardray::parser
