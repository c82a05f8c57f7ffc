// Splines of the scene language (`spline { ... }`): their points and their evaluation as POV-Ray 3.7 does it.
#pragma once

#include <array>
#include <string_view>
#include <vector>

namespace wardray::parser {

/// A `spline { ... }` value: points sorted by their parameter T, each with five components of which `terms` are
/// significant (the result of a call has that many components).
struct Spline {
    /// The interpolation; `cubic_spline` is POV-Ray's Catmull-Rom spline.
    enum class Type { Linear, Quadratic, Cubic, Natural };
    struct Point {
        double t = 0.0;
        std::array<double, 5> v{};
    };
    Type type = Type::Linear;
    int terms = 2;
    std::vector<Point> points;
};

/// The spline type a keyword names (linear_spline, quadratic_spline, cubic_spline, natural_spline); false for
/// other words.
bool spline_type_from_keyword(std::string_view word, Spline::Type& type);
/// The keyword of a spline type.
const char* spline_type_keyword(Spline::Type type);
/// The fewest points with which `type` interpolates as its name says (fewer points fall back as POV-Ray does).
std::size_t spline_min_points(Spline::Type type);

/// Adds a point keeping the points sorted by T, as POV-Ray 3.7 does: a T already present replaces that point's
/// value, except that a T equal to the largest T so far (with two or more points) is ignored.
void insert_spline_point(Spline& spline, double t, const std::array<double, 5>& value);

/// The spline's value at `t` interpolated with `type` (all five components); `t` outside the points' range gives
/// an end value, as POV-Ray 3.7 does. The spline must have at least one point.
std::array<double, 5> evaluate_spline(const Spline& spline, Spline::Type type, double t);

}  // namespace wardray::parser
