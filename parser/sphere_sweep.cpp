// The sphere_sweep reader: the spline type, the control spheres and the depth tolerance, checked as POV-Ray does.
#include <cmath>

#include "parser/parser.h"

namespace wardray::parser {

SphereSweep Parser::read_sphere_sweep(const Token& kw) {
    SphereSweep sweep;
    const Token type = peek();
    if (is_word(type, "linear_spline")) sweep.spline = SphereSweep::Spline::Linear;
    else if (is_word(type, "b_spline")) sweep.spline = SphereSweep::Spline::BSpline;
    else if (is_word(type, "cubic_spline")) sweep.spline = SphereSweep::Spline::Cubic;
    else fail(type, "a sphere_sweep needs linear_spline, b_spline or cubic_spline first, found " + describe_token(type));
    next();
    accept(",");
    const Token at = peek();
    const double count = parse_float();
    // POV-Ray compat: the count is truncated; splines need the two extra spheres that shape their ends.
    const int n = std::isfinite(count) && std::fabs(count) < 1e9 ? static_cast<int>(count) : 0;
    const int needed = sweep.spline == SphereSweep::Spline::Linear ? 2 : 4;
    if (n < needed)
        fail(at, "a sphere_sweep with " + std::string(type.text.view()) + " needs at least " +
                     std::to_string(needed) + " spheres");
    for (int i = 0; i < n; ++i) {
        accept(",");
        sweep.centers.push_back(parse_vector());
        accept(",");
        sweep.radii.push_back(parse_float());
    }
    if (is_word(peek(), "tolerance")) {
        next();
        sweep.tolerance = parse_float();
    }
    return sweep;
}

}  // namespace wardray::parser
