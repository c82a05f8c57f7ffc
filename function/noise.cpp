// Noise: POV-Ray 3.7's lattice noise (texture.cpp's Noise/DNoise), turbulence, hash and random tables.
// The tables are regenerated here from POV-Ray's seeds so that every noise-based pattern matches its images.
#include "function/noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/constants.h"

namespace wardray::function {

namespace {

// POV-Ray's table of 267 lattice coefficients (texture.cpp, RTable; its odd slots hold half the value before).
constexpr std::array<double, 267> kRTable = {
    -1, 0.604974, -0.937102, 0.414115, 0.576226, -0.0161593, 0.432334, 0.103685,
    0.590539, 0.0286412, 0.46981, -0.84622, -0.0734112, -0.304097, -0.40206, -0.210132,
    -0.919127, 0.652033, -0.83151, -0.183948, -0.671107, 0.852476, 0.043595, -0.404532,
    0.75494, -0.335653, 0.618433, 0.605707, 0.708583, -0.477195, 0.899474, 0.490623,
    0.221729, -0.400381, -0.853727, -0.932586, 0.659113, 0.961303, 0.325948, -0.750851,
    0.842466, 0.734401, -0.649866, 0.394491, -0.466056, -0.434073, 0.109026, 0.0847028,
    -0.738857, 0.241505, 0.16228, -0.71426, -0.883665, -0.150408, -0.90396, -0.686549,
    -0.785214, 0.488548, 0.0246433, 0.142473, -0.602136, 0.375845, -0.00779736, 0.498955,
    -0.268147, 0.856382, -0.386007, -0.596094, -0.867735, -0.570977, -0.914366, 0.28896,
    0.672206, -0.233783, 0.94815, 0.895262, 0.343252, -0.173388, -0.767971, -0.314748,
    0.824308, -0.342092, 0.721431, -0.24004, -0.63653, 0.553277, 0.376272, 0.158984,
    -0.452659, 0.396323, -0.420676, -0.454154, 0.122179, 0.295857, 0.0664225, -0.202075,
    -0.724788, 0.453513, 0.224567, -0.908812, 0.176349, -0.320516, -0.697139, 0.742702,
    -0.900786, 0.471489, -0.133532, 0.119127, -0.889769, -0.23183, -0.669673, -0.046891,
    -0.803433, -0.966735, 0.475578, -0.652644, 0.0112459, -0.730007, 0.128283, 0.145647,
    -0.619318, 0.272023, 0.392966, 0.646418, -0.0207675, -0.315908, 0.480797, 0.535668,
    -0.250172, -0.83093, -0.653773, -0.443809, 0.119982, -0.897642, 0.89453, 0.165789,
    0.633875, -0.886839, 0.930877, -0.537194, 0.587732, 0.722011, -0.209461, -0.0424659,
    -0.814267, -0.919432, 0.280262, -0.66302, -0.558099, -0.537469, -0.598779, 0.929656,
    -0.170794, -0.537163, 0.312581, 0.959442, 0.722652, 0.499931, 0.175616, -0.534874,
    -0.685115, 0.444999, 0.17171, 0.108202, -0.768704, -0.463828, 0.254231, 0.546014,
    0.869474, 0.875212, -0.944427, 0.130724, -0.110185, 0.312184, -0.33138, -0.629206,
    0.0606546, 0.722866, -0.0979477, 0.821561, 0.0931258, -0.972808, 0.0318151, -0.867033,
    -0.387228, 0.280995, -0.218189, -0.539178, -0.427359, -0.602075, 0.311971, 0.277974,
    0.773159, 0.592493, -0.0331884, -0.630854, -0.269947, 0.339132, 0.581079, 0.209461,
    -0.317433, -0.284993, 0.181323, 0.341634, 0.804959, -0.229572, -0.758907, -0.336721,
    0.605463, -0.991272, -0.0188754, -0.300191, 0.368307, -0.176135, -0.3832, -0.749569,
    0.62356, -0.573938, 0.278309, -0.971313, 0.839994, -0.830686, 0.439078, 0.66128,
    0.694514, 0.0565042, 0.54342, -0.438804, -0.0228428, -0.687068, 0.857267, 0.301991,
    -0.494255, -0.941039, 0.775509, 0.410575, -0.362081, -0.671534, -0.348379, 0.932433,
    0.886442, 0.868681, -0.225666, -0.062211, -0.0976425, -0.641444, -0.848112, 0.724697,
    0.473503, 0.998749, 0.174701, 0.559625, -0.029099, -0.337392, -0.958129, -0.659785,
    0.236042, -0.246937, 0.659449, -0.027512, 0.821897, -0.226215, 0.0181735, 0.500481,
    -0.420127, -0.427878, 0.566186,
};

// POV-Ray's 32-bit linear congruential generator as written in its noise set-up: x ← x·1812433253 + 12345,
// value bits 16..30.
struct PovLcg {
    std::uint32_t state;
    int next() {
        state = state * 1812433253u + 12345u;
        return static_cast<int>((state >> 16) & 0x7FFFu);
    }
};

// DNoise's coefficients regrouped by hash value h: c[j] = {R[h+j], R[h+4+j], R[h+8+j], 0}, the x, y and z blocks
// side by side, c[0] already halved (0.5·R is exact, and every use halves it).
using Lanes = double __attribute__((vector_size(32)));

struct BlockCoefficients {
    Lanes c[4];
};

struct Tables {
    std::array<unsigned short, 8192> hash{};
    std::array<BlockCoefficients, 256> blocks{};
    // Noise's coefficient row of hash value h: {R[h]/2, R[h+1], R[h+2], R[h+3]}.
    std::array<Lanes, 256> rows{};
    std::array<double, 32768> rands{};
    // Perlin solid noise (generator 3): permutation and unit gradients.
    static constexpr int kEntries = 2048;
    std::array<int, 2 * (kEntries + 1)> perm{};
    std::array<Vec3, 2 * (kEntries + 1)> grad{};
    std::vector<WaveSource> waves;

