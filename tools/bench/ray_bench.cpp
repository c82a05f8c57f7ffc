// ray_bench: traces one scene's gather and shadow rays through wardray's SceneGeometry and through bare Embree on
// the same geometry, and prints rays per second for each and their ratio (issue 18's ray-throughput target).
//   ray_bench [--size W H] [--gather N] [--rounds R] [--threads T] [--only wardray|embree1|embree16] [--check-only]
//             [--dump OUT] FILE
// --only runs one variant (for a profiler); --check-only one round of each (the smoke test); --dump writes wardray's
// every answer, each field exact, to OUT and times nothing (two builds' dumps must be the same file).
// The rays are those a radiosity render traces: from the surface seen through each pixel, N cosine-distributed
// gather rays and a shadow ray to each light the surface faces; from each gather ray's hit, a shadow ray to one
// light (the render's one light per gather-path hit). The variants run interleaved, R rounds; the median counts.
// Rates are rays per CPU second of the tracing threads (their own CPU time, so other work on the machine does not
// count). This is the one file outside geometry/ that includes Embree: it measures wardray against Embree itself.
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <ctime>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "camera/camera.h"
#include "geometry/instance.h"
#include "geometry/object_query.h"
#include "geometry/scene_geometry.h"
#include "parser/parse.h"

namespace {

using namespace wardray;
using geometry::Ray;
using geometry::RayKind;

constexpr float kInfF = std::numeric_limits<float>::infinity();

// A small deterministic generator (SplitMix64), so every run and machine records the same rays.
struct Random {
    std::uint64_t state;
    double next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return static_cast<double>(z >> 11) * 0x1.0p-53;
    }
};

// A cosine-distributed direction about the unit normal n (Malley's method: a uniform disc point lifted).
Vec3 cosine_direction(const Vec3& n, Random& rng) {
    const Vec3 helper = std::fabs(n.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 t = normalize(cross(helper, n));
    const Vec3 b = cross(n, t);
    const double r = std::sqrt(rng.next());
    const double phi = 2.0 * M_PI * rng.next();
    const double x = r * std::cos(phi), y = r * std::sin(phi);
    return normalize(x * t + y * b + std::sqrt(std::fmax(0.0, 1.0 - x * x - y * y)) * n);
}

struct RaySet {
    std::vector<Ray> gather;  ///< intersect(): closest hit
    std::vector<Ray> shadow;  ///< occluded(): any hit
};

// A shadow ray from p towards the light when the surface (normal n, facing the viewer) faces it, as the render's.
void add_shadow_ray(const geometry::SceneGeometry& geometry, const scene::Light& light, const Vec3& p, const Vec3& n,
                    std::vector<Ray>& out) {
    const Vec3 to = light.position - p;
    const double distance = length(to);
    if (!(distance > 0.0)) return;
    const Vec3 dir = to / distance;
    if (dot(dir, n) <= 0.0) return;
    const double offset = geometry.self_intersection_offset(p);
    if (distance - offset > offset) out.push_back(Ray{p, dir, offset, distance - offset, RayKind::Shadow});
}

// The rays of one render: camera hits, their gather rays and shadow rays, and the gather hits' shadow rays.
RaySet record_rays(const scene::Scene& scene, const geometry::SceneGeometry& geometry, int width, int height,
                   int gather_per_hit) {
    RaySet rays;
    const camera::CameraModel cam(scene.camera, width, height, scene.global.noise_generator);
    Random rng{12345};
    std::size_t light_pick = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto ray = cam.ray(x + 0.5, y + 0.5);
            if (!ray) continue;
            const auto hit = geometry.intersect(*ray);
            if (!hit) continue;
            const Vec3 n = dot(hit->normal, ray->direction) > 0.0 ? -hit->normal : hit->normal;
            for (const scene::Light& light : scene.lights) add_shadow_ray(geometry, light, hit->position, n, rays.shadow);
            for (int i = 0; i < gather_per_hit; ++i) {
                const Vec3 dir = cosine_direction(n, rng);
                const Ray g{hit->position, dir, geometry.self_intersection_offset(hit->position), 1e30, RayKind::Gather};
                rays.gather.push_back(g);
                if (scene.lights.empty()) continue;
                const auto second = geometry.intersect(g);
                if (!second) continue;
                const Vec3 n2 = dot(second->normal, dir) > 0.0 ? -second->normal : second->normal;
                add_shadow_ray(geometry, scene.lights[light_pick++ % scene.lights.size()], second->position, n2,
                               rays.shadow);
            }
        }
    return rays;
}

