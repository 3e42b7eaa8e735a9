// POV-Ray's internal functions, `function { internal(N) }` in functions.inc. Each takes the point x, y, z and
// the extra parameters documented in functions.inc. The formulas are those POV-Ray 3.7 evaluates (its
// source/backend/vm/fnintern.cpp was read for what each N computes), kept in the same order of operations so
// that the values agree to the last bit — including its quirks (f_enneper's integer fractions 2/3, 1/4, …
// that are 0, f_kampyle_of_eudoxus_2d's P1*P2). The ones built on POV-Ray's noise are in function_noise.cpp.
#include <algorithm>
#include <climits>
#include <cmath>

#include "runtime/function_noise.hpp"
#include "runtime/function_value.hpp"

namespace povtrace::sdl {

namespace {

constexpr double kPi = M_PI;
constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kDegree = M_PI / 180.0;

// The evaluation state of one call: p[0..2] = x, y, z, p[3 + i] = extra parameter i (modifiable copies).
struct Point {
  double* p;
  double& X() const { return p[0]; }
  double& Y() const { return p[1]; }
  double& Z() const { return p[2]; }
  double& P(int i) const { return p[3 + i]; }
};

// Most of the algebraic surfaces scale their polynomial by a field strength and clip it to ±10.
double clip10(double strength, double r) { return std::min(10.0, std::max(strength * r, -10.0)); }

// The "2-D" surfaces can be spun around the y axis (a surface of revolution): with `sor` > 0 the distance
// from the y axis, less `offset`, replaces x, and the (x, y) plane is then turned by `angle` degrees.
// x2 and y2 are the squares of the (possibly new) x and y.
void surface_of_revolution(const Point& q, double sor, double offset, double angle, double& x2, double& y2) {
  if (!(sor > 0)) return;
  const double d = std::sqrt(x2 + q.Z() * q.Z()) - offset;
  const double th = angle * kDegree;
  if (th != 0) {
    const double ny = d * std::sin(th) + q.Y() * std::cos(th);
    q.X() = d * std::cos(th) - q.Y() * std::sin(th);
    q.Y() = ny;
  } else {
    q.X() = d;
  }
  x2 = q.X() * q.X();
  y2 = q.Y() * q.Y();
}

// The rounded "superellipse" cross-section used by the helices and the spiral: exponent 2/e on |a| and |b|.
double cross_section(double a, double b, double e, double outer) {
  const double t = 2.0 / e;
  return std::pow(std::pow(std::fabs(a), t) + std::pow(std::fabs(b), t), outer);
}

// exp(-(a·x² + b·y² + c·z²)·k) for the three axis-aligned ellipsoid fields of the blob-like surfaces.
double ellipsoid_field(double xx, double yy, double zz, double k) { return std::exp(-(xx + yy + zz) * k); }

double algbr_cyl1(const Point& q) {
  double x2 = q.X() * q.X(), y2 = q.Y() * q.Y();
  surface_of_revolution(q, q.P(2), q.P(3), q.P(4), x2, y2);
  q.X() = std::fabs(q.X());
  const double r = -(x2 * q.X() - x2 + y2);
  return -std::min(q.P(1), std::max(q.P(0) * r, -q.P(1)));
}

double algbr_cyl(const Point& q, int which) {
  double x2 = q.X() * q.X(), y2 = q.Y() * q.Y();
  surface_of_revolution(q, q.P(2), q.P(3), q.P(4), x2, y2);
  const double X = q.X(), Y = q.Y();
  double r = 0;
  if (which == 2) r = -(2 * x2 * x2 - 3 * x2 * Y + y2 - 2 * y2 * Y + y2 * y2);
  else if (which == 3) r = -(x2 * x2 + x2 * y2 - 2 * x2 * Y - X * y2 + y2);
  else r = -(x2 * x2 + y2 * y2 + 2 * x2 * y2 + 3 * x2 * Y - y2 * Y);
  return std::min(q.P(1), std::max(q.P(0) * r, -q.P(1)));
}

double bicorn(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  const double a2 = q.P(1) * q.P(1);
  const double s = x2 + z2 + 2 * q.P(1) * q.Y() - a2;
  return clip10(q.P(0), y2 * (a2 - (x2 + z2)) - s * s);
}

double bifolia(const Point& q) {
  const double x2 = q.X() * q.X(), z2 = q.Z() * q.Z();
  const double s = x2 + q.Y() * q.Y() + z2;
  return clip10(q.P(0), -(s * s - q.P(1) * (x2 + z2) * q.Y()));
}

double blob(const Point& q) {
  const double y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  const double h = q.P(0) * 0.5;
  double a = ((q.X() + h) * (q.X() + h) + y2 + z2) * q.P(2) * q.P(2);
  if (a > 1.) a = 1.;
  double b = ((q.X() - h) * (q.X() - h) + y2 + z2) * q.P(4) * q.P(4);
  if (b > 1) b = 1.;
  return -(q.P(1) * (1. - a) * (1. - a) + q.P(3) * (1. - b) * (1. - b));
}

double blob2(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  const double dx = q.X() - q.P(0);
  const double f = std::exp(-(x2 + y2 + z2) * q.P(1)) + std::exp(-(dx * dx + y2 + z2) * q.P(1));
  return q.P(3) - f * q.P(2);
}

double boy_surface(const Point& q) {
  const double X = q.X(), Y = q.Y(), Z = q.Z();
  const double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
  const double w = 1 - Z, h = x2 + y2;
  const double root2 = std::sqrt(2.0);
  const double r =
      q.P(1) * (64 * w * w * w * z2 * Z - 48 * w * w * z2 * (3 * x2 + 3 * y2 + 2 * z2) +
                12 * w * Z * (27 * h * h - 24 * z2 * h + 36 * root2 * Y * Z * (y2 - 3 * x2) + 4 * z2 * z2) +
                (9 * x2 + 9 * y2 - 2 * z2) * (-81 * h * h - 72 * z2 * h + 108 * root2 * X * Z * (x2 - 3 * y2) +
                                              4 * z2 * z2));
  return clip10(q.P(0), r);
}

double comma(const Point& q) {
  if (q.X() == 0 && q.Z() == 0) q.X() = 0.0001;
  const double s = q.P(0);
  const double th = std::atan2(q.Z(), q.X());
  const double r = std::sqrt((q.X() + s * 0.25) * (q.X() + s * 0.25) + q.Z() * q.Z());
  double tail = std::cos(th * 0.5) * s * 0.5 - std::sqrt((r - s * 0.75) * (r - s * 0.75) + q.Y() * q.Y());
  tail = std::min(q.Z(), tail);
  const double head = s * 0.5 - std::sqrt((q.X() - s * 0.5) * (q.X() - s * 0.5) + q.Z() * q.Z() + q.Y() * q.Y());
  return -std::max(tail, head);
}

// f_cross_ellipsoids (max of the three fields), f_flange_cover (sum), f_isect_ellipsoids (min).
double three_ellipsoids(const Point& q, int combine) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  const double e = q.P(0), k = q.P(1);
  const double f1 = ellipsoid_field(x2 * e, y2 * e, z2, k);
  const double f2 = ellipsoid_field(x2 * e, y2, z2 * e, k);
  const double f3 = ellipsoid_field(x2, y2 * e, z2 * e, k);
  double f = 0;
  if (combine > 0) f = std::max(std::max(f1, f2), f3);
  else if (combine < 0) f = std::min(std::min(f1, f2), f3);
  else f = f1 + f2 + f3;
  return q.P(3) - f * q.P(2);
}

double cushion_like(const Point& q, bool odd) {
  const double Z = q.Z();
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = Z * Z;
  const double xy = odd ? 2 * y2 * x2 : 2 * x2 * y2;
  return clip10(q.P(0), z2 * x2 - z2 * z2 - 2 * Z * x2 + 2 * z2 * Z + x2 - z2 - (x2 - Z) * (x2 - Z) - y2 * y2 - xy -
                            y2 * z2 + 2 * y2 * Z + y2);
}

double dupin_cyclid(const Point& q) {
  const double X = q.X(), Y = q.Y();
  const double x2 = X * X, y2 = Y * Y, z2 = q.Z() * q.Z();
  const double k2 = q.P(5) * q.P(5);
  const double b2 = q.P(2) * q.P(2), d2 = q.P(4) * q.P(4);
  const double p1 = b2 - d2 - (q.P(3) + q.P(1)) * (q.P(3) + q.P(1));
  const double p2 = b2 - d2 - (q.P(3) - q.P(1)) * (q.P(3) - q.P(1));
  const double c2 = q.P(3) * q.P(3), a2 = q.P(1) * q.P(1);
  const double r =
      -(p1 * p2 * (x2 * x2 + y2 * y2 + z2 * z2) + 2 * (p1 * p2 * (x2 * y2 + x2 * z2 + y2 * z2)) +
        2 * k2 * ((-d2 - c2 + b2 + a2) * (2 * X * q.P(3) + 2 * Y * q.P(4) - k2) - 4 * q.P(4) * b2 * Y) *
            (x2 + y2 + z2) +
        4 * k2 * k2 * (q.P(3) * X + q.P(4) * Y) * (-k2 + q.P(4) * Y + q.P(3) * X) + 4 * k2 * k2 * a2 * y2 +
        k2 * k2 * k2 * k2);
  return clip10(q.P(0), r);
}

double enneper(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  if (std::fabs(q.Z()) < 0.2) q.Z() = 0.2;
  // POV-Ray writes 2/3, 1/4, 8/9 and 2/9 in integer arithmetic: all four are 0.
  const double a = (y2 - x2) / (2 * q.Z()) + 2 * z2 / 9 + 0;
  const double b = (y2 - x2) / (4 * q.Z()) - 0 * (x2 + y2 + 0 * z2) + 0;
  return clip10(q.P(0), -(a * a * a - 6 * b * b));
}

double helical_torus(const Point& q) {
  double rxz = std::sqrt(q.X() * q.X() + q.Z() * q.Z());
  if (q.X() == 0 && q.Z() == 0) q.X() = 0.000001;
  const double ph = std::atan2(q.X(), q.Z());
  double t = std::atan2(rxz - q.P(0), q.Y());
  const double r = std::sqrt((rxz - q.P(0)) * (rxz - q.P(0)) + q.Y() * q.Y());
  double th = std::fmod(ph * q.P(1) + t * q.P(2), kTwoPi);
  if (th < 0) th += kTwoPi;
  t = std::atan2((th - kPi) * q.P(8), r - q.P(5));
  t = std::cos(t * q.P(7) + ph * q.P(9)) * q.P(3) + q.P(4);
  rxz = q.P(4) + q.P(5) - q.P(0) - rxz;
  th = th - kPi;
  t = t - std::min(std::sqrt((r - q.P(5)) * (r - q.P(5)) + th * th * q.P(6)), r + q.P(5));
  return -std::max(rxz, t);
}

double helix1(const Point& q) {
  const double r = std::sqrt(q.X() * q.X() + q.Z() * q.Z());
  if (q.X() == 0 && q.Z() == 0) q.X() = 0.000001;
  double th = std::atan2(q.Z(), q.X());
  th = std::fmod(th * q.P(0) + q.Y() * q.P(1) * q.P(0), kTwoPi);
  if (th < 0) th += kTwoPi;
  q.Z() = (th - kPi) / q.P(4) / (q.P(1) * q.P(0));
  q.X() = r - q.P(3);
  double section = 0;
  if (q.P(5) == 1) {
    section = std::sqrt(q.X() * q.X() + q.Z() * q.Z());
  } else {
    if (q.P(6) != 0) {
      const double c = std::cos(q.P(6) * kDegree), s = std::sin(q.P(6) * kDegree);
      const double nx = q.X() * c - q.Z() * s;
      q.Z() = q.X() * s + q.Z() * c;
      q.X() = nx;
    }
    if (q.P(5) != 0) section = cross_section(q.X(), q.Z(), q.P(5), q.P(5) * .5);
    else section = std::max(std::fabs(q.X()), std::fabs(q.Z()));
  }
  return -q.P(2) + std::min(q.P(3) + r, section);
}

double helix2(const Point& q) {
  const double angle = q.Y() * q.P(1);
  const double c = std::cos(angle), s = std::sin(angle);
  const double dx = q.X() - q.P(3) * c, dz = q.Z() - q.P(3) * s;
  q.X() = dx * c + dz * s;
  q.Z() = -dx * s + dz * c;
  if (q.P(5) == 1) return std::sqrt(q.X() * q.X() + q.Z() * q.Z()) - q.P(2);
  double section = 0;
  if (q.P(5) != 0) section = cross_section(q.X(), q.Z(), q.P(5), q.P(5) * .5);
  else section = std::max(std::fabs(q.X()), std::fabs(q.Z()));
  return section - q.P(2);
}

// f_hex_x / f_hex_y: distance-like values to a hexagonal grid of cells in the x-y plane.
double hex(const Point& q, bool want_y) {
  const double root3 = std::sqrt(3.0);
  double a = std::fabs(std::fmod(std::fabs(q.X()), root3) - root3 / 2);
  double b = std::fabs(std::fmod(std::fabs(q.Y()), 3) - 1.5);
  const double a2 = root3 / 2 - a, b2 = 1.5 - b;
  if ((a * a + b * b) > (a2 * a2 + b2 * b2)) {
    a = a2;
    b = b2;
  }
  const double th = std::atan2(b, a);
  if (th < kPi / 6) return want_y ? b : a;
  if (!want_y) return std::cos(kPi / 3) * a + std::sin(kPi / 3) * b;
  return std::fabs(-std::sin(kPi / 3) * a + std::cos(kPi / 3) * b);
}

double hunt_surface(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  const double a = x2 + y2 + z2 - 13, b = 3 * x2 + y2 - 4 * z2 - 12;
  return clip10(q.P(0), -(4 * a * a * a + 27 * b * b));
}

double hyperbolic_torus(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  const double a = q.P(1) * q.P(1), b = q.P(2) * q.P(2);
  return clip10(q.P(0), -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * z2 - 2 * (a + b) * x2 + y2 * y2 - 2 * y2 * z2 +
                          2 * (a - b) * y2 + z2 * z2 + 2 * (a + b) * z2 + (a - b) * (a - b)));
}

