// Pattern wraps on surfaces: samples each primitive's flat faces, spheres and cylinder sides and compares its
// texture just inside and just outside, so that a jump rounding decides (POV-Ray's speckle) is reported.
#include "texture/pattern_wraps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <set>
#include <tuple>
#include <variant>

#include "core/diagnostic_list.h"
#include "core/transform.h"
#include "core/vec3.h"
#include "geometry/surface_pieces.h"
#include "scene/scene.h"
#include "texture/normal.h"
#include "texture/pattern.h"
#include "texture/pigment.h"

namespace wardray::texture {

namespace {

// Points sampled on each surface; a surface is reported when the texture jumps at half of them or more.
constexpr int kSamples = 8;
// How far either side of the surface the texture is looked at: this much of the surface's distance from the
// origin along its normal (what rounds when a ray meets it), and kMixing of the point's distance from the origin
// (the rounding of transforms that mix the coordinates).
constexpr double kStep = 1e-13;
constexpr double kMixing = 4e-15;
// Texture looks (pigment channels, normal components, map weights) differ when they differ by more than this.
constexpr double kDifferent = 0.01;
// Looks evaluated in all: a scene of many patterned objects is cut short rather than slowed down.
constexpr std::size_t kLookBudget = 200'000;

// What a value of a look belongs to: a layer's pigment or normal, or a texture_map.
struct Owner {
    const char* part = "";
    SourceLoc loc;
    const scene::Pigment* pigment = nullptr;
    const scene::Normal* normal = nullptr;
    const scene::Pattern* map = nullptr;
};

// The texture at a point, as numbers: each layer's pigment (five channels) and perturbed normal, each value with
// the index of its owner.
struct Look {
    std::vector<double> values;
    std::vector<std::size_t> owners;
};

// A point sampled on a surface: world position and unit outward normal.
struct Sample {
    Vec3 p;
    Vec3 n;
};

bool pattern_varies(const scene::Pattern& p) { return p.type != scene::Pattern::Type::None; }

// Whether the texture has anything that can vary from point to point (a solid colour everywhere cannot jump).
bool textured(const scene::Texture& t) {
    if (!t.texture_map.empty() || !t.pigment.is_solid() || t.normal.perturbs()) return true;
    return std::any_of(t.layers.begin(), t.layers.end(), textured);
}

// A fixed, well spread number in [0, 1) for the k-th sample's `axis`-th coordinate (an additive recurrence with
// irrational steps, so that samples avoid the symmetric places of faces and patterns).
double spread(int k, int axis) {
    constexpr std::array<double, 4> kSteps = {0.6180339887498949, 0.7548776662466927, 0.5698402909980532,
                                              0.4142135623730950};
    const double v = 0.1234 + (k + 1) * kSteps[static_cast<std::size_t>(axis) % kSteps.size()];
    return v - std::floor(v);
}

class Finder {
public:
    explicit Finder(const scene::Scene& scene)
        : m_noise_generator(scene.global.noise_generator), m_camera(scene.camera) {
        for (const scene::Object& o : scene.objects) collect(o, Transform{});
    }

    std::vector<PatternWrap>& found() { return m_found; }

private:
    void collect(const scene::Object& o, const Transform& outer) {
        if (o.no_image || o.uv_mapping) return;  // unseen, or textured in uv space
        const Transform world = o.transform.then(outer);
        if (const auto* csg = std::get_if<scene::Csg>(&o.shape)) {
            for (const scene::Object& child : csg->children) collect(child, world);
            return;
        }
        const scene::Texture& texture = *o.texture;
        if (!textured(texture) || m_looks >= kLookBudget) return;
        bool nested_uv = false;
        if (scene::texture_uses_uv(texture, nested_uv)) return;
        for (const geometry::FlatPiece& piece : geometry::flat_pieces(o.shape)) {
            const std::vector<Sample> samples = flat_samples(piece, world);
            // A solid's face turned away from the camera is not seen (but for reflections): a box's bottom on a
            // floor, say.
            const bool solid_face = !piece.corners.empty() && !piece.two_sided && !o.inverse && !samples.empty();
            if (!(solid_face && turned_away(samples.front()))) test(o, texture, samples, "flat face");
        }
        for (const geometry::RoundPiece& piece : geometry::round_pieces(o.shape))
            test(o, texture, round_samples(piece, world), piece.cylinder ? "cylinder side" : "sphere");
    }