// ---- Bare Embree: the same objects, triangles native, every other shape a user primitive with no wrapper. ----

float float_down(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -kInfF);
    return f;
}
float float_up(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, kInfF);
    return f;
}

// One user geometry: the non-mesh objects that the same kinds of ray see (Embree's mask is per geometry).
struct UserGroup {
    std::vector<geometry::ShapeInstance> shapes;  ///< by primID
    std::vector<geometry::Bounds> boxes;          ///< their float-safe boxes
    std::vector<std::uint32_t> objects;           ///< their scene objects
};

struct BareScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    UserGroup groups[16];                           ///< by visibility mask
    std::vector<std::int64_t> object_of_geometry;   ///< triangle geomID -> object
    std::vector<const UserGroup*> group_of_geometry;  ///< user geomID -> its group (null for triangles)

    ~BareScene() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
    /// The object a hit names, or -1 for none.
    std::int64_t object(unsigned geom_id, unsigned prim_id) const {
        if (geom_id == RTC_INVALID_GEOMETRY_ID) return -1;
        const UserGroup* g = group_of_geometry[geom_id];
        return g ? g->objects[prim_id] : object_of_geometry[geom_id];
    }
};

// The ray kinds that see an object, one bit each, as an Embree mask; a ray's mask is its kind's bit.
unsigned visibility_mask(const geometry::ShapeInstance& inst) {
    unsigned mask = 0;
    for (const RayKind k : {RayKind::Camera, RayKind::Reflection, RayKind::Shadow, RayKind::Gather})
        if (inst.visible_to(k)) mask |= 1u << static_cast<unsigned>(k);
    return mask;
}
unsigned ray_mask(RayKind kind) { return 1u << static_cast<unsigned>(kind); }

// Records an attached geometry's owner.
void attached(BareScene& bare, unsigned id, const UserGroup* group, std::int64_t object) {
    if (bare.group_of_geometry.size() <= id) {
        bare.group_of_geometry.resize(id + 1, nullptr);
        bare.object_of_geometry.resize(id + 1, -1);
    }
    bare.group_of_geometry[id] = group;
    bare.object_of_geometry[id] = object;
}

void bare_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* group = static_cast<const UserGroup*>(args->geometryUserPtr);
    const geometry::Bounds& b = group->boxes[args->primID];
    *args->bounds_o = RTCBounds{float_down(b.lower.x), float_down(b.lower.y), float_down(b.lower.z), 0.0f,
                                float_up(b.upper.x),   float_up(b.upper.y),   float_up(b.upper.z),   0.0f};
}

// The shape's own double-precision intersection on the float ray, for each active ray of the packet.
void bare_intersect(const RTCIntersectFunctionNArguments* args) {
    const auto* group = static_cast<const UserGroup*>(args->geometryUserPtr);
    const geometry::ShapeInstance& shape = group->shapes[args->primID];
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        const Vec3 o{RTCRayN_org_x(rays, args->N, i), RTCRayN_org_y(rays, args->N, i), RTCRayN_org_z(rays, args->N, i)};
        const Vec3 d{RTCRayN_dir_x(rays, args->N, i), RTCRayN_dir_y(rays, args->N, i), RTCRayN_dir_z(rays, args->N, i)};
        const auto hit = shape.nearest(o, d, RTCRayN_tnear(rays, args->N, i), RTCRayN_tfar(rays, args->N, i));
        if (!hit) continue;
        RTCRayN_tfar(rays, args->N, i) = static_cast<float>(hit->t);
        RTCHitN_Ng_x(hits, args->N, i) = static_cast<float>(hit->normal.x);
        RTCHitN_Ng_y(hits, args->N, i) = static_cast<float>(hit->normal.y);
        RTCHitN_Ng_z(hits, args->N, i) = static_cast<float>(hit->normal.z);
        RTCHitN_u(hits, args->N, i) = 0.0f;
        RTCHitN_v(hits, args->N, i) = 0.0f;
        RTCHitN_primID(hits, args->N, i) = args->primID;
        RTCHitN_geomID(hits, args->N, i) = args->geomID;
        RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
    }
}

