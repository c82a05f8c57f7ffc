// Media sampling: POV-Ray 3.7's ComputeMedia (media.cpp) over one ray segment: the intervals lit by each light,
// the sampling intervals, regular (methods 1, 2) and adaptive (method 3) sampling, and the phase functions.
#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

#include "core/constants.h"
#include "core/render_seed.h"
#include "media/media_density.h"
#include "media/participating_media.h"
#include "texture/pigment.h"

namespace wardray::media {

namespace {

// POV-Ray's BOUND_HUGE (the depth of a ray that hits nothing), MAX_DISTANCE and SMALL_TOLERANCE.
constexpr double kBoundHuge = 2.0e10;
constexpr double kMaxDistance = 1.0e7;
constexpr double kSmallTolerance = 0.001;

Vec3 exp3(const Vec3& v) { return {std::exp(v.x), std::exp(v.y), std::exp(v.z)}; }
double colour_distance(const Vec3& a, const Vec3& b) {
    return std::fabs(a.x - b.x) + std::fabs(a.y - b.y) + std::fabs(a.z - b.z);
}
bool is_zero(const Color& c) { return c.r == 0.0 && c.g == 0.0 && c.b == 0.0; }
Vec3 extinction_of(const scene::Media& m) { return m.absorption.rgb() + m.scattering.rgb() * m.extinction; }

// A stretch of the ray lit (or not) by the lights (POV-Ray's LitInterval).
struct LitInterval {
    bool lit = false;
    double s0 = 0.0, s1 = 0.0;
};

// The stretch of the ray one light reaches (LightSourceEntry).
struct LightEntry {
    std::size_t light = 0;
    double s0 = 0.0, s1 = 0.0;
};

// One sampling interval and what its samples gathered (MediaInterval).
struct Interval {
    bool lit = false;
    int samples = 0;
    double s0 = 0.0, s1 = 0.0, ds = 0.0;
    Vec3 od, te, te2;
};

// Jitter and method 1's random positions: SplitMix64 seeded by the ray and the render seed, so renders repeat for
// any thread count.
class Random {
public:
    Random(const Segment& s, std::uint64_t seed) {
        auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
        m_state = bits(s.origin.x) ^ (bits(s.origin.y) * 0x9E3779B97F4A7C15ull) ^ (bits(s.origin.z) << 7) ^
                  (bits(s.direction.x) * 0xBF58476D1CE4E5B9ull) ^ (bits(s.direction.y) >> 3) ^
                  (bits(s.direction.z) * 0x94D049BB133111EBull);
        m_state = reseed(m_state, seed);
    }
    double uniform() {
        std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    }

private:
    std::uint64_t m_state = 0;
};

// POV-Ray's ComputeSpotLightInterval: where the ray is inside the spotlight's falloff cone.
bool spot_interval(const Segment& ray, const scene::Light& light, double& d1, double& d2) {
    const double cos_falloff = std::cos(light.falloff * std::numbers::pi / 180.0);
    const Vec3 axis = normalize(light.point_at - light.position);
    const double m = 1.0 / (cos_falloff * cos_falloff);
    const Vec3 v1 = ray.origin - light.position;
    const double k1 = dot(ray.direction, axis);
    const double k2 = dot(v1, axis);
    const double l = length(v1);
    const bool in_cone = l > kPovEpsilon && k2 / l >= cos_falloff;
    if (k1 <= 0.0 && k2 < 0.0) return false;
    const double k3 = dot(v1, ray.direction);
    const double k4 = dot(v1, v1);
    const double a = 1.0 - k1 * k1 * m;
    const double b = k3 - k1 * k2 * m;
    const double c = k4 - k2 * k2 * m;
    // POV-Ray tests the discriminant (a squared length) against EPSILON; relative to the squared distance from the
    // light the test is the same in any scene unit (a scene scaled by 1e-4 would otherwise see most rays graze).
    const double epsilon = kPovEpsilon * k4;
    if (a != 0.0) {
        double d = b * b - a * c;
        if (d > epsilon) {
            d = std::sqrt(d);
            double t1 = (-b + d) / a, t2 = (-b - d) / a;
            if (t1 > t2) std::swap(t1, t2);
            const double l1 = k2 + t1 * k1, l2 = k2 + t2 * k1;
            if (l1 <= 0.0 && l2 <= 0.0) return false;
            if (l1 <= 0.0 || l2 <= 0.0) {
                if (l1 <= 0.0) {
                    if (in_cone) {
                        t1 = 0.0;
                        t2 = t2 > 0.0 ? t2 : kMaxDistance;
                    } else {
                        t1 = t2;
                        t2 = kMaxDistance;
                    }
                } else if (in_cone) {
                    t2 = t1;
                    t1 = 0.0;
                } else {
                    t2 = kMaxDistance;
                }
            }
            d1 = t1;
            d2 = t2;
            return true;
        }
        if (d > -epsilon) {
            d1 = in_cone ? 0.0 : -b / a;
            d2 = in_cone ? -b / a : kMaxDistance;
            return true;
        }
    } else if (in_cone) {
        d1 = 0.0;
        d2 = -c / b;
        return true;
    }
    return false;
}

// POV-Ray's ComputeCylinderLightInterval: where the ray is inside the cylinder light's falloff radius.
bool cylinder_interval(const Segment& ray, const scene::Light& light, double& d1, double& d2) {
    const Vec3 axis = normalize(light.point_at - light.position);
    const Vec3 v1 = ray.origin - light.position;
    const double k1 = dot(ray.direction, axis);
    const double k2 = dot(v1, axis);
    if (k1 <= 0.0 && k2 < 0.0) return false;
    const double a = 1.0 - k1 * k1;
    if (a == 0.0) return false;
    const double k3 = dot(v1, ray.direction);
    const double k4 = dot(v1, v1);
    const double b = k3 - k1 * k2;
    const double c = k4 - k2 * k2 - light.falloff * light.falloff;
    double d = b * b - a * c;
    // As for spotlights: EPSILON relative to the squared distance from the light, whatever the scene's unit.
    if (!(d > kPovEpsilon * k4)) return false;
    d = std::sqrt(d);
    double t1 = (-b + d) / a, t2 = (-b - d) / a;
    if (t1 > t2) std::swap(t1, t2);
    const double l1 = k2 + t1 * k1, l2 = k2 + t2 * k1;
    if (l1 <= 0.0 && l2 <= 0.0) return false;
    if (l1 <= 0.0 || l2 <= 0.0) {
        if (l1 <= 0.0) t1 = 0.0;
        else t2 = (kMaxDistance - k2) / k1;
    }
    d1 = t1;
    d2 = t2;
    return true;
}

using Thresholds = ParticipatingMedia::Thresholds;

// One ComputeMedia call: the media, the segment and what its samples need.
class Walk {
public:
    Walk(const scene::Scene& scene, const Thresholds& thresholds, int noise, const MediaList& media,
         const Segment& segment, double depth, const LightQuery* lights, std::uint64_t seed)
        : m_scene(scene), m_thresholds(thresholds), m_noise(noise), m_media(media), m_ray(segment), m_depth(depth),
          m_lights(lights), m_photons(lights ? lights->photons() : nullptr), m_random(segment, seed) {}