    // Whether the sample's outer side faces away from the camera: the eye is behind its plane or, for an
    // orthographic camera, every ray runs along its outward normal. Cameras whose rays do not start at one place
    // (cylinder, mesh_camera) see everything.
    bool turned_away(const Sample& s) const {
        using Type = scene::Camera::Type;
        switch (m_camera.type) {
            case Type::Orthographic:
                return dot(s.n, m_camera.direction) > 0.0;
            case Type::Cylinder:
            case Type::MeshCamera:
                return false;
            default:
                return dot(s.n, m_camera.location - s.p) < 0.0;
        }
    }

    static Sample placed(const Transform& world, const Vec3& p_object, const Vec3& n_object) {
        return {world.point(p_object), normalize(world.normal(n_object))};
    }

    // Points spread over a flat face (generic mixtures of its corners), or around a plane's point.
    static std::vector<Sample> flat_samples(const geometry::FlatPiece& piece, const Transform& world) {
        std::vector<Sample> out;
        if (piece.corners.empty()) {
            const auto [u, v] = geometry::plane_basis(piece.normal);
            for (int k = 0; k < kSamples; ++k)
                out.push_back(placed(world, piece.point + u * (6.0 * spread(k, 0) - 3.0) + v * (6.0 * spread(k, 1) - 3.0),
                                     piece.normal));
            return out;
        }
        for (int k = 0; k < kSamples; ++k) {
            Vec3 p;
            double total = 0.0;
            for (std::size_t c = 0; c < piece.corners.size(); ++c) {
                const double w = 0.05 + spread(k + 3 * static_cast<int>(c), static_cast<int>(c));
                p += piece.corners[c] * w;
                total += w;
            }
            out.push_back(placed(world, p / total, piece.normal));
        }
        return out;
    }

    // Points spread over a sphere or a cylinder's side.
    static std::vector<Sample> round_samples(const geometry::RoundPiece& piece, const Transform& world) {
        std::vector<Sample> out;
        const Vec3 axis = piece.cap - piece.base;
        const auto [u, v] = geometry::plane_basis(piece.cylinder ? normalize(axis) : Vec3{0, 0, 1});
        for (int k = 0; k < kSamples; ++k) {
            const double angle = 2.0 * std::numbers::pi * spread(k, 0);
            const Vec3 around = u * std::cos(angle) + v * std::sin(angle);
            if (piece.cylinder) {
                const Vec3 at = piece.base + axis * (0.1 + 0.8 * spread(k, 1));
                out.push_back(placed(world, at + around * piece.radius, around));
            } else {
                const double z = 2.0 * spread(k, 1) - 1.0;
                const Vec3 d = around * std::sqrt(1.0 - z * z) + Vec3{0, 0, 1} * z;
                out.push_back(placed(world, piece.base + d * piece.radius, d));
            }
        }
        return out;
    }

    std::size_t owner(Owner o) {
        m_owners.push_back(std::move(o));
        return m_owners.size() - 1;
    }