void bare_occluded(const RTCOccludedFunctionNArguments* args) {
    const auto* group = static_cast<const UserGroup*>(args->geometryUserPtr);
    const geometry::ShapeInstance& shape = group->shapes[args->primID];
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        const Vec3 o{RTCRayN_org_x(args->ray, args->N, i), RTCRayN_org_y(args->ray, args->N, i),
                     RTCRayN_org_z(args->ray, args->N, i)};
        const Vec3 d{RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                     RTCRayN_dir_z(args->ray, args->N, i)};
        if (shape.crosses(o, d, RTCRayN_tnear(args->ray, args->N, i), RTCRayN_tfar(args->ray, args->N, i)))
            RTCRayN_tfar(args->ray, args->N, i) = -kInfF;
    }
}

// The scene's objects as wardray places them (ShapeInstance::create), handed to Embree with its defaults plus the
// scene flags wardray sets (robust, high-quality build), so the two differ only in how a ray is traced. Visibility
// flags (no_shadow, no_image, ...) are geometry masks. Planes and other unbounded shapes get a box 1e4 times the
// scene's size.
void build_bare(const scene::Scene& scene, BareScene& bare) {
    bare.device = rtcNewDevice(nullptr);
    bare.scene = rtcNewScene(bare.device);
    if (!rtcGetDeviceProperty(bare.device, RTC_DEVICE_PROPERTY_RAY_MASK_SUPPORTED))
        std::fprintf(stderr, "ray_bench: this Embree ignores ray masks; visibility flags are not honoured\n");
    rtcSetSceneFlags(bare.scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(bare.scene, RTC_BUILD_QUALITY_HIGH);
    std::optional<geometry::Bounds> all;
    std::vector<std::pair<UserGroup*, std::size_t>> unbounded;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        auto inst = geometry::ShapeInstance::create(scene.objects[i], i);
        if (!inst) continue;
        inst->cull_by_bounds();
        const unsigned mask = visibility_mask(*inst);
        if (inst->is_plain_mesh() && inst->world_bounds()) {
            const auto& mesh = std::get<geometry::MeshShape>(inst->shape());
            RTCGeometry geom = rtcNewGeometry(bare.device, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                  3 * sizeof(float), mesh.vertices().size()));
            auto* f = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                     3 * sizeof(unsigned), mesh.faces().size()));
            for (std::size_t k = 0; k < mesh.vertices().size(); ++k) {
                const Vec3 p = inst->transform().point(mesh.vertices()[k]);
                for (int c = 0; c < 3; ++c) v[3 * k + c] = static_cast<float>(p[c]);
            }
            for (std::size_t k = 0; k < mesh.faces().size(); ++k)
                for (int c = 0; c < 3; ++c) f[3 * k + c] = static_cast<unsigned>(mesh.faces()[k].v[c]);
            rtcSetGeometryMask(geom, mask);
            rtcCommitGeometry(geom);
            attached(bare, rtcAttachGeometry(bare.scene, geom), nullptr, i);
            rtcReleaseGeometry(geom);
            all = all ? all->merged(*inst->world_bounds()) : *inst->world_bounds();
            continue;
        }
        UserGroup& group = bare.groups[mask];
        if (const auto& b = inst->world_bounds()) {
            const double pad = 1e-6 * (b->magnitude() + max_abs_component(b->upper - b->lower));
            group.boxes.push_back({b->lower - Vec3{pad, pad, pad}, b->upper + Vec3{pad, pad, pad}});
            all = all ? all->merged(*b) : *b;
        } else {
            unbounded.emplace_back(&group, group.shapes.size());
            group.boxes.emplace_back();
        }
        group.objects.push_back(i);
        group.shapes.push_back(std::move(*inst));
    }
    const double far = 1e4 * (all ? std::fmax(all->magnitude(), 1.0) : 1.0);
    for (const auto& [group, k] : unbounded) group->boxes[k] = {Vec3{-far, -far, -far}, Vec3{far, far, far}};
    for (unsigned mask = 0; mask < 16; ++mask) {
        UserGroup& group = bare.groups[mask];
        if (group.shapes.empty()) continue;
        RTCGeometry geom = rtcNewGeometry(bare.device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned>(group.shapes.size()));
        rtcSetGeometryUserData(geom, &group);
        rtcSetGeometryBoundsFunction(geom, bare_bounds, nullptr);
        rtcSetGeometryIntersectFunction(geom, bare_intersect);
        rtcSetGeometryOccludedFunction(geom, bare_occluded);
        rtcSetGeometryMask(geom, mask);
        rtcCommitGeometry(geom);
        attached(bare, rtcAttachGeometry(bare.scene, geom), &group, -1);
        rtcReleaseGeometry(geom);
    }
    rtcCommitScene(bare.scene);
    if (rtcGetDeviceError(bare.device) != RTC_ERROR_NONE) {
        std::fprintf(stderr, "ray_bench: Embree error while building the bare scene\n");
        std::exit(1);
    }
}

