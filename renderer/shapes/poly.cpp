// Polynomial surfaces: poly, cubic, quartic of order 2 to 35.
//
// SDL: `poly { N, <c…> }`, `cubic { <20 coefficients> }`, `quartic { <35 coefficients> }`, `sturm` (POV-Ray 3.7
// reference "Poly"). The surface is P(x, y, z) = Σ c·xⁱyʲzᵏ = 0, terms ordered with x's power from N down to 0, then
// y's from N − i down, then z's from N − i − j down.
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/poly.cpp, 3.7-stable):
// - The world ray goes into object space by the inverse POV-Ray composes (Poly::object_from_world) and its direction
//   is normalised (length L); roots are object-space depths,
//   reported as depth / L. A root counts when it is above DEPTH_TOLERANCE = 1e-4 (object space), with no upper limit,
//   and a root equal to an earlier one is reported once.
// - Order 2 solves its quadratic directly: the coefficients of t², t, 1 from the expanded terms; when |a| < 1e-20 it
//   is linear (no root if |b| < 1e-20 too); a negative discriminant gives no root, otherwise both roots.
// - Orders 3 to 35 substitute the ray into every non-zero term (binomial expansion of each power), drop leading
//   coefficients that are exactly 0, and hand what is left to Solve_Polynomial with ROOT_TOLERANCE = 1e-4 and the
//   `sturm` flag (povtrace's solve_polynomial reproduces its rules: degree 5 and above always by Sturm sequences in
//   [0, MAX_DISTANCE], `sturm` or not); an equation reduced to degree 1 or less has no roots.
// - Inside: P(p) < INSIDE_TOLERANCE = 1e-4 in object space (inverted by `inverse`).
// - Normal: the gradient of P in object space (POV-Ray's normal0 above order 4, the same sums written out below), carried to world space by the inverse transpose and normalised; a zero
//   gradient gives <1, 0, 0>.
// - Bounds: none (POV-Ray gives polys infinite bounds unless bounded_by says otherwise).
#include <array>
#include <cmath>
#include <limits>

#include "renderer/geometry.hpp"
#include "renderer/shapes/poly_shape.hpp"
#include "runtime/polynomial_roots.hpp"
#include "renderer/shapes/poly.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double depth_tolerance = 1e-4;
constexpr double root_tolerance = 1e-4;
constexpr double coefficient_limit = 1e-20;
constexpr double inside_tolerance = 1e-4;

const PolyData& data_of(const Primitive& p) { return static_cast<const PolyData&>(*p.data); }

// Powers 0…order of one coordinate (entries above `order` are never read).
std::array<double, PolyData::max_order + 1> powers(double v, int order) {
  std::array<double, PolyData::max_order + 1> out;
  out[0] = 1.0;
  for (int i = 1; i <= order; ++i) out[i] = out[i - 1] * v;
  return out;
}

// Calls f(i, j, k, c) for every term in POV-Ray's order.
template <class F>
void for_each_term(const PolyData& d, F&& f) {
  int term = 0;
  for (int i = d.order; i >= 0; --i)
    for (int j = d.order - i; j >= 0; --j)
      for (int k = d.order - (i + j); k >= 0; --k) f(i, j, k, d.coefficients[static_cast<std::size_t>(term++)]);
}

double binomial(int n, int r) {
  double b = 1;
  for (int i = 1; i <= r; ++i) b = b * (n - r + i) / i;
  return b;
}

// sum += term through a volatile store: no vectoriser may reorder the additions into one coefficient.
inline void add_in_order(double& sum, double term) {
  volatile double v = sum + term;
  sum = v;
}

