// PathSequence: Sobol direction numbers built from primitive polynomials, a nested (Owen) scrambling by hashing.
#include "lighting/path_sequence.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>

namespace wardray::lighting {

namespace {

constexpr int kBits = 32;
using DirectionNumbers = std::array<std::array<std::uint32_t, kBits>, kPathDimensions>;

/// One dimension's primitive polynomial over GF(2) of degree `degree`, its inner coefficients `inner` (the
/// coefficient of x^(degree-1) in the highest bit), and its first `degree` odd initial numbers m_k < 2^k.
struct Polynomial {
    int degree;
    std::uint32_t inner;
    std::array<std::uint32_t, 5> initial;
};

/// Dimensions 1 to 8 (dimension 0 is van der Corput's): x+1, x²+x+1, x³+x+1, x³+x²+1, x⁴+x+1, x⁴+x³+1, x⁵+x²+1,
/// x⁵+x³+1
/// with Joe & Kuo's (2008) initial numbers.
constexpr std::array<Polynomial, kPathDimensions - 1> kPolynomials{{
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
    {5, 4, {1, 1, 5, 5, 5}},
}};

/// v_k = m_k / 2^k as 32-bit fractions, m_k from Sobol's recurrence
/// m_k = 2a_1 m_{k-1} ⊕ 4a_2 m_{k-2} ⊕ ... ⊕ 2^s m_{k-s} ⊕ m_{k-s} (Bratley & Fox 1988, eq. 2).
DirectionNumbers make_direction_numbers() {
    DirectionNumbers v{};
    for (int k = 0; k < kBits; ++k) v[0][k] = 1u << (kBits - 1 - k);
    for (int d = 1; d < kPathDimensions; ++d) {
        const Polynomial& poly = kPolynomials[d - 1];
        const int s = poly.degree;
        std::array<std::uint32_t, kBits> m{};
        for (int k = 0; k < kBits; ++k) {
            if (k < s) {
                m[k] = poly.initial[k];
            } else {
                std::uint32_t next = m[k - s] ^ (m[k - s] << s);
                for (int i = 1; i < s; ++i)
                    if ((poly.inner >> (s - 1 - i)) & 1u) next ^= m[k - i] << i;
                m[k] = next;
            }
            v[d][k] = m[k] << (kBits - 1 - k);
        }
    }
    return v;
}

const DirectionNumbers& direction_numbers() {
    static const DirectionNumbers v = make_direction_numbers();
    return v;
}

/// SplitMix64's finaliser: a 64-bit mix whose output bits all depend on every input bit.
std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/// The bits of `x` in reverse order.
std::uint32_t reverse_bits(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
    x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
    return (x >> 16) | (x << 16);
}

/// A nested scrambling of the 32-bit fraction `x` keyed by `key` (Laine & Karras 2011's construction, as Burley
/// 2020 uses it for Owen scrambling): on the reversed bits, adding a key and x ^= x·c for even c change a bit only
/// by the bits below it, i.e. each digit of `x` by the digits above it, so elementary intervals go to elementary
/// intervals and a net stays a net. Adding a uniform key first makes the result uniform for any `x`.
std::uint32_t nested_scramble(std::uint32_t x, std::uint64_t key) {
    std::uint32_t r = reverse_bits(x);
    r += static_cast<std::uint32_t>(key);
    r ^= r * 0x9E3779B8u;
    r ^= r * 0x85EBCA6Au;
    r += static_cast<std::uint32_t>(key >> 32);
    r ^= r * 0xC2B2AE3Cu;
    r ^= r * 0x27D4EB2Eu;
    return reverse_bits(r);
}

}  // namespace

double path_sample(std::uint32_t index, int dimension, std::uint64_t seed) {
    const auto& v = direction_numbers()[dimension];
    std::uint32_t x = 0;
    for (int k = 0; index != 0; ++k, index >>= 1) x ^= v[k] & (0u - (index & 1u));  // branchless: bits are random
    const std::uint64_t key = mix64(seed ^ (0xD1B54A32D192ED03ull * static_cast<std::uint64_t>(dimension + 1)));
    const std::uint32_t scrambled = nested_scramble(x, key);
    // The 21 bits below the scrambled 32 are uniform, so the sample is uniform in [0, 1) to a double's precision.
    const std::uint64_t fill = mix64(key ^ (static_cast<std::uint64_t>(x) * 0x632BE59BD9B4E019ull)) >> 43;
    return static_cast<double>((static_cast<std::uint64_t>(scrambled) << 21) | fill) * 0x1.0p-53;
}

Vec3 cosine_direction(double u, double v) {
    const double sin_theta = std::sqrt(u);
    const double cos_theta = std::sqrt(std::max(0.0, 1.0 - u));
    const double phi = 2.0 * std::numbers::pi * v;
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

}  // namespace wardray::lighting