    // The look of `t` at `p` (the texture's enclosing space) with geometric normal `n`; `map_owner` is the
    // texture_map all values belong to when inside one.
    void look(const scene::Texture& t, const Vec3& p, const Vec3& n, Look& out, std::ptrdiff_t map_owner) {
        SurfacePoint surface{p, n, -n, false};
        if (!t.texture_map.empty() && !t.material_map) {
            const scene::Pattern& pattern = t.map_pattern;
            const std::size_t self = map_owner >= 0 ? static_cast<std::size_t>(map_owner)
                                                    : owner({"texture_map", {}, nullptr, nullptr, &pattern});
            const Vec3 q = warp_point(pattern, p);
            if (pattern.type == scene::Pattern::Type::Average) {
                for (const scene::TextureMapEntry& e : t.texture_map) look(e.texture, q, n, out, static_cast<std::ptrdiff_t>(self));
                return;
            }
            const auto& map = t.texture_map;
            const MapLookup m = search_map(pattern_value(pattern, q, m_noise_generator, &surface),
                                           static_cast<int>(map.size()), [&](int i) { return map[i].value; });
            Look cur, prev;
            look(map[static_cast<std::size_t>(m.cur)].texture, q, n, cur, static_cast<std::ptrdiff_t>(self));
            if (m.prev != m.cur) look(map[static_cast<std::size_t>(m.prev)].texture, q, n, prev, static_cast<std::ptrdiff_t>(self));
            for (std::size_t k = 0; k < cur.values.size(); ++k) {
                const bool blend = prev.values.size() == cur.values.size();
                out.values.push_back(blend ? cur.values[k] * m.fraction + prev.values[k] * (1.0 - m.fraction)
                                           : cur.values[k]);
                out.owners.push_back(self);
            }
            return;
        }
        auto layer_look = [&](const scene::Texture& layer) {
            // A solid pigment counts too: texture_map entries of different colours jump between them.
            const Color c = evaluate_pigment(layer.pigment, p, m_noise_generator, &surface);
            const std::size_t who = map_owner >= 0 ? static_cast<std::size_t>(map_owner)
                                                   : owner({"pigment", layer.pigment.loc, &layer.pigment});
            for (double v : {c.r, c.g, c.b, c.filter, c.transmit}) {
                out.values.push_back(v);
                out.owners.push_back(who);
            }
            if (layer.normal.perturbs()) {
                const Vec3 tilted = perturb_normal(layer.normal, n, p, m_noise_generator, &surface);
                const std::size_t who = map_owner >= 0 ? static_cast<std::size_t>(map_owner)
                                                       : owner({"normal", layer.normal.loc, nullptr, &layer.normal});
                for (int a = 0; a < 3; ++a) {
                    out.values.push_back(tilted[a]);
                    out.owners.push_back(who);
                }
            }
        };
        layer_look(t);
        for (const scene::Texture& layer : t.layers) layer_look(layer);
    }

    // The owner of the first value that differs between the two looks, or -1 when they agree.
    static std::ptrdiff_t first_difference(const Look& a, const Look& b) {
        if (a.values.size() != b.values.size()) return a.owners.empty() ? -1 : static_cast<std::ptrdiff_t>(a.owners[0]);
        for (std::size_t k = 0; k < a.values.size(); ++k) {
            const double scale = std::max({1.0, std::abs(a.values[k]), std::abs(b.values[k])});
            if (std::abs(a.values[k] - b.values[k]) > kDifferent * scale) return static_cast<std::ptrdiff_t>(a.owners[k]);
        }
        return -1;
    }

    // The keyword of the pattern of `o` whose value jumps between the two points, when it is the pigment's, the
    // normal's or the map's own (or a pigment_map entry's); else empty.
    std::string jumping_pattern(const Owner& o, const Vec3& inside, const Vec3& outside) const {
        auto jumps = [&](const scene::Pattern& pattern, const Vec3& a, const Vec3& b) {
            if (!pattern_varies(pattern)) return false;
            const double va = pattern_value(pattern, a, m_noise_generator);
            const double vb = pattern_value(pattern, b, m_noise_generator);
            return std::abs(va - vb) > kDifferent;
        };
        auto keyword = [](const scene::Pattern& pattern) {
            for (const auto& k : scene::k_pattern_keywords)
                if (k.value == pattern.type) return std::string(k.keyword);
            return std::string();
        };
        const scene::Pattern* head = o.map ? o.map : o.pigment ? &o.pigment->pattern : o.normal ? &o.normal->pattern : nullptr;
        if (head == nullptr) return "";
        const Vec3 a = warp_point(*head, inside), b = warp_point(*head, outside);
        // POV-Ray compat: quilted's normal flips across its cells' faces though its value does not.
        if (jumps(*head, a, b) || (o.normal && head->type == scene::Pattern::Type::Quilted)) return keyword(*head);
        if (o.pigment)
            for (const scene::PigmentMapEntry& e : o.pigment->pigment_map)
                if (jumps(e.pigment.pattern, warp_point(e.pigment.pattern, a), warp_point(e.pigment.pattern, b)))
                    return keyword(e.pigment.pattern);
        return "";
    }