double kampyle_of_eudoxus(const Point& q) {
  const double x2 = q.X() * q.X();
  const double a = q.P(2), b = q.P(1);
  return clip10(q.P(0), -((q.Y() * q.Y() + q.Z() * q.Z()) - a * a * x2 * x2 + a * a * b * b * x2));
}

double kampyle_of_eudoxus_2d(const Point& q) {
  double x2 = q.X() * q.X(), y2 = q.Y() * q.Y();
  surface_of_revolution(q, q.P(3), q.P(4), q.P(5), x2, y2);
  const double a = q.P(2), b = q.P(1);
  return clip10(q.P(0), -(y2 - a * a * x2 * x2 + a * a * b * a * x2));   // sic: P1*P2, as POV-Ray
}

double klein_bottle(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  const double s = x2 + y2 + z2;
  const double m = s - 2 * q.Y() - 1;
  return clip10(q.P(0), -((s + 2 * q.Y() - 1) * (m * m - 8 * z2) + 16 * q.X() * q.Z() * m));
}

double kummer_v1(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  return clip10(q.P(0), -(x2 * x2 + y2 * y2 + z2 * z2 - x2 - y2 - z2 - x2 * y2 - x2 * z2 - y2 * z2 + 1));
}

double kummer_v2(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  return clip10(q.P(0), -(x2 * x2 + y2 * y2 + z2 * z2 + q.P(1) * (x2 + y2 + z2) +
                          q.P(2) * (x2 * y2 + x2 * z2 + y2 * z2) + q.P(3) * q.X() * q.Y() * q.Z() - 1));
}