// The float ray Embree gets: wardray's ray with its MIN_ISECT_DEPTH start, so both search the same span. A span
// that ends at a point (a shadow ray's light) ends 1e-5 of its length short, as a float renderer's must: lights
// that lie in a surface (cornell's patches are in the ceiling's plane) would otherwise block half the shadow rays.
void to_embree(const geometry::SceneGeometry& geometry, const Ray& r, float& ox, float& oy, float& oz, float& dx,
               float& dy, float& dz, float& tnear, float& tfar) {
    ox = static_cast<float>(r.origin.x);
    oy = static_cast<float>(r.origin.y);
    oz = static_cast<float>(r.origin.z);
    dx = static_cast<float>(r.direction.x);
    dy = static_cast<float>(r.direction.y);
    dz = static_cast<float>(r.direction.z);
    tnear = static_cast<float>(std::fmax(r.t_min, geometry.min_isect_parameter(r.direction)));
    tfar = r.t_max < 1e30 ? float_down(r.t_max * (1.0 - 1e-5)) : 3e38f;
}

// ---- Timing ----

// CPU time of the calling thread: on a machine shared with other work, a thread's own time counts the work it did,
// not the time it waited for a core.
double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Runs body(begin, end) over [0, n) on `threads` threads in chunks; returns the CPU seconds of all of them.
double timed(std::size_t n, int threads, const std::function<void(std::size_t, std::size_t)>& body) {
    if (threads <= 1) {
        const double start = thread_cpu_seconds();
        body(0, n);
        return thread_cpu_seconds() - start;
    }
    std::atomic<std::size_t> next{0};
    constexpr std::size_t chunk = 1024;  // a multiple of 16, so packets never straddle chunks
    std::vector<double> cpu(threads, 0.0);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            const double start = thread_cpu_seconds();
            for (std::size_t b; (b = next.fetch_add(chunk)) < n;) body(b, std::min(n, b + chunk));
            cpu[t] = thread_cpu_seconds() - start;
        });
    for (auto& th : pool) th.join();
    double sum = 0.0;
    for (const double c : cpu) sum += c;
    return sum;
}

