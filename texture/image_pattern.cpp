// The image_pattern pattern as POV-Ray 3.7's image_pattern computes it: an image's grey level as a pattern value.
#include <algorithm>

#include "texture/image_map.h"
#include "texture/pigment.h"

namespace wardray::texture {

double image_pattern_pattern(const scene::Pattern& pat, const Vec3& p, int) {
    if (!pat.params->image) return 0.0;
    double x = 0.0, y = 0.0;
    if (!image_position(*pat.params->image, p, x, y)) return 0.0;
    int index = -1;
    const Color c = image_color_at(*pat.params->image, x, y, index);
    // POV-Ray compat: use_index still takes the grey level (its Use flag is never 0 here); use_alpha takes the
    // transmit of an image with alpha (its alpha channel's or its palette's), the red channel of one without.
    const bool transparency = pat.params->image->image && pat.params->image->image->has_alpha;
    const double value = !pat.params->image->use_alpha ? grey(c.rgb()) : transparency ? c.transmit : c.r;
    return std::clamp(value, 0.0, 1.0);
}

}  // namespace wardray::texture
