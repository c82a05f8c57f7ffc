// Pigment evaluation: pattern value, then colour-map or pigment-map lookup with linear blending (POV-Ray 3.7).
#include "texture/pigment.h"

#include "texture/image_map.h"
#include "texture/pattern.h"

namespace wardray::texture {

namespace {

// POV-Ray's Do_Average_Pigments: the entries' colours weighted by their map values (summed in single precision).
Color average_pigments(const std::vector<scene::PigmentMapEntry>& map, const Vec3& tp, int noise_generator,
                       const SurfacePoint* surface) {
    Color sum{0.0, 0.0, 0.0, 0.0, 0.0};
    float total = 0.0f;
    for (const scene::PigmentMapEntry& e : map) {
        const Color c = evaluate_pigment(e.pigment, tp, noise_generator, surface);
        sum = {sum.r + c.r * e.value, sum.g + c.g * e.value, sum.b + c.b * e.value,
               sum.filter + c.filter * e.value, sum.transmit + c.transmit * e.value};
        total += static_cast<float>(e.value);
    }
    const double t = total;
    return {sum.r / t, sum.g / t, sum.b / t, sum.filter / t, sum.transmit / t};
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
