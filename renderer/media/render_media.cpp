#include "renderer/media/render_media.hpp"

#include <cmath>

#include "renderer/pattern/render_pigment.hpp"

namespace povtrace::render {

namespace {
// The regularized lower incomplete gamma P(a, x) by its power series (converges quickly for x < a + 1).
double lower_gamma_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 1000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::fabs(term) < std::fabs(sum) * 1e-16) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// The regularized upper incomplete gamma Q(a, x) by its continued fraction (modified Lentz; for x ≥ a + 1).
double upper_gamma_fraction(double a, double x) {
  constexpr double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double step = d * c;
    h *= step;
    if (std::fabs(step - 1.0) < 1e-16) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

// Q(a, x) = 1 − P(a, x).
double upper_gamma(double a, double x) {
  if (x <= 0) return 1.0;
  return x < a + 1.0 ? 1.0 - lower_gamma_series(a, x) : upper_gamma_fraction(a, x);
}

Rgb rgb(const Colour& c) { return {c.r, c.g, c.b}; }
}  // namespace

double inverse_chi_square_complement(double dof, double q) {
  // P(X > x) = Q(dof/2, x/2) falls from 1 at x = 0 towards 0: bisect on it.
  double lo = 0.0, hi = dof + 10.0;
  for (int i = 0; i < 2000 && upper_gamma(0.5 * dof, 0.5 * hi) > q; ++i) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (upper_gamma(0.5 * dof, 0.5 * mid) > q ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

RenderMedia build_render_media(const Media& m, ImageCache* images, bool quick_colours) {
  RenderMedia r;
  r.method = m.method;
  r.intervals = m.intervals;
  r.min_samples = m.min_samples;
  r.max_samples = m.max_samples;
  r.ratio = m.ratio;
  r.jitter = m.jitter;
  r.aa_threshold = m.aa_threshold;
  r.aa_level = m.aa_level;
  r.absorption = rgb(m.absorption);
  r.emission = rgb(m.emission);
  r.scattering = rgb(m.scattering);
  r.extinction = r.absorption + r.scattering * m.extinction;
  r.scattering_type = m.scattering_type;
  r.eccentricity = m.eccentricity;
  const auto non_zero = [](Rgb c) { return c.x != 0 || c.y != 0 || c.z != 0; };
  r.use_scattering = non_zero(r.scattering);
  r.use_extinction = non_zero(r.absorption) || r.use_scattering;
  r.constant = m.densities.empty();
  for (auto d = m.densities.rbegin(); d != m.densities.rend(); ++d)
    r.densities.push_back(build_render_pigment(*d, images, quick_colours));
  r.plain_for_shadows = m.densities.empty() || m.densities.back().pattern == PatternKind::solid;
  // The confidence test of the extra samples (Media::PostProcess): thresholds proportional to the chi-square
  // quantiles of 1 … max_samples degrees of freedom, scaled so that max_samples − 1 of them give `variance`.
  r.sample_threshold.assign(static_cast<std::size_t>(m.max_samples), 0.0);
  if (m.max_samples > 1) {
    double t = inverse_chi_square_complement(m.max_samples - 1, m.confidence);
    t = t > 0.0 ? m.variance / t : m.variance * 1e-10;
    for (int i = 0; i < m.max_samples; ++i)
      r.sample_threshold[static_cast<std::size_t>(i)] = t * inverse_chi_square_complement(i + 1, m.confidence);
  }
  return r;
}

}  // namespace povtrace::render
