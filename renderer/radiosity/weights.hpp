// Which cached radiosity samples a query may reuse, and with what weight (docs/issue19-study.md §3.2–3.4;
// POV-Ray 3.7 source/backend/lighting/radiosity.cpp, RadiosityCache::AverageNearBlock, RadiosityFunction::
// ComputeAmbient and SceneRadiositySettings::GetRecursionSettings). Pure functions of plain values: the cache
// (octree.hpp) only decides which samples are offered, these decide what each offered sample contributes.
#pragma once

#include <cstdint>

#include "scene/vecmath.hpp"

namespace povtrace::render::radiosity {

// The part of a stored sample the weight depends on (study §3.1). Radii and quality are single precision, as
// POV-Ray stores them; its filing and its reuse both read these stored values.
struct SampleGeometry {
  Vec3 point;
  Vec3 normal;          // the normal it was filed under (unit)
  Vec3 to_nearest;      // unit direction of its shortest ray
  float radius = 0;     // harmonic-mean ray length, clamped (r_i)
  float nearest = 0;    // length of its shortest ray (r_min,i)
  float quality = 1;    // mean quality of its rays (q_i)
  int depth = 0;        // bounce depth it was gathered at
  int pass = 0;         // pass that made it
  int tile = 0;         // tile (block) that made it
};

// One lookup: the surface point and normal asking, its bounce depth, error bound E (query_error_bound) and
// where it runs.
struct Query {
  Vec3 point;
  Vec3 normal;          // unit
  double error_bound = 0;
  int depth = 0;
  bool final_pass = false;   // the final render, not a pretrace pass
};

// Named constants of POV-Ray's reuse test.
inline constexpr double near_epsilon = 1e-6;       // AVG_NEAR_EPSILON: closer than this counts as "at the point"
inline constexpr double in_front_limit = -0.05;    // IN_FRONT_LIMIT
inline constexpr double weight_epsilon = 0.001;    // RAD_EPSILON: weights at or below are dropped
inline constexpr double weak_ray_weight = 0.25;    // WEIGHT_ERROR_BOUND_OFFSET

// The sample is offered to this query at all: same bounce depth (the octree walk's test in POV-Ray). Which
// samples of the query's own pass it may see is decided by the store (sample_levels.hpp: what was merged is seen
// by every later block, a block's new samples by itself only), so POV-Ray's High_Reproducibility rule on pass
// and tile ids is not applied here; the ids stay on the samples as a record of where they were made.
bool sample_visible(const Query& q, const SampleGeometry& s);

// The sample's radius of influence towards the query point, ρ: its stored radius, pulled towards its nearest-hit
// distance when the query lies in the direction of that hit: with c = to_nearest·(P − Pi)/|P − Pi| > 0,
// ρ = c·r_min + (1 − c)·r (unchanged when |P − Pi| ≤ 1e−6 or c ≤ 0).
double effective_radius(const SampleGeometry& s, Vec3 query_point);

// Ward's error of reusing the sample at (p, n) given ρ: |p − Pi|/ρ + 2·√|1 − n·Ni|.
double reuse_error(const SampleGeometry& s, Vec3 p, Vec3 n, double rho);

// How far the sample lies in front of the query surface: (P − Pi)/|P − Pi| · normalise(N + Ni); 1 when
// |P − Pi| ≤ 1e−6. Opposite normals (N + Ni = 0) give NaN, as in POV-Ray, and NaN fails the in-front test.
double in_front(const SampleGeometry& s, Vec3 p, Vec3 n);

// The two weight shapes of t = e/E in [0, 1): linear 1 − t (pretrace and bounces), and the pseudo-sigmoid of
// the final pass at depth 0: 1 − 2t² below t = ½, 2(1 − t)² from there.
double linear_weight(double t);
double smooth_weight(double t);

// The factor that fades a sample slightly in front (f ≤ 0) from 1 at f = 0 to 0 at f = −0.05: 1 − f/(−0.05).
double in_front_fade(double f);

// The weight the sample contributes to the query, quality included; 0 when it is not usable (not visible,
// outside the quick radius r·E or the effective radius ρ·E, error ≥ E, in front by −0.05 or more, or a weight
// ≤ 0.001 before the quality factor).
double sample_weight(const Query& q, const SampleGeometry& s);

// E for a query (study §3.3): (E0·[lef in the pretrace] + max(0, 0.25 − w_ray))·2^depth, w_ray being the
// weight the shading hands to the query.
double query_error_bound(double error_bound, double low_error_factor, bool pretrace, double ray_weight, int depth);

// The reuse count c_d (study §1): nearest_count at depth 0, min(2, nearest_count) at depth 1, 1 deeper.
int reuse_count(int nearest_count, int depth);

// Whether a lookup that found the weight sum `sum` is enough (study §3.4): 4·Σw ≥ c_d, or in the final pass
// without always_sample any positive Σw.
bool reuse_is_enough(double sum, int reuse_count, bool final_pass, bool always_sample);

// The running ray quality after a query that ended with weight sum `sum` (gather included): min(q, 4·Σw/c_d),
// computed in single precision as POV-Ray does.
float quality_after_query(float quality, double sum, int reuse_count);

}  // namespace povtrace::render::radiosity
