// Quadric surfaces: `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }` (POV-Ray 3.7 reference "Quadric"; shapes_old.inc's
// Ellipsoid, Cylinder_X/Y/Z, QCone_X/Y/Z, Paraboloid_X/Y, Hyperboloid… are quadrics).
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/quadrics.cpp, 3.7-stable):
// - The quadric is kept in world space: each transform is applied to its coefficient matrix (as a symmetric 4×4
//   form Q, transformed by M⁻¹ Q M⁻ᵀ), and the world ray (unit direction) is solved directly, so the depth tolerance
//   is DEPTH_TOLERANCE = 1e-6 in world units, with the MAX_DISTANCE = 1e7 upper limit.
// - Roots: with a, b, c the coefficients of a t² + 2b t + c, no root when d = b² − ac <= 0 (a grazing ray misses);
//   else (−b ± √d)/a. Without quadratic terms (a = 0) the single root −c/(2b) (none when b = 0).
// - Inside: the form's value <= 0 (the surface counts as inside); `inverse` flips it.
// - Normal: the gradient, normalised; <1, 0, 0> where it vanishes.
// - Bounds: none (POV-Ray bounds a quadric only when bounded_by says so).
#include <cmath>
#include <limits>

#include "renderer/geometry.hpp"
#include "renderer/shapes/poly_shape.hpp"
#include "renderer/shapes/quadric.hpp"

namespace povtrace::render {

namespace {
constexpr double depth_tolerance = 1e-6;

// The symmetric 4×4 form of A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J.
using Form = std::array<std::array<double, 4>, 4>;

Form form_of(const Quadric& q) {
  return {{{q.square.x, q.mixed.x / 2, q.mixed.y / 2, q.linear.x / 2},
           {q.mixed.x / 2, q.square.y, q.mixed.z / 2, q.linear.y / 2},
           {q.mixed.y / 2, q.mixed.z / 2, q.square.z, q.linear.z / 2},
           {q.linear.x / 2, q.linear.y / 2, q.linear.z / 2, q.constant}}};
}

// Points are row vectors [x y z 1]; a world point p has object point p·N with N = M⁻¹ (4×4, last column 0 0 0 1).
Form to_world(const Form& q, const Matrix& object_from_world) {
  double n[4][4] = {};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 3; ++c) n[r][c] = object_from_world.m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
  n[3][3] = 1;
  Form out{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double sum = 0;
      for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 4; ++l) sum += n[i][k] * q[static_cast<std::size_t>(k)][static_cast<std::size_t>(l)] * n[j][l];
      out[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = sum;
    }
  return out;
}

const QuadricData& data_of(const Primitive& p) { return static_cast<const QuadricData&>(*p.data); }
}  // namespace

Primitive make_quadric(const Quadric& q, const Matrix& world_from_object) {
  const Form f = world_from_object == Matrix::identity() ? form_of(q) : to_world(form_of(q), world_from_object.inverse());
  auto d = std::make_shared<QuadricData>();
  d->a = f[0][0];
  d->e = f[1][1];
  d->h = f[2][2];
  d->b = 2 * f[0][1];
  d->c = 2 * f[0][2];
  d->f = 2 * f[1][2];
  d->d = 2 * f[0][3];
  d->g = 2 * f[1][3];
  d->i = 2 * f[2][3];
  d->j = f[3][3];
  Primitive p;
  p.type = ShapeType::quadric;
  p.data = std::move(d);
  return p;
}

namespace shapes {

Intersections QuadricShape::intersect(const Primitive& p, const Ray& ray) {
  const QuadricData& q = data_of(p);
  const double xo = ray.origin.x, yo = ray.origin.y, zo = ray.origin.z;
  const double xd = ray.direction.x, yd = ray.direction.y, zd = ray.direction.z;
  const double a = xd * (q.a * xd + q.b * yd + q.c * zd) + yd * (q.e * yd + q.f * zd) + zd * q.h * zd;
  const double b = xd * (q.a * xo + 0.5 * (q.b * yo + q.c * zo + q.d)) + yd * (q.e * yo + 0.5 * (q.b * xo + q.f * zo + q.g)) +
                   zd * (q.h * zo + 0.5 * (q.c * xo + q.f * yo + q.i));
  const double c = xo * (q.a * xo + q.b * yo + q.c * zo + q.d) + yo * (q.e * yo + q.f * zo + q.g) + zo * (q.h * zo + q.i) +
                   q.j;
  double t1, t2;
  if (a != 0.0) {
    double d = b * b - a * c;
    if (d <= 0.0) return {};
    d = std::sqrt(d);
    t1 = (-b + d) / a;
    t2 = (-b - d) / a;
  } else {
    if (b == 0.0) return {};
    t1 = -0.5 * c / b;
    t2 = tolerance::max_distance;
  }
  if (t1 > t2) std::swap(t1, t2);
  Intersections out;
  for (const double t : {t1, t2})
    if (t > depth_tolerance && t < tolerance::max_distance) out.t[out.count++] = t;
  return out;
}

Vec3 QuadricShape::normal(const Primitive& p, Vec3 w) {
  const QuadricData& q = data_of(p);
  const Vec3 n{2.0 * q.a * w.x + q.b * w.y + q.c * w.z + q.d, q.b * w.x + 2.0 * q.e * w.y + q.f * w.z + q.g,
               q.c * w.x + q.f * w.y + 2.0 * q.h * w.z + q.i};
  const double len = std::sqrt(dot(n, n));
  if (len == 0.0) return {1, 0, 0};
  return n * (1.0 / len);
}

bool QuadricShape::inside(const Primitive& p, Vec3 w) {
  const QuadricData& q = data_of(p);
  const bool in = w.x * (q.a * w.x + q.b * w.y + q.d) + w.y * (q.e * w.y + q.f * w.z + q.g) +
                      w.z * (q.h * w.z + q.c * w.x + q.i) + q.j <=
                  0.0;
  return p.inverse ? !in : in;
}

Bounds QuadricShape::world_bounds(const Primitive&) {
  const double inf = std::numeric_limits<double>::infinity();
  return Bounds{Vec3{-inf, -inf, -inf}, Vec3{inf, inf, inf}};
}

}  // namespace shapes
}  // namespace povtrace::render
