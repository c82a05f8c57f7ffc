// Ground fog: POV-Ray 3.7's closed-form mean density of fog_type 2 along a ray segment.
#include "media/ground_fog.h"

#include <cmath>

#include "core/constants.h"

namespace wardray::media {

double ground_fog_density(double start, double end) {
    // ∫ density dh over [start, end] divided by (end − start): below 0 the density is 1 (the integral is h), above
    // it 1/(1 + h²) (the integral is atan h).
    if (start <= 0.0) return end <= 0.0 ? 1.0 : (std::atan(end) - start) / (end - start);
    if (end <= 0.0) return (std::atan(start) - end) / (start - end);
    const double delta = start - end;
    // POV-Ray compat: a segment level to within EPSILON takes the density at its start.
    if (std::fabs(delta) > kPovEpsilon) return (std::atan(start) - std::atan(end)) / delta;
    return 1.0 / (start * start + 1.0);
}

}  // namespace wardray::media
