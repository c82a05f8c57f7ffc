// Complex exp, ln, the circular and hyperbolic functions and their inverses, and pwr, as POV-Ray 3.7's hcmplx.cpp
// defines them (principal branches through ln and a square root of half the argument).
#include "geometry/julia_complex.h"

#include <cmath>

namespace wardray::geometry {

namespace {

using Function = scene::JuliaFractal::Function;

Complex mul(const Complex& a, const Complex& b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }

// a / b; `fallback` when b is zero (POV-Ray leaves the result as it was).
Complex div(const Complex& a, const Complex& b, const Complex& fallback) {
    const double mod = b.re * b.re + b.im * b.im;
    if (mod == 0.0) return fallback;
    const double xr = b.re / mod, yr = -b.im / mod;
    return {a.re * xr - a.im * yr, a.re * yr + a.im * xr};
}

Complex ln(const Complex& z) { return {std::log(std::sqrt(z.re * z.re + z.im * z.im)), std::atan2(z.im, z.re)}; }

Complex csqrt(const Complex& z) {
    if (z.re == 0.0 && z.im == 0.0) return {};
    const double mag = std::sqrt(std::sqrt(z.re * z.re + z.im * z.im));
    const double theta = std::atan2(z.im, z.re) / 2.0;
    return {mag * std::cos(theta), mag * std::sin(theta)};
}

// atanh(z) = ln((1 + z) / (1 - z)) / 2; `fallback` at ±1 (POV-Ray leaves the result as it was).
Complex atanh(const Complex& z, const Complex& fallback) {
    if (z.re == 0.0) return {0.0, std::atan(z.im)};
    if (std::fabs(z.re) == 1.0 && z.im == 0.0) return fallback;
    if (std::fabs(z.re) < 1.0 && z.im == 0.0) return {std::log((1.0 + z.re) / (1.0 - z.re)) / 2.0, 0.0};
    const Complex q = ln(div({1.0 + z.re, z.im}, {1.0 - z.re, -z.im}, {}));
    return {0.5 * q.re, 0.5 * q.im};
}

Complex atan(const Complex& z) {
    if (z.re == 0.0 && z.im == 0.0) return {};
    if (z.im == 0.0) return {std::atan(z.re), 0.0};
    if (z.re == 0.0) {
        // atan(i y) = i atanh(y).
        const Complex y{z.im, 0.0};
        const Complex a = atanh(y, y);
        return {-a.im, a.re};
    }
    // atan(z) = i/2 ln((1 - i z) / (1 + i z)).
    const Complex iz{-z.im, z.re};
    const Complex q = ln(div({1.0 - iz.re, -iz.im}, {1.0 + iz.re, iz.im}, {}));
    return {-q.im * 0.5, 0.5 * q.re};
}

}  // namespace

Complex julia_complex_function(Function f, const Complex& z, const Complex& exponent) {
    const double x = z.re, y = z.im;
    switch (f) {
        case Function::Exp: return {std::exp(x) * std::cos(y), std::exp(x) * std::sin(y)};
        case Function::Ln: return ln(z);
        case Function::Sin: return {std::sin(x) * std::cosh(y), std::cos(x) * std::sinh(y)};
        case Function::Sinh: return {std::sinh(x) * std::cos(y), std::cosh(x) * std::sin(y)};
        case Function::Cos: return {std::cos(x) * std::cosh(y), -std::sin(x) * std::sinh(y)};
        case Function::Cosh: return {std::cosh(x) * std::cos(y), std::sinh(x) * std::sin(y)};
        case Function::Asin: {
            // asin(z) = -i ln(i z + sqrt(1 - z²)).
            const Complex z2 = mul(z, z);
            const Complex s = csqrt({1.0 - z2.re, -z2.im});
            const Complex l = ln({s.re - y, s.im + x});
            return {l.im, -l.re};
        }
        case Function::Acos: {
            // acos(z) = -i ln(z + sqrt(z² - 1)).
            const Complex z2 = mul(z, z);
            const Complex s = csqrt({z2.re - 1.0, z2.im});
            const Complex l = ln({s.re + x, s.im + y});
            return {l.im, -l.re};
        }
        case Function::Asinh: {
            const Complex z2 = mul(z, z);
            const Complex s = csqrt({z2.re + 1.0, z2.im});
            return ln({s.re + x, s.im + y});
        }
        case Function::Acosh: {
            const Complex z2 = mul(z, z);
            const Complex s = csqrt({z2.re - 1.0, z2.im});
            return ln({x + s.re, y + s.im});
        }
        case Function::Atanh: return atanh(z, {});
        case Function::Atan: return atan(z);
        case Function::Tan: {
            const double denom = std::cos(2.0 * x) + std::cosh(2.0 * y);
            if (denom == 0.0) return {};
            return {std::sin(2.0 * x) / denom, std::sinh(2.0 * y) / denom};
        }
        case Function::Tanh: {
            const double denom = std::cosh(2.0 * x) + std::cos(2.0 * y);
            if (denom == 0.0) return {};
            return {std::sinh(2.0 * x) / denom, std::sin(2.0 * y) / denom};
        }
        case Function::Pwr: {
            if (x == 0.0 && y == 0.0) return {};
            const Complex t = mul(ln(z), exponent);
            // POV-Ray compat: exp underflows to 0 below -690.
            const double e = t.re < -690.0 ? 0.0 : std::exp(t.re);
            return {e * std::cos(t.im), e * std::sin(t.im)};
        }
        case Function::Sqr: return mul(z, z);
        case Function::Cube: return mul(mul(z, z), z);
        case Function::Reciprocal: return div({1.0, 0.0}, z, {});
    }
    return {};
}

}  // namespace wardray::geometry
