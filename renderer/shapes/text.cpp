// Text: glyph outlines extruded along z.
//
// SDL: `text { ttf "font.ttf" "string" thickness, <offset> object_modifiers… }` (POV-Ray 3.7 reference "Text"); the
// parser reads the font and lays the glyphs out (parser/objects/text.cpp). Primitive: data = TextData (all glyphs of one
// text object: POV-Ray's union of one child per character, kept as one primitive so that CSG sees the whole text);
// SurfaceHit::element = TextSurface, with a wall's normal in (u, v).
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/truetype.cpp GetZeroOneHits,
// GlyphIntersect, Inside, Compute_BBox, and csg.cpp for the union, 3.7-stable):
// - The world ray is carried into the glyph's space without normalising its direction, so every depth is a world
//   distance. Hits must lie deeper than 1e-6 (TTF_Tolerance).
// - Faces: unless |D.z| < 1e-10, the ray meets z = 0 at t = −P.z / D.z and z = thickness at that t plus
//   thickness / D.z; each counts when the point (x, y) there is inside the outline (inside_glyph). Normals −z and +z.
// - Walls: none when both |D.x| and |D.y| are below 1e-10. Otherwise the depth of a wall point comes from x when
//   |D.x| >= 1e-10, else from y. A straight edge (x0, y0) → (x1, y1) is skipped when the ray's projection is
//   within 1e-10 of parallel to it; its parameter must lie in [0, 1]; normal (y1 − y0, −(x1 − x0), 0). A quadratic
//   piece is met where the projected ray's line equation Dy·x − Dx·y + (Py·Dx − Px·Dy) vanishes along it (roots in
//   [0, 1] of solve_glyph_quadratic); normal (y'(s), −x'(s), 0). A wall point counts when 0 <= z <= thickness.
// - Normals are carried to world space by the inverse transpose and normalised.
// - Inside: 0 <= z <= thickness and inside_glyph, for any glyph (the union). An inverted text is, by De Morgan,
//   the intersection of its inverted glyphs: a hit on one glyph then survives only outside every other glyph.
// - Bounds: each glyph's header box (em units, z from −1e-6 to thickness + 1e-6) at its translation.
#include <cmath>
#include <stdexcept>

#include "renderer/shapes/text.hpp"
#include "runtime/glyph_contour_walk.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double text_depth = 1e-6;   // truetype.cpp TTF_Tolerance

const TextData& data_of(const Primitive& p) { return static_cast<const TextData&>(*p.data); }

struct LocalRay {
  Vec3 p, d;
};

LocalRay to_object(const Primitive& p, const Ray& ray) {
  if (!p.transformed) return {ray.origin, ray.direction};
  return {p.object_from_world.point(ray.origin), p.object_from_world.vector(ray.direction)};
}

// Slab test of the ray against the glyph's box, padded: it only culls glyphs the ray cannot meet.
bool meets_box(const TextShapeGlyph& g, const LocalRay& r) {
  double near = -tolerance::bound_huge, far = tolerance::bound_huge;
  for (int a = 0; a < 3; ++a) {
    const double pad = 1e-7 * (1.0 + std::abs(g.lo[a]) + std::abs(g.hi[a]));
    const double lo = g.lo[a] - pad, hi = g.hi[a] + pad;
    if (std::abs(r.d[a]) < 1e-300) {
      if (r.p[a] < lo || r.p[a] > hi) return false;
      continue;
    }
    double t0 = (lo - r.p[a]) / r.d[a], t1 = (hi - r.p[a]) / r.d[a];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
    if (near > far) return false;
  }
  return far > 0.0;
}

class GlyphHits {
 public:
  GlyphHits(const Primitive& p, const LocalRay& r, double thickness, HitBuffer& out)
      : p_(p), r_(r), thickness_(thickness), out_(out) {}

  void faces(const GlyphOutline& g) {
    if (std::abs(r_.d.z) < tolerance::epsilon) return;
    double t = -r_.p.z / r_.d.z;
    if (t > text_depth && inside_glyph(g, r_.p.x + t * r_.d.x, r_.p.y + t * r_.d.y)) add(t, TextSurface::front, 0, 0);
    t += thickness_ / r_.d.z;
    if (t > text_depth && inside_glyph(g, r_.p.x + t * r_.d.x, r_.p.y + t * r_.d.y)) add(t, TextSurface::back, 0, 0);
  }

  void walls(const GlyphOutline& g) {
    if (std::abs(r_.d.x) < tolerance::epsilon && std::abs(r_.d.y) < tolerance::epsilon) return;
    by_x_ = std::abs(r_.d.x) >= tolerance::epsilon;
    for (const GlyphContour& c : g.contours) contour(c);
  }

