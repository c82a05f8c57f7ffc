// CacheCarry: the previous frame's records into the next frame's cache, less those near what moved.
#include "app/cache_carry.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "geometry/object_query.h"

namespace wardray::app {

namespace {

// A box around what changed: one object's extent in one frame.
struct ChangedBox {
    Vec3 lo, hi;
};

// The distance from `p` to the box (0 inside it).
double distance_to(const ChangedBox& b, const Vec3& p) {
    const Vec3 d{std::max({b.lo.x - p.x, 0.0, p.x - b.hi.x}), std::max({b.lo.y - p.y, 0.0, p.y - b.hi.y}),
                 std::max({b.lo.z - p.z, 0.0, p.z - b.hi.z})};
    return length(d);
}

// The boxes of the objects that differ between the frames (compared by index, in both frames' places); false
// when one of them has no finite extent, so no record can be shown to be clear of it.
bool changed_boxes(const scene::Scene& before, const scene::Scene& after, std::vector<ChangedBox>& boxes) {
    const geometry::ObjectQuery query;
    const std::size_t n = std::max(before.objects.size(), after.objects.size());
    for (std::size_t i = 0; i < n; ++i) {
        const scene::Object* a = i < before.objects.size() ? &before.objects[i] : nullptr;
        const scene::Object* b = i < after.objects.size() ? &after.objects[i] : nullptr;
        if (a && b && *a == *b) continue;
        for (const scene::Object* o : {a, b}) {
            if (!o) continue;
            const auto extent = query.extent(*o);
            if (!extent) return false;
            const auto [lo, hi] = *extent;
            const Vec3 span = hi - lo;
            if (!std::isfinite(span.x) || !std::isfinite(span.y) || !std::isfinite(span.z) || span.x > 1e15 ||
                span.y > 1e15 || span.z > 1e15)
                return false;
            boxes.push_back({lo, hi});
        }
    }
    return true;
}

}  // namespace

std::optional<std::pair<std::size_t, std::size_t>> CacheCarry::start(const scene::Scene& scene,
                                                                     cache::IrradianceCache& cache) const {
    if (!active() || !m_previous) return std::nullopt;
    std::istringstream in(m_records);
    try {
        cache.load(in);
    } catch (const cache::CacheFileError&) {
        return std::nullopt;  // the frames' radiosity blocks differ in depth count: start afresh
    }
    std::size_t total = 0;
    for (int d = 0; d < cache.depth_count(); ++d) total += cache.records(d).size();
    if (m_mode == CarryMode::All) return std::make_pair(total, std::size_t{0});
    const scene::Scene& before = *m_previous;
    std::vector<ChangedBox> boxes;
    // Indirect light depends on every light, the sky and the radiosity settings: a change there voids every record.
    const bool lighting_same = before.lights == scene.lights && before.background == scene.background &&
                               before.sky_sphere == scene.sky_sphere && before.global.radiosity == scene.global.radiosity;
    if (!lighting_same || !changed_boxes(before, scene, boxes)) {
        const std::size_t dropped = cache.keep_records([](const cache::IrradianceRecord&) { return false; });
        return std::make_pair(std::size_t{0}, dropped);
    }
    // A box of half-diagonal r at distance d covers about π r² / d² of the hemisphere's 2π: a record is kept when
    // every changed box is farther than r / sqrt(2 · share).
    const double factor = 1.0 / std::sqrt(2.0 * kChangedShare);
    const std::size_t dropped = cache.keep_records([&](const cache::IrradianceRecord& r) {
        for (const ChangedBox& b : boxes)
            if (distance_to(b, r.position) < 0.5 * length(b.hi - b.lo) * factor) return false;
        return true;
    });
    return std::make_pair(total - dropped, dropped);
}

void CacheCarry::finish(const scene::Scene& scene, const cache::IrradianceCache& cache) {
    if (!active()) return;
    std::ostringstream out;
    cache.save(out);
    m_records = out.str();
    m_previous = scene;
}

}  // namespace wardray::app