    Vec3 run(const Vec3& colour);
    /// POV-Ray's ComputeMediaAndDepositPhotons and DepositMediaPhotons.
    Vec3 deposit(const Vec3& colour, const PhotonDeposit& d, std::vector<DepositPoint>& out);

private:
    void light_entries();
    void lit_intervals(std::vector<LitInterval>& lit) const;
    void sample_intervals(const std::vector<LitInterval>& lit, const scene::Media& im);
    void sample(Interval& iv, double d0, Vec3& col, Vec3& od, int method);
    void recursive(Interval& iv, double d1, double d3, Vec3& result, const Vec3& c1, const Vec3& c3, Vec3& od_result,
                   const Vec3& od1, const Vec3& od3, int depth, double jitter);
    void regular(const scene::Media& im, bool all_constant);
    void adaptive(const scene::Media& im);
    double phase(const Vec3& to_light) const;

    const scene::Scene& m_scene;
    const Thresholds& m_thresholds;
    int m_noise;
    const MediaList& m_media;
    Segment m_ray;
    double m_depth;
    const LightQuery* m_lights;  ///< null on a shadow ray and on a photon's ray
    const MediaPhotons* m_photons;  ///< null without photons in media
    std::vector<MediaPhotons::Sample> m_gathered;
    Random m_random;
    bool m_use_scattering = false;
    double m_aa_threshold = 0.0;
    std::vector<LightEntry> m_entries;
    std::vector<Interval> m_intervals;
};

Vec3 Walk::run(const Vec3& colour) {
    const bool shadow = m_lights == nullptr;
    // POV-Ray: the media with the most intervals sets the sampling; the smallest aa_threshold applies.
    const scene::Media* im = m_media.items[0];
    bool use_extinction = false;
    bool all_constant = shadow;
    m_aa_threshold = HUGE_VAL;
    for (int i = 0; i < m_media.size; ++i) {
        const scene::Media& m = *m_media.items[i];
        if (m.intervals > im->intervals) im = &m;
        m_aa_threshold = std::min(m_aa_threshold, m.aa_threshold);
        use_extinction = use_extinction || !is_zero(m.absorption) || !is_zero(m.scattering);
        m_use_scattering = m_use_scattering || !is_zero(m.scattering);
        // POV-Ray compat: only the first density decides whether the media counts as constant here.
        if (!m.densities.empty()) all_constant = all_constant && m.densities.front().is_solid();
    }
    if (shadow && !use_extinction) return colour;
    std::vector<LitInterval> lit;
    if (!shadow) light_entries();
    lit_intervals(lit);
    sample_intervals(lit, *im);
    if (im->method == 3 && !all_constant) adaptive(*im);
    else regular(*im, all_constant);
    // POV-Ray's ComputeMediaColour: each interval's light, dimmed by the optical depth in front of it.
    Vec3 od, te;
    for (const Interval& iv : m_intervals) {
        const double n = 1.0 / iv.samples;
        te += iv.te * n * exp3(-od);
        od += iv.od * n;
    }
    return colour * exp3(-od) + te;
}

Vec3 Walk::deposit(const Vec3& colour, const PhotonDeposit& d, std::vector<DepositPoint>& out) {
    const scene::Media* im = m_media.items[0];
    bool use_extinction = false;
    for (int i = 0; i < m_media.size; ++i) {
        const scene::Media& m = *m_media.items[i];
        if (m.intervals > im->intervals) im = &m;
        use_extinction = use_extinction || !is_zero(m.absorption) || !is_zero(m.scattering);
        m_use_scattering = m_use_scattering || !is_zero(m.scattering);
    }
    // POV-Ray compat: media without extinction neither dim the photon nor keep any of it.
    if (!use_extinction) return colour;
    // The lit and sampling intervals as for a camera ray: the lights' cones split the ray.
    std::vector<LitInterval> lit;
    light_entries();
    lit_intervals(lit);
    sample_intervals(lit, *im);
    for (Interval& iv : m_intervals) {
        // One photon every step · factor; past max_steps, max_steps photons spaced wider.
        int n = static_cast<int>(iv.ds / (d.step * d.factor));
        double factor = d.factor;
        if (n > d.max_steps) {
            n = d.max_steps;
            factor = iv.ds / (d.step * n);
        }
        for (int j = 0; j < n; ++j) {
            const double d0 = (j + 0.5 + m_random.uniform() * d.jitter - 0.5 * d.jitter) / n;
            Vec3 c, od;
            sample(iv, d0, c, od, 2);
            if (m_use_scattering) out.push_back({iv.s0 + d0 * iv.ds, factor});
        }
    }
    // POV-Ray compat: an interval without a sample divides 0 by 0 here (NaN).
    Vec3 od;
    for (const Interval& iv : m_intervals) od += iv.od / static_cast<double>(iv.samples);
    return colour * exp3(-od);
}

void Walk::light_entries() {
    for (std::size_t i = 0; i < m_scene.lights.size(); ++i) {
        const scene::Light& light = m_scene.lights[i];
        // POV-Ray compat: shadowless lights (FILL_LIGHT_SOURCE) never light media.
        if (!light.media_interaction || light.shadowless) continue;
        double t1 = 0.0, t2 = m_depth;
        bool insert = true;
        // POV-Ray drops a cone that ends within SMALL_TOLERANCE of the origin; as a fraction of the segment (or of
        // the distance to the light, for a ray to the sky) it drops the same cones in any scene unit.
        const double tolerance = kSmallTolerance * std::min(m_depth, length(m_ray.origin - light.position));
        if (light.type == scene::Light::Type::Spot)
            insert = spot_interval(m_ray, light, t1, t2) && t1 < m_depth && t2 > tolerance;
        else if (light.type == scene::Light::Type::Cylinder)
            insert = cylinder_interval(m_ray, light, t1, t2) && t1 < m_depth && t2 > tolerance;
        if (insert) m_entries.push_back({i, std::max(t1, 0.0), std::min(t2, m_depth)});
    }
}

void Walk::lit_intervals(std::vector<LitInterval>& lit) const {
    if (!m_entries.empty()) {
        // POV-Ray compat (its "workaround" path): starts and ends are sorted separately, then merged.
        std::vector<double> s0, s1;
        for (const LightEntry& e : m_entries) {
            s0.push_back(e.s0);
            s1.push_back(e.s1);
        }
        std::sort(s0.begin(), s0.end());
        std::sort(s1.begin(), s1.end());
        if (s0[0] > 0.0) lit.push_back({false, 0.0, s0[0]});
        lit.push_back({true, s0[0], s1[0]});
        for (std::size_t i = 1; i < s0.size(); ++i) {
            if (s0[i] > lit.back().s1) {
                const double from = lit.back().s1;
                lit.push_back({false, from, s0[i]});
                lit.push_back({true, s0[i], s1[i]});
            } else if (s1[i] > lit.back().s1) {
                lit.back().s1 = s1[i];
            }
        }
        if (lit.back().s1 < m_depth) {
            const double from = lit.back().s1;
            lit.push_back({false, from, m_depth});
        }
    }
    if (lit.empty()) lit.push_back({false, 0.0, m_depth});
}

void Walk::sample_intervals(const std::vector<LitInterval>& lit, const scene::Media& im) {
    // POV-Ray's ComputeMediaSampleInterval: at least one interval per lit interval.
    const std::size_t count = std::max(static_cast<std::size_t>(im.intervals), lit.size());
    auto split = [&](const LitInterval& l, std::size_t n) {
        const double delta = (l.s1 - l.s0) / static_cast<double>(n);
        for (std::size_t j = 0; j < n; ++j)
            m_intervals.push_back({l.lit, 0, l.s0 + delta * j, l.s0 + delta * (j + 1), delta, {}, {}, {}});
    };
    if (lit.size() == 1) {
        // One interval for unlit constant media, else uniform intervals.
        if (!lit[0].lit && im.densities.empty()) split(lit[0], 1);
        else split(lit[0], count);
    } else {
        // Intervals shared out by `ratio` between lit and unlit stretches.
        double sum = 0.0;
        for (const LitInterval& l : lit) sum += l.lit ? im.ratio : 1.0 - im.ratio;
        std::size_t remaining = count;
        for (std::size_t i = 0; i < lit.size(); ++i) {
            const double weight = lit[i].lit ? im.ratio : 1.0 - im.ratio;
            std::size_t n = static_cast<std::size_t>(weight / sum * static_cast<double>(count)) + 1;
            const std::size_t r = remaining - lit.size() + i + 1;
            n = std::min(n, r);
            split(lit[i], n);
            remaining -= n;
        }
    }
    // Stretches before the first and after the last interval are sampled too.
    if (m_intervals.front().s0 > 0.0) {
        const double s = m_intervals.front().s0;
        m_intervals.insert(m_intervals.begin(), Interval{false, 0, 0.0, s, s, {}, {}, {}});
    }
    if (m_intervals.back().s1 < m_depth) {
        const double s = m_intervals.back().s1;
        m_intervals.push_back({false, 0, s, m_depth, m_depth - s, {}, {}, {}});
    }
}

double Walk::phase(const Vec3& to_light) const {
    // POV-Ray's phase functions, normalised so that isotropic scattering is 1; averaged over the media.
    const double alpha = dot(to_light, m_ray.direction);
    double k = 0.0;
    for (int i = 0; i < m_media.size; ++i) {
        const scene::Media& m = *m_media.items[i];
        switch (m.scattering_type) {
            case 4: k += 0.799372013 * (1.0 + alpha * alpha); break;                                // Rayleigh
            case 2: k += 0.576655375 * (1.0 + 9.0 * std::pow(0.5 * (1.0 + alpha), 8.0)); break;    // Mie hazy
            case 3: k += 0.495714547 * (1.0 + 50.0 * std::pow(0.5 * (1.0 + alpha), 32.0)); break;  // Mie murky
            case 5: {                                                                             // Henyey-Greenstein
                const double g = m.eccentricity;
                k += (1.0 - g * g) / std::pow(1.0 + g * g - 2.0 * g * alpha, 1.5);
                break;
            }
            default: k += 1.0; break;
        }
    }
    return k / m_media.size;
}

void Walk::sample(Interval& iv, double d0, Vec3& col, Vec3& od, int method) {
    // POV-Ray's ComputeOneMediaSample at fraction d0 of the interval.
    const bool shadow = m_lights == nullptr;
    d0 *= iv.ds;
    const double d1 = iv.s0 + d0;
    const Vec3 h = m_ray.origin + m_ray.direction * d1;
    Vec3 emission, extinction, scattering;
    for (int i = 0; i < m_media.size; ++i) {
        const scene::Media& m = *m_media.items[i];
        const Vec3 density = media_density(m, h, m_noise);
        extinction += density * extinction_of(m);
        if (!shadow) {
            emission += density * m.emission.rgb();
            scattering += density * m.scattering.rgb();
        }
    }
    od = extinction * iv.ds;
    if (method != 3) iv.od += od;
    if (!shadow && m_use_scattering) {
        if (iv.lit) {
            for (const LightEntry& e : m_entries) {
                if (d1 < e.s0 || d1 > e.s1) continue;
                Vec3 to_light;
                const Vec3 light = m_lights->arriving(e.light, h, to_light);
                if (light == Vec3{}) continue;
                emission += scattering * light * phase(to_light);
            }
        }
        // POV-Ray's ComputeMediaPhotons, lit interval or not: the photons within a sphere of radius r, each
        // scattered by the phase function, over the sphere's volume 4/3 π r³ (Jensen & Christensen 1998, eq. 7).
        if (m_photons) {
            const double r = m_photons->gather(h, m_gathered);
            Vec3 sum;
            for (const MediaPhotons::Sample& ph : m_gathered) sum += scattering * ph.colour * phase(ph.to_origin);
            if (r > 0.0) emission += sum * (3.0 / (4.0 * std::numbers::pi * r * r * r));
        }
    }
    // Method 3 attenuates in order later; the others assume constant extinction over the interval.
    if (method == 3) emission = emission * iv.ds;
    else emission = emission * iv.ds * exp3(-extinction * d0);
    col = emission;
    if (method != 3) {
        iv.te += emission;
        iv.te2 += emission * emission;
    }
    ++iv.samples;
}

void Walk::recursive(Interval& iv, double d1, double d3, Vec3& result, const Vec3& c1, const Vec3& c3,
                     Vec3& od_result, const Vec3& od1, const Vec3& od3, int depth, double jitter) {
    // POV-Ray's ComputeOneMediaSampleRecursive, with its 1:1:1 and 2:1 weights.
    const double d2 = 0.5 * (d1 + d3);
    const double jd = jitter != 0.0 ? d2 + jitter * (d3 - d1) * (m_random.uniform() - 0.5) : d2;
    Vec3 c2, od2, r2, odr2;
    sample(iv, jd, c2, od2, 3);
    if (depth <= 0) {
        result = (c1 + c2 + c3) / 3.0;
        od_result = (od1 + od2 + od3) / 3.0;
        return;
    }
    if (colour_distance(c1, c2) > m_aa_threshold) {
        recursive(iv, d1, d2, r2, c1, c2, odr2, od1, od2, depth - 1, jitter);
        result = r2 / 2.0;
        od_result = odr2 / 2.0;
    } else {
        result = c1 / 3.0 + c2 / 6.0;
        od_result = od1 / 3.0 + od2 / 6.0;
    }
    if (colour_distance(c2, c3) > m_aa_threshold) {
        recursive(iv, d2, d3, r2, c2, c3, odr2, od2, od3, depth - 1, jitter);
        result += r2 / 2.0;
        od_result += odr2 / 2.0;
    } else {
        result += c2 / 6.0 + c3 / 3.0;
        od_result += od2 / 6.0 + od3 / 3.0;
    }
}

void Walk::adaptive(const scene::Media& im) {
    // POV-Ray's ComputeMediaAdaptiveSampling: samples/2 + 1 (at least 2) points spaced 1/(count + 1) apart, each
    // pair refined recursively up to aa_level where neighbours differ by more than aa_threshold.
    const double jitter = im.jitter;
    auto jittered = [&](double d, double dd) { return jitter != 0.0 ? d + dd * jitter * (m_random.uniform() - 0.5) : d; };
    for (Interval& iv : m_intervals) {
        const int count = std::max(2, static_cast<int>(im.min_samples / 2.0) + 1);
        const double dd = 1.0 / (count + 1);
        double d0 = 0.0;
        Vec3 c0, od0, c1, od1, result, od_result;
        sample(iv, jittered(d0, dd), c0, od0, 3);
        iv.te = Vec3{};
        iv.od = Vec3{};
        const double n = 1.0 / count;
        d0 += dd;
        for (int j = 1; j <= count; ++j, d0 += dd) {
            sample(iv, jittered(d0, dd), c1, od1, 3);
            recursive(iv, d0 - dd, d0, result, c0, c1, od_result, od0, od1, im.aa_level - 1, jitter);
            // POV-Ray compat: the samples go in order, so each is dimmed by the depth gathered before it.
            iv.te += result * exp3(-iv.od * n);
            c0 = c1;
            iv.od += od_result;
            od0 = od1;
        }
        iv.samples = count;
    }
}

void Walk::regular(const scene::Media& im, bool all_constant) {
    // POV-Ray's ComputeMediaRegularSampling: method 2 stratified (jittered), method 1 (and 3 on constant shadow
    // rays) at random positions; constant media on shadow rays need only one sample.
    Vec3 c0, od0;
    const int min_samples = im.min_samples;
    for (Interval& iv : m_intervals) {
        for (int j = 0; j < min_samples; ++j) {
            if (im.method == 2) {
                const double d0 = (j + 0.5) / min_samples + m_random.uniform() * im.jitter / min_samples;
                sample(iv, d0, c0, od0, 2);
            } else {
                sample(iv, m_random.uniform(), c0, od0, 1);
            }
            if (all_constant) break;
        }
    }
    if (m_lights == nullptr || im.max_samples <= min_samples) return;
    // More samples until the variance is below the confidence threshold for the count so far.
    const std::vector<double>& threshold = m_thresholds.at(&im);
    auto variance = [](const Interval& iv) {
        const double n = 1.0 / iv.samples;
        return (iv.te2 * n - (iv.te * n) * (iv.te * n)) * n;
    };
    for (Interval& iv : m_intervals) {
        if (iv.samples >= im.max_samples) continue;
        Vec3 va = variance(iv);
        while (true) {
            const double th = threshold[static_cast<std::size_t>(std::min(iv.samples, im.max_samples) - 1)];
            if (va.x < th && va.y < th && va.z < th) break;
            sample(iv, m_random.uniform(), c0, od0, 1);
            if (iv.samples > im.max_samples) break;
            va = variance(iv);
        }
    }
}

}  // namespace

namespace {

/// Calls `f` on every medium of the interiors of `o` and its CSG children (a child's own interior is the one rays
/// inside it see).
template <typename F>
void for_each_interior_media(const scene::Object& o, const F& f) {
    for (const scene::Media& m : o.interior.media) f(m);
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape))
        for (const scene::Object& child : csg->children) for_each_interior_media(child, f);
}

}  // namespace

