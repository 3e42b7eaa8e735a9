// julia_fractal placed in the scene, as POV-Ray 3.7's Fractal::All_Intersections, Normal and Inside do it (facts
// from source/backend/shape/fractal.cpp, 3.7-stable; docs/issue21-julia-fractal.md §3, §7):
// - The world ray goes to object space; its direction is normalised there when its length is not exactly 1 (length
//   factor Len), and object depths become world depths times Len. The march and its hits are julia_fractal_math.cpp's.
// - The normal found at the hit goes to world space by the inverse transpose and is normalised.
// - Inside is the plain iteration at the object-space point (the caller applies `inverse`).
// - Bounds: the cube around the bounding sphere.
#include "renderer/shapes/julia_fractal.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace povtrace::render::shapes {

namespace {
const JuliaFractalData& data_of(const Primitive& p) { return static_cast<const JuliaFractalData&>(*p.data); }

julia::Fractal fractal_of(const JuliaFractal& d) {
  julia::Fractal f;
  for (std::size_t k = 0; k < 4; ++k) {
    f.c[k] = d.julia[k];
    f.slice[k] = d.slice[k];
  }
  f.algebra = static_cast<julia::Algebra>(d.algebra);
  f.function = static_cast<julia::Function>(d.function);
  f.exponent[0] = d.exponent[0];
  f.exponent[1] = d.exponent[1];
  f.max_iteration = d.max_iteration;
  f.precision = d.precision;
  f.slice_distance = d.slice_distance;
  julia::prepare(f);
  return f;
}

// What a hit found that its depth cannot give back: POV-Ray's hit point (the bisection's end inside the set, carried
// to world space) and the normal built from the orbit there. Kept per thread in a ring; a hit's element is its slot.
// A hit is read (shaded, filtered) before its thread has made kHitRecords more julia hits, far more than the hits of
// one ray's closest-hit search.
struct HitRecord {
  Vec3 point, normal;
};
constexpr std::uint32_t kHitRecords = 1u << 16;
thread_local std::vector<HitRecord> hit_records;
thread_local std::uint32_t next_record = 0;

std::uint32_t record(Vec3 point, Vec3 normal) {
  if (hit_records.empty()) hit_records.resize(kHitRecords);
  const std::uint32_t slot = next_record++ & (kHitRecords - 1);
  hit_records[slot] = {point, normal};
  return slot;
}

// The march's hits of the world ray as SurfaceHits (world depths, packed world normals); none for a ray whose
// direction vanishes in object space.
template <class Found>
void march(const Primitive& p, const Ray& ray, bool all_hits, Found&& found) {
  Vec3 origin = ray.origin, direction = ray.direction;
  double len = 1.0;
  if (p.transformed) {
    direction = p.object_from_world.vector(ray.direction);
    const double l2 = dot(direction, direction);
    if (l2 == 0.0) return;
    if (l2 != 1.0) {
      len = 1.0 / std::sqrt(l2);
      direction = direction * len;
    }
    origin = p.object_from_world.point(ray.origin);
  }
  thread_local std::vector<julia::FractalHit> hits;
  hits.clear();
  julia::intersect(data_of(p).fractal, origin, direction, all_hits, hits);
  for (const julia::FractalHit& h : hits) {
    Vec3 n = p.transformed ? p.object_from_world.normal_from_inverse(h.normal) : h.normal;
    n = n * (1.0 / std::sqrt(dot(n, n)));
    const Vec3 point = p.transformed ? p.world_from_object.point(h.point) : h.point;
    found(SurfaceHit{h.depth * len, &p, record(point, n), 0, 0});
  }
}
}  // namespace

Primitive JuliaFractalShape::build(const JuliaFractal& description, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::julia_fractal, world_from_object);
  // POV-Ray's own inverse, composed transform by transform along with world_from_object (transform_object).
  if (p.transformed) p.object_from_world = description.object_from_world;
  auto data = std::make_shared<JuliaFractalData>();
  data->fractal = fractal_of(description);
  p.data = std::move(data);
  return p;
}

void JuliaFractalShape::collect(const Primitive& p, const Ray& ray, HitBuffer& out) {
  march(p, ray, p.csg_child, [&](const SurfaceHit& hit) { out.push_back(hit); });
}

// POV-Ray's Find_Intersection keeps the nearest hit above the minimum depth; an object that is no CSG child reports
// only its first hit, so a first hit too near hides any farther one, as it does in POV-Ray.
std::optional<SurfaceHit> JuliaFractalShape::nearest(const Primitive& p, const Ray& ray, double t_min, double t_max) {
  std::optional<SurfaceHit> best;
  march(p, ray, p.csg_child, [&](const SurfaceHit& hit) {
    if (hit.t > t_min && hit.t < t_max && (!best || hit.t < best->t)) best = hit;
  });
  return best;
}

Vec3 JuliaFractalShape::hit_normal(const SurfaceHit& hit, Vec3) { return hit_records[hit.element].normal; }

Vec3 JuliaFractalShape::hit_point(const SurfaceHit& hit) { return hit_records[hit.element].point; }

// Without a hit, the normal is the one the march finds nearest the point, marching in from the bounding sphere
// along the line through the centre (POV-Ray's normals exist only with a hit's orbit).
Vec3 JuliaFractalShape::normal(const Primitive& p, Vec3 world_point) {
  const julia::Fractal& f = data_of(p).fractal;
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  const double l = std::sqrt(dot(q, q));
  const Vec3 out = l > 0 ? q * (1.0 / l) : Vec3{0, 0, 1};
  std::vector<julia::FractalHit> hits;
  julia::intersect(f, out * (2.0 * f.radius + 1.0), -out, true, hits);
  Vec3 n = out;
  double best = std::numeric_limits<double>::infinity();
  for (const julia::FractalHit& h : hits)
    if (const double d = dot(h.point - q, h.point - q); d < best) {
      best = d;
      n = h.normal;
    }
  if (p.transformed) n = p.object_from_world.normal_from_inverse(n);
  return n * (1.0 / std::sqrt(dot(n, n)));
}

bool JuliaFractalShape::inside(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  return julia::inside(data_of(p).fractal, q);
}

Bounds JuliaFractalShape::object_bounds(const Primitive& p) {
  const double r = data_of(p).fractal.radius;
  Bounds b;
  b.extend(Vec3{-r, -r, -r});
  b.extend(Vec3{r, r, r});
  return b;
}

}  // namespace povtrace::render::shapes