double lemniscate_of_gerono(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  return clip10(q.P(0), -(x2 * x2 - x2 + y2 + z2));
}

double lemniscate_of_gerono_2d(const Point& q) {
  double x2 = q.X() * q.X(), y2 = q.Y() * q.Y();
  surface_of_revolution(q, q.P(3), q.P(4), q.P(5), x2, y2);
  const double a = q.P(2), b = q.P(1);
  return clip10(q.P(0), -(y2 - a * a * b * b * x2 + a * a * x2 * x2));
}

// One strand of f_mesh1: distance to a wavy thread across the grid.
double mesh_strand(double along, double period, double thickness, double height) {
  double r = std::fmod(along, period * 2);
  if (r < 0) r += period * 2;
  r = std::fabs(r - period) * thickness;
  return -std::sqrt(height * height + r * r);
}

double mesh1(const Point& q) {
  const double X = q.X(), Y = q.Y(), Z = q.Z();
  const double dx = q.P(0), dz = q.P(1), k = q.P(2), amp = q.P(3), h = q.P(4);
  const double wx = kPi / dx, wz = kPi / dz;
  double t = mesh_strand(X, dx, k, (Y - std::cos(Z * wz) * amp) * h);
  t = std::max(mesh_strand(X - dx, dx, k, (Y + std::cos(Z * wz) * amp) * h), t);
  t = std::max(mesh_strand(Z, dz, k, (Y + std::cos(X * wx) * amp) * h), t);
  return -std::max(mesh_strand(Z - dz, dz, k, (Y - std::cos(X * wx) * amp) * h), t);
}

