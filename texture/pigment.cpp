// Pigment evaluation: pattern value, then colour-map or pigment-map lookup with linear blending (POV-Ray 3.7).
#include "texture/pigment.h"

#include "texture/image_map.h"
#include "texture/pattern.h"

namespace wardray::texture {

namespace {

// POV-Ray's Do_Average_Pigments (PigmentBlendMap::ComputeAverage): the entries' colours weighted by their map values,
// in single precision as POV-Ray's colours are. The last bit matters: six weights of 1/6 averaging white give 1
// there, where double sums give 1 + 1e-7, which a function pattern reading the colour wraps to 0.
Color average_pigments(const std::vector<scene::PigmentMapEntry>& map, const Vec3& tp, int noise_generator,
                       const SurfacePoint* surface) {
    float sum[5] = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    float total = 0.0f;
    for (const scene::PigmentMapEntry& e : map) {
        const Color c = evaluate_pigment(e.pigment, tp, noise_generator, surface);
        const float w = static_cast<float>(e.value);
        const double channels[5] = {c.r, c.g, c.b, c.filter, c.transmit};
        for (int i = 0; i < 5; ++i) sum[i] += w * static_cast<float>(channels[i]);
        total += w;
    }
    return {sum[0] / total, sum[1] / total, sum[2] / total, sum[3] / total, sum[4] / total};
}

}  // namespace

Color evaluate_patterned_pigment(const scene::Pigment& pigment, const Vec3& p, int noise_generator,
                                 const SurfacePoint* surface) {
    const Vec3 tp = warp_point(pigment.pattern, p);
    if (pigment.image_map) return image_map_color(*pigment.image_map, tp);
    if (pigment.pattern.type == scene::Pattern::Type::Average && !pigment.pigment_map.empty())
        return average_pigments(pigment.pigment_map, tp, noise_generator, surface);
    const double value = pattern_value(pigment.pattern, tp, noise_generator, surface);
    if (!pigment.pigment_map.empty()) {
        // POV-Ray compat: map entries are evaluated at the parent's warped point (they live in its space).
        const auto& map = pigment.pigment_map;
        const MapLookup m = search_map(value, static_cast<int>(map.size()), [&](int i) { return map[i].value; });
        const Color cur = evaluate_pigment(map[m.cur].pigment, tp, noise_generator, surface);
        if (m.prev == m.cur) return cur;
        const Color prev = evaluate_pigment(map[m.prev].pigment, tp, noise_generator, surface);
        return lerp(prev, cur, m.fraction);
    }
    const auto& map = pigment.color_map;
    if (map.empty()) return pigment.color;
    const MapLookup m = search_map(value, static_cast<int>(map.size()), [&](int i) { return map[i].value; });
    if (m.prev == m.cur) return map[m.cur].color;
    return lerp(map[m.prev].color, map[m.cur].color, m.fraction);
}

}  // namespace wardray::texture
