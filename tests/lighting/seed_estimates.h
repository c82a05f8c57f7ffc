// The mean and variance over render seeds of one estimate, for the reference paths' expectation tests.
#pragma once

#include <cstdint>
#include <vector>

namespace wardray::lighting {

struct Estimates {
    double mean = 0.0;
    double variance = 0.0;
};

/// `estimate(seed)` for seeds 1 to `seeds`: their mean and their sample variance.
template <typename Estimate>
Estimates over_seeds(int seeds, Estimate&& estimate) {
    Estimates e;
    std::vector<double> values;
    for (int s = 1; s <= seeds; ++s) {
        values.push_back(estimate(static_cast<std::uint64_t>(s)));
        e.mean += values.back() / seeds;
    }
    for (double v : values) e.variance += (v - e.mean) * (v - e.mean) / (seeds - 1);
    return e;
}

}  // namespace wardray::lighting