double mitre(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  return clip10(q.P(0), -(4 * x2 * (x2 + y2 + z2) - y2 * (1 - y2 - z2)));
}

double nodal_cubic(const Point& q) {
  const double Y = q.Y(), Z = q.Z();
  return clip10(q.P(0), -(Y * Y * Y + Z * Z * Z - 6 * Y * Z));
}

double ovals_of_cassini(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  const double s = x2 + y2 + z2 + q.P(1) * q.P(1);
  return clip10(q.P(0), -(s * s - q.P(3) * q.P(1) * q.P(1) * (x2 + z2) - q.P(2) * q.P(2)));
}

double parabolic_torus(const Point& q) {
  const double Z = q.Z();
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = Z * Z;
  const double a = q.P(1) * q.P(1), b = q.P(2) * q.P(2);
  return clip10(q.P(0), -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * Z - (a + b) * x2 + y2 * y2 - 2 * y2 * Z +
                          (a - b) * y2 + z2 + (a + b) * Z + (a - b) * (a - b)));
}

double piriform_2d(const Point& q) {
  double x2 = q.X() * q.X(), y2 = q.Y() * q.Y();
  surface_of_revolution(q, q.P(4), q.P(5), q.P(6), x2, y2);
  const double s = q.P(3);
  return clip10(q.P(0), -(q.Y() * q.Y() - q.P(1) * s * s * x2 * q.X() - q.P(2) * s * s * x2 * x2));
}

