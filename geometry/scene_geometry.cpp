// SceneGeometry: the Embree device and scene (with scene_geometry_trace.cpp, the only files that include
// embree3/rtcore.h), with analytic shapes and CSG as user geometry computed in double precision, meshes as native
// triangles refined in double, and unbounded shapes intersected outside the BVH. This half builds it.
#include "geometry/scene_geometry.h"
#include "geometry/float_padding.h"
#include "geometry/scene_geometry_data.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace wardray::geometry {

using namespace detail;

namespace {

void on_embree_error(void* user, RTCError code, const char* message) {
    auto* impl = static_cast<GeometryData*>(user);
    // Only record while building (single-threaded); queries never write shared state.
    if (!impl->building.load(std::memory_order_relaxed) || !impl->error.empty()) return;
    impl->error = message ? message : ("code " + std::to_string(static_cast<int>(code)));
}

void bounds_callback(const RTCBoundsFunctionArguments* args) {
    const auto* group = static_cast<const UserGroup*>(args->geometryUserPtr);
    const Bounds& b = (*group->padded)[group->prims[args->primID]];
    RTCBounds* out = args->bounds_o;
    out->lower_x = float_down(b.lower.x);
    out->lower_y = float_down(b.lower.y);
    out->lower_z = float_down(b.lower.z);
    out->upper_x = float_up(b.upper.x);
    out->upper_y = float_up(b.upper.y);
    out->upper_z = float_up(b.upper.z);
}

// At most this many faces' normals are kept (24 bytes each), over all meshes; the rest compute theirs per hit.
constexpr std::size_t kFlatNormalBudget = std::size_t{1} << 21;

// One top-level mesh as a native Embree triangle geometry with world-space float vertices; `normals_left` is what
// remains of kFlatNormalBudget.
void attach_mesh(GeometryData& impl, std::uint32_t mesh_index, std::size_t& normals_left) {
    const ShapeInstance& inst = impl.meshes[mesh_index];
    MeshTrace& trace = impl.mesh_traces[mesh_index];
    trace.inst = &inst;
    const auto& mesh = std::get<MeshShape>(inst.shape());
    RTCGeometry geom = rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    impl.check("triangle geometry creation");
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.vertices().size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), mesh.faces().size()));
    impl.check("triangle buffers");
    for (std::size_t i = 0; i < mesh.vertices().size(); ++i) {
        const Vec3 p = inst.transform().point(mesh.vertices()[i]);
        for (int k = 0; k < 3; ++k) vertices[3 * i + k] = static_cast<float>(p[k]);
    }
    for (std::size_t i = 0; i < mesh.faces().size(); ++i)
        for (int k = 0; k < 3; ++k) indices[3 * i + k] = static_cast<unsigned>(mesh.faces()[i].v[k]);
    const auto& faces = mesh.faces();
    if (faces.size() <= normals_left &&
        std::all_of(faces.begin(), faces.end(), [](const MeshShape::Face& f) { return f.n[0] < 0; })) {
        normals_left -= faces.size();
        trace.flat_normals.resize(faces.size());
        for (std::size_t i = 0; i < faces.size(); ++i) trace.flat_normals[i] = inst.face_world_normal(i, {});
    }
    rtcSetGeometryUserData(geom, &trace);
    rtcSetGeometryMask(geom, visibility_mask(inst));
    rtcSetGeometryIntersectFilterFunction(geom, triangle_intersect_filter);
    rtcSetGeometryOccludedFilterFunction(geom, triangle_occluded_filter);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(impl.scene, geom);
    rtcReleaseGeometry(geom);
    impl.check("triangle geometry setup");
}

// The analytic shapes and CSG objects as one Embree user geometry (a primitive per object).
void attach_user_geometry(GeometryData& impl, RTCScene scene, std::vector<UserGroup>& groups,
                          const std::vector<Bounds>& padded, unsigned mask_shift);
}  // namespace

