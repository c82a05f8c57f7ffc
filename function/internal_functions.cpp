// POV-Ray 3.7's internal functions, numbered as functions.inc numbers them. The formulas follow POV-Ray's
// definitions of functions.inc (its fnintern module); each one is checked against POV-Ray's own values in
// tests/parser/data/internal.pov.
#include "function/internal_functions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "function/noise.h"

namespace wardray::function {

namespace {

constexpr double k_pi = std::numbers::pi;
constexpr double k_two_pi = 2.0 * std::numbers::pi;

// Parameters after x, y and z, for internal(0) .. internal(78), in functions.inc's order.
constexpr std::array<unsigned char, 79> k_parameter_counts = {
    5, 5, 5, 5, 2, 2, 5, 4, 2, 1,  // algbr_cyl1..4, bicorn, bifolia, blob, blob2, boy_surface, comma
    4, 1, 1, 1, 1, 6, 6, 3, 1, 4,  // cross_ellipsoids .. devils_curve_2d, dupin_cyclid, ellipsoid, enneper, flange
    3, 6, 1, 1, 10, 7, 7, 1, 1, 6, // folium_surface(_2d), glob, heart, helical_torus, helix1, helix2, hex_x/y, hetero
    1, 3, 4, 3, 6, 1, 1, 4, 1, 6,  // hunt .. kampyle(_2d), klein_bottle, kummer v1/v2, lemniscate(_2d)
    5, 1, 1, 1, 4, 1, 3, 0, 1, 1,  // mesh1, mitre, nodal_cubic, odd, ovals_of_cassini, paraboloid, parabolic_torus,
                                   // ph, pillow, piriform
    7, 5, 6, 1, 1, 1, 3, 0, 6, 6,  // piriform_2d, poly4, polytubes, quantum, quartic_paraboloid/saddle/cylinder,
                                   // r, ridge, ridged_mf
    4, 1, 5, 4, 6, 1, 4, 7, 2, 0,  // rounded_box, sphere, spikes(_2d), spiral, steiners_roman, strophoid(_2d),
                                   // superellipsoid, th
    2, 3, 1, 1, 2, 6, 0, 0, 1};    // torus, torus2, torus_gumdrop, umbrella, witch_of_agnesi(_2d), noise3d,
                                   // pattern, noise_generator

double sq(double v) { return v * v; }

// Most algebraic surfaces scale their polynomial by the field strength P0 and clamp it to [-10, 10].
double strength(const double* a, double r) { return std::min(10.0, std::max(a[3] * r, -10.0)); }

// A working copy of x, y, z with the squares the formulas use.
struct Point {
    double x, y, z, x2, y2, z2;
    explicit Point(const double* a) : x(a[0]), y(a[1]), z(a[2]), x2(a[0] * a[0]), y2(a[1] * a[1]), z2(a[2] * a[2]) {}
};

// The "_2d" functions' optional sweep: when `on` > 0 the curve in the x-y plane is turned about the y axis at
// distance `offset` and tilted by `degrees` (POV-Ray's ROT2D).
void rotate_2d(Point& p, double on, double offset, double degrees) {
    if (!(on > 0.0)) return;
    const double r = std::sqrt(p.x2 + p.z * p.z) - offset;
    const double th = degrees * k_pi / 180.0;
    if (th != 0.0) {
        const double x = r * std::cos(th) - p.y * std::sin(th);
        p.y = r * std::sin(th) + p.y * std::cos(th);
        p.x = x;
    } else {
        p.x = r;
    }
    p.x2 = p.x * p.x;
    p.y2 = p.y * p.y;
}

// The "minimum radius" cross section of the helices and the spiral: circle (1), rounded rectangle (other),
// square (0).
double cross_section(double u, double v, double shape) {
    if (shape == 1.0) return std::sqrt(u * u + v * v);
    if (shape == 0.0) return std::max(std::fabs(u), std::fabs(v));
    const double e = 2.0 / shape;
    return std::pow(std::pow(std::fabs(u), e) + std::pow(std::fabs(v), e), shape * 0.5);
}

// The algebraic cylinders 0..3 share their sweep (P2..P4) and clamp to [-P1, P1].
double algbr_clamp(const double* a, double r) { return std::min(a[4], std::max(a[3] * r, -a[4])); }

double algbr_cyl1(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[5], a[6], a[7]);
    const double ax = std::fabs(p.x);
    return -algbr_clamp(a, -(p.x2 * ax - p.x2 + p.y2));
}
double algbr_cyl2(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[5], a[6], a[7]);
    return algbr_clamp(a, -(2 * p.x2 * p.x2 - 3 * p.x2 * p.y + p.y2 - 2 * p.y2 * p.y + p.y2 * p.y2));
}
double algbr_cyl3(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[5], a[6], a[7]);
    return algbr_clamp(a, -(p.x2 * p.x2 + p.x2 * p.y2 - 2 * p.x2 * p.y - p.x * p.y2 + p.y2));
}
double algbr_cyl4(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[5], a[6], a[7]);
    return algbr_clamp(a, -(p.x2 * p.x2 + p.y2 * p.y2 + 2 * p.x2 * p.y2 + 3 * p.x2 * p.y - p.y2 * p.y));
}
double bicorn(const double* a, const EvalContext&) {
    const Point p(a);
    const double r2 = a[4] * a[4];
    const double q = p.x2 + p.z2 + 2 * a[4] * p.y - r2;
    return strength(a, p.y2 * (r2 - (p.x2 + p.z2)) - q * q);
}
double bifolia(const double* a, const EvalContext&) {
    const Point p(a);
    const double r = p.x2 + p.y2 + p.z2;
    return strength(a, -(r * r - a[4] * (p.x2 + p.z2) * p.y));
}
double blob(const double* a, const EvalContext&) {
    const Point p(a);
    const double half = a[3] * 0.5;
    const double r1 = std::min(1.0, (sq(p.x + half) + p.y2 + p.z2) * a[5] * a[5]);
    const double r2 = std::min(1.0, (sq(p.x - half) + p.y2 + p.z2) * a[7] * a[7]);
    return -(a[4] * sq(1.0 - r1) + a[6] * sq(1.0 - r2));
}
double blob2(const double* a, const EvalContext&) {
    const Point p(a);
    const double r = std::exp(-(p.x2 + p.y2 + p.z2) * a[4]) + std::exp(-(sq(p.x - a[3]) + p.y2 + p.z2) * a[4]);
    return a[6] - r * a[5];
}
double boy_surface(const double* a, const EvalContext&) {
    const Point p(a);
    const double w = 1 - p.z, ph = p.x2 + p.y2, s2 = std::sqrt(2.0);
    const double r =
        a[4] * (64 * w * w * w * p.z2 * p.z - 48 * w * w * p.z2 * (3 * p.x2 + 3 * p.y2 + 2 * p.z2) +
                12 * w * p.z * (27 * ph * ph - 24 * p.z2 * ph + 36 * s2 * p.y * p.z * (p.y2 - 3 * p.x2) + 4 * p.z2 * p.z2) +
                (9 * p.x2 + 9 * p.y2 - 2 * p.z2) *
                    (-81 * ph * ph - 72 * p.z2 * ph + 108 * s2 * p.x * p.z * (p.x2 - 3 * p.y2) + 4 * p.z2 * p.z2));
    return strength(a, r);
}
double comma(const double* a, const EvalContext&) {
    double x = a[0];
    const double y = a[1], z = a[2], s = a[3];
    if (x == 0.0 && z == 0.0) x = 0.0001;
    const double th = std::atan2(z, x);
    const double r = std::sqrt(sq(x + s * 0.25) + z * z);
    const double ring = std::min(z, std::cos(th * 0.5) * s * 0.5 - std::sqrt(sq(r - s * 0.75) + y * y));
    const double ball = s * 0.5 - std::sqrt(sq(x - s * 0.5) + z * z + y * y);
    return -std::max(ring, ball);
}
// Three ellipsoids along the axes, each exp(-(scaled squared distance) * P1).
std::array<double, 3> axis_ellipsoids(const double* a) {
    const Point p(a);
    return {std::exp(-(p.x2 * a[3] + p.y2 * a[3] + p.z2) * a[4]), std::exp(-(p.x2 * a[3] + p.y2 + p.z2 * a[3]) * a[4]),
            std::exp(-(p.x2 + p.y2 * a[3] + p.z2 * a[3]) * a[4])};
}
double cross_ellipsoids(const double* a, const EvalContext&) {
    const auto e = axis_ellipsoids(a);
    return a[6] - std::max({e[0], e[1], e[2]}) * a[5];
}
double crossed_trough(const double* a, const EvalContext&) { return strength(a, a[0] * a[0] * a[2] * a[2] - a[1]); }
double cubic_saddle(const double* a, const EvalContext&) {
    return strength(a, -(a[0] * a[0] * a[0] - a[1] * a[1] * a[1] - a[2]));
}
// f_cushion and f_odd are the same polynomial.
double cushion_polynomial(const Point& p) {
    return p.z2 * p.x2 - p.z2 * p.z2 - 2 * p.z * p.x2 + 2 * p.z2 * p.z + p.x2 - p.z2 - sq(p.x2 - p.z) -
           p.y2 * p.y2 - 2 * p.x2 * p.y2 - p.y2 * p.z2 + 2 * p.y2 * p.z + p.y2;
}
double cushion(const double* a, const EvalContext&) { return strength(a, cushion_polynomial(Point(a))); }
double devils_curve(const double* a, const EvalContext&) {
    const Point p(a);
    return strength(a, -(p.x2 * p.x2 + 2 * p.x2 * p.z2 - 0.36 * p.x2 - p.y2 * p.y2 + 0.25 * p.y2 + p.z2 * p.z2));
}
double devils_curve_2d(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[6], a[7], a[8]);
    return strength(a, -(p.x2 * (p.x2 - a[4] * a[4]) - p.y2 * (p.y2 - a[5] * a[5])));
}
double dupin_cyclid(const double* a, const EvalContext&) {
    const Point p(a);
    const double P1 = a[4], P2 = a[5], P3 = a[6], P4 = a[7], P5 = a[8];
    const double r2 = P5 * P5, ph = P2 * P2, th = P4 * P4;
    const double p1 = ph - th - sq(P3 + P1), p2 = ph - th - sq(P3 - P1), p3 = P3 * P3, p4 = P1 * P1;
    const double r = -(p1 * p2 * (p.x2 * p.x2 + p.y2 * p.y2 + p.z2 * p.z2) +
                       2 * (p1 * p2 * (p.x2 * p.y2 + p.x2 * p.z2 + p.y2 * p.z2)) +
                       2 * r2 * ((-th - p3 + ph + p4) * (2 * p.x * P3 + 2 * p.y * P4 - r2) - 4 * P4 * ph * p.y) *
                           (p.x2 + p.y2 + p.z2) +
                       4 * r2 * r2 * (P3 * p.x + P4 * p.y) * (-r2 + P4 * p.y + P3 * p.x) + 4 * r2 * r2 * p4 * p.y2 +
                       r2 * r2 * r2 * r2);
    return strength(a, r);
}
double ellipsoid(const double* a, const EvalContext&) {
    return std::sqrt(sq(a[0]) * sq(a[3]) + sq(a[1]) * sq(a[4]) + sq(a[2]) * sq(a[5]));
}
double flange_cover(const double* a, const EvalContext&) {
    const auto e = axis_ellipsoids(a);
    return a[6] - (e[0] + e[1] + e[2]) * a[5];
}
double folium_surface(const double* a, const EvalContext&) {
    const Point p(a);
    return strength(a, (p.y2 + p.z2) * (1 + (a[5] - 4 * a[4]) * p.x) + p.x2 * (1 + a[5]));
}
double folium_surface_2d(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[6], a[7], a[8]);
    return strength(a, -(p.y2 * (1 + (a[5] - 4 * a[4]) * p.x) + p.x2 * (1 + a[5])));
}
double glob(const double* a, const EvalContext&) {
    const double x2 = a[0] * a[0];
    return strength(a, 0.5 * x2 * x2 * a[0] + 0.5 * x2 * x2 - (a[1] * a[1] + a[2] * a[2]));
}
double heart(const double* a, const EvalContext&) {
    const Point p(a);
    const double q = 2 * p.x2 + p.y2 + p.z2 - 1;
    return strength(a, -(q * q * q - 0.1 * p.x2 * p.z2 * p.z - p.y2 * p.z2 * p.z));
}
double helical_torus(const double* a, const EvalContext&) {
    const double* P = a + 3;
    double x = a[0];
    const double y = a[1], z = a[2];
    double r2 = std::sqrt(x * x + z * z);
    if (x == 0.0 && z == 0.0) x = 0.000001;
    const double ph = std::atan2(x, z);
    double temp = std::atan2(r2 - P[0], y);
    const double r = std::sqrt(sq(r2 - P[0]) + y * y);
    double th = std::fmod(ph * P[1] + temp * P[2], k_two_pi);
    if (th < 0) th += k_two_pi;
    temp = std::atan2((th - k_pi) * P[8], r - P[5]);
    temp = std::cos(temp * P[7] + ph * P[9]) * P[3] + P[4];
    r2 = P[4] + P[5] - P[0] - r2;
    th -= k_pi;
    temp -= std::min(std::sqrt(sq(r - P[5]) + th * th * P[6]), r + P[5]);
    return -std::max(r2, temp);
}
double helix1(const double* a, const EvalContext&) {
    const double* P = a + 3;
    double x = a[0];
    const double y = a[1], z = a[2];
    const double r = std::sqrt(x * x + z * z);
    if (x == 0.0 && z == 0.0) x = 0.000001;
    double th = std::fmod(std::atan2(z, x) * P[0] + y * P[1] * P[0], k_two_pi);
    if (th < 0) th += k_two_pi;
    double w = (th - k_pi) / P[4] / (P[1] * P[0]);
    double u = r - P[3];
    double r2 = 0.0;
    if (P[5] == 1.0) {
        r2 = std::sqrt(u * u + w * w);
    } else {
        if (P[6] != 0.0) {
            const double c = std::cos(P[6] * k_pi / 180.0), s = std::sin(P[6] * k_pi / 180.0);
            const double u2 = u * c - w * s;
            w = u * s + w * c;
            u = u2;
        }
        r2 = cross_section(u, w, P[5]);
    }
    return -P[2] + std::min(P[3] + r, r2);
}
double helix2(const double* a, const EvalContext&) {
    const double* P = a + 3;
    const double th = a[1] * P[1];
    const double c = std::cos(th), s = std::sin(th);
    const double x2 = a[0] - P[3] * c, z2 = a[2] - P[3] * s;
    const double u = x2 * c + z2 * s, w = -x2 * s + z2 * c;
    return cross_section(u, w, P[5]) - P[2];
}
// The hexagonal tiling of f_hex_x and f_hex_y: the point folded into one cell, and whether it is past 30 degrees.
struct HexCell {
    double x, y;
    bool steep;
};
HexCell hex_cell(const double* a) {
    const double s3 = std::sqrt(3.0);
    double x1 = std::fabs(std::fmod(std::fabs(a[0]), s3) - s3 / 2);
    double y1 = std::fabs(std::fmod(std::fabs(a[1]), 3.0) - 1.5);
    const double x2 = s3 / 2 - x1, y2 = 1.5 - y1;
    if (x1 * x1 + y1 * y1 > x2 * x2 + y2 * y2) {
        x1 = x2;
        y1 = y2;
    }
    return {x1, y1, !(std::atan2(y1, x1) < k_pi / 6)};
}
double hex_x(const double* a, const EvalContext&) {
    const HexCell c = hex_cell(a);
    return c.steep ? std::cos(k_pi / 3) * c.x + std::sin(k_pi / 3) * c.y : c.x;
}
double hex_y(const double* a, const EvalContext&) {
    const HexCell c = hex_cell(a);
    return c.steep ? std::fabs(-std::sin(k_pi / 3) * c.x + std::cos(k_pi / 3) * c.y) : c.y;
}
// Noise in [-1, 1] with the generator a function names in its parameter (two low bits).
double signed_noise(const Vec3& p, int generator) { return noise(p, generator) * 2.0 - 1.0; }
int noise_generator_of(double v) { return static_cast<int>(v) & 3; }
double hetero_mf(const double* a, const EvalContext&) {
    const double* P = a + 3;
    const int gen = noise_generator_of(P[5]);
    Vec3 v{a[0], a[1], a[2]};
    double signal = signed_noise(v, gen) + P[3];
    v = v * P[1];
    const double step = std::pow(P[1], -P[0]);
    double weight = step;
    for (int i = 1; i < P[2]; ++i) {
        double inc = (signed_noise(v, gen) + P[3]) * weight;
        for (int k = static_cast<int>(P[4]); k > 0; --k) inc *= signal;
        signal += inc;
        v = v * P[1];
        weight *= step;
    }
    const double rem = P[2] - static_cast<int>(P[2]);
    if (rem != 0.0) signal += rem * (signed_noise(v, gen) + P[3]) * weight * signal;
    return signal;
}
double hunt_surface(const double* a, const EvalContext&) {
    const Point p(a);
    const double q = p.x2 + p.y2 + p.z2 - 13;
    return strength(a, -(4 * q * q * q + 27 * sq(3 * p.x2 + p.y2 - 4 * p.z2 - 12)));
}
double hyperbolic_torus(const double* a, const EvalContext&) {
    const Point p(a);
    const double ph = a[4] * a[4], th = a[5] * a[5];
    return strength(a, -(p.x2 * p.x2 + 2 * p.x2 * p.y2 - 2 * p.x2 * p.z2 - 2 * (ph + th) * p.x2 + p.y2 * p.y2 -
                         2 * p.y2 * p.z2 + 2 * (ph - th) * p.y2 + p.z2 * p.z2 + 2 * (ph + th) * p.z2 + sq(ph - th)));
}
double isect_ellipsoids(const double* a, const EvalContext&) {
    const auto e = axis_ellipsoids(a);
    return a[6] - std::min({e[0], e[1], e[2]}) * a[5];
}
double kampyle_of_eudoxus(const double* a, const EvalContext&) {
    const double x2 = a[0] * a[0];
    return strength(a, -((a[1] * a[1] + a[2] * a[2]) - a[5] * a[5] * x2 * x2 + a[5] * a[5] * a[4] * a[4] * x2));
}
double kampyle_of_eudoxus_2d(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[6], a[7], a[8]);
    // POV-Ray compat: the last term is P2² P1 P2 x², not P2² P1² x² as in the 3-D version.
    return strength(a, -(p.y2 - a[5] * a[5] * p.x2 * p.x2 + a[5] * a[5] * a[4] * a[5] * p.x2));
}
double klein_bottle(const double* a, const EvalContext&) {
    const Point p(a);
    const double s = p.x2 + p.y2 + p.z2;
    const double m = s - 2 * p.y - 1;
    return strength(a, -((s + 2 * p.y - 1) * (m * m - 8 * p.z2) + 16 * p.x * p.z * m));
}
double kummer_surface_v1(const double* a, const EvalContext&) {
    const Point p(a);
    return strength(a, -(p.x2 * p.x2 + p.y2 * p.y2 + p.z2 * p.z2 - p.x2 - p.y2 - p.z2 - p.x2 * p.y2 - p.x2 * p.z2 -
                         p.y2 * p.z2 + 1));
}
double kummer_surface_v2(const double* a, const EvalContext&) {
    const Point p(a);
    return strength(a, -(p.x2 * p.x2 + p.y2 * p.y2 + p.z2 * p.z2 + a[4] * (p.x2 + p.y2 + p.z2) +
                         a[5] * (p.x2 * p.y2 + p.x2 * p.z2 + p.y2 * p.z2) + a[6] * p.x * p.y * p.z - 1));
}
double lemniscate_of_gerono(const double* a, const EvalContext&) {
    const Point p(a);
    return strength(a, -(p.x2 * p.x2 - p.x2 + p.y2 + p.z2));
}
double lemniscate_of_gerono_2d(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[6], a[7], a[8]);
    return strength(a, -(p.y2 - a[5] * a[5] * a[4] * a[4] * p.x2 + a[5] * a[5] * p.x2 * p.x2));
}
// The distance across one strand of f_mesh1's weave: u folded into [0, 2 period), centred, scaled.
double strand(double u, double period, double scale) {
    double r = std::fmod(u, period * 2);
    if (r < 0) r += period * 2;
    return std::fabs(r - period) * scale;
}
double mesh1(const double* a, const EvalContext&) {
    const double* P = a + 3;
    const double x = a[0], y = a[1], z = a[2];
    const double th = k_pi / P[0], ph = k_pi / P[1];
    const auto tube = [&](double across, double height) { return -std::sqrt(height * height + across * across); };
    double t = tube(strand(x, P[0], P[2]), (y - std::cos(z * ph) * P[3]) * P[4]);
    t = std::max(tube(strand(x - P[0], P[0], P[2]), (y + std::cos(z * ph) * P[3]) * P[4]), t);
    t = std::max(tube(strand(z, P[1], P[2]), (y + std::cos(x * th) * P[3]) * P[4]), t);
    return -std::max(tube(strand(z - P[1], P[1], P[2]), (y - std::cos(x * th) * P[3]) * P[4]), t);
}
double mitre(const double* a, const EvalContext&) {
    const Point p(a);
    return strength(a, -(4 * p.x2 * (p.x2 + p.y2 + p.z2) - p.y2 * (1 - p.y2 - p.z2)));
}
double nodal_cubic(const double* a, const EvalContext&) {
    return strength(a, -(a[1] * a[1] * a[1] + a[2] * a[2] * a[2] - 6 * a[1] * a[2]));
}
double odd(const double* a, const EvalContext&) { return strength(a, cushion_polynomial(Point(a))); }
double ovals_of_cassini(const double* a, const EvalContext&) {
    const Point p(a);
    const double r2 = p.x2 + p.y2 + p.z2 + a[4] * a[4];
    return strength(a, -(r2 * r2 - a[6] * a[4] * a[4] * (p.x2 + p.z2) - a[5] * a[5]));
}
double paraboloid(const double* a, const EvalContext&) { return strength(a, -(a[0] * a[0] - a[1] + a[2] * a[2])); }
double parabolic_torus(const double* a, const EvalContext&) {
    const Point p(a);
    const double ph = a[4] * a[4], th = a[5] * a[5];
    return strength(a, -(p.x2 * p.x2 + 2 * p.x2 * p.y2 - 2 * p.x2 * p.z - (ph + th) * p.x2 + p.y2 * p.y2 -
                         2 * p.y2 * p.z + (ph - th) * p.y2 + p.z2 + (ph + th) * p.z + sq(ph - th)));
}
double polar_angle(const double* a, const EvalContext&) { return std::atan2(std::sqrt(sq(a[0]) + sq(a[2])), a[1]); }
double pillow(const double* a, const EvalContext&) {
    const Point p(a);
    return strength(a, p.x2 * p.x2 + p.y2 * p.y2 + p.z2 * p.z2 - (p.x2 + p.y2 + p.z2));
}
double piriform(const double* a, const EvalContext&) {
    const double x2 = a[0] * a[0];
    return -strength(a, -((x2 * x2 - x2 * a[0]) + a[1] * a[1] + a[2] * a[2]));
}
double piriform_2d(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[7], a[8], a[9]);
    return strength(a, -(p.y * p.y - a[4] * a[6] * a[6] * p.x2 * p.x - a[5] * a[6] * a[6] * p.x2 * p.x2));
}
double poly4(const double* a, const EvalContext&) {
    const double y = a[1], y2 = y * y;
    const double r = std::max(-5.0, a[3] + a[4] * y + a[5] * y2 + a[6] * y2 * y + a[7] * y2 * y2);
    return -r + std::sqrt(a[0] * a[0] + a[2] * a[2]);
}
double polytubes(const double* a, const EvalContext&) {
    const double* P = a + 3;
    const double y = a[1], y2 = y * y;
    const double radius = P[1] + P[2] * y + P[3] * y2 + P[4] * y2 * y + P[5] * y2 * y2;
    double r = -10000.0;
    for (int i = 0; i < static_cast<int>(P[0]); ++i) {
        const double dx = a[0] - radius * std::sin(k_two_pi / P[0] * i);
        const double dz = a[2] - radius * std::cos(k_two_pi / P[0] * i);
        r = std::max(r, -std::sqrt(dx * dx + dz * dz));
    }
    return -r;
}
double quantum(const double* a, const EvalContext&) {
    double x = a[0];
    const double y = a[1], z = a[2];
    if (x == 0.0 && z == 0.0) x = 1e-6;
    double r = std::sqrt(x * x + z * z);
    const double th = std::cos(std::atan2(r, y));
    r = std::sqrt(r * r + y * y) * 2.0;
    const double t = r * r * std::exp(-r * 0.33333333) * (3.0 * th * th - 1);
    return (t * t - 12.0) * (-0.1);
}
double quartic_paraboloid(const double* a, const EvalContext&) {
    const double x2 = a[0] * a[0], z2 = a[2] * a[2];
    return strength(a, -(x2 * x2 + z2 * z2 - a[1]));
}
double quartic_saddle(const double* a, const EvalContext&) {
    const double x2 = a[0] * a[0], z2 = a[2] * a[2];
    return strength(a, -(x2 * x2 - z2 * z2 - a[1]));
}
double quartic_cylinder(const double* a, const EvalContext&) {
    const double xz = a[0] * a[0] + a[2] * a[2];
    return strength(a, -(xz * a[1] * a[1] + a[5] * a[5] * xz - a[5] * a[5] * a[4] * a[4]));
}
double radius(const double* a, const EvalContext&) { return std::sqrt(sq(a[0]) + sq(a[1]) + sq(a[2])); }
double ridge(const double* a, const EvalContext&) {
    const double* P = a + 3;
    const Vec3 p{a[0], a[1], a[2]};
    const int gen = noise_generator_of(P[5]);
    const int octaves = static_cast<int>(P[1]);
    const double rscale = 1.0 / std::max(P[4], 1.0 - P[4]);
    const double scale = 1.0 / std::max(P[3], 1.0 - P[3]);
    const double resid = P[1] - octaves;
    const auto crest = [&](const Vec3& q) { return std::fabs(noise(q, gen) - P[4]) * rscale - P[3]; };
    double value = crest(p), total = 1.0, l = P[0], o = P[2];
    for (int i = 2; i <= octaves; ++i) {
        value += o * crest(p * l);
        total += o;
        l *= P[0];
        o *= P[2];
    }
    if (resid != 0.0) {
        value += o * crest(p * l) * resid;
        total += o * resid;
    }
    return value * scale / total;
}
double ridged_mf(const double* a, const EvalContext&) {
    const double* P = a + 3;
    const int gen = noise_generator_of(P[5]);
    Vec3 v{a[0], a[1], a[2]};
    const auto crest = [&](const Vec3& q) { return sq(P[3] - std::fabs(signed_noise(q, gen))); };
    double signal = crest(v), result = signal;
    // POV-Ray compat: octave i weighs frequency^-H with frequency P1^i (POV-Ray tabulates these once).
    double frequency = 1.0;
    for (int i = 1; i < P[2]; ++i) {
        v = v * P[1];
        frequency *= P[1];
        const double weight = std::clamp(signal * P[4], 0.0, 1.0);
        signal = crest(v) * weight;
        result += signal * std::pow(frequency, -P[0]);
    }
    return result;
}
double rounded_box(const double* a, const EvalContext&) {
    double outside = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double d = std::fabs(a[i]) - (a[4 + i] - a[3]);  // past the box the rounding is laid around
        if (d > 0.0) outside += sq(d);
    }
    return -a[3] + std::sqrt(outside) - 1e-6;
}
double sphere(const double* a, const EvalContext&) { return -a[3] + std::sqrt(sq(a[0]) + sq(a[1]) + sq(a[2])); }
double spikes(const double* a, const EvalContext&) {
    const Point p(a);
    const auto e = axis_ellipsoids(a);
    const double r = std::exp(-(p.x2 + p.y2 + p.z2) * a[6]) * a[7] - e[0] - e[1] - e[2];
    return -r * a[5];
}
double spikes_2d(const double* a, const EvalContext&) {
    const double x = a[0], z = a[2];
    return -(a[3] * std::cos(a[4] * x) * std::cos(a[5] * z) * std::exp(-a[6] * (x * x + z * z)) - a[1]);
}
double spiral(const double* a, const EvalContext&) {
    const double* P = a + 3;
    double x = a[0];
    const double y = a[1], z = a[2];
    double r = std::sqrt(x * x + z * z);
    if (x == 0.0 && z == 0.0) x = 0.000001;
    r += P[0] * std::atan2(z, x) / k_two_pi;
    double r2 = std::fmod(r, P[0]) - P[0] * 0.5;
    if (P[5] == 1.0) {
        r2 = std::sqrt(r2 * r2 + y * y);
    } else if (P[5] != 0.0) {
        const double e = 2 / P[5];
        r2 = std::pow(std::pow(std::fabs(r2), e) + std::pow(std::fabs(y), e), 1.0 / e);
    } else {
        r2 = std::max(std::fabs(r2), std::fabs(y));
    }
    r = std::sqrt(x * x + y * y + z * z);
    return -std::min(P[2] - r, P[1] - std::min(r2, r));
}
double steiners_roman(const double* a, const EvalContext&) {
    const Point p(a);
    return strength(a, -(p.x2 * p.y2 + p.x2 * p.z2 + p.y2 * p.z2 + p.x * p.y * p.z));
}
double strophoid(const double* a, const EvalContext&) {
    const double x = a[0], x2 = x * x, r2 = a[6] * a[6];
    return strength(a, -((a[5] - x) * (a[1] * a[1] + a[2] * a[2]) - r2 * a[4] * x2 - r2 * x2 * x));
}
double strophoid_2d(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[7], a[8], a[9]);
    const double r2 = a[6] * a[6];
    return strength(a, -((a[5] - p.x) * p.y2 - r2 * a[4] * p.x2 - r2 * p.x2 * p.x));
}
double superellipsoid(const double* a, const EvalContext&) {
    const double e = a[3], n = a[4];
    const double xy = std::pow(std::pow(std::fabs(a[0]), 2.0 / e) + std::pow(std::fabs(a[1]), 2.0 / e), e / n);
    return 1.0 - std::pow(xy + std::pow(std::fabs(a[2]), 2.0 / n), n * 0.5);
}
double azimuth(const double* a, const EvalContext&) { return std::atan2(a[0], a[2]); }
double torus(const double* a, const EvalContext&) {
    return -a[4] + std::sqrt(sq(std::sqrt(sq(a[0]) + sq(a[2])) - a[3]) + sq(a[1]));
}
double torus2(const double* a, const EvalContext&) {
    const Point p(a);
    const double ph = a[4] * a[4], th = a[5] * a[5];
    return strength(a, -(p.x2 * p.x2 + p.y2 * p.y2 + p.z2 * p.z2 + 2 * p.x2 * p.y2 + 2 * p.x2 * p.z2 +
                         2 * p.y2 * p.z2 - 2 * (ph + th) * p.x2 + 2 * (ph - th) * p.y2 - 2 * (ph + th) * p.z2 +
                         sq(ph - th)));
}
double torus_gumdrop(const double* a, const EvalContext&) {
    const Point p(a);
    const double yz = p.y2 + p.z2;
    return strength(a, -(4 * (p.x2 * p.x2 + yz * yz) + 17 * p.x2 * yz - 20 * (p.x2 + yz) + 17));
}
double umbrella(const double* a, const EvalContext&) { return strength(a, -(a[0] * a[0] - a[1] * a[2] * a[2])); }
double witch_of_agnesi(const double* a, const EvalContext&) {
    return strength(a, -(a[4] * (a[1] - 1) + (a[0] * a[0] + a[2] * a[2]) * a[1]));
}
double witch_of_agnesi_2d(const double* a, const EvalContext&) {
    Point p(a);
    rotate_2d(p, a[6], a[7], a[8]);
    return strength(a, -(a[4] * a[4] * p.y + p.x2 * p.y - a[5]));
}
double noise3d(const double* a, const EvalContext& c) { return noise({a[0], a[1], a[2]}, c.noise_generator); }
double noise_with_generator(const double* a, const EvalContext&) {
    return noise({a[0], a[1], a[2]}, noise_generator_of(a[3]));
}