double poly4(const Point& q) {
  const double Y = q.Y(), y2 = Y * Y;
  double radius = q.P(0) + q.P(1) * Y + q.P(2) * y2 + q.P(3) * y2 * Y + q.P(4) * y2 * y2;
  if (radius < -5.) radius = -5.;
  return -radius + std::sqrt(q.X() * q.X() + q.Z() * q.Z());
}

double polytubes(const Point& q) {
  const double Y = q.Y(), y2 = Y * Y;
  const double radius = q.P(1) + q.P(2) * Y + q.P(3) * y2 + q.P(4) * y2 * Y + q.P(5) * y2 * y2;
  double r = -10000;
  // POV-Ray's (int) conversion: NaN and out-of-range counts give INT_MIN on x86, so no tube at all.
  const double count = q.P(0);
  const int tubes = count > -2147483649.0 && count < 2147483648.0 ? static_cast<int>(count) : INT_MIN;
  for (int i = 0; i < tubes; ++i) {
    const double dx = q.X() - radius * std::sin(2 * kPi / q.P(0) * i);
    const double dz = q.Z() - radius * std::cos(2 * kPi / q.P(0) * i);
    r = std::max(r, -std::sqrt(dx * dx + dz * dz));
  }
  return -r;
}

double quantum(const Point& q) {
  if (q.X() == 0 && q.Z() == 0) q.X() = 1e-6;
  double r = std::sqrt(q.X() * q.X() + q.Z() * q.Z());
  const double c = std::cos(std::atan2(r, q.Y()));
  r = std::sqrt(r * r + q.Y() * q.Y()) * 2.;
  const double t = r * r * std::exp(-r * 0.33333333) * (3. * c * c - 1);
  return (t * t - 12.0) * (-0.1);
}

double quartic_cylinder(const Point& q) {
  const double x2 = q.X() * q.X(), z2 = q.Z() * q.Z();
  const double a = q.P(2), b = q.P(1);
  return clip10(q.P(0), -((x2 + z2) * q.Y() * q.Y() + a * a * (x2 + z2) - a * a * b * b));
}

double rounded_box(const Point& q) {
  const double radius = q.P(0);
  // Beyond the inner box (half-size less the radius) on the positive and on the negative side.
  const double hx = q.P(1) - radius, hy = q.P(2) - radius, hz = q.P(3) - radius;
  const double px = q.X() < hx ? 0 : q.X() - hx;
  const double py = q.Y() < hy ? 0 : q.Y() - hy;
  const double pz = q.Z() < hz ? 0 : q.Z() - hz;
  const double lx = radius - q.P(1), ly = radius - q.P(2), lz = radius - q.P(3);
  const double nx = q.X() > lx ? 0 : lx - q.X();
  const double ny = q.Y() > ly ? 0 : ly - q.Y();
  const double nz = q.Z() > lz ? 0 : lz - q.Z();
  const double dx = std::max(nx, px), dy = std::max(ny, py), dz = std::max(nz, pz);
  return -radius + std::sqrt(dx * dx + dy * dy + dz * dz) - 1e-6;
}

