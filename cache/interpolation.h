// Interpolation: which cached records are valid at a point, how they are weighted, and their gradient extrapolation.
#pragma once

#include "cache/irradiance_record.h"
#include "scene/scene.h"
#include "core/vec3.h"

namespace wardray::cache {

/// The parameters of one lookup, derived from the scene's radiosity block by lookup_params().
///
/// error_bound mapping (POV-Ray 3.7, radiosity.cpp AverageNearBlock): a record is valid when
///   ε = |p − p_i| / R_i + 2 √(1 − n·n_i) < error_bound_eff,
/// with R_i the clamped harmonic mean distance, and
///   error_bound_eff = error_bound × (low_error_factor in pretrace passes) [+ (0.25 − w) when the ray weight w is
///   below 0.25] × 2^depth.
/// wardray keeps that test unchanged, so error_bound (default 1.8) covers the same area per record as in POV-Ray
/// and trades error for time on the same scale; the gradients then lower the error at the same record count.
struct LookupParams {
    double error_bound = 1.8;  ///< error_bound_eff
    double reuse_count = 5.0;  ///< POV-Ray's nearest_count at this depth: 4·Σ coverage must reach it
    bool accept_any = true;    ///< POV-Ray's final pass: one valid record suffices unless always_sample
    bool smooth_coverage = true;  ///< POV-Ray smooths coverage weights in the final pass at depth 0 only
    bool gradients = true;        ///< add the gradient terms (off: POV-Ray 3.7's plain weighted average)
};

/// The lookup parameters POV-Ray 3.7 uses at `depth` in a final (`final_pass`) or pretrace pass, for a ray of
/// importance `ray_weight` (POV-Ray's weight of the ray that asks; 1 for camera rays).
LookupParams lookup_params(const scene::RadiositySettings& settings, int depth, bool final_pass,
                           double ray_weight = 1.0);

/// POV-Ray's default low_error_factor, the pretrace's error bound as a fraction of the final pass's.
constexpr double kPovLowErrorFactor = 0.5;

/// The low_error_factor wardray's pretrace uses for a scene's `low_error_factor` when the record passes follow it
/// (--gi-pretrace-bound=final): min(1, low_error_factor / 0.5). At POV-Ray's default the pretrace makes its records
/// at the final pass's bound. POV-Ray tightens it so that its final pass, which makes records as it goes, finds
/// few holes; wardray's record passes fill those before the final pass, and the gradients make a record reach
/// farther, so the pretrace's extra records cost more time than they take off the error (docs/reports/radiosity.md,
/// "The pretrace's error bound"). A smaller factor still asks for a denser pretrace, in the same proportion; a
/// larger one is the final pass's bound, as a sparser pretrace only leaves the record passes more to make.
double pretrace_low_error_factor(double low_error_factor);

/// Ward, Rubinstein & Clear 1988's error term with POV-Ray's doubled rotational part (see LookupParams):
/// ε = |p − p_i| / R_i + 2 √(1 − n·n_i).
double record_error(const IrradianceRecord& record, const Vec3& p, const Vec3& n);
/// record_error() of a record's packed geometry.
double record_error(const RecordGeometry& record, const Vec3& p, const Vec3& n);

/// The behind test's measure (Ward, Rubinstein & Clear 1988, "in front" test), scale-free:
/// (p − p_i)·(n + n_i)/|n + n_i| / R_i; clearly negative means the record lies in front of p.
double front_distance(const IrradianceRecord& record, const Vec3& p, const Vec3& n);
/// front_distance() of a record's packed geometry.
double front_distance(const RecordGeometry& record, const Vec3& p, const Vec3& n);

/// True when `record` may be reused at (p, n): ε below the bound, normals within 90°, and not in front of p.
bool is_valid(const IrradianceRecord& record, const Vec3& p, const Vec3& n, double error_bound);

/// The record's value moved to (p, n) with its gradients (Ward & Heckbert 1992):
/// E_i + (n_i × n)·∇r E_i + (p − p_i)·∇t E_i per channel, never crossing zero.
Vec3 extrapolate(const IrradianceRecord& record, const Vec3& p, const Vec3& n, bool gradients = true);
/// extrapolate() of the record made of these two parts.
Vec3 extrapolate(const RecordGeometry& geometry, const RecordValues& values, const Vec3& p, const Vec3& n,
                 bool gradients = true);

/// The outcome of a lookup.
struct Interpolation {
    Vec3 irradiance;          ///< weighted average of the valid records (zero when none)
    double weight_sum = 0.0;  ///< Σ w_i
    double coverage = 0.0;    ///< POV-Ray's reuse: Σ of the coverage weights, each in (0, 1]
    int records = 0;          ///< how many records were valid
    bool sufficient = false;  ///< enough records to skip a new gather (LookupParams::reuse_count, accept_any)
};

/// A valid record's weights at the lookup point: Ward's w_i and POV-Ray's coverage weight.
struct RecordWeight {
    double weight = 0.0;
    double coverage = 0.0;
};

/// Sums valid records into the interpolation at one point, in the order they are offered (which makes the result
/// deterministic for a deterministic order).
class InterpolationAccumulator {
public:
    /// `n` is normalised here.
    InterpolationAccumulator(const Vec3& p, const Vec3& n, const LookupParams& params);
    /// Tests `record` and adds it when valid; returns whether it was valid (weigh(), then add_weighted()).
    bool add(const IrradianceRecord& record);
    /// Tests a record by its geometry alone; when valid, writes its weights to `out` and returns true.
    bool weigh(const RecordGeometry& record, RecordWeight& out) const {
        return may_accept(record.position, record.normal, record.radius) && weigh_near(record, out);
    }
    /// weigh() for a record already known to lie within error_bound() × R_i of the point (RecordOctree::visit_near
    /// makes that test exactly as may_accept() does): the other tests only.
    bool weigh_near(const RecordGeometry& record, RecordWeight& out) const;
    /// Adds a record that weigh() accepted with weights `w`; the record is read only here.
    void add_weighted(const IrradianceRecord& record, const RecordWeight& w);
    /// add_weighted() of the record made of these two parts.
    void add_weighted(const RecordGeometry& geometry, const RecordValues& values, const RecordWeight& w);
    /// A quick necessary condition for add() to accept a record at `position` with `normal` and (at least) `radius`:
    /// near enough for ε alone and facing the same side (the distance first: it rejects most candidates).
    bool may_accept(const Vec3& position, const Vec3& normal, double radius) const {
        const Vec3 d = m_p - position;
        const double reach = m_params.error_bound * radius;
        if (!(dot(d, d) < reach * reach)) return false;
        return dot(m_n, normal) > 0.0;
    }
    /// The error bound of the lookup (LookupParams::error_bound).
    double error_bound() const { return m_params.error_bound; }
    /// The weighted average so far.
    Interpolation result() const;

private:
    /// Adds a record's value extrapolated to the point, with its weights.
    void add_sample(const Vec3& extrapolated, const RecordWeight& w);

    Vec3 m_p;
    Vec3 m_n;
    LookupParams m_params;
    double m_inverse_bound = 0.0;  ///< 1 / error_bound
    double m_weight_floor = 0.0;   ///< the ε at which Ward's weight is bounded
    Vec3 m_sum;
    double m_weight_sum = 0.0;
    double m_coverage = 0.0;
    int m_records = 0;
};

}  // namespace wardray::cache