    void test(const scene::Object& o, const scene::Texture& texture, const std::vector<Sample>& samples,
              const char* surface) {
        std::vector<std::size_t> votes;
        std::vector<std::pair<Vec3, Vec3>> where;  // a pair of points on either side, per owner
        for (const Sample& s : samples) {
            if (m_looks >= kLookBudget) return;
            m_looks += 2;
            const double step = kStep * std::max(1.0, std::abs(dot(s.n, s.p))) + kMixing * length(s.p);
            const Vec3 inside = s.p - s.n * step, outside = s.p + s.n * step;
            Look a, b;
            m_owners.clear();
            look(texture, inside, s.n, a, -1);
            look(texture, outside, s.n, b, -1);
            const std::ptrdiff_t who = first_difference(a, b);
            if (who < 0) continue;
            const auto index = static_cast<std::size_t>(who);
            if (votes.size() <= index) {
                votes.resize(index + 1, 0);
                where.resize(index + 1);
            }
            if (votes[index]++ == 0) where[index] = {inside, outside};
        }
        for (std::size_t k = 0; k < votes.size(); ++k) {
            if (2 * votes[k] < samples.size()) continue;
            // The owners are rebuilt per look in the same order: index k names the same part each time.
            Look again;
            m_owners.clear();
            look(texture, where[k].first, samples.front().n, again, -1);
            if (k >= m_owners.size()) continue;
            const Owner& who = m_owners[k];
            m_found.push_back({who.map ? o.loc : who.loc, o.loc, scene::shape_keyword(o.shape), surface, who.part,
                               jumping_pattern(who, where[k].first, where[k].second)});
            return;  // one report per primitive
        }
    }

    int m_noise_generator = 2;
    const scene::Camera& m_camera;
    std::vector<Owner> m_owners;
    std::vector<PatternWrap> m_found;
    std::size_t m_looks = 0;
};

// Whether the pattern's value wraps from 1 back to 0 (a ramp through space) rather than jumping otherwise.
bool wraps(const std::string& pattern) {
    for (const char* p : {"gradient", "onion", "marble", "wood", "radial", "spiral1", "spiral2", "agate", "ripples",
                          "waves", "spherical", "cylindrical", "planar", "boxed"})
        if (pattern == p) return true;
    return false;
}

}  // namespace

std::vector<PatternWrap> find_pattern_wraps(const scene::Scene& scene, std::size_t limit, std::size_t* total) {
    Finder finder(scene);
    std::vector<PatternWrap> out;
    // One report per pair of places: a declared object used many times shows its surface once.
    std::set<std::tuple<std::string, std::uint32_t, std::uint32_t, std::string, std::uint32_t, std::uint32_t>> seen;
    std::size_t distinct = 0;
    for (PatternWrap& w : finder.found()) {
        if (!seen.emplace(w.where.path, w.where.line, w.where.column, w.object.path, w.object.line, w.object.column)
                 .second)
            continue;
        ++distinct;
        if (out.size() < limit) out.push_back(std::move(w));
    }
    if (total) *total = distinct;
    return out;
}

std::vector<Diagnostic> pattern_wrap_warnings(const scene::Scene& scene, std::size_t limit) {
    std::size_t total = 0;
    std::vector<Diagnostic> out;
    for (const PatternWrap& w : find_pattern_wraps(scene, limit, &total)) {
        Diagnostic d;
        d.severity = Severity::Warning;
        d.loc = w.where;
        const std::string what = w.part == std::string("texture_map") ? "the texture_map of this " + w.object_kind
                                                                       : "this " + w.part;
        // Why it jumps: the pattern's value wraps (from 1 back to 0, the ramp's and the map's two ends), or
        // quilted's normal flips at a face of its cells.
        const std::string why = w.pattern.empty()     ? "a pattern inside it jumps there"
                              : w.pattern == "quilted" && w.part == std::string("normal")
                                  ? "its quilted normal flips there, at a face of its unit cells"
                              : wraps(w.pattern) ? "its " + w.pattern + " pattern wraps there, from the end of its map to the start"
                                                 : "its " + w.pattern + " pattern jumps there";
        const bool whole = w.surface == std::string("sphere") || w.object_kind == std::string("plane") ||
                           w.object_kind == std::string("disc") || w.object_kind == std::string("polygon");
        const std::string on = whole ? "the surface of the " + w.object_kind
                                     : "a " + w.surface + " of the " + w.object_kind;
        d.message = "pattern wrap on a surface: " + what + " changes abruptly exactly on " + on + " at " +
                    place(w.object) + " (" + why + "); POV-Ray "
                    "shows either side at random there (a speckle), so this picture may differ from POV-Ray's; "
                    "scale or translate the pattern or the object by a small amount";
        out.push_back(std::move(d));
    }
    add_count_of_the_rest(out, total, "pattern wrap on a surface", "surfaces");
    return out;
}

}  // namespace wardray::texture
