// The render's seed (--seed): one number that changes every stochastic part of a render, each still a fixed
// function of what it samples, so the image stays the same for any thread count.
#pragma once

#include <cstdint>

namespace wardray {

/// A random stream's seed `value` turned by the render seed `seed`: seed 0 leaves it as it is (the images without
/// --seed), any other seed XORs in its SplitMix64 finaliser (Steele, Lea & Flood 2014), an unrelated stream.
constexpr std::uint64_t reseed(std::uint64_t value, std::uint64_t seed) {
    if (seed == 0) return value;
    std::uint64_t z = seed * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return value ^ z ^ (z >> 31);
}

}  // namespace wardray
