// Blob surfaces: component texture weights from the densities of geometry::BlobShape.
#include "lighting/blob_texture.h"

#include <algorithm>
#include <optional>

#include "geometry/blob.h"

namespace wardray::lighting {

namespace {

// The blob's elements, rebuilt only when a thread meets a blob of other components than the last one it shaded.
const geometry::BlobShape* shape_of(const scene::Blob& blob) {
    thread_local double threshold = 0.0;
    thread_local std::vector<scene::Blob::Component> components;
    thread_local std::optional<geometry::BlobShape> shape;
    thread_local bool built = false;
    if (!built || threshold != blob.threshold || components != blob.components) {
        threshold = blob.threshold;
        components = blob.components;
        shape = geometry::BlobShape::create(blob);
        built = true;
    }
    return shape ? &*shape : nullptr;
}

}  // namespace

void blob_textures(const scene::Blob& blob, const scene::Texture& own, const Vec3& p_world,
                   WeightedTextures& out) {
    out.clear();
    const geometry::BlobShape* shape = shape_of(blob);
    if (shape == nullptr) return;
    thread_local std::vector<double> density;
    shape->component_densities(blob.placement->inverse_point(p_world), density);
    double sum = 0.0;
    for (std::size_t i = 0; i < density.size(); ++i) {
        if (!(density[i] > 0.0)) continue;
        const int k = blob.components[i].texture;
        const scene::Texture* tx = k >= 0 ? &blob.textures[static_cast<std::size_t>(k)] : &own;
        // Components showing one texture add their weights: the colour is linear in them.
        const auto same = std::find_if(out.begin(), out.end(), [tx](const WeightedTexture& w) { return w.first == tx; });
        if (same != out.end()) same->second += density[i];
        else out.emplace_back(tx, density[i]);
        sum += density[i];
    }
    for (WeightedTexture& w : out) w.second /= sum;
}

}  // namespace wardray::lighting