// internal(0) .. internal(78); null where wardray does not evaluate it: 18 (f_enneper, whose values differ from
// POV-Ray 3.7's) and 77 (the pattern function, built apart).
constexpr std::array<InternalFunction, 79> k_functions = {
    algbr_cyl1, algbr_cyl2, algbr_cyl3, algbr_cyl4, bicorn, bifolia, blob, blob2, boy_surface, comma,
    cross_ellipsoids, crossed_trough, cubic_saddle, cushion, devils_curve, devils_curve_2d, dupin_cyclid, ellipsoid,
    nullptr, flange_cover, folium_surface, folium_surface_2d, glob, heart, helical_torus, helix1, helix2, hex_x,
    hex_y, hetero_mf, hunt_surface, hyperbolic_torus, isect_ellipsoids, kampyle_of_eudoxus, kampyle_of_eudoxus_2d,
    klein_bottle, kummer_surface_v1, kummer_surface_v2, lemniscate_of_gerono, lemniscate_of_gerono_2d, mesh1, mitre,
    nodal_cubic, odd, ovals_of_cassini, paraboloid, parabolic_torus, polar_angle, pillow, piriform, piriform_2d,
    poly4, polytubes, quantum, quartic_paraboloid, quartic_saddle, quartic_cylinder, radius, ridge, ridged_mf,
    rounded_box, sphere, spikes, spikes_2d, spiral, steiners_roman, strophoid, strophoid_2d, superellipsoid, azimuth,
    torus, torus2, torus_gumdrop, umbrella, witch_of_agnesi, witch_of_agnesi_2d, noise3d, nullptr,
    noise_with_generator};

}  // namespace

std::size_t internal_function_arity(int n) {
    if (n < 0 || n >= static_cast<int>(k_parameter_counts.size())) return 0;
    return 3 + k_parameter_counts[static_cast<std::size_t>(n)];
}

InternalFunction internal_function(int n) {
    if (n < 0 || n >= static_cast<int>(k_functions.size())) return nullptr;
    return k_functions[static_cast<std::size_t>(n)];
}

}  // namespace wardray::function