SceneGeometry::SceneGeometry(const scene::Scene& scene) : m_impl(std::make_unique<Impl>()) {
    Impl& impl = *m_impl;
    // Room for every object but the plain meshes (which go to Embree as triangles), so a scene of 20,000 objects
    // does not leave the list's growth holding twice its size at the peak of memory.
    std::size_t plain_meshes = 0;
    for (const scene::Object& o : scene.objects)
        plain_meshes += std::holds_alternative<scene::Mesh>(o.shape) && o.clipped_by.empty() && o.bounded_by.empty();
    impl.bounded.reserve(scene.objects.size() - plain_meshes);
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        auto inst = ShapeInstance::create(scene.objects[i], i, false, ObjectLifetime::Outlives);
        if (!inst) {
            impl.skipped.push_back(i);
            impl.skip_reasons.push_back(last_skip_reason());
            continue;
        }
        inst->cull_by_bounds();
        if (const auto& b = inst->world_bounds()) {
            impl.bounds = impl.bounds ? impl.bounds->merged(*b) : *b;
            if (inst->is_plain_mesh()) impl.meshes.push_back(std::move(*inst));
            else impl.bounded.push_back(std::move(*inst));
        } else {
            impl.unbounded.push_back(std::move(*inst));
        }
    }
    // Scene magnitude: bounded surfaces, plus where each plane passes nearest the world origin.
    if (impl.bounds) impl.magnitude = impl.bounds->magnitude();
    for (const ShapeInstance& inst : impl.unbounded) {
        // Lines through the origin along x, y and z: the nearest crossing is within sqrt(3) of the plane's distance.
        double nearest = inf;
        for (int k = 0; k < 3; ++k) {
            Vec3 axis;
            axis[k] = 1.0;
            for (const SurfaceHit& h : inst.intersect_all(Vec3{}, axis, -inf, inf))
                nearest = std::fmin(nearest, std::fabs(h.t));
        }
        if (std::isfinite(nearest)) impl.magnitude = std::fmax(impl.magnitude, nearest);
    }
    if (!std::isfinite(impl.magnitude)) impl.magnitude = 0.0;

    if (impl.bounded.empty() && impl.meshes.empty()) {
        impl.building = false;
        return;
    }
    // Pad every box by more than the float ray's rounding, for rays from anywhere in the scene.
    const double scene_pad = 1e-6 * impl.bounds->magnitude();
    std::vector<Bounds> boxes;
    boxes.reserve(impl.bounded.size());
    for (const ShapeInstance& inst : impl.bounded) boxes.push_back(*inst.world_bounds());
    impl.padded_bounds = padded_for_scene(boxes, impl.bounds->magnitude());
    const Vec3 v{2 * scene_pad, 2 * scene_pad, 2 * scene_pad};
    impl.padded_scene_bounds = Bounds{impl.bounds->lower - v, impl.bounds->upper + v};
    // Rays from near the objects need far less when one object makes the scene huge: a sky sphere of radius 1e6
    // pads a chair's 1 cm tubes by 1 unit, and each ray near them then calls back for dozens of objects.
    impl.near_magnitude = near_origin_magnitude(boxes, impl.bounds->magnitude());
    if (std::isfinite(impl.near_magnitude))
        impl.near_bounds = padded_for_origins(boxes, impl.padded_bounds, impl.near_magnitude);
    // The unpadded boxes are not needed in the BVH's build, the peak of memory.
    std::vector<Bounds>().swap(boxes);

    impl.device = rtcNewDevice(nullptr);
    if (!impl.device) throw std::runtime_error("Embree error: cannot create device");
    rtcSetDeviceErrorFunction(impl.device, on_embree_error, &impl);
    impl.scene = rtcNewScene(impl.device);
    impl.check("scene creation");
    rtcSetSceneFlags(impl.scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(impl.scene, RTC_BUILD_QUALITY_HIGH);

    impl.mesh_traces.resize(impl.meshes.size());
    std::size_t normals_left = kFlatNormalBudget;
    for (std::uint32_t i = 0; i < impl.meshes.size(); ++i) attach_mesh(impl, i, normals_left);
    if (!impl.bounded.empty()) {
        if (std::isfinite(impl.near_magnitude)) {
            // The near boxes in the scene with the meshes, under masks shifted past the ray kinds' bits so that a far
            // ray can meet the meshes alone there; the loose boxes in a BVH of their own.
            attach_user_geometry(impl, impl.scene, impl.user_groups, impl.near_bounds, kFarShift);
            impl.far_scene = rtcNewScene(impl.device);
            impl.check("scene creation");
            rtcSetSceneFlags(impl.far_scene, RTC_SCENE_FLAG_ROBUST);
            rtcSetSceneBuildQuality(impl.far_scene, RTC_BUILD_QUALITY_HIGH);
            attach_user_geometry(impl, impl.far_scene, impl.far_groups, impl.padded_bounds, 0);
            rtcCommitScene(impl.far_scene);
            impl.check("BVH build");
        } else {
            attach_user_geometry(impl, impl.scene, impl.user_groups, impl.padded_bounds, 0);
        }
    }
    rtcCommitScene(impl.scene);
    impl.check("BVH build");
    impl.building = false;
}