ParticipatingMedia::ParticipatingMedia(const scene::Scene& scene, std::uint64_t seed)
    : m_scene(scene), m_noise_generator(scene.global.noise_generator), m_seed(seed) {
    m_atmosphere.add(scene.media);
    // POV-Ray's Media::PostProcess: the variance below which methods 1 and 2 stop adding samples, per sample count.
    auto thresholds = [&](const scene::Media& m) {
        if (m.method == 3 || m.max_samples <= m.min_samples) return;
        std::vector<double>& th = m_thresholds[&m];
        th.assign(static_cast<std::size_t>(m.max_samples), 0.0);
        double t = inverse_chi_square_tail(m.max_samples - 1, m.confidence);
        t = t > 0.0 ? m.variance / t : m.variance * kPovEpsilon;
        for (int i = 0; i < m.max_samples; ++i) th[i] = t * inverse_chi_square_tail(i + 1, m.confidence);
    };
    for (const scene::Media& m : scene.media) thresholds(m);
    for (const scene::Object& o : scene.objects)
        for_each_interior_media(o, thresholds);
}

bool ParticipatingMedia::in_scene(const scene::Scene& scene) {
    if (!scene.media.empty()) return true;
    bool any = false;
    for (const scene::Object& o : scene.objects) for_each_interior_media(o, [&](const scene::Media&) { any = true; });
    return any;
}