    Tables() {
        // Hash: a Fisher-Yates style shuffle of 0..4095 driven by the LCG seeded with 0, then duplicated.
        for (int i = 0; i < 4096; ++i) hash[i] = static_cast<unsigned short>(i);
        PovLcg lcg{0};
        for (int i = 4095; i >= 0; --i) std::swap(hash[i], hash[lcg.next() % 4096]);
        for (int i = 0; i < 4096; ++i) hash[4096 + i] = hash[i];

        // POV-Ray compat: PatternRands is boost's uniform_real over mt19937 with its default seed, one 32-bit
        // draw per value: x / 2^32.
        std::mt19937 mt;
        for (double& r : rands) r = static_cast<double>(mt()) / 4294967296.0;

        // Solid noise: random gradients inside the unit ball (rejection), then a pairwise permutation.
        PovLcg g{1};
        for (int i = 0; i < kEntries; ++i) {
            Vec3 v;
            double s = 0.0;
            do {
                for (int j = 0; j < 3; ++j)
                    v[j] = static_cast<double>((g.next() % (kEntries << 1)) - kEntries) / kEntries;
                s = dot(v, v);
            } while (s > 1.0 || s < 1.0e-5);
            grad[i] = v / std::sqrt(s);
        }
        for (int i = 0; i < kEntries; ++i) perm[i] = i;
        for (int i = kEntries; i > 0; i -= 2) {
            const int k = perm[i];
            const int j = g.next() % kEntries;
            perm[i] = perm[j];
            perm[j] = k;
        }
        for (int i = 0; i < kEntries + 2; ++i) {
            perm[kEntries + i] = perm[i];
            grad[kEntries + i] = grad[i];
        }

        for (std::size_t h = 0; h < blocks.size(); ++h) {
            for (std::size_t j = 0; j < 4; ++j) {
                const double scale = j == 0 ? 0.5 : 1.0;
                blocks[h].c[j] =
                    Lanes{scale * kRTable[h + j], scale * kRTable[h + 4 + j], scale * kRTable[h + 8 + j], 0.0};
            }
            rows[h] = Lanes{0.5 * kRTable[h], kRTable[h + 1], kRTable[h + 2], kRTable[h + 3]};
        }
    }
};

const Tables& tables() {
    static const Tables t;
    return t;
}

constexpr double kEpsilon = kPovEpsilon;  // POV-Ray's EPSILON
constexpr int kNoiseMin = -10000;     // POV-Ray's NOISE_MINX/Y/Z

template <typename T>
T s_curve(T t) { return t * t * (3.0 - 2.0 * t); }

// One lattice axis: the wrapped 12-bit cell index and the offset inside the cell.
// POV-Ray compat: negative coordinates round with (int)(x - (1 - EPSILON)), not floor.
// A double outside int's range (or NaN) gives INT_MIN, as x86's conversion that POV-Ray's (int) cast compiles to
// does, instead of undefined behaviour.
int to_int_as_x86(double v) {
#if defined(__SSE2__)
    return _mm_cvttsd_si32(_mm_set_sd(v));  // that conversion itself, without a branch
#else
    constexpr double k_limit = 2147483648.0;  // 2^31
    return v >= -k_limit && v < k_limit ? static_cast<int>(v) : std::numeric_limits<int>::min();
#endif
}

void lattice(double x, int& cell, double& frac) {
    // One conversion of the selected coordinate, so that the sign picks a value instead of a branch to mispredict.
    const int tmp = to_int_as_x86(x >= 0.0 ? x : x - (1.0 - kEpsilon));
    // Unsigned, so the offset by NOISE_MIN wraps instead of overflowing near INT_MAX; the low 12 bits are the same.
    cell = static_cast<int>((static_cast<unsigned>(tmp) - static_cast<unsigned>(kNoiseMin)) & 0xFFFu);
    frac = x - tmp;
}

// The lattice cell around a point as POV-Ray's Noise and DNoise set it up: its z cell, the offsets and s-curve
// weights, and the hashes, weights and offsets of the four corners of a face (index xy: x + 2y).
struct Cell {
    int iz;
    double fz, sz, tz;
    int hxy[4];
    double wxy[4], ox[4], oy[4];
};

inline Cell lattice_cell(const Tables& t, const Vec3& p) {
    Cell c;
    int ix, iy;
    double fx, fy;
    lattice(p.x, ix, fx);
    lattice(p.y, iy, fy);
    lattice(p.z, c.iz, c.fz);
    const double sx = s_curve(fx), sy = s_curve(fy);
    c.sz = s_curve(c.fz);
    const double tx = 1.0 - sx, ty = 1.0 - sy;
    c.tz = 1.0 - c.sz;
    auto hash2 = [&](int a, int b) { return static_cast<int>(t.hash[t.hash[a] ^ b]); };
    const int hxy[4] = {hash2(ix, iy), hash2(ix + 1, iy), hash2(ix, iy + 1), hash2(ix + 1, iy + 1)};
    const double wxy[4] = {tx * ty, sx * ty, tx * sy, sx * sy};
    const double ox[4] = {fx, fx - 1.0, fx, fx - 1.0};
    const double oy[4] = {fy, fy, fy - 1.0, fy - 1.0};
    for (int i = 0; i < 4; ++i) {
        c.hxy[i] = hxy[i];
        c.wxy[i] = wxy[i];
        c.ox[i] = ox[i];
        c.oy[i] = oy[i];
    }
    return c;
}

// POV-Ray's noise sums over the eight corners of the lattice cell around `p` (corner k: face k / 4, xy k mod 4,
// POV-Ray's order), each corner adding weight · (R[h]/2 + R[h+1]·dx + R[h+2]·dy + R[h+3]·dz).
inline double corner_sum(const Vec3& p) {
    const Tables& t = tables();
    const Cell cell = lattice_cell(t, p);
    double sum = 0.0;
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
        const int xy = k & 3;
        const bool upper = k >= 4;
        const int h = t.hash[cell.hxy[xy] ^ (upper ? cell.iz + 1 : cell.iz)] & 0xFF;
        const double weight = cell.wxy[xy] * (upper ? cell.sz : cell.tz);
        const double dz = upper ? cell.fz - 1.0 : cell.fz;
        const Lanes& r = t.rows[static_cast<std::size_t>(h)];
        sum += weight * (r[0] + r[1] * cell.ox[xy] + r[2] * cell.oy[xy] + r[3] * dz);
    }
    return sum;
}

// Two doubles side by side (GCC's vector extension, one SSE2 register): lane i belongs to point i of a pair.
using Pair = double __attribute__((vector_size(16)));
using PairIndex = long long __attribute__((vector_size(16)));

inline Pair load_pair(const double* p) {
    Pair v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// corner_sum of two points at once: each lane does exactly corner_sum's operations in its order, so both sums are
// the same to the bit; the pair only shares the instructions (noise is bound by its instruction count, not by the
// latency of one evaluation).
inline Pair corner_sum_pair(const Vec3& p0, const Vec3& p1) {
    const Tables& t = tables();
    int ix[2], iy[2], iz[2];
    double fx[2], fy[2], fz[2];
    for (int i = 0; i < 2; ++i) {
        const Vec3& p = i ? p1 : p0;
        lattice(p.x, ix[i], fx[i]);
        lattice(p.y, iy[i], fy[i]);
        lattice(p.z, iz[i], fz[i]);
    }
    const Pair px = {fx[0], fx[1]}, py = {fy[0], fy[1]}, pz = {fz[0], fz[1]};
    const Pair sx = s_curve(px), sy = s_curve(py), sz = s_curve(pz);
    const Pair tx = 1.0 - sx, ty = 1.0 - sy, tz = 1.0 - sz;
    auto hash2 = [&](int a, int b) { return static_cast<int>(t.hash[t.hash[a] ^ b]); };
    int hxy[2][4];
    for (int i = 0; i < 2; ++i) {
        hxy[i][0] = hash2(ix[i], iy[i]);
        hxy[i][1] = hash2(ix[i] + 1, iy[i]);
        hxy[i][2] = hash2(ix[i], iy[i] + 1);
        hxy[i][3] = hash2(ix[i] + 1, iy[i] + 1);
    }
    const Pair wxy[4] = {tx * ty, sx * ty, tx * sy, sx * sy};
    const Pair ox[4] = {px, px - 1.0, px, px - 1.0};
    const Pair oy[4] = {py, py, py - 1.0, py - 1.0};
    Pair sum = {0.0, 0.0};
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
        const int xy = k & 3;
        const bool upper = k >= 4;
        const int h0 = t.hash[hxy[0][xy] ^ (upper ? iz[0] + 1 : iz[0])] & 0xFF;
        const int h1 = t.hash[hxy[1][xy] ^ (upper ? iz[1] + 1 : iz[1])] & 0xFF;
        // The two points' coefficient rows, turned into columns {R0 of point 0, R0 of point 1}, ...
        const double* r0 = reinterpret_cast<const double*>(&t.rows[static_cast<std::size_t>(h0)]);
        const double* r1 = reinterpret_cast<const double*>(&t.rows[static_cast<std::size_t>(h1)]);
        const Pair a01 = load_pair(r0), a23 = load_pair(r0 + 2), b01 = load_pair(r1), b23 = load_pair(r1 + 2);
        const Pair c0 = __builtin_shuffle(a01, b01, PairIndex{0, 2});
        const Pair c1 = __builtin_shuffle(a01, b01, PairIndex{1, 3});
        const Pair c2 = __builtin_shuffle(a23, b23, PairIndex{0, 2});
        const Pair c3 = __builtin_shuffle(a23, b23, PairIndex{1, 3});
        const Pair weight = wxy[xy] * (upper ? sz : tz);
        sum += weight * (c0 + c1 * ox[xy] + c2 * oy[xy] + c3 * (upper ? pz - 1.0 : pz));
    }
    return sum;
}

// DNoise's three corner sums side by side: lane b adds, corner by corner in POV-Ray's order, exactly the terms
// weight · (R[h+4b]/2 + R[h+4b+1]·dx + R[h+4b+2]·dy + R[h+4b+3]·dz) that POV-Ray adds to its component b, so each
// component is POV-Ray's to the bit, with a third of the loads and arithmetic of one block at a time.
// Four lanes (x, y, z, unused) in one AVX register; the default build pairs x and y and adds z alone.

[[gnu::target("avx2"), gnu::always_inline]] inline Lanes dnoise_avx2(const Vec3& p) {
    const Tables& t = tables();
    const Cell cell = lattice_cell(t, p);
    Lanes sum = {0.0, 0.0, 0.0, 0.0};
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
        const int xy = k & 3;
        const bool upper = k >= 4;
        const int h = t.hash[cell.hxy[xy] ^ (upper ? cell.iz + 1 : cell.iz)] & 0xFF;
        const double weight = cell.wxy[xy] * (upper ? cell.sz : cell.tz);
        const double dz = upper ? cell.fz - 1.0 : cell.fz;
        const Lanes* c = t.blocks[static_cast<std::size_t>(h)].c;
        sum += weight * (c[0] + c[1] * cell.ox[xy] + c[2] * cell.oy[xy] + c[3] * dz);
    }
    return sum;
}

