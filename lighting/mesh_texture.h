// Mesh surfaces: uv coordinates from uv_vectors and the per-triangle textures of mesh and mesh2.
#pragma once

#include <array>

#include "geometry/scene_geometry.h"
#include "scene/object.h"

namespace wardray::lighting {

/// The (u, v, 0) of a mesh hit, interpolated from its corners' uv_vectors (POV-Ray's Mesh::UVCoord: the
/// barycentric weights of the point); corners without uv_vectors are at (0, 0).
Vec3 mesh_uv(const scene::Mesh& mesh, const geometry::Hit& hit);

/// The textures a mesh face shows and their weights (POV-Ray's Mesh::Determine_Textures): none (the object's
/// texture applies), one, or one per corner blended across the triangle. Returns how many.
int mesh_face_textures(const scene::Mesh& mesh, const scene::Object& object, const geometry::Hit& hit,
                       std::array<const scene::Texture*, 3>& textures, std::array<double, 3>& weights);

/// POV-Ray's SmoothTriangle::Calculate_Smooth_T: where M lies on the segment from A to the point Q where the
/// line A→M meets the line BC (0 at A, 1 on BC).
double smooth_t(const Vec3& m, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace wardray::lighting