Vec3 ParticipatingMedia::along(const MediaList& media, const Segment& segment, const Vec3& colour,
                               const LightQuery& lights) const {
    if (media.empty()) return colour;
    const double depth = std::isfinite(segment.length) ? segment.length : kBoundHuge;
    Walk walk(m_scene, m_thresholds, m_noise_generator, media, segment, depth, &lights, m_seed);
    return walk.run(colour);
}

Vec3 ParticipatingMedia::deposit_photons(const MediaList& media, const Segment& segment, const Vec3& colour,
                                         const PhotonDeposit& deposit, std::vector<DepositPoint>& out) const {
    if (media.empty() || !(deposit.step > 0.0)) return colour;
    const double depth = std::isfinite(segment.length) ? segment.length : kBoundHuge;
    Walk walk(m_scene, m_thresholds, m_noise_generator, media, segment, depth, nullptr, m_seed);
    return walk.deposit(colour, deposit, out);
}

Vec3 ParticipatingMedia::transmittance(const MediaList& media, const Segment& segment) const {
    if (media.empty()) return {1.0, 1.0, 1.0};
    const double depth = std::isfinite(segment.length) ? segment.length : kBoundHuge;
    Walk walk(m_scene, m_thresholds, m_noise_generator, media, segment, depth, nullptr, m_seed);
    return walk.run({1.0, 1.0, 1.0});
}

}  // namespace wardray::media
