// Random: the photon pass's deterministic random numbers (SplitMix64, Steele et al. 2014), one stream per seed, so
// every photon's jitter depends on what it is, never on the thread that shoots it.
#pragma once

#include <cstdint>

namespace wardray::photons {

/// A SplitMix64 stream.
class Random {
public:
    explicit Random(std::uint64_t seed) : m_state(seed) {}

    /// The next 64 random bits.
    std::uint64_t next() {
        std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1).
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [0, n) for n > 0.
    int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }

private:
    std::uint64_t m_state;
};

/// Mixes several values into one seed.
inline std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b) {
    Random r(a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull));
    return r.next();
}

}  // namespace wardray::photons