[[gnu::always_inline]] inline Vec3 dnoise_sse2(const Vec3& p) {
    const Tables& t = tables();
    const Cell cell = lattice_cell(t, p);
    Pair sum_xy = {0.0, 0.0};
    double sum_z = 0.0;
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
        const int xy = k & 3;
        const bool upper = k >= 4;
        const int h = t.hash[cell.hxy[xy] ^ (upper ? cell.iz + 1 : cell.iz)] & 0xFF;
        const double weight = cell.wxy[xy] * (upper ? cell.sz : cell.tz);
        const double dx = cell.ox[xy], dy = cell.oy[xy], dz = upper ? cell.fz - 1.0 : cell.fz;
        const Lanes* c = t.blocks[static_cast<std::size_t>(h)].c;
        auto low = [&](int j) { return load_pair(reinterpret_cast<const double*>(&c[j])); };
        sum_xy += weight * (low(0) + low(1) * dx + low(2) * dy + low(3) * dz);
        sum_z += weight * (c[0][2] + c[1][2] * dx + c[2][2] * dy + c[3][2] * dz);
    }
    return {sum_xy[0], sum_xy[1], sum_z};
}

using LaneIndex = long long __attribute__((vector_size(32)));

// Rows a, b, c, d of four doubles each, as four columns (col[i] = {a[i], b[i], c[i], d[i]}).
[[gnu::target("avx2"), gnu::always_inline]] inline void transpose(Lanes a, Lanes b, Lanes c, Lanes d, Lanes (&col)[4]) {
    const Lanes ab_even = __builtin_shuffle(a, b, LaneIndex{0, 4, 2, 6});
    const Lanes ab_odd = __builtin_shuffle(a, b, LaneIndex{1, 5, 3, 7});
    const Lanes cd_even = __builtin_shuffle(c, d, LaneIndex{0, 4, 2, 6});
    const Lanes cd_odd = __builtin_shuffle(c, d, LaneIndex{1, 5, 3, 7});
    col[0] = __builtin_shuffle(ab_even, cd_even, LaneIndex{0, 1, 4, 5});
    col[1] = __builtin_shuffle(ab_odd, cd_odd, LaneIndex{0, 1, 4, 5});
    col[2] = __builtin_shuffle(ab_even, cd_even, LaneIndex{2, 3, 6, 7});
    col[3] = __builtin_shuffle(ab_odd, cd_odd, LaneIndex{2, 3, 6, 7});
}

