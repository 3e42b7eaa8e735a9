// POV-Ray 3.7's julia_fractal math (see julia_fractal_math.hpp and ../notes julia_fractal_spec.md). Every
// expression keeps POV-Ray's order of floating-point operations, because the march, the bisection and the stale
// iteration stack amplify a one-ulp difference into a different hit; it reproduces POV's trace()/inside() bit for
// bit when compiled without FMA contraction (x86-64 without -march has no FMA).
#include "renderer/shapes/julia_fractal_math.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace povtrace::render::julia {
namespace {

constexpr double kTolerance = 1e-7;       // fractal.cpp's Fractal_Tolerance: start clamp, nudge, bisection stop
constexpr double kHyperTolerance = 1e-8;  // hcmplx.cpp's own Fractal_Tolerance: the step-estimate slope test
constexpr double kEpsilon = 1e-10;        // POV's EPSILON in the bounding-sphere test

struct H {  // a quaternion or hypercomplex number x + yi + zj + wk
  double x = 0, y = 0, z = 0, w = 0;
};
struct Cx {  // a complex number for the duplex form of the hypercomplex functions
  double re = 0, im = 0;
};

enum class Kind { quat_sqr, quat_cube, hyper_sqr, hyper_cube, hyper_reciprocal, hyper_function };

Kind kind_of(const Fractal& f) {
  // The parser refuses quaternion with anything but sqr or cube, so any other function here means sqr.
  if (f.algebra == Algebra::quaternion) return f.function == Function::cube ? Kind::quat_cube : Kind::quat_sqr;
  switch (f.function) {
    case Function::sqr: return Kind::hyper_sqr;
    case Function::cube: return Kind::hyper_cube;
    case Function::reciprocal: return Kind::hyper_reciprocal;
    default: return Kind::hyper_function;
  }
}

// POV-Ray keeps one iteration stack per render thread, shared by every fractal and never cleared: a normal reads
// slots 0..max_iteration even when the last orbit escaped early, so stale slots from earlier evaluations of the
// same ray are part of the result. POV mallocs it (garbage at first); ours starts zeroed, and growing keeps the
// old contents.
thread_local std::vector<H> t_orbit;

H* orbit_stack(const Fractal& f) {
  const auto slots = static_cast<std::size_t>(std::max(f.max_iteration, 1)) + 1;
  if (t_orbit.size() < slots) t_orbit.resize(slots);
  return t_orbit.data();
}

// ---- complex functions (hcmplx.cpp's complex_fn), in POV's sequence --------------------------------------------

Cx cmul(Cx a, Cx b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }

// POV leaves the target unwritten when |b|² == 0; we return (0,0). Unreachable from atan/atanh in practice.
Cx cdiv(Cx a, Cx b) {
  const double m = b.re * b.re + b.im * b.im;
  if (m == 0) return {};
  const double p = b.re / m, q = -(b.im / m);
  return {a.re * p - a.im * q, a.re * q + a.im * p};
}

Cx cln(Cx a) { return {std::log(std::sqrt(a.re * a.re + a.im * a.im)), std::atan2(a.im, a.re)}; }

Cx csqrt(Cx a) {
  if (a.re == 0 && a.im == 0) return {};
  const double mag = std::sqrt(std::sqrt(a.re * a.re + a.im * a.im)), theta = std::atan2(a.im, a.re) / 2.0;
  return {mag * std::cos(theta), mag * std::sin(theta)};
}

// POV's atanh leaves its target unwritten for |x| == 1, y == 0. atan relies on that (it calls atanh in place, so
// the target keeps its input); for the other callers `unwritten` is (0,0), our choice for POV's uninitialised local.
Cx catanh(Cx s, Cx unwritten) {
  if (s.re == 0) return {0, std::atan(s.im)};
  if (std::fabs(s.re) == 1 && s.im == 0) return unwritten;
  if (std::fabs(s.re) < 1 && s.im == 0) return {std::log((1 + s.re) / (1 - s.re)) / 2, 0};
  const Cx r = cln(cdiv({1 + s.re, s.im}, {1 - s.re, -s.im}));
  return {.5 * r.re, .5 * r.im};
}

Cx catan(Cx s) {
  if (s.re == 0 && s.im == 0) return {};
  if (s.re != 0 && s.im == 0) return {std::atan(s.re), 0};
  if (s.re == 0) {
    const Cx t = catanh({s.im, +0.0}, {s.im, +0.0});
    return {-t.im, t.re};
  }
  const Cx k{-s.im, s.re};
  const Cx r = cln(cdiv({1 - k.re, -k.im}, {1 + k.re, k.im}));
  return {(-r.im) * .5, .5 * r.re};
}

// tan/tanh: POV leaves the target unwritten when the denominator is 0; we return (0,0).
Cx ctan(Cx s) {
  const double x = 2 * s.re, y = 2 * s.im, d = std::cos(x) + std::cosh(y);
  if (d == 0) return {};
  return {std::sin(x) / d, std::sinh(y) / d};
}

Cx ctanh(Cx s) {
  const double x = 2 * s.re, y = 2 * s.im, d = std::cosh(x) + std::cos(y);
  if (d == 0) return {};
  return {std::sinh(x) / d, std::sin(y) / d};
}

Cx cpwr(Cx s, Cx e) {
  if (s.re == 0 && s.im == 0) return {};
  const Cx t = cmul(cln(s), e);
  const double ex = t.re < -690 ? 0.0 : std::exp(t.re);  // POV's underflow cut
  return {ex * std::cos(t.im), ex * std::sin(t.im)};
}

Cx complex_function(Function fn, Cx s, Cx e) {
  const double x = s.re, y = s.im;
  switch (fn) {
    case Function::exp: {
      const double ex = std::exp(x);
      return {ex * std::cos(y), ex * std::sin(y)};
    }
    case Function::ln: return cln(s);
    case Function::sin: return {std::sin(x) * std::cosh(y), std::cos(x) * std::sinh(y)};
    case Function::cos: return {std::cos(x) * std::cosh(y), (-std::sin(x)) * std::sinh(y)};
    case Function::sinh: return {std::sinh(x) * std::cos(y), std::cosh(x) * std::sin(y)};
    case Function::cosh: return {std::cosh(x) * std::cos(y), std::sinh(x) * std::sin(y)};
    case Function::tan: return ctan(s);
    case Function::tanh: return ctanh(s);
    case Function::asin: {
      Cx t = cmul(s, s);
      t = csqrt({1 - t.re, -t.im});
      t = cln({t.re + (-y), t.im + x});
      return {t.im, -t.re};
    }
    case Function::acos: {
      Cx t = cmul(s, s);
      t = csqrt({t.re - 1, t.im});
      t = cln({t.re + x, t.im + y});
      return {t.im, -t.re};
    }
    case Function::asinh: {
      Cx t = cmul(s, s);
      t = csqrt({t.re + 1, t.im});
      return cln({t.re + x, t.im + y});
    }
    case Function::acosh: {
      Cx t = cmul(s, s);
      t = csqrt({t.re - 1, t.im});
      return cln({x + t.re, y + t.im});
    }
    case Function::atanh: return catanh(s, {});
    case Function::atan: return catan(s);
    case Function::pwr: return cpwr(s, e);
    default: return {};  // sqr/cube/reciprocal never come here (hyper_function only)
  }
}

// ---- hypercomplex helpers (hcmplx.cpp) ------------------------------------------------------------------------

H hmul(H a, H b) {
  return {a.x * b.x - a.y * b.y - a.z * b.z + a.w * b.w, a.y * b.x + a.x * b.y - a.w * b.z - a.z * b.w,
          a.z * b.x - a.w * b.y + a.x * b.z - a.y * b.w, a.w * b.x + a.z * b.y + a.y * b.z + a.x * b.w};
}

H hsqr(H a) {
  return {a.x * a.x - a.y * a.y - a.z * a.z + a.w * a.w, 2.0 * (a.x * a.y - a.z * a.w),
          2.0 * (a.z * a.x - a.w * a.y), 2.0 * (a.w * a.x + a.z * a.y)};
}

// POV's reciprocal leaves its target unwritten when det == 0 (e.g. x = w, y = −z), so the caller's local keeps the
// previous iteration's value. We do the same with a zero-initialised local: `out` is untouched then.
void hrecip(H a, H& out) {
  const double det = ((a.x - a.w) * (a.x - a.w) + (a.y + a.z) * (a.y + a.z)) *
                     ((a.x + a.w) * (a.x + a.w) + (a.y - a.z) * (a.y - a.z));
  if (det == 0) return;
  const double m = a.x * a.x + a.y * a.y + a.z * a.z + a.w * a.w, t = a.x * a.w - a.y * a.z;
  out = {(a.x * m - 2 * a.w * t) / det, (-a.y * m - 2 * a.z * t) / det, (-a.z * m - 2 * a.y * t) / det,
         (a.w * m - 2 * a.x * t) / det};
}

// f applied through the duplex form: two complex evaluations on (x−w, y+z) and (x+w, y−z).
H hfunc(const Fractal& f, H a) {
  const Cx e{f.exponent[0], f.exponent[1]};
  const Cx ra = complex_function(f.function, {a.x - a.w, a.y + a.z}, e);
  const Cx rb = complex_function(f.function, {a.x + a.w, a.y - a.z}, e);
  return {.5 * (ra.re + rb.re), .5 * (ra.im + rb.im), .5 * (ra.im - rb.im), .5 * (rb.re - ra.re)};
}

H plus_c(H a, const Fractal& f) { return {a.x + f.c[0], a.y + f.c[1], a.z + f.c[2], a.w + f.c[3]}; }

// ---- the iteration --------------------------------------------------------------------------------------------

// The slice maps the 3-D point into 4-D: w solves S·(x,y,z,w) = slice_distance.
H start_value(const Fractal& f, double x, double y, double z) {
  return {x, y, z, (((f.slice_distance - f.slice[0] * x) - f.slice[1] * y) - f.slice[2] * z) / f.slice[3]};
}

// The squared norm tested against the escape value, summed in each variant's own order.
double orbit_norm(Kind k, H a) {
  switch (k) {
    case Kind::quat_sqr:
    case Kind::quat_cube: return (a.y * a.y + a.z * a.z + a.w * a.w) + a.x * a.x;
    case Kind::hyper_sqr: return (a.x * a.x + a.w * a.w) + (a.y * a.y + a.z * a.z);
    default: return a.x * a.x + a.y * a.y + a.z * a.z + a.w * a.w;
  }
}

H advance(const Fractal& f, Kind k, H a, H& reciprocal) {
  switch (k) {
    case Kind::quat_sqr: {
      const double d = a.y * a.y + a.z * a.z + a.w * a.w, x2 = a.x * a.x, twice_x = a.x * 2.0;
      return {(x2 - d) + f.c[0], twice_x * a.y + f.c[1], twice_x * a.z + f.c[2], twice_x * a.w + f.c[3]};
    }
    case Kind::quat_cube: {
      const double d = a.y * a.y + a.z * a.z + a.w * a.w, x2 = a.x * a.x, t = 3.0 * x2 - d;
      return {a.x * (x2 - 3.0 * d) + f.c[0], a.y * t + f.c[1], a.z * t + f.c[2], a.w * t + f.c[3]};
    }
    case Kind::hyper_sqr: {
      const double yz = a.y * a.y + a.z * a.z, xw = a.x * a.x + a.w * a.w;
      return {(xw - yz) + f.c[0], 2.0 * (a.x * a.y - a.z * a.w) + f.c[1], 2.0 * (a.x * a.z - a.w * a.y) + f.c[2],
              2.0 * (a.x * a.w + a.y * a.z) + f.c[3]};
    }
    // POV-Ray's hypercomplex "cube" iterates hsqr, i.e. z² + c (only its step estimate and normal differ).
    case Kind::hyper_cube: return plus_c(hsqr(a), f);
    case Kind::hyper_reciprocal: hrecip(a, reciprocal); return plus_c(reciprocal, f);
    case Kind::hyper_function: return plus_c(hfunc(f, a), f);
  }
  return a;
}

struct Escape {
  int at = 0;       // the step i (1..N) whose test failed; 0 when z_0..z_{N-1} all stayed within exit_value
  double norm = 0;  // the failing norm
};

// Writes z_0 and every iterate z_i into the stack; on escape the higher slots keep their stale values. z_N is
// computed but never tested.
Escape run_orbit(const Fractal& f, Kind k, H z, H* stack) {
  stack[0] = z;
  H reciprocal{};
  for (int i = 1; i <= f.max_iteration; ++i) {
    const double n = orbit_norm(k, z);
    if (n > f.exit_value) return {i, n};
    z = advance(f, k, z, reciprocal);
    stack[i] = z;
  }
  return {};
}

// POV-Ray's plain Iteration. Its Iteration_HCompl_Func takes the start's third component from y (and w from that
// wrong z); D_Iteration_HCompl_Func uses z. Fixed only in 3.8, so kept for 3.7 parity.
bool plain_iteration(const Fractal& f, Kind k, Vec3 p, H* stack) {
  const H z0 = k == Kind::hyper_function ? start_value(f, p.x, p.y, p.y) : start_value(f, p.x, p.y, p.z);
  return run_orbit(f, k, z0, stack).at == 0;
}

// ---- normals (also the hypercomplex step estimate's gradient) ---------------------------------------------------

Vec3 quaternion_normal(Kind k, const H* stack, int n) {
  double rows[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  for (int i = 1; i <= n; ++i) {
    const H s = stack[i - 1];
    const double t = s.y * s.y + s.z * s.z + s.w * s.w, x2 = s.x * s.x, x3 = x2 - t, x4 = 3.0 * x2 - t;
    for (auto& r : rows) {
      const double n1 = r[0], n2 = r[1], n3 = r[2], n4 = r[3];
      if (k == Kind::quat_sqr) {
        r[0] = n1 * s.x - n2 * s.y - n3 * s.z - n4 * s.w;
        r[1] = n1 * s.y + s.x * n2;
        r[2] = n1 * s.z + s.x * n3;
        r[3] = n1 * s.w + s.x * n4;
      } else {
        const double d = 2.0 * (n2 * s.y + n3 * s.z + n4 * s.w), d2 = 6.0 * s.x * n1 - d;
        r[0] = (n1 * x3 - s.x * d) * 3.0;
        r[1] = n2 * x4 + s.y * d2;
        r[2] = n3 * x4 + s.z * d2;
        r[3] = n4 * x4 + s.w * d2;
      }
    }
  }
  const H s = stack[n];
  Vec3 out;
  for (int j = 0; j < 3; ++j) out[j] = rows[j][0] * s.x + rows[j][1] * s.y + rows[j][2] * s.z + rows[j][3] * s.w;
  return out;
}

// POV's hypercomplex normals chain f(z_i) itself (not f'(z_i)) from z_0, and only sqr scales by 2^max(K,1); that
// factor vanishes on normalisation but changes the step estimate.
Vec3 hyper_normal(const Fractal& f, Kind k, const H* stack, int count) {
  H a = stack[0], reciprocal{};
  double pw = 2.0;
  for (int i = 1; i < count; ++i) {
    const H s = stack[i];
    switch (k) {
      case Kind::hyper_sqr: a = hmul(s, a); pw *= 2.0; break;
      case Kind::hyper_reciprocal: {
        hrecip(s, reciprocal);  // det == 0 keeps the previous value, as POV's local does
        const H q = hsqr(reciprocal);
        a = hmul(a, {-q.x, -q.y, -q.z, -q.w});
        break;
      }
      case Kind::hyper_function: a = hmul(hfunc(f, s), a); break;
      default: a = hmul(s, a); break;  // hyper_cube
    }
  }
  H n = stack[count];
  if (k == Kind::hyper_sqr) n = {n.x * pw, n.y * pw, n.z * pw, n.w * pw};
  return {a.x * n.x + a.y * n.y + a.z * n.z + a.w * n.w, -a.y * n.x + a.x * n.y - a.w * n.z + a.z * n.w,
          -a.z * n.x - a.w * n.y + a.x * n.z + a.y * n.w};
}

Vec3 orbit_normal(const Fractal& f, Kind k, const H* stack, int count) {
  return k == Kind::quat_sqr || k == Kind::quat_cube ? quaternion_normal(k, stack, count)
                                                     : hyper_normal(f, k, stack, count);
}

// ---- the march's evaluator: inside, or a step length (POV's D_Iteration) --------------------------------------

struct Probe {
  bool inside = false;
  double step = 0;
};

// Quaternion distance estimate from the derivative product over z_0..z_{i-1}.
double quaternion_step(Kind k, const H* stack, Escape e) {
  const bool sqr = k == Kind::quat_sqr;
  H q = stack[0];
  double pw = sqr ? 0.5 : 1.0 / 3.0;
  for (int j = 1; j < e.at; ++j) {
    const H s = stack[j];
    if (sqr) {
      q = {q.x * s.x - q.y * s.y - q.z * s.z - q.w * s.w, q.x * s.y + q.y * s.x + q.w * s.z - q.z * s.w,
           q.x * s.z + q.z * s.x + q.y * s.w - q.w * s.y, q.x * s.w + q.w * s.x + q.z * s.y - q.y * s.z};
      pw /= 2.0;
    } else {
      q = {q.x * s.x - q.y * s.y - q.z * s.z - q.w * s.w, q.x * s.y + q.y * s.x - q.z * s.w + q.w * s.z,
           q.x * s.z + q.y * s.w + q.z * s.x - q.w * s.y, q.x * s.w - q.y * s.z + q.z * s.y + q.w * s.x};
      pw /= 3.0;
    }
  }
  return (pw * std::sqrt(e.norm / (q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w))) * std::log(e.norm);
}

// Hypercomplex step: norm over twice the slope along the ray, accepted only inside (precision, 30·precision).
double hyper_step(const Fractal& f, Kind k, const H* stack, Escape e, Vec3 dir) {
  const double s = dot(orbit_normal(f, k, stack, e.at - 1), dir);
  if (s < -kHyperTolerance) {
    const double s2 = -2.0 * s;
    if (e.norm > f.precision * s2 && e.norm < 30 * f.precision * s2) return e.norm / s2;
  }
  return f.precision;
}

Probe march_probe(const Fractal& f, Kind k, Vec3 p, Vec3 dir, H* stack) {
  const Escape e = run_orbit(f, k, start_value(f, p.x, p.y, p.z), stack);
  if (e.at == 0) return {true, f.precision};
  if (k == Kind::quat_sqr || k == Kind::quat_cube) return {false, quaternion_step(k, stack, e)};
  return {false, hyper_step(f, k, stack, e, dir)};
}

// POV's Sphere::Intersect with centre 0 and radius² radius2: the entry and exit depths.
bool bounding_sphere(const Fractal& f, Vec3 origin, Vec3 dir, double& t0, double& t1) {
  const Vec3 oc{0.0 - origin.x, 0.0 - origin.y, 0.0 - origin.z};
  const double ocs = dot(oc, oc), tca = dot(oc, dir);
  if (ocs >= f.radius2 && tca < kEpsilon) return false;
  const double h2 = (f.radius2 - ocs) + tca * tca;
  if (!(h2 > kEpsilon)) return false;
  const double h = std::sqrt(h2);
  t0 = tca - h;
  t1 = tca + h;
  return true;
}

}  // namespace

void prepare(Fractal& f) {
  double r = 4.0;  // every hypercomplex variant: radius 4, exit 16
  f.exit_value = 16.0;
  if (f.algebra == Algebra::quaternion) {
    r = 1.0 + std::sqrt(f.c[0] * f.c[0] + f.c[1] * f.c[1] + f.c[2] * f.c[2] + f.c[3] * f.c[3]);
    r += kTolerance;
    if (r > 2.0) r = 2.0;
    f.exit_value = r * r + kTolerance;
  }
  f.radius = r;
  f.radius2 = r * r;
}

// POV-Ray's Fractal::All_Intersections in object space: coarse march with D_Iteration, bisection with the plain
// Iteration, the normal from whatever the stack then holds.
void intersect(const Fractal& f, Vec3 origin, Vec3 dir, bool all_hits, std::vector<FractalHit>& out) {
  double depth = 0, dmax = 0;
  if (!bounding_sphere(f, origin, dir, depth, dmax) || dmax < kTolerance) return;
  if (depth < kTolerance) depth = kTolerance;
  const Kind k = kind_of(f);
  H* stack = orbit_stack(f);

  Vec3 p = dir * depth + origin;
  Probe cur = march_probe(f, k, p, dir, stack);
  if (cur.inside) {  // POV nudges a start inside the set by 2·tolerance and looks again (secondary rays)
    p = p + dir * (2 * kTolerance);
    depth += 2 * kTolerance;
    if (depth > dmax) return;
    cur = march_probe(f, k, p, dir, stack);
  }
  double step = cur.step;
  bool last = false;  // the last bisection result; survives across crossings of the same ray, as in POV
  Vec3 a = p;         // the near end of the bracketing interval, on the `cur` side
  Probe next;
  while (depth < dmax) {
    for (;;) {  // coarse march until the side changes
      if (step < f.precision) step = f.precision;
      depth += step;
      if (depth > dmax) return;
      a = p;
      p = p + dir * step;
      next = march_probe(f, k, p, dir, stack);
      if (next.inside != cur.inside) {
        depth -= step;
        break;
      }
      step = next.step;
    }
    while (step > kTolerance) {  // bisection of [a, a + step]
      step *= 0.5;
      const Vec3 mid = a + dir * step;
      last = plain_iteration(f, k, mid, stack);
      if (last == cur.inside) {
        a = mid;
        depth += step;
        if (depth > dmax) return;
      }
    }
    // Report the inside end of the interval, refilling the stack for it unless it already holds its orbit.
    if (!cur.inside) {
      a = a + dir * step;
      depth += step;
      plain_iteration(f, k, a, stack);
    } else if (last != cur.inside) {
      plain_iteration(f, k, a, stack);
    }
    out.push_back({depth, a, orbit_normal(f, k, stack, f.max_iteration)});
    if (!all_hits) return;
    // POV resumes marching from p but leaves depth at the hit: later hits of the ray report depths that lag.
    step = next.step;
    cur = next;
  }
}

bool inside(const Fractal& f, Vec3 point) { return plain_iteration(f, kind_of(f), point, orbit_stack(f)); }

}  // namespace povtrace::render::julia
