// The mesh_camera block: rays per pixel, distribution, optional maximum distance, meshes and `smooth`.
#include "parser/parser.h"

namespace wardray::parser {

void SceneReader::parse_mesh_camera(CameraSpec& spec, const Token& kw) {
    expect("{");
    MeshCameraSpec& mc = spec.mesh_camera;
    mc = MeshCameraSpec{};
    const Token rays_at = peek();
    const double rays = parse_float();
    // POV-Ray compat: both numbers are converted to unsigned integers.
    mc.rays_per_pixel = rays >= 0.0 ? static_cast<int>(rays) : -1;
    if (mc.rays_per_pixel == 0) fail(rays_at, "Rays per pixel may not be 0");
    accept(",");
    const Token dist_at = peek();
    const double dist = parse_float();
    mc.distribution = dist >= 0.0 ? static_cast<int>(dist) : -1;
    if (mc.distribution < 0 || mc.distribution > 3) fail(dist_at, "Unrecognized distribution method");
    if ((mc.distribution == 2 || mc.distribution == 3) && mc.rays_per_pixel != 1)
        fail(rays_at, "Rays per pixel must be 1 for distribution method #2 or #3");
    accept(",");
    if (starts_value(peek())) {
        const Token at = peek();
        mc.max_distance = parse_float();
        if (mc.max_distance != 0.0) warn_unsupported(at, "mesh_camera maximum ray distance");
    }
    std::vector<MeshCameraSpec::PlacedMesh> meshes;
    while (true) {
        expand_macros();
        const Token t = peek();
        if (!is_word(t, "mesh") && !is_word(t, "mesh2")) break;
        next();
        // POV-Ray compat (Parse_Mesh_Camera): mesh2 is read with the mesh reader too, so only its identifier works.
        Token as_mesh = t;
        as_mesh.text = std::string_view("mesh");
        ObjectValue ov = parse_object(as_mesh);
        if (ov.parts.size() != 1 || !std::holds_alternative<Mesh>(ov.parts.front().object.shape))
            fail(t, "expected a mesh or mesh2 in mesh_camera");
        Object& o = ov.parts.front().object;
        meshes.push_back({std::move(std::get<Mesh>(o.shape)), o.transform});
    }
    if (is_word(peek(), "smooth")) {
        const Token s = next();
        mc.smooth = true;
        if (mc.distribution != 3) fail(s, "Smooth can only be used with distribution method #3");
    }
    if (!accept("}")) fail(peek(), "expected mesh, mesh2, smooth or '}' in mesh_camera but found " +
                                       describe_token(peek()));
    if (meshes.empty()) fail(kw, "mesh_camera needs a mesh or mesh2");
    if (mc.distribution == 0 && mc.rays_per_pixel > static_cast<int>(meshes.size()))
        fail(kw, "Rays per pixel must not be more than the number of meshes for distribution method #0");
    mc.meshes = std::make_shared<const std::vector<MeshCameraSpec::PlacedMesh>>(std::move(meshes));
}

}  // namespace wardray::parser