// Noise's corner sums of four points at once, lane i for p[i]: each lane does exactly corner_sums' operations
// in its order (the rows' first coefficients come halved, as corner_sums halves them), so each sum is the same
// to the bit.
[[gnu::target("avx2"), gnu::always_inline]] inline Lanes noise_sums_avx2(const Vec3* p) {
    const Tables& t = tables();
    int ix[4], iy[4], iz[4];
    double fx[4], fy[4], fz[4];
    for (int i = 0; i < 4; ++i) {
        lattice(p[i].x, ix[i], fx[i]);
        lattice(p[i].y, iy[i], fy[i]);
        lattice(p[i].z, iz[i], fz[i]);
    }
    const Lanes px = {fx[0], fx[1], fx[2], fx[3]}, py = {fy[0], fy[1], fy[2], fy[3]};
    const Lanes pz = {fz[0], fz[1], fz[2], fz[3]};
    // s_curve, written out: a template instantiated for Lanes would be compiled without AVX.
    const Lanes sx = px * px * (3.0 - 2.0 * px), sy = py * py * (3.0 - 2.0 * py), sz = pz * pz * (3.0 - 2.0 * pz);
    const Lanes tx = 1.0 - sx, ty = 1.0 - sy, tz = 1.0 - sz;
    auto hash2 = [&](int a, int b) { return static_cast<int>(t.hash[t.hash[a] ^ b]); };
    int hxy[4][4];
    for (int i = 0; i < 4; ++i) {
        hxy[i][0] = hash2(ix[i], iy[i]);
        hxy[i][1] = hash2(ix[i] + 1, iy[i]);
        hxy[i][2] = hash2(ix[i], iy[i] + 1);
        hxy[i][3] = hash2(ix[i] + 1, iy[i] + 1);
    }
    const Lanes wxy[4] = {tx * ty, sx * ty, tx * sy, sx * sy};
    const Lanes ox[4] = {px, px - 1.0, px, px - 1.0};
    const Lanes oy[4] = {py, py, py - 1.0, py - 1.0};
    Lanes sum = {0.0, 0.0, 0.0, 0.0};
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
        const int xy = k & 3;
        const bool upper = k >= 4;
        Lanes r[4];
        for (int i = 0; i < 4; ++i) {
            const int h = t.hash[hxy[i][xy] ^ (upper ? iz[i] + 1 : iz[i])] & 0xFF;
            r[i] = t.rows[static_cast<std::size_t>(h)];
        }
        Lanes c[4];
        transpose(r[0], r[1], r[2], r[3], c);
        const Lanes weight = wxy[xy] * (upper ? sz : tz);
        const Lanes dz = upper ? pz - 1.0 : pz;
        sum += weight * (c[0] + c[1] * ox[xy] + c[2] * oy[xy] + c[3] * dz);
    }
    return sum;
}