 private:
  void add(double t, TextSurface s, double nx, double ny) {
    out_.push_back(SurfaceHit{t, &p_, static_cast<std::uint32_t>(s), nx, ny});
  }
  // A wall point at depth t counts when it lies between the faces.
  void wall_point(double t, double nx, double ny) {
    const double z = r_.p.z + t * r_.d.z;
    if (z >= 0 && z <= thickness_ && t > text_depth) add(t, TextSurface::wall, nx, ny);
  }
  void edge(double x0, double y0, double x1, double y1) {
    const double dx = x1 - x0, dy = y1 - y0;
    const double den = dy * r_.d.x - dx * r_.d.y;
    if (std::abs(den) < tolerance::epsilon) return;
    const double s = (r_.d.x * (r_.p.y - y0) - r_.d.y * (r_.p.x - x0)) / den;
    if (s < 0.0 || s > 1.0) return;
    const double t = by_x_ ? ((x0 + s * dx) - r_.p.x) / r_.d.x : ((y0 + s * dy) - r_.p.y) / r_.d.y;
    wall_point(t, dy, -dx);
  }
  void curve(const double px[3], const double py[3]) {
    const double xt2 = px[0] - 2.0 * px[1] + px[2], xt1 = 2.0 * (px[1] - px[0]), xt0 = px[0];
    const double yt2 = py[0] - 2.0 * py[1] + py[2], yt1 = 2.0 * (py[1] - py[0]), yt0 = py[0];
    const double a = r_.d.y, b = -r_.d.x, c = r_.p.y * r_.d.x - r_.p.x * r_.d.y;
    const double coefficients[3] = {a * xt2 + b * yt2, a * xt1 + b * yt1, a * xt0 + b * yt0 + c};
    double roots[2];
    const int count = solve_glyph_quadratic(coefficients, roots);
    for (int k = 0; k < count; ++k) {
      const double s = roots[k];
      const double t = by_x_ ? ((s * s * xt2 + s * xt1 + xt0) - r_.p.x) / r_.d.x
                             : ((s * s * yt2 + s * yt1 + yt0) - r_.p.y) / r_.d.y;
      wall_point(t, 2.0 * yt2 * s + yt1, -2.0 * xt2 * s - xt1);
    }
  }
  // The contour's pieces as inside_glyph walks them (runtime/glyph_contour_walk.hpp).
  void contour(const GlyphContour& c) {
    walk_glyph_contour(
        c, [&](double x0, double y0, double x1, double y1) { edge(x0, y0, x1, y1); },
        [&](const double px[3], const double py[3]) { curve(px, py); });
  }

  const Primitive& p_;
  LocalRay r_;
  double thickness_;
  HitBuffer& out_;
  bool by_x_ = true;
};

bool inside_one(const TextData& d, const TextShapeGlyph& g, Vec3 q) {
  return q.z >= 0.0 && q.z <= d.thickness && inside_glyph(*g.outline, q.x - g.x, q.y - g.y);
}

bool inside_any(const TextData& d, Vec3 q, std::size_t except = static_cast<std::size_t>(-1)) {
  for (std::size_t i = 0; i < d.glyphs.size(); ++i)
    if (i != except && inside_one(d, d.glyphs[i], q)) return true;
  return false;
}
}  // namespace

void TextShape::collect(const Primitive& p, const Ray& ray, HitBuffer& out) {
  const TextData& d = data_of(p);
  const LocalRay r = to_object(p, ray);
  for (std::size_t i = 0; i < d.glyphs.size(); ++i) {
    const TextShapeGlyph& g = d.glyphs[i];
    const LocalRay local{r.p - Vec3{g.x, g.y, 0.0}, r.d};
    if (!meets_box(g, local)) continue;
    const std::size_t begin = out.size();
    GlyphHits hits(p, local, d.thickness, out);
    hits.faces(*g.outline);
    hits.walls(*g.outline);
    if (!p.inverse || d.glyphs.size() < 2) continue;
    std::size_t kept = begin;   // an inverted text is the intersection of its inverted glyphs
    for (std::size_t k = begin; k < out.size(); ++k)
      if (!inside_any(d, r.p + r.d * out[k].t, i)) out[kept++] = out[k];
    out.resize(kept);
  }
}

std::optional<SurfaceHit> TextShape::nearest(const Primitive& p, const Ray& ray, double t_min, double t_max) {
  thread_local HitBuffer scratch;
  scratch.clear();
  collect(p, ray, scratch);
  std::optional<SurfaceHit> nearest;
  for (const SurfaceHit& h : scratch) {
    if (!(h.t > t_min) || !(h.t < t_max) || (nearest && !(h.t < nearest->t))) continue;
    nearest = h;
  }
  return nearest;
}

Vec3 TextShape::hit_normal(const SurfaceHit& hit, Vec3) {
  const auto surface = static_cast<TextSurface>(hit.element);
  Vec3 n{hit.u, hit.v, 0.0};
  if (surface == TextSurface::front) n = {0, 0, -1};
  if (surface == TextSurface::back) n = {0, 0, 1};
  if (hit.leaf->transformed) n = hit.leaf->object_from_world.normal_from_inverse(n);
  return normalize(n);
}

Vec3 TextShape::normal(const Primitive&, Vec3) {
  throw std::logic_error("a text's normal comes with its hit (the wall or face it is on)");
}

bool TextShape::inside(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  return inside_any(data_of(p), q) != p.inverse;
}

Bounds TextShape::object_bounds(const Primitive& p) {
  Bounds b;
  for (const TextShapeGlyph& g : data_of(p).glyphs) {
    b.extend(g.lo + Vec3{g.x, g.y, 0.0});
    b.extend(g.hi + Vec3{g.x, g.y, 0.0});
  }
  return b;
}

}  // namespace povtrace::render::shapes
