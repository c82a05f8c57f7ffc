// Blob surfaces: the component textures a blob shows at a point, weighted by the components' densities there.
#pragma once

#include <utility>

#include <boost/container/small_vector.hpp>

#include "core/vec3.h"
#include "scene/object.h"

namespace wardray::lighting {

/// A texture and its share of a surface point's colour.
using WeightedTexture = std::pair<const scene::Texture*, double>;
/// The textures of one surface point: a few, kept on the stack (shading recurses, so no thread-local list will do).
using WeightedTextures = boost::container::small_vector<WeightedTexture, 8>;

/// The textures a blob with component textures shows at the world point `p_world` (POV-Ray's
/// Blob::Determine_Textures): each component's texture (`own`, the object's, for a component without one) weighted
/// by its absolute density there, the weights summing to 1, one entry per distinct texture. Empty when no
/// component reaches the point.
void blob_textures(const scene::Blob& blob, const scene::Texture& own, const Vec3& p_world,
                   WeightedTextures& out);

}  // namespace wardray::lighting
