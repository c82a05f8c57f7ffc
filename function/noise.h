// Noise: POV-Ray 3.7's lattice noise, its vector form, turbulence and the pattern random table, bit for bit
// (in function/ because the internal functions of functions.inc use it as the patterns do).
#pragma once

#include <cstddef>
#include <vector>

#include "core/vec3.h"

namespace wardray::function {

/// fBm parameters of POV-Ray's `turbulence` (octaves, omega, lambda keep POV-Ray's defaults).
struct TurbulenceParams {
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
};

/// POV-Ray's scalar `Noise(p, noise_generator)` in [0, 1]: generator 1 (original), 2 (range corrected, the 3.7
/// default) or 3 (Perlin's solid noise).
double noise(const Vec3& p, int generator);

/// noise(p[i], generator) into out[i] for each i < count: the same values to the bit, several points sharing
/// the instructions (patterns that sum octaves of noise call this once instead of noise per octave).
void noise_batch(const Vec3* p, std::size_t count, int generator, double* out);

/// POV-Ray's vector `DNoise(p)`: each component a lattice noise without offset or clamping (about -1..1).
Vec3 dnoise(const Vec3& p);

/// POV-Ray's scalar `Turbulence`: a sum of octaves of noise (Perlin 1985, fBm), generator-specific remapping.
double turbulence(const Vec3& p, const TurbulenceParams& t, int generator);

/// POV-Ray's `DTurbulence`: the vector fBm used to displace points.
Vec3 dturbulence(const Vec3& p, const TurbulenceParams& t);

/// Whether noise_batch, dnoise, turbulence and dturbulence use their AVX2 builds (the default on a processor that
/// has AVX2) or their SSE2 builds; both give the same bits, which a test checks by switching. Not thread-safe.
void use_avx2_noise(bool on);

/// POV-Ray's `Hash3d`: the 12-bit hash of an integer lattice cell.
int hash3d(int a, int b, int c);

/// POV-Ray's `PatternRands(i)`: entry i mod 32768 of a fixed table of uniform doubles in [0, 1).
double pattern_rand(std::size_t i);

/// Centre and relative frequency of one of POV-Ray's wave sources (used by `ripples` and `waves`).
struct WaveSource {
    Vec3 center;
    double frequency = 1.0;
};

/// The wave sources exactly as POV-Ray makes them (Initialize_Waves) for the scene's `number_of_waves`, 10 unless
/// set_number_of_waves said otherwise.
const std::vector<WaveSource>& wave_sources();

/// Makes wave_sources() give POV-Ray's first `count` sources (global_settings { number_of_waves }). Not
/// thread-safe: call it before rendering (the integrator does, from the scene's setting).
void set_number_of_waves(int count);

}  // namespace wardray::function