// Coefficients of P(o + t·d) by powers of t, highest (t^order) first.
std::array<double, PolyData::max_order + 1> ray_polynomial(const PolyData& d, Vec3 o, Vec3 dir) {
  const int n = d.order;
  const auto ox = powers(o.x, n), oy = powers(o.y, n), oz = powers(o.z, n);
  const auto dx = powers(dir.x, n), dy = powers(dir.y, n), dz = powers(dir.z, n);
  std::array<double, PolyData::max_order + 1> eqn{};
  for_each_term(d, [&](int i, int j, int k, double c) {
    if (c == 0) return;
    // (o + t d)^i = Σ_h C(i,h) d^(i−h) o^h t^(i−h): index by the power of o, as the term's t-power is i − h.
    double tx[PolyData::max_order + 1], ty[PolyData::max_order + 1], tz[PolyData::max_order + 1];
    for (int h = 0; h <= i; ++h) tx[h] = binomial(i, h) * dx[static_cast<std::size_t>(i - h)] * ox[static_cast<std::size_t>(h)];
    for (int h = 0; h <= j; ++h) ty[h] = binomial(j, h) * dy[static_cast<std::size_t>(j - h)] * oy[static_cast<std::size_t>(h)];
    for (int h = 0; h <= k; ++h) tz[h] = binomial(k, h) * dz[static_cast<std::size_t>(k - h)] * oz[static_cast<std::size_t>(h)];
    const int offset = n - (i + j + k);
    // The order of the additions into each coefficient is POV-Ray's as its g++ -O3 build runs them: the loop over
    // y's powers vectorised two at a time (outer-loop vectorisation), so within a pair b, b + 1 the slot that both
    // reach gets (b + 1, e) before (b, e + 1); an odd last b comes after. Written out here so that every build of
    // povtrace adds in that order (the last bit decides the roots of ill-conditioned polys, prim_poly_sturm_noise).
    for (int a = 0; a <= i; ++a) {
      const double ca = c * tx[a];
      int b = 0;
      for (; b + 1 <= j; b += 2) {
        const double cab0 = ca * ty[b], cab1 = ca * ty[b + 1];
        for (int e = 0; e <= k; ++e) {
          add_in_order(eqn[static_cast<std::size_t>(offset + a + b + e)], cab0 * tz[e]);
          add_in_order(eqn[static_cast<std::size_t>(offset + a + b + 1 + e)], cab1 * tz[e]);
        }
      }
      for (; b <= j; ++b) {
        const double cab = ca * ty[b];
        for (int e = 0; e <= k; ++e) add_in_order(eqn[static_cast<std::size_t>(offset + a + b + e)], cab * tz[e]);
      }
    }
  });
  return eqn;
}

int quadratic_roots(const PolyData& d, Vec3 o, Vec3 v, double* roots) {
  const double* a = d.coefficients.data();
  const double ac = a[0] * v.x * v.x + a[1] * v.x * v.y + a[2] * v.x * v.z + a[4] * v.y * v.y + a[5] * v.y * v.z +
                    a[7] * v.z * v.z;
  const double bc = 2 * a[0] * o.x * v.x + a[1] * (o.x * v.y + v.x * o.y) + a[2] * (o.x * v.z + v.x * o.z) +
                    a[3] * v.x + 2 * a[4] * o.y * v.y + a[5] * (o.y * v.z + v.y * o.z) + a[6] * v.y +
                    2 * a[7] * o.z * v.z + a[8] * v.z;
  const double cc = a[0] * o.x * o.x + a[1] * o.x * o.y + a[2] * o.x * o.z + a[3] * o.x + a[4] * o.y * o.y +
                    a[5] * o.y * o.z + a[6] * o.y + a[7] * o.z * o.z + a[8] * o.z + a[9];
  if (std::fabs(ac) < coefficient_limit) {
    if (std::fabs(bc) < coefficient_limit) return 0;
    roots[0] = -cc / bc;
    return 1;
  }
  double disc = bc * bc - 4.0 * ac * cc;
  if (disc < 0.0) return 0;
  disc = std::sqrt(disc);
  roots[0] = (-bc + disc) / (2.0 * ac);
  roots[1] = (-bc - disc) / (2.0 * ac);
  return 2;
}