struct Variant {
    const char* name;
    std::function<double()> gather;  ///< seconds for every gather ray
    std::function<double()> shadow;  ///< seconds for every shadow ray
    std::vector<double> gather_s, shadow_s;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

// Every field of wardray's answer to each ray, doubles as exact hex floats, one line a ray: two builds that answer
// alike write the same file.
bool dump_answers(const geometry::SceneGeometry& geometry, const RaySet& rays, const char* path) {
    std::FILE* out = std::fopen(path, "w");
    if (!out) return false;
    for (const Ray& ray : rays.gather) {
        const auto hit = geometry.intersect(ray);
        if (!hit) {
            std::fprintf(out, "-\n");
            continue;
        }
        const auto v = [&](const Vec3& p) { std::fprintf(out, " %a %a %a", p.x, p.y, p.z); };
        std::fprintf(out, "%a", hit->t);
        v(hit->position);
        v(hit->normal);
        std::fprintf(out, " %u %u:%u %d %a %a %d", hit->object, hit->leaf ? hit->leaf->loc.line : 0u,
                     hit->leaf ? hit->leaf->loc.column : 0u, hit->face, hit->bary_u, hit->bary_v,
                     hit->has_params ? 1 : 0);
        v(hit->params);
        std::fprintf(out, "\n");
    }
    for (const Ray& ray : rays.shadow) std::fprintf(out, "%d\n", geometry.occluded(ray) ? 1 : 0);
    return std::fclose(out) == 0;
}

int main(int argc, char** argv) {
    int width = 128, height = 128, gather_per_hit = 16, rounds = 5, threads = 1;
    bool check_only = false;
    const char* file = nullptr;
    const char* dump = nullptr;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "--size" && i + 2 < argc) {
            width = std::atoi(argv[++i]);
            height = std::atoi(argv[++i]);
        } else if (a == "--gather" && i + 1 < argc) {
            gather_per_hit = std::atoi(argv[++i]);
        } else if (a == "--rounds" && i + 1 < argc) {
            rounds = std::atoi(argv[++i]);
        } else if (a == "--threads" && i + 1 < argc) {
            threads = std::atoi(argv[++i]);
        } else if (a == "--only" && i + 1 < argc) {
            only = argv[++i];
        } else if (a == "--check-only") {
            check_only = true;
        } else if (a == "--dump" && i + 1 < argc) {
            dump = argv[++i];
        } else if (!a.empty() && a[0] != '-') {
            file = argv[i];
        } else {
            file = nullptr;
            break;
        }
    }
    if (!file || width < 1 || height < 1 || gather_per_hit < 1 || rounds < 1 || threads < 1) {
        std::fprintf(stderr, "usage: ray_bench [--size W H] [--gather N] [--rounds R] [--threads T] "
                             "[--only wardray|embree1|embree16] [--check-only] [--dump OUT] FILE\n");
        return 2;
    }
    parser::ParseOptions options;
    options.library_paths.push_back("/usr/share/povray-3.7/include");
    options.image_width = width;
    options.image_height = height;
    static const geometry::ObjectQuery query;
    options.query = &query;
    auto parsed = parser::parse_file(file, options);
    if (!parsed.ok()) {
        std::fprintf(stderr, "ray_bench: %s does not parse\n", file);
        return 1;
    }
    const scene::Scene& scene = *parsed.scene;
    const geometry::SceneGeometry geometry(scene);
    const RaySet rays = record_rays(scene, geometry, width, height, gather_per_hit);
    if (dump) {
        if (dump_answers(geometry, rays, dump)) return 0;
        std::fprintf(stderr, "ray_bench: cannot write %s\n", dump);
        return 1;
    }
    BareScene bare;
    build_bare(scene, bare);
    const std::size_t ng = rays.gather.size(), ns = rays.shadow.size();

    // Every variant's answers, kept so the compiler cannot drop the work and so they can be compared.
    std::vector<std::int64_t> w_object(ng, -1), e_object(ng, -1), p_object(ng, -1);
    std::vector<char> w_blocked(ns), e_blocked(ns), p_blocked(ns);

    auto wardray_gather = [&] {
        return timed(ng, threads, [&](std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) {
                const auto hit = geometry.intersect(rays.gather[i]);
                w_object[i] = hit ? static_cast<std::int64_t>(hit->object) : -1;
            }
        });
    };
    auto wardray_shadow = [&] {
        return timed(ns, threads, [&](std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) w_blocked[i] = geometry.occluded(rays.shadow[i]);
        });
    };
    auto embree1_gather = [&] {
        return timed(ng, threads, [&](std::size_t b, std::size_t e) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            for (std::size_t i = b; i < e; ++i) {
                alignas(16) RTCRayHit rh{};
                RTCRay& r = rh.ray;
                to_embree(geometry, rays.gather[i], r.org_x, r.org_y, r.org_z, r.dir_x, r.dir_y, r.dir_z, r.tnear,
                          r.tfar);
                r.mask = ray_mask(RayKind::Gather);
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(bare.scene, &ctx, &rh);
                e_object[i] = bare.object(rh.hit.geomID, rh.hit.primID);
            }
        });
    };
    auto embree1_shadow = [&] {
        return timed(ns, threads, [&](std::size_t b, std::size_t e) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            for (std::size_t i = b; i < e; ++i) {
                alignas(16) RTCRay r{};
                to_embree(geometry, rays.shadow[i], r.org_x, r.org_y, r.org_z, r.dir_x, r.dir_y, r.dir_z, r.tnear,
                          r.tfar);
                r.mask = ray_mask(RayKind::Shadow);
                rtcOccluded1(bare.scene, &ctx, &r);
                e_blocked[i] = r.tfar < 0.0f;
            }
        });
    };
    auto embree16_gather = [&] {
        return timed(ng, threads, [&](std::size_t b, std::size_t e) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            for (std::size_t s = b; s < e; s += 16) {
                alignas(64) RTCRayHit16 rh{};
                alignas(64) int valid[16];
                for (int k = 0; k < 16; ++k) {
                    const bool on = s + k < e;
                    valid[k] = on ? -1 : 0;
                    if (!on) continue;
                    to_embree(geometry, rays.gather[s + k], rh.ray.org_x[k], rh.ray.org_y[k], rh.ray.org_z[k],
                              rh.ray.dir_x[k], rh.ray.dir_y[k], rh.ray.dir_z[k], rh.ray.tnear[k], rh.ray.tfar[k]);
                    rh.ray.mask[k] = ray_mask(RayKind::Gather);
                    rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                    rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
                }
                rtcIntersect16(valid, bare.scene, &ctx, &rh);
                for (int k = 0; k < 16 && s + k < e; ++k)
                    p_object[s + k] = bare.object(rh.hit.geomID[k], rh.hit.primID[k]);
            }
        });
    };
    auto embree16_shadow = [&] {
        return timed(ns, threads, [&](std::size_t b, std::size_t e) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            for (std::size_t s = b; s < e; s += 16) {
                alignas(64) RTCRay16 r{};
                alignas(64) int valid[16];
                for (int k = 0; k < 16; ++k) {
                    const bool on = s + k < e;
                    valid[k] = on ? -1 : 0;
                    if (!on) continue;
                    to_embree(geometry, rays.shadow[s + k], r.org_x[k], r.org_y[k], r.org_z[k], r.dir_x[k],
                              r.dir_y[k], r.dir_z[k], r.tnear[k], r.tfar[k]);
                    r.mask[k] = ray_mask(RayKind::Shadow);
                }
                rtcOccluded16(valid, bare.scene, &ctx, &r);
                for (int k = 0; k < 16 && s + k < e; ++k) p_blocked[s + k] = r.tfar[k] < 0.0f;
            }
        });
    };

    std::vector<Variant> variants = {{"wardray intersect/occluded", wardray_gather, wardray_shadow, {}, {}},
                                     {"Embree rtcIntersect1/rtcOccluded1", embree1_gather, embree1_shadow, {}, {}},
                                     {"Embree rtcIntersect16/rtcOccluded16", embree16_gather, embree16_shadow, {}, {}}};
    const char* keys[] = {"wardray", "embree1", "embree16"};
    if (!only.empty()) {
        std::size_t k = 0;
        while (k < 3 && only != keys[k]) ++k;
        if (k == 3) {
            std::fprintf(stderr, "ray_bench: --only takes wardray, embree1 or embree16\n");
            return 2;
        }
        variants = {variants[k]};
    }
    for (int r = 0; r < (check_only ? 1 : rounds); ++r)
        for (Variant& v : variants) {
            v.gather_s.push_back(v.gather());
            v.shadow_s.push_back(v.shadow());
        }

    // Agreement: the same object hit (or none), the same shadow answer. Float and double differ at grazing rays and
    // edges, so a few per ten thousand may differ.
    std::size_t gather_diff = 0, shadow_diff = 0, packet_diff = 0, gather_hits = 0, blocked = 0;
    for (std::size_t i = 0; i < ng; ++i) {
        gather_diff += w_object[i] != e_object[i];
        packet_diff += e_object[i] != p_object[i];
        gather_hits += w_object[i] >= 0;
    }
    for (std::size_t i = 0; i < ns; ++i) {
        shadow_diff += w_blocked[i] != e_blocked[i];
        packet_diff += e_blocked[i] != p_blocked[i];
        blocked += w_blocked[i];
    }
    std::printf("scene %s  %dx%d, %d gather rays per camera hit, %d thread(s), %d round(s), median, rays per CPU "
                "second\n", file, width,
                height, gather_per_hit, threads, check_only ? 1 : rounds);
    std::printf("rays: %zu gather (%.1f %% hit), %zu shadow (%.1f %% blocked); objects %zu\n", ng,
                ng ? 100.0 * gather_hits / ng : 0.0, ns, ns ? 100.0 * blocked / ns : 0.0, scene.objects.size());
    if (only.empty())
        std::printf("disagreements with wardray: %zu gather, %zu shadow (Embree packets vs single: %zu)\n",
                    gather_diff, shadow_diff, packet_diff);
    double base = 0.0;
    for (const Variant& v : variants) {
        const double g = median(v.gather_s), s = median(v.shadow_s);
        const double all = (g + s) > 0.0 ? (ng + ns) / (g + s) : 0.0;
        if (base == 0.0) base = all;
        std::printf("%-36s gather %7.3f Mrays/s  shadow %7.3f Mrays/s  all %7.3f Mrays/s  wardray/this %.3f\n",
                    v.name, g > 0 ? ng / g / 1e6 : 0.0, s > 0 ? ns / s / 1e6 : 0.0, all / 1e6,
                    all > 0.0 ? base / all : 0.0);
    }
    // A smoke test's verdict: wardray and bare Embree must see nearly the same scene.
    const double tolerance = 0.002 * static_cast<double>(ng + ns) + 2.0;
    return !only.empty() || static_cast<double>(gather_diff + shadow_diff) <= tolerance ? 0 : 3;
}