// Whether the processor has AVX2, and whether the noise functions use their AVX2 builds (by default where it has).
bool probe_avx2() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2");
}
bool g_avx2 = probe_avx2();

[[gnu::target("avx2")]] Vec3 dnoise_avx2_vec(const Vec3& p) {
    const Lanes d = dnoise_avx2(p);
    return {d[0], d[1], d[2]};
}

[[gnu::target("avx2")]] Vec3 dturbulence_avx2(const Vec3& p, const TurbulenceParams& t) {
    // The octaves are independent until they are added, so the processor overlaps their evaluations.
    Lanes result = dnoise_avx2(p);
    double l = t.lambda;
    double o = t.omega;
    for (int i = 2; i <= t.octaves; ++i) {
        result += o * dnoise_avx2(p * l);
        if (i < t.octaves) {
            l *= t.lambda;
            o *= t.omega;
        }
    }
    return {result[0], result[1], result[2]};
}

Vec3 dturbulence_sse2(const Vec3& p, const TurbulenceParams& t) {
    Vec3 result = dnoise_sse2(p);
    double l = t.lambda;
    double o = t.omega;
    for (int i = 2; i <= t.octaves; ++i) {
        result += o * dnoise_sse2(p * l);
        if (i < t.octaves) {
            l *= t.lambda;
            o *= t.omega;
        }
    }
    return result;
}

