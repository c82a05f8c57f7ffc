// POV-Ray 3.7's internal functions, numbered as functions.inc numbers them. The formulas follow POV-Ray's
// definitions (its documentation of functions.inc); each evaluated one is checked against POV-Ray's own values
// in tests/parser/data/internal.pov.
#include "function/internal_functions.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace wardray::function {

namespace {

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

// The distance from the origin, and the two angles of spherical coordinates about y.
double radius(const double* a) { return std::sqrt(sq(a[0]) + sq(a[1]) + sq(a[2])); }
double polar_angle(const double* a) { return std::atan2(std::sqrt(sq(a[0]) + sq(a[2])), a[1]); }
double azimuth(const double* a) { return std::atan2(a[0], a[2]); }

// A sphere of radius P0: negative inside.
double sphere(const double* a) { return radius(a) - a[3]; }

// An ellipsoid: the length of the point scaled by P0, P1, P2 per axis.
double ellipsoid(const double* a) { return std::sqrt(sq(a[0] * a[3]) + sq(a[1] * a[4]) + sq(a[2] * a[5])); }

// A torus about y with major radius P0 and minor radius P1.
double torus(const double* a) { return std::hypot(std::hypot(a[0], a[2]) - a[3], a[1]) - a[4]; }

// The quartic torus: field strength P0, major radius P1, minor radius P2, clamped to [-10, 10] as POV-Ray does.
double torus2(const double* a) {
    const double x2 = sq(a[0]);
    const double y2 = sq(a[1]);
    const double z2 = sq(a[2]);
    const double major2 = sq(a[4]);
    const double minor2 = sq(a[5]);
    const double sum2 = x2 + y2 + z2;
    const double quartic = sq(sum2) - 2.0 * (major2 + minor2) * (x2 + z2) + 2.0 * (major2 - minor2) * y2 +
                           sq(major2 - minor2);
    return std::clamp(-a[3] * quartic, -10.0, 10.0);
}

// A paraboloid opening along y with field strength P0, clamped to [-10, 10].
double paraboloid(const double* a) { return std::clamp(a[3] * (a[1] - sq(a[0]) - sq(a[2])), -10.0, 10.0); }

// A box with rounded edges: radius P0, half sizes P1, P2, P3 (POV-Ray moves the surface out by 1e-6).
double rounded_box(const double* a) {
    double outside = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double inner = a[4 + i] - a[3];  // half size of the box the rounding is laid around
        const double d = std::fabs(a[i]) - inner;
        if (d > 0.0) outside += sq(d);
    }
    return std::sqrt(outside) - a[3] - 1e-6;
}

// A superellipsoid with east-west exponent P0 and north-south exponent P1: 0 on the surface, positive inside.
double superellipsoid(const double* a) {
    const double e = a[3];
    const double n = a[4];
    const double xy = std::pow(std::pow(std::fabs(a[0]), 2.0 / e) + std::pow(std::fabs(a[1]), 2.0 / e), e / n);
    return 1.0 - std::pow(xy + std::pow(std::fabs(a[2]), 2.0 / n), n * 0.5);
}

}  // namespace

std::size_t internal_function_arity(int n) {
    if (n < 0 || n >= static_cast<int>(k_parameter_counts.size())) return 0;
    return 3 + k_parameter_counts[static_cast<std::size_t>(n)];
}

InternalFunction internal_function(int n) {
    switch (n) {
        case 17: return ellipsoid;
        case 45: return paraboloid;
        case 47: return polar_angle;
        case 57: return radius;
        case 60: return rounded_box;
        case 61: return sphere;
        case 68: return superellipsoid;
        case 69: return azimuth;
        case 70: return torus;
        case 71: return torus2;
        default: return nullptr;
    }
}

}  // namespace wardray::function