double spikes(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  const double e = q.P(0), k = q.P(1);
  const double r = std::exp(-(x2 + y2 + z2) * q.P(3)) * q.P(4) - ellipsoid_field(x2 * e, y2 * e, z2, k) -
                   ellipsoid_field(x2 * e, y2, z2 * e, k) - ellipsoid_field(x2, y2 * e, z2 * e, k);
  return -r * q.P(2);
}

double spikes_2d(const Point& q) {
  const double X = q.X(), Z = q.Z();
  return -(q.P(0) * std::cos(q.P(1) * X) * std::cos(q.P(2) * Z) * std::exp(-q.P(3) * (X * X + Z * Z)) - q.Y());
}

double spiral(const Point& q) {
  double r = std::sqrt(q.X() * q.X() + q.Z() * q.Z());
  if (q.X() == 0 && q.Z() == 0) q.X() = 0.000001;
  const double th = std::atan2(q.Z(), q.X());
  r = r + q.P(0) * th / kTwoPi;
  double d = std::fmod(r, q.P(0)) - q.P(0) * 0.5;
  if (q.P(5) == 1) d = std::sqrt(d * d + q.Y() * q.Y());
  else if (q.P(5) != 0) d = cross_section(d, q.Y(), q.P(5), 1. / (2 / q.P(5)));
  else d = std::max(std::fabs(d), std::fabs(q.Y()));
  r = std::sqrt(q.X() * q.X() + q.Y() * q.Y() + q.Z() * q.Z());
  return -std::min(q.P(2) - r, q.P(1) - std::min(d, r));
}

double strophoid(const Point& q, bool two_d) {
  double x2 = q.X() * q.X(), y2 = q.Y() * q.Y();
  if (two_d) surface_of_revolution(q, q.P(4), q.P(5), q.P(6), x2, y2);
  const double a2 = q.P(3) * q.P(3);
  const double side = two_d ? y2 : q.Y() * q.Y() + q.Z() * q.Z();
  return clip10(q.P(0), -((q.P(2) - q.X()) * side - a2 * q.P(1) * x2 - a2 * x2 * q.X()));
}

double superellipsoid(const Point& q) {
  const double e = q.P(0), n = q.P(1);
  const double p = 2 / e, inv_n = 1 / n;
  return 1 - std::pow(std::pow(std::pow(std::fabs(q.X()), p) + std::pow(std::fabs(q.Y()), p), e * inv_n) +
                          std::pow(std::fabs(q.Z()), 2 * inv_n),
                      n * .5);
}

double torus(const Point& q) {
  const double d = std::sqrt(q.X() * q.X() + q.Z() * q.Z()) - q.P(0);
  return -q.P(1) + std::sqrt(d * d + q.Y() * q.Y());
}

double torus2(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  const double a = q.P(1) * q.P(1), b = q.P(2) * q.P(2);
  return clip10(q.P(0), -(x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 + 2 * y2 * z2 - 2 * (a + b) * x2 +
                          2 * (a - b) * y2 - 2 * (a + b) * z2 + (a - b) * (a - b)));
}

double torus_gumdrop(const Point& q) {
  const double x2 = q.X() * q.X(), y2 = q.Y() * q.Y(), z2 = q.Z() * q.Z();
  return clip10(q.P(0), -(4 * (x2 * x2 + (y2 + z2) * (y2 + z2)) + 17 * x2 * (y2 + z2) - 20 * (x2 + y2 + z2) + 17));
}

double witch_of_agnesi_2d(const Point& q) {
  double x2 = q.X() * q.X(), y2 = q.Y() * q.Y();
  surface_of_revolution(q, q.P(3), q.P(4), q.P(5), x2, y2);
  return clip10(q.P(0), -(q.P(1) * q.P(1) * q.Y() + x2 * q.Y() - q.P(2)));
}

double folium_surface_2d(const Point& q) {
  double x2 = q.X() * q.X(), y2 = q.Y() * q.Y();
  surface_of_revolution(q, q.P(3), q.P(4), q.P(5), x2, y2);
  return clip10(q.P(0), -(y2 * (1 + (q.P(2) - 4 * q.P(1)) * q.X()) + x2 * (1 + q.P(2))));
}

double devils_curve_2d(const Point& q) {
  double x2 = q.X() * q.X(), y2 = q.Y() * q.Y();
  surface_of_revolution(q, q.P(3), q.P(4), q.P(5), x2, y2);
  return clip10(q.P(0), -(x2 * (x2 - q.P(1) * q.P(1)) - y2 * (y2 - q.P(2) * q.P(2))));
}

