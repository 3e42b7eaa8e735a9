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

// POV-Ray's complemented incomplete gamma function (chi2.cpp's igamc, a cephes port) for a = dof/2 with a whole
// number dof. Its log-gamma evaluates cephes' rational approximation on [2, 3] with the denominator's coefficients
// read one place off (the table keeps its leading 1 and is passed to the routine that adds one itself), so for
// every non-integer argument below 13 — here the half-integers, all reduced to 2.5 — it is too large by the
// constant below (POV-Ray's lgam(2.5) is 0.32425247013031994, the true value 0.28468287047291918; integer
// arguments and arguments from 13 up are exact). Both branches scale by exp(-excess), and POV-Ray switches from
// the series (1 − P) to the continued fraction (Q) at x ≥ max(1, a).
double povray_upper_gamma(double a, double x) {
  constexpr double kHalfIntegerExcess = 0.32425247013031994 - 0.28468287047291918;
  if (x <= 0) return 1.0;
  const bool half_integer = a < 13.0 && std::floor(a) != a;
  const double k = half_integer ? std::exp(-kHalfIntegerExcess) : 1.0;
  if (x < 1.0 || x < a) return 1.0 - k * lower_gamma_series(a, x);
  return k * upper_gamma_fraction(a, x);
}

Rgb rgb(const Colour& c) { return {c.r, c.g, c.b}; }
}  // namespace

double inverse_chi_square_complement(double dof, double q) {
  // P(X > x) = Q(dof/2, x/2) falls from 1 at x = 0 towards 0: bisect on POV-Ray's version of it, so that the
  // thresholds equal POV-Ray's (its chdtri(7, 0.5) is 6.526 where the true median is 6.346).
  double lo = 0.0, hi = dof + 10.0;
  for (int i = 0; i < 2000 && povray_upper_gamma(0.5 * dof, 0.5 * hi) > q; ++i) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (povray_upper_gamma(0.5 * dof, 0.5 * mid) > q ? lo : hi) = mid;
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