// Perlin's gradient noise (Perlin 1989, "Hypertexture"), POV-Ray's SolidNoise, about -1..1.
double solid_noise(const Vec3& p) {
    const Tables& t = tables();
    constexpr double kRollover = 10000000.023157213;
    int b0[3], b1[3];
    double r0[3], r1[3];
    for (int a = 0; a < 3; ++a) {
        const double v = p[a] + kRollover;
        const int it = to_int_as_x86(std::floor(v));
        b0[a] = it & (Tables::kEntries - 1);
        b1[a] = (b0[a] + 1) & (Tables::kEntries - 1);
        r0[a] = v - it;
        r1[a] = r0[a] - 1.0;
    }
    const int i = t.perm[b0[0]], j = t.perm[b1[0]];
    const int b00 = t.perm[i + b0[1]], b10 = t.perm[j + b0[1]], b01 = t.perm[i + b1[1]], b11 = t.perm[j + b1[1]];
    const double sx = s_curve(r0[0]), sy = s_curve(r0[1]), sz = s_curve(r0[2]);
    auto at = [&](int idx, double rx, double ry, double rz) { return dot(t.grad[idx], Vec3{rx, ry, rz}); };
    auto lerp = [](double s, double a, double b) { return a + s * (b - a); };
    double layer[2];
    for (int k = 0; k < 2; ++k) {
        const int bz = k ? b1[2] : b0[2];
        const double rz = k ? r1[2] : r0[2];
        const double a = lerp(sx, at(b00 + bz, r0[0], r0[1], rz), at(b10 + bz, r1[0], r0[1], rz));
        const double b = lerp(sx, at(b01 + bz, r0[0], r1[1], rz), at(b11 + bz, r1[0], r1[1], rz));
        layer[k] = lerp(sy, a, b);
    }
    return lerp(sz, layer[0], layer[1]);
}

}  // namespace