const InternalFunctionInfo kInfo[kInternalFunctionCount] = {
    {"f_algbr_cyl1", 8, true}, {"f_algbr_cyl2", 8, true}, {"f_algbr_cyl3", 8, true},
    {"f_algbr_cyl4", 8, true}, {"f_bicorn", 5, true}, {"f_bifolia", 5, true},
    {"f_blob", 8, true}, {"f_blob2", 7, true}, {"f_boy_surface", 5, true},
    {"f_comma", 4, true}, {"f_cross_ellipsoids", 7, true}, {"f_crossed_trough", 4, true},
    {"f_cubic_saddle", 4, true}, {"f_cushion", 4, true}, {"f_devils_curve", 4, true},
    {"f_devils_curve_2d", 9, true}, {"f_dupin_cyclid", 9, true}, {"f_ellipsoid", 6, true},
    {"f_enneper", 4, true}, {"f_flange_cover", 7, true}, {"f_folium_surface", 6, true},
    {"f_folium_surface_2d", 9, true}, {"f_glob", 4, true}, {"f_heart", 4, true},
    {"f_helical_torus", 13, true}, {"f_helix1", 10, true}, {"f_helix2", 10, true},
    {"f_hex_x", 4, true}, {"f_hex_y", 4, true}, {"f_hetero_mf", 9, true},
    {"f_hunt_surface", 4, true}, {"f_hyperbolic_torus", 6, true}, {"f_isect_ellipsoids", 7, true},
    {"f_kampyle_of_eudoxus", 6, true}, {"f_kampyle_of_eudoxus_2d", 9, true}, {"f_klein_bottle", 4, true},
    {"f_kummer_surface_v1", 4, true}, {"f_kummer_surface_v2", 7, true}, {"f_lemniscate_of_gerono", 4, true},
    {"f_lemniscate_of_gerono_2d", 9, true}, {"f_mesh1", 8, true}, {"f_mitre", 4, true},
    {"f_nodal_cubic", 4, true}, {"f_odd", 4, true}, {"f_ovals_of_cassini", 7, true},
    {"f_paraboloid", 4, true}, {"f_parabolic_torus", 6, true}, {"f_ph", 3, true},
    {"f_pillow", 4, true}, {"f_piriform", 4, true}, {"f_piriform_2d", 10, true},
    {"f_poly4", 8, true}, {"f_polytubes", 9, true}, {"f_quantum", 4, true},
    {"f_quartic_paraboloid", 4, true}, {"f_quartic_saddle", 4, true}, {"f_quartic_cylinder", 6, true},
    {"f_r", 3, true}, {"f_ridge", 9, true}, {"f_ridged_mf", 9, true},
    {"f_rounded_box", 7, true}, {"f_sphere", 4, true}, {"f_spikes", 8, true},
    {"f_spikes_2d", 7, true}, {"f_spiral", 9, true}, {"f_steiners_roman", 4, true},
    {"f_strophoid", 7, true}, {"f_strophoid_2d", 10, true}, {"f_superellipsoid", 5, true},
    {"f_th", 3, true}, {"f_torus", 5, true}, {"f_torus2", 6, true},
    {"f_torus_gumdrop", 4, true}, {"f_umbrella", 4, true}, {"f_witch_of_agnesi", 5, true},
    {"f_witch_of_agnesi_2d", 9, true}, {"f_noise3d", 3, true}, {"f_pattern", 3, true},
    {"f_noise_generator", 4, true},
};

}  // namespace

const InternalFunctionInfo& internal_function_info(int id) { return kInfo[id]; }