int higher_roots(const PolyData& d, Vec3 o, Vec3 v, double* roots) {
  const auto eqn = ray_polynomial(d, o, v);
  int first = 0;
  while (first <= d.order && eqn[static_cast<std::size_t>(first)] == 0.0) ++first;
  const int degree = d.order - first;
  if (degree <= 1) return 0;
  return poly::solve_polynomial(degree, eqn.data() + first, roots, d.sturm, root_tolerance, tolerance::max_distance);
}
}  // namespace

Intersections PolyShape::intersect(const Primitive& p, const Ray& ray) {
  const PolyData& d = data_of(p);
  const Vec3 o = p.transformed ? p.object_from_world.point(ray.origin) : ray.origin;
  Vec3 v = p.transformed ? p.object_from_world.vector(ray.direction) : ray.direction;
  const double len = std::sqrt(dot(v, v));
  v *= 1.0 / len;
  double roots[PolyData::max_order];
  const int count = d.order == 2 ? quadratic_roots(d, o, v, roots) : higher_roots(d, o, v, roots);
  Intersections out;
  for (int i = 0; i < count; ++i) {
    if (!(roots[i] > depth_tolerance)) continue;
    bool repeated = false;
    for (int j = 0; j < i; ++j) repeated = repeated || roots[j] == roots[i];
    if (repeated || out.count == Intersections::capacity) continue;
    // Depth-sorted, as every few-root shape reports them.
    int at = out.count++;
    const double t = roots[i] / len;
    while (at > 0 && out.t[at - 1] > t) {
      out.t[at] = out.t[at - 1];
      --at;
    }
    out.t[at] = t;
  }
  return out;
}

double poly_value(const PolyData& d, Vec3 q) {
  const auto x = powers(q.x, d.order), y = powers(q.y, d.order), z = powers(q.z, d.order);
  double sum = 0;
  for_each_term(d, [&](int i, int j, int k, double c) {
    if (c != 0.0) sum += c * x[static_cast<std::size_t>(i)] * y[static_cast<std::size_t>(j)] * z[static_cast<std::size_t>(k)];
  });
  return sum;
}

Vec3 PolyShape::normal(const Primitive& p, Vec3 world_point) {
  const PolyData& d = data_of(p);
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  const auto x = powers(q.x, d.order), y = powers(q.y, d.order), z = powers(q.z, d.order);
  Vec3 g{0, 0, 0};
  for_each_term(d, [&](int i, int j, int k, double c) {
    const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j), uk = static_cast<std::size_t>(k);
    if (i >= 1) g.x += i * c * x[ui - 1] * y[uj] * z[uk];
    if (j >= 1) g.y += j * c * x[ui] * y[uj - 1] * z[uk];
    if (k >= 1) g.z += k * c * x[ui] * y[uj] * z[uk - 1];
  });
  if (p.transformed) g = p.object_from_world.normal_from_inverse(g);
  const double l2 = dot(g, g);
  if (!(l2 > 0.0)) return {1, 0, 0};
  return g * (1.0 / std::sqrt(l2));
}

bool PolyShape::inside(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  const bool in = poly_value(data_of(p), q) < inside_tolerance;
  return p.inverse ? !in : in;
}

Bounds PolyShape::world_bounds(const Primitive&) {
  const double inf = std::numeric_limits<double>::infinity();
  return Bounds{Vec3{-inf, -inf, -inf}, Vec3{inf, inf, inf}};
}

}  // namespace povtrace::render::shapes

namespace povtrace::render {
Primitive make_poly(const Poly& poly, const Matrix& world_from_object) {
  auto data = std::make_shared<PolyData>();
  data->order = poly.order;
  data->sturm = poly.sturm;
  data->coefficients = *poly.coefficients;
  Primitive p;
  p.type = ShapeType::poly;
  p.transformed = !(world_from_object == Matrix::identity());
  p.world_from_object = world_from_object;
  if (p.transformed) p.object_from_world = poly.object_from_world;   // POV-Ray's composed inverse
  p.data = std::move(data);
  return p;
}
}  // namespace povtrace::render
