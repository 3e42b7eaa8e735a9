#include "renderer/radiosity/weights.hpp"

#include <algorithm>
#include <cmath>

namespace povtrace::render::radiosity {

bool sample_visible(const Query& q, const SampleGeometry& s) { return s.depth == q.depth; }

double effective_radius(const SampleGeometry& s, Vec3 query_point) {
  const Vec3 delta = query_point - s.point;
  const double dist = length(delta);
  const double r = s.radius;
  if (!(dist > near_epsilon)) return r;
  const double c = dot(s.to_nearest, delta / dist);
  return c > 0 ? c * static_cast<double>(s.nearest) + (1 - c) * r : r;
}

double reuse_error(const SampleGeometry& s, Vec3 p, Vec3 n, double rho) {
  const double translate = length(p - s.point) / rho;
  const double rotate = 2 * std::sqrt(std::fabs(1 - dot(n, s.normal)));
  return translate + rotate;
}

double in_front(const SampleGeometry& s, Vec3 p, Vec3 n) {
  const Vec3 delta = p - s.point;
  const double dist = length(delta);
  if (!(dist > near_epsilon)) return 1;
  const Vec3 half = n + s.normal;
  return dot(delta / dist, half) / length(half);
}

double linear_weight(double t) { return 1 - t; }

double smooth_weight(double t) {
  if (t < 0.5) return 1 - (2 * t) * (2 * t) / 2;
  return (2 * (1 - t)) * (2 * (1 - t)) / 2;
}

double in_front_fade(double f) { return 1 - f / in_front_limit; }

namespace {

// Steps 1–4 of the test (study §3.2): the error e when the sample is close enough, else a negative value.
double error_if_close(const Query& q, const SampleGeometry& s) {
  const Vec3 delta = q.point - s.point;
  const double quick = static_cast<double>(s.radius) * q.error_bound;
  if (!(dot(delta, delta) < quick * quick)) return -1;
  const double rho = effective_radius(s, q.point);
  if (!(length(delta) < rho * q.error_bound)) return -1;
  const double e = reuse_error(s, q.point, q.normal, rho);
  return e < q.error_bound ? e : -1;
}

}  // namespace

double sample_weight(const Query& q, const SampleGeometry& s) {
  if (!sample_visible(q, s)) return 0;
  const double e = error_if_close(q, s);
  if (e < 0) return 0;
  const double f = in_front(s, q.point, q.normal);
  if (!(f > in_front_limit)) return 0;
  const double t = e / q.error_bound;
  double w = (q.final_pass && s.depth == 0) ? smooth_weight(t) : linear_weight(t);
  if (f <= 0) w *= in_front_fade(f);
  if (!(w > weight_epsilon)) return 0;
  return w * static_cast<double>(s.quality);
}

double query_error_bound(double error_bound, double low_error_factor, bool pretrace, double ray_weight, int depth) {
  double e = pretrace ? error_bound * low_error_factor : error_bound;
  if (ray_weight < weak_ray_weight) e += weak_ray_weight - ray_weight;
  return e * std::pow(2.0, depth);
}

int reuse_count(int nearest_count, int depth) {
  if (depth == 0) return nearest_count;
  if (depth == 1) return std::min(2, nearest_count);
  return 1;
}

bool reuse_is_enough(double sum, int reuse_count, bool final_pass, bool always_sample) {
  if (sum * 4 >= reuse_count) return true;
  return final_pass && !always_sample && sum > 0;
}

float quality_after_query(float quality, double sum, int reuse_count) {
  const float q = static_cast<float>(4 * sum) / static_cast<float>(reuse_count);
  return std::min(q, quality);
}

}  // namespace povtrace::render::radiosity
