// The `function { ... }` pattern on the function VM.
#include "texture/function_pattern.h"

#include <array>
#include <cmath>

namespace wardray::texture {

double function_pattern(const scene::Pattern& pattern, const Vec3& p, int generator) {
    if (!pattern.params->function) return 0.0;
    const std::array<double, 3> args{p.x, p.y, p.z};
    const double value = pattern.params->function->evaluate(args, function::EvalContext{generator});
    // POV-Ray compat: only values above 1 are reduced here; negative ones fold later with the others.
    return value > 1.0 ? std::fmod(value, 1.0) : value;
}

}  // namespace wardray::texture