namespace {

// POV-Ray's Noise from its corner sum: generator 2 stretches the measured range -1.05242..0.988997 onto [0, 1]
// (POV-Ray compat), the others add 0.5; both clamp.
double noise_from_sum(double sum, int generator) {
    if (generator == 2) {
        sum = (sum + 1.05242) * 0.48985582;
    } else {
        sum += 0.5;
    }
    return std::clamp(sum, 0.0, 1.0);
}

// fBm's octaves, a few at a time: calls points(first, count, q) for the octave points q of octaves first ..
// first + count - 1 (1-based), then octave(k, i) for each octave k in order with its index i into q's results.
constexpr int kOctaveChunk = 8;

template <typename Points, typename Octave>
void for_octaves(int octaves, Points points, Octave octave) {
    for (int first = 1; first <= octaves; first += kOctaveChunk) {
        const int count = std::min(kOctaveChunk, octaves - first + 1);
        points(first, count);
        for (int j = 0; j < count; ++j) octave(first + j, j);
    }
}

}  // namespace

double noise(const Vec3& p, int generator) {
    if (generator == 3) {
        // POV-Ray compat: 1.59 and 0.985 re-centre Perlin's noise on [0, 1].
        return std::clamp(0.5 * (1.59 * solid_noise(p) + 0.985), 0.0, 1.0);
    }
    return noise_from_sum(corner_sum(p), generator);
}