namespace {

void attach_user_geometry(GeometryData& impl, RTCScene scene, std::vector<UserGroup>& groups,
                           const std::vector<Bounds>& padded, unsigned mask_shift) {
    // A geometry per visibility mask, each listing its instances in scene order; one when every object is seen by
    // every ray, as most scenes are.
    std::uint32_t group_of_mask[16];
    std::fill(std::begin(group_of_mask), std::end(group_of_mask), UINT32_MAX);
    std::vector<unsigned> masks;
    for (std::uint32_t i = 0; i < impl.bounded.size(); ++i) {
        const unsigned mask = visibility_mask(impl.bounded[i]);
        if (group_of_mask[mask] == UINT32_MAX) {
            group_of_mask[mask] = static_cast<std::uint32_t>(groups.size());
            groups.push_back({&impl, {}, &padded});
            masks.push_back(mask);
        }
        groups[group_of_mask[mask]].prims.push_back(i);
    }
    for (std::size_t g = 0; g < groups.size(); ++g) {
        UserGroup& group = groups[g];
        RTCGeometry geom = rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_USER);
        impl.check("geometry creation");
        rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned>(group.prims.size()));
        rtcSetGeometryUserData(geom, &group);
        rtcSetGeometryMask(geom, masks[g] << mask_shift);
        rtcSetGeometryBoundsFunction(geom, bounds_callback, nullptr);
        rtcSetGeometryIntersectFunction(geom, intersect_callback);
        rtcSetGeometryOccludedFunction(geom, occluded_callback);
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        impl.check("geometry setup");
    }
}

}  // namespace

SceneGeometry::~SceneGeometry() = default;

std::optional<Bounds> SceneGeometry::bounds() const { return m_impl->bounds; }

const std::vector<std::uint32_t>& SceneGeometry::skipped_objects() const { return m_impl->skipped; }
const std::vector<SkipReason>& SceneGeometry::skip_reasons() const { return m_impl->skip_reasons; }

std::vector<Diagnostic> SceneGeometry::shape_warnings() const {
    // POV-Ray compat: only top-level objects report (CSG does not pass the message on to its children).
    std::vector<Diagnostic> out;
    for (const ShapeInstance& inst : m_impl->bounded)
        if (const auto* iso = std::get_if<IsosurfaceShape>(&inst.shape()))
            if (auto w = iso->gradient_warning()) out.push_back(std::move(*w));
    return out;
}

double SceneGeometry::min_isect_parameter(const Vec3& direction) const {
    return min_isect_depth_of(*m_impl, length(direction));
}

double SceneGeometry::self_intersection_offset(const Vec3& p) const {
    return 1e-9 * max_of(max_abs_component(p), 1e-6 * m_impl->magnitude);
}

double self_intersection_offset(const Vec3& p) {
    // The floor only keeps the result positive at the origin; SceneGeometry's version knows the scene's size.
    return 1e-9 * std::fmax(max_abs_component(p), std::numeric_limits<double>::min());
}

}  // namespace wardray::geometry