double evaluate_internal_function(int id, double* p, int scene_noise_generator) {
  const Point q{p};
  const double X = q.X(), Y = q.Y(), Z = q.Z();
  switch (id) {
    case 0: return algbr_cyl1(q);
    case 1: return algbr_cyl(q, 2);
    case 2: return algbr_cyl(q, 3);
    case 3: return algbr_cyl(q, 4);
    case 4: return bicorn(q);
    case 5: return bifolia(q);
    case 6: return blob(q);
    case 7: return blob2(q);
    case 8: return boy_surface(q);
    case 9: return comma(q);
    case 10: return three_ellipsoids(q, 1);
    case 11: return clip10(q.P(0), X * X * Z * Z - Y);
    case 12: return clip10(q.P(0), -(X * X * X - Y * Y * Y - Z));
    case 13: return cushion_like(q, false);
    case 14: {
      const double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
      return clip10(q.P(0), -(x2 * x2 + 2 * x2 * z2 - 0.36 * x2 - y2 * y2 + 0.25 * y2 + z2 * z2));
    }
    case 15: return devils_curve_2d(q);
    case 16: return dupin_cyclid(q);
    case 17: return std::sqrt(X * X * q.P(0) * q.P(0) + Y * Y * q.P(1) * q.P(1) + Z * Z * q.P(2) * q.P(2));
    case 18: return enneper(q);
    case 19: return three_ellipsoids(q, 0);
    case 20: {
      const double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
      return clip10(q.P(0), (y2 + z2) * (1 + (q.P(2) - 4 * q.P(1)) * X) + x2 * (1 + q.P(2)));
    }
    case 21: return folium_surface_2d(q);
    case 22: {
      const double x2 = X * X;
      return clip10(q.P(0), 0.5 * x2 * x2 * X + 0.5 * x2 * x2 - (Y * Y + Z * Z));
    }
    case 23: {
      const double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
      const double s = 2 * x2 + y2 + z2 - 1;
      return clip10(q.P(0), -(s * s * s - 0.1 * x2 * z2 * Z - y2 * z2 * Z));
    }
    case 24: return helical_torus(q);
    case 25: return helix1(q);
    case 26: return helix2(q);
    case 27: return hex(q, false);
    case 28: return hex(q, true);
    case 30: return hunt_surface(q);
    case 31: return hyperbolic_torus(q);
    case 32: return three_ellipsoids(q, -1);
    case 33: return kampyle_of_eudoxus(q);
    case 34: return kampyle_of_eudoxus_2d(q);
    case 35: return klein_bottle(q);
    case 36: return kummer_v1(q);
    case 37: return kummer_v2(q);
    case 38: return lemniscate_of_gerono(q);
    case 39: return lemniscate_of_gerono_2d(q);
    case 40: return mesh1(q);
    case 41: return mitre(q);
    case 42: return nodal_cubic(q);
    case 43: return cushion_like(q, true);
    case 44: return ovals_of_cassini(q);
    case 45: return clip10(q.P(0), -(X * X - Y + Z * Z));
    case 46: return parabolic_torus(q);
    case 47: return std::atan2(std::sqrt(X * X + Z * Z), Y);
    case 48: {
      const double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
      return clip10(q.P(0), x2 * x2 + y2 * y2 + z2 * z2 - (x2 + y2 + z2));
    }
    case 49: {
      const double x2 = X * X;
      return -clip10(q.P(0), -((x2 * x2 - x2 * X) + Y * Y + Z * Z));
    }
    case 50: return piriform_2d(q);
    case 51: return poly4(q);
    case 52: return polytubes(q);
    case 53: return quantum(q);
    case 54: {
      const double x2 = X * X, z2 = Z * Z;
      return clip10(q.P(0), -(x2 * x2 + z2 * z2 - Y));
    }
    case 55: {
      const double x2 = X * X, z2 = Z * Z;
      return clip10(q.P(0), -(x2 * x2 - z2 * z2 - Y));
    }
    case 56: return quartic_cylinder(q);
    case 57: return std::sqrt(X * X + Y * Y + Z * Z);
    case 29: return hetero_mf(p);
    case 58: return ridge(p);
    case 59: return ridged_mf(p);
    case 60: return rounded_box(q);
    case 61: return -q.P(0) + std::sqrt(X * X + Y * Y + Z * Z);
    case 62: return spikes(q);
    case 63: return spikes_2d(q);
    case 64: return spiral(q);
    case 65: {
      const double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
      return clip10(q.P(0), -(x2 * y2 + x2 * z2 + y2 * z2 + X * Y * Z));
    }
    case 66: return strophoid(q, false);
    case 67: return strophoid(q, true);
    case 68: return superellipsoid(q);
    case 69: return std::atan2(X, Z);
    case 70: return torus(q);
    case 71: return torus2(q);
    case 72: return torus_gumdrop(q);
    case 73: return clip10(q.P(0), -(X * X - Y * Z * Z));
    case 74: return clip10(q.P(0), -(q.P(1) * (Y - 1) + (X * X + Z * Z) * Y));
    case 75: return witch_of_agnesi_2d(q);
    case 76: return noise3d(p, scene_noise_generator);
    case 78: return noise_with_generator(p);
    case 77: return 0.0;   // internal(77) without a pattern (a bare `function { internal(77) }`) is 0 in POV-Ray
    default: return 0.0;   // not evaluable: the caller checks InternalFunctionInfo::evaluable first
  }
}

}  // namespace povtrace::sdl