namespace {

// noise_batch four points at a time, for processors with AVX2 (the rest as noise_batch does it).
[[gnu::target("avx2")]] std::size_t noise_batch_avx2(const Vec3* p, std::size_t count, int generator, double* out) {
    std::size_t i = 0;
    for (; i + 3 < count; i += 4) {
        const Lanes sums = noise_sums_avx2(p + i);
        for (std::size_t j = 0; j < 4; ++j) out[i + j] = noise_from_sum(sums[j], generator);
    }
    return i;
}

}  // namespace

void noise_batch(const Vec3* p, std::size_t count, int generator, double* out) {
    std::size_t i = 0;
    if (generator != 3) {
        if (g_avx2) i = noise_batch_avx2(p, count, generator, out);
        for (; i + 1 < count; i += 2) {
            const Pair sums = corner_sum_pair(p[i], p[i + 1]);
            out[i] = noise_from_sum(sums[0], generator);
            out[i + 1] = noise_from_sum(sums[1], generator);
        }
    }
    for (; i < count; ++i) out[i] = noise(p[i], generator);
}

Vec3 dnoise(const Vec3& p) { return g_avx2 ? dnoise_avx2_vec(p) : dnoise_sse2(p); }

double turbulence(const Vec3& p, const TurbulenceParams& t, int generator) {
    // fBm: Σ omega^i · noise(lambda^i · p); generators 2 and 3 remap each octave by 2n − 0.5 (the first clamped).
    // The octaves' noises are evaluated a few at a time, then added in order with the same lambda and omega
    // products as one octave at a time.
    const int octaves = std::max(t.octaves, 1);
    Vec3 q[kOctaveChunk];
    double n[kOctaveChunk];
    double value = 0.0;
    double l = t.lambda;
    double o = t.omega;
    auto points = [&](int first, int count) {
        for (int j = 0; j < count; ++j) {
            const int k = first + j;
            q[j] = k == 1 ? p : p * l;
            if (k > 1 && k < octaves) l *= t.lambda;
        }
        noise_batch(q, static_cast<std::size_t>(count), generator, n);
    };
    auto octave = [&](int k, int j) {
        if (k == 1) {
            value = generator > 1 ? std::clamp(2.0 * n[j] - 0.5, 0.0, 1.0) : n[j];
            return;
        }
        value += o * (generator > 1 ? 2.0 * n[j] - 0.5 : n[j]);
        if (k < octaves) o *= t.omega;
    };
    for_octaves(octaves, points, octave);
    return value;
}

Vec3 dturbulence(const Vec3& p, const TurbulenceParams& t) {
    return g_avx2 ? dturbulence_avx2(p, t) : dturbulence_sse2(p, t);
}

void use_avx2_noise(bool on) { g_avx2 = on && probe_avx2(); }

int hash3d(int a, int b, int c) {
    const auto& h = tables().hash;
    return h[h[h[a & 0xFFF] ^ (b & 0xFFF)] ^ (c & 0xFFF)];
}

double pattern_rand(std::size_t i) { return tables().rands[i % 32768]; }

namespace {

std::vector<WaveSource> make_wave_sources(int count) {
    std::vector<WaveSource> w;
    // POV-Ray's Initialize_Waves: centres from DNoise at (i, 0, 0), frequencies from an LCG.
    PovLcg lcg{static_cast<std::uint32_t>(-560851967)};
    for (int i = 0; i < count; ++i) {
        WaveSource s;
        s.center = normalize(dnoise(Vec3{static_cast<double>(i), 0.0, 0.0}));
        s.frequency = lcg.next() * 0.000030518509476 + 0.01;
        w.push_back(s);
    }
    return w;
}

std::vector<WaveSource>& current_wave_sources() {
    static std::vector<WaveSource> sources = make_wave_sources(10);
    return sources;
}

}  // namespace

const std::vector<WaveSource>& wave_sources() { return current_wave_sources(); }

void set_number_of_waves(int count) {
    std::vector<WaveSource>& sources = current_wave_sources();
    if (static_cast<int>(sources.size()) != count) sources = make_wave_sources(count);
}

}  // namespace wardray::function
