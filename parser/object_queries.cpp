// Geometric queries the SDL evaluates at parse time on declared objects (povray-sdl-and-geometry.md §5, §8, §10):
// inside(O, P), min_extent(O), max_extent(O). Parser-side only — no renderer code: the inside tests of the
// shapes povtrace describes (sphere, box, plane, CSG) and POV-Ray's bounding boxes, which it stores in single
// precision (BBOX_VAL is a float).
//
// Bounding boxes follow POV-Ray's rules: a sphere moved by translations, rotations and uniform scales keeps a
// tight box around its moved centre; any other transform (and any transform of a box) takes the box of the 8
// transformed corners of the object-space box; a plane's box is the huge ±1e10 box; a union's box encloses its
// children's boxes and becomes the huge box when wider than 1e6. One approximation: POV-Ray transforms a union's
// box itself when the union is transformed after it is built, povtrace recomputes it from the transformed
// children — identical for translations and scales, tighter after rotations.
#include <cmath>

#include <stdexcept>

#include "parser/extent_box.hpp"
#include "parser/interpreter.hpp"

namespace povtrace::sdl {

namespace {
constexpr double kInsideEpsilon = 1e-10;

bool is_identity(const Matrix& m) { return m == Matrix::identity(); }

constexpr double kEpsilon = 1e-10;          // POV-Ray's EPSILON
constexpr double kSmallTolerance = 0.001;   // SMALL_TOLERANCE: a disc's box is this thick either side

// POV-Ray's Compute_Coordinate_Transform: the map from the canonical shape (z from 0 to 1, radius 1) to a shape of
// this radius and length along `up` (unit) from `origin`: a scaling, the rotation about <-up.y, up.x, 0> that takes
// +z to `up` (about x when `up` is ±z), then the translation. The rotation decides how a square cross-section
// turns about the axis, so the box of the 8 transformed corners depends on it.
Matrix canonical_to_shape(Vec3 origin, Vec3 up, double radius, double length) {
  Vec3 axis{-up.y, up.x, 0};
  if (std::fabs(up.z) > 1.0 - kEpsilon) {
    axis = {1, 0, 0};
    up.z = up.z < 0 ? -1.0 : 1.0;
  }
  const Vec3 a = normalize(axis);
  const double angle = std::acos(up.z), c = std::cos(angle), s = std::sin(angle);
  Matrix rotation;   // POV-Ray's Compute_Axis_Rotation_Transform, in its row-vector layout (ours too)
  rotation.m[0] = {a.x * a.x + c * (1 - a.x * a.x), a.x * a.y * (1 - c) + a.z * s, a.x * a.z * (1 - c) - a.y * s};
  rotation.m[1] = {a.x * a.y * (1 - c) - a.z * s, a.y * a.y + c * (1 - a.y * a.y), a.y * a.z * (1 - c) + a.x * s};
  rotation.m[2] = {a.x * a.z * (1 - c) + a.y * s, a.y * a.z * (1 - c) - a.x * s, a.z * a.z + c * (1 - a.z * a.z)};
  return Matrix::scaling({radius, radius, length}) * rotation * Matrix::translation(origin);
}

// Cone::Compute_Cone_Data / Compute_Cylinder_Data, then Compute_BBox: the canonical box from z = dist to 1 (0 for a
// cylinder, and for a cone whose radii differ by less than EPSILON), carried by the canonical transform and the
// object's own. A cone is turned so that its wider end is at z = 1, the narrow end at dist, the apex at 0.
ExtentBox cone_box(Vec3 base, double base_radius, Vec3 apex, double apex_radius, const Matrix& object) {
  Vec3 axis = apex - base;
  const double len = length(axis);
  axis = axis / len;   // the parser refuses coincident end points
  auto cylinder = [&]() {
    const Vec3 a = normalize(apex - base);
    return ExtentBox::make({-1, -1, 0}, {2, 2, 1}).transformed(canonical_to_shape(base, a, apex_radius, len) * object);
  };
  if (std::fabs(apex_radius - base_radius) < kEpsilon) return cylinder();
  if (apex_radius < base_radius) {
    std::swap(base, apex);
    std::swap(base_radius, apex_radius);
    axis = -1.0 * axis;
  }
  const double to_origin = base_radius * len / (apex_radius - base_radius);
  const Vec3 origin = base - to_origin * axis;
  const double total = to_origin + len;
  if ((apex_radius - base_radius) * len / total < kEpsilon) return cylinder();
  const double dist = to_origin / total;
  return ExtentBox::make({-1, -1, dist}, {2, 2, 1 - dist}).transformed(canonical_to_shape(origin, axis, apex_radius, total) *
                                                                  object);
}

// A similarity: the linear part is a rotation times a uniform scale (orthogonal rows of one length). Returns the
// scale factor, or 0 if the matrix is not one.
double similarity_scale(const Matrix& m) {
  const Vec3 r[3] = {{m.m[0][0], m.m[0][1], m.m[0][2]}, {m.m[1][0], m.m[1][1], m.m[1][2]},
                     {m.m[2][0], m.m[2][1], m.m[2][2]}};
  const double s = length(r[0]);
  const double tol = 1e-12 * std::max(1.0, s * s);
  if (s == 0) return 0;
  for (int i = 0; i < 3; ++i) {
    if (std::fabs(dot(r[i], r[i]) - s * s) > tol) return 0;
    for (int j = i + 1; j < 3; ++j)
      if (std::fabs(dot(r[i], r[j])) > tol) return 0;
  }
  return s;
}

// Features of an object that change its geometry, which povtrace does not model (the first found is named): an
// unsupported shape or object modifier anywhere in its tree. The harmless ones (appearance, flags) are ignored. (A
// parsed object records only its first unsupported feature; a later clipped_by behind a harmless one goes unseen.)
std::optional<std::string> unsupported_geometry(const Object& o) {
  if (o.unsupported) {
    const std::string& n = o.unsupported->name;
    static const char* const harmless[] = {
        "'normal { }' perturbation", "the object modifier 'double_illuminate'",
        "the object modifier 'sturm'", "the object modifier 'interior_texture'", "the object modifier 'uv_mapping'",
        "the object modifier 'photons'", "the object modifier 'radiosity'", "the object modifier 'split_union'",
        "the object modifier 'cutaway_textures'", "the object modifier 'hierarchy'", "the material item"};
    bool ok = false;
    for (const char* h : harmless) ok = ok || n.starts_with(h);
    if (!ok) return n;
  }
  if (const auto* csg = std::get_if<Csg>(&o.shape))
    for (const auto& c : csg->children)
      if (auto u = unsupported_geometry(c)) return u;
  for (const auto* list : {&o.clipped_by, &o.bounded_by})
    for (const auto& c : *list)
      if (auto u = unsupported_geometry(c)) return u;
  return std::nullopt;
}

// The shapes whose inside test (or, with `box`, whose bounding box) the parser does not carry itself (the renderer
// has them): the first one in the object's tree, or nothing.
std::optional<std::string> shape_outside_parser(const Object& o, bool box = false) {
  if (const auto* csg = std::get_if<Csg>(&o.shape))
    for (const auto& c : csg->children)
      if (auto u = shape_outside_parser(c, box)) return u;
  for (const auto* list : {&o.clipped_by, &o.bounded_by})
    for (const auto& c : *list)
      if (auto u = shape_outside_parser(c, box)) return u;
  if (!box && std::holds_alternative<Cylinder>(o.shape)) return std::string("the shape 'cylinder'");
  if (!box && std::holds_alternative<Cone>(o.shape)) return std::string("the shape 'cone'");
  if (!box && std::holds_alternative<Disc>(o.shape)) return std::string("the shape 'disc'");
  if (!box && std::holds_alternative<Torus>(o.shape)) return std::string("the shape 'torus'");
  if (std::holds_alternative<Poly>(o.shape)) return std::string("the shape 'poly'");
  if (std::holds_alternative<Quadric>(o.shape)) return std::string("the shape 'quadric'");
  if (std::holds_alternative<Superellipsoid>(o.shape)) return std::string("the shape 'superellipsoid'");
  if (std::holds_alternative<HeightField>(o.shape)) return std::string("the shape 'height_field'");
  if (std::holds_alternative<Blob>(o.shape)) return std::string("the shape 'blob'");
  if (std::holds_alternative<Lathe>(o.shape)) return std::string("the shape 'lathe'");
  if (std::holds_alternative<Prism>(o.shape)) return std::string("the shape 'prism'");
  if (std::holds_alternative<Sor>(o.shape)) return std::string("the shape 'sor'");
  if (std::holds_alternative<Isosurface>(o.shape)) return std::string("the shape 'isosurface'");
  return std::nullopt;
}

// POV-Ray shrinks an object's box to its clip and bound objects' boxes when that is smaller, which the boxes
// here do not model yet: extents of such objects are refused.
bool has_clip_or_bound(const Object& o) {
  if (!o.clipped_by.empty() || !o.bounded_by.empty()) return true;
  if (const auto* csg = std::get_if<Csg>(&o.shape))
    for (const auto& c : csg->children)
      if (has_clip_or_bound(c)) return true;
  return false;
}

// Inside_Object: inside every clip object (never inverted with the object) and inside the object itself.
bool inside(const Object& o, Vec3 p, bool invert) {
  for (const auto& clip : o.clipped_by)
    if (!inside(clip, p, false)) return false;
  invert = invert != o.inverse;
  struct Test {
    const Object& o;
    Vec3 p;
    bool invert;
    bool operator()(const Sphere& s) const {
      const Vec3 q = o.world_from_object.inverse().point(p) - s.centre;
      const double d2 = dot(q, q), r2 = s.radius * s.radius;
      return invert ? d2 > r2 : d2 < r2;   // the surface is inside neither way
    }
    bool operator()(const Box& b) const {
      const Vec3 q = o.world_from_object.inverse().point(p);
      const bool in = q.x >= b.corner1.x && q.x <= b.corner2.x && q.y >= b.corner1.y && q.y <= b.corner2.y &&
                      q.z >= b.corner1.z && q.z <= b.corner2.z;
      return in != invert;
    }
    bool operator()(const Plane& pl) const {
      // In world space with the unit normal, as POV-Ray keeps a transformed plane.
      const Matrix inv = o.world_from_object.inverse();
      const Vec3 n = inv.normal_from_inverse(pl.normal);
      const Vec3 on = o.world_from_object.point(pl.normal * pl.distance);
      const double value = dot(n, p - on) / length(n);
      return invert ? value > -kInsideEpsilon : value < kInsideEpsilon;
    }
    // A triangle or polygon has no inside, inverse or not (POV-Ray's Inside returns false, Invert does nothing).
    bool operator()(const Triangle&) const { return false; }
    bool operator()(const Polygon&) const { return false; }
    bool operator()(const Mesh& m) const {
      if (!m.data->inside_vector) return false;   // no inside_vector: no inside, inverse or not
      return mesh_inside(*m.data, o.world_from_object, p) != invert;
    }
    bool operator()(const Csg& c) const {
      // Difference = intersection with the later children inverted; an inverted CSG swaps any and all (§10).
      const bool all = (c.kind == CsgKind::intersection || c.kind == CsgKind::difference) != invert;
      for (std::size_t i = 0; i < c.children.size(); ++i) {
        const bool child_inverted = (c.kind == CsgKind::difference && i > 0) != invert;
        const bool in = inside(c.children[i], p, child_inverted);
        if (all && !in) return false;
        if (!all && in) return true;
      }
      return all;
    }
    // Refused (or handed to the renderer's geometry) by shape_outside_parser before any visit.
    bool operator()(const Cylinder&) const { throw std::logic_error("inside() of a cylinder"); }
    bool operator()(const Cone&) const { throw std::logic_error("inside() of a cone"); }
    bool operator()(const Disc&) const { throw std::logic_error("inside() of a disc"); }
    bool operator()(const Torus&) const { throw std::logic_error("inside() of a torus"); }
    bool operator()(const Poly&) const { throw std::logic_error("inside() of a poly"); }
    bool operator()(const Quadric&) const { throw std::logic_error("inside() of a quadric"); }
    bool operator()(const Superellipsoid&) const { throw std::logic_error("inside() of a superellipsoid"); }
    bool operator()(const HeightField&) const { throw std::logic_error("inside() of a height_field"); }
    bool operator()(const Blob&) const { throw std::logic_error("inside() of a blob"); }
    // A text is a union of its glyphs (an inverted one, by De Morgan, the intersection of the inverted glyphs).
    bool operator()(const Text& text) const {
      const Vec3 q = o.world_from_object.inverse().point(p);
      bool in = false;
      for (const TextGlyph& g : text.glyphs)
        in = in || (q.z >= 0.0 && q.z <= text.thickness && inside_glyph(*g.outline, q.x - g.x, q.y - g.y));
      return in != invert;
    }
    bool operator()(const Lathe&) const { throw std::logic_error("inside() of a lathe"); }
    bool operator()(const Prism&) const { throw std::logic_error("inside() of a prism"); }
    bool operator()(const Sor&) const { throw std::logic_error("inside() of a sor"); }
    bool operator()(const Isosurface&) const { throw std::logic_error("inside() of an isosurface"); }
  };
  return std::visit(Test{o, p, invert}, o.shape);
}

// The union of the glyphs' boxes as POV-Ray builds it (TrueType::Compute_BBox: the header box in em units,
// z from −1e-6 to thickness + 1e-6, carried by the glyph's translation; CSG::Compute_BBox), then carried through
// each transform applied since, one after the other (CSG::Transform).
ExtentBox text_box(const Text& text) {
  constexpr double kTextTolerance = 1e-6;   // truetype.cpp TTF_Tolerance
  Vec3 lo{kBoundHuge, kBoundHuge, kBoundHuge}, hi{-kBoundHuge, -kBoundHuge, -kBoundHuge};
  for (const TextGlyph& g : text.glyphs) {
    const GlyphOutline& outline = *g.outline;
    const double funit = 1.0 / outline.units_per_em;
    const Vec3 min{outline.x_min * funit, outline.y_min * funit, -kTextTolerance};
    const Vec3 max{outline.x_max * funit, outline.y_max * funit, text.thickness + kTextTolerance};
    const ExtentBox b = ExtentBox::make(min, max - min).transformed(Matrix::translation({g.x, g.y, 0.0}));
    lo = povtrace::min(lo, b.lo());
    hi = povtrace::max(hi, b.hi());
  }
  ExtentBox box = ExtentBox::huge();
  if (lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z) {
    box = ExtentBox::from_min_max(lo, hi);
    for (int i = 0; i < 3; ++i)
      if (box.lengths[i] > kCriticalLength) box = ExtentBox::huge();
  }
  for (const Matrix& m : text.box_transforms) box = box.transformed(m);
  return box;
}

ExtentBox bounding_box(const Object& o) {
  struct Box_ {
    const Object& o;
    ExtentBox operator()(const Sphere& s) const {
      const Matrix& m = o.world_from_object;
      if (const double k = similarity_scale(m); k > 0) {
        const Vec3 c = m.point(s.centre);
        const double r = s.radius * k;
        return ExtentBox::make(c - Vec3{r, r, r}, {2 * r, 2 * r, 2 * r});
      }
      const ExtentBox local = ExtentBox::make(s.centre - Vec3{s.radius, s.radius, s.radius},
                                    {2 * s.radius, 2 * s.radius, 2 * s.radius});
      return local.transformed(m);
    }
    ExtentBox operator()(const Box& b) const {
      const ExtentBox local = ExtentBox::make(b.corner1, b.corner2 - b.corner1);
      return is_identity(o.world_from_object) ? local : local.transformed(o.world_from_object);
    }
    ExtentBox operator()(const Plane&) const { return ExtentBox::huge(); }
    // Triangles: the box of the world corners grown by EPSILON; polygons and meshes: the object-space box of
    // their points carried to world space (POV-Ray's Compute_BBox, then Recompute_BBox for each transform).
    ExtentBox operator()(const Triangle& t) const {
      Vec3 lo{kBoundHuge, kBoundHuge, kBoundHuge}, hi = -lo;
      for (const Vec3& c : t.corners) {
        lo = min(lo, o.world_from_object.point(c));
        hi = max(hi, o.world_from_object.point(c));
      }
      const Vec3 e{kInsideEpsilon, kInsideEpsilon, kInsideEpsilon};
      return ExtentBox::from_min_max(lo - e, hi + e);
    }
    ExtentBox operator()(const Polygon& poly) const {
      Vec3 lo{kBoundHuge, kBoundHuge, kBoundHuge}, hi = -lo;
      for (const auto& q : poly.points) {
        const Vec3 w = (poly.world_from_plane * o.world_from_object).point({q[0], q[1], 0});
        lo = min(lo, w);
        hi = max(hi, w);
      }
      return ExtentBox::from_min_max(lo, hi);
    }
    ExtentBox operator()(const Mesh& m) const {
      Vec3 lo{kBoundHuge, kBoundHuge, kBoundHuge}, hi = -lo;
      for (std::uint32_t i = 0; i < m.data->vertices.size() / 3; ++i) {
        lo = min(lo, m.data->vertex(i));
        hi = max(hi, m.data->vertex(i));
      }
      const ExtentBox local = ExtentBox::from_min_max(lo, hi);
      return is_identity(o.world_from_object) ? local : local.transformed(o.world_from_object);
    }
    ExtentBox operator()(const Csg& c) const {
      Vec3 lo{kBoundHuge, kBoundHuge, kBoundHuge}, hi{-kBoundHuge, -kBoundHuge, -kBoundHuge};
      for (const auto& child : c.children) {
        const ExtentBox b = bounding_box(child);
        lo = min(lo, b.lo());
        hi = max(hi, b.hi());
      }
      if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return ExtentBox::huge();   // no children: the initial box
      ExtentBox u = ExtentBox::from_min_max(lo, hi);
      for (int i = 0; i < 3; ++i)
        if (u.lengths[i] > kCriticalLength) return ExtentBox::huge();
      return u;
    }
    // Refused (or handed to the renderer's geometry) by shape_outside_parser before any visit.
    // Parse_Cone and Parse_Cylinder read the first end point as the apex, the second as the base.
    ExtentBox operator()(const Cylinder& c) const { return cone_box(c.end2, c.radius, c.end1, c.radius, o.world_from_object); }
    ExtentBox operator()(const Cone& c) const { return cone_box(c.end2, c.radius2, c.end1, c.radius1, o.world_from_object); }
    // Disc::Compute_BBox: the unit disc's square, SMALL_TOLERANCE thick, scaled by the outer radius, placed by the
    // disc's canonical transform (radius and length 1) and the object's.
    ExtentBox operator()(const Disc& d) const {
      const double r = d.radius;
      return ExtentBox::make({-r, -r, -kSmallTolerance}, {2 * r, 2 * r, 2 * kSmallTolerance})
          .transformed(canonical_to_shape(d.centre, d.normal, 1.0, 1.0) * o.world_from_object);
    }
    // Torus::Compute_BBox: the box of radius R + r around the centre, r high, carried by the torus's transform.
    ExtentBox operator()(const Torus& t) const {
      const double r1 = t.minor, r2 = t.major + t.minor;
      return ExtentBox::make({-r2, -r1, -r2}, {2.0 * r2, 2.0 * r1, 2.0 * r2}).transformed(o.world_from_object);
    }
    ExtentBox operator()(const Poly&) const { throw std::logic_error("extent of a poly"); }
    ExtentBox operator()(const Quadric&) const { throw std::logic_error("extent of a quadric"); }
    ExtentBox operator()(const Superellipsoid&) const { throw std::logic_error("extent of a superellipsoid"); }
    ExtentBox operator()(const HeightField&) const { throw std::logic_error("extent of a height_field"); }
    ExtentBox operator()(const Blob&) const { throw std::logic_error("extent of a blob"); }
    ExtentBox operator()(const Text& text) const { return text_box(text); }
    ExtentBox operator()(const Lathe&) const { throw std::logic_error("extent of a lathe"); }
    ExtentBox operator()(const Prism&) const { throw std::logic_error("extent of a prism"); }
    ExtentBox operator()(const Sor&) const { throw std::logic_error("extent of a sor"); }
    ExtentBox operator()(const Isosurface&) const { throw std::logic_error("extent of an isosurface"); }
  };
  return std::visit(Box_{o}, o.shape);
}
}  // namespace

// The object an identifier token names, for inside(), trace(), min_extent() and max_extent() (§5: they take an
// object identifier).
const std::shared_ptr<const SceneItem>& Interpreter::object_identifier(const Token& id, std::string_view function) {
  const Value* v = lookup(id);
  const auto* item = v ? std::get_if<std::shared_ptr<const SceneItem>>(v) : nullptr;
  if (!item || !std::holds_alternative<Object>(**item))
    fail_expected(id, "an object identifier in " + std::string(function) + "()");
  return *item;
}

// The renderer's form of a declared object, made once per declared value: scenes trace the same object in loops.
// The cache keeps the values it was made from alive, so an address is never reused for another object; it is
// emptied when it grows past a few hundred objects (a loop declaring and tracing a new object each time).
const PreparedObject& Interpreter::prepared_object(const std::shared_ptr<const SceneItem>& item) {
  constexpr std::size_t kMaxPreparedObjects = 256;
  if (auto found = prepared_objects_.find(item.get()); found != prepared_objects_.end()) return *found->second.prepared;
  if (prepared_objects_.size() >= kMaxPreparedObjects) prepared_objects_.clear();
  PreparedEntry entry{item, options_.object_geometry->prepare(std::get<Object>(*item))};
  return *prepared_objects_.emplace(item.get(), std::move(entry)).first->second.prepared;
}

// inside(O, P) → 1 or 0; min_extent(O), max_extent(O) → the corners of O's bounding box. O must be an object
// identifier (§5). inside() of shapes the parser does not test itself asks the renderer's geometry.
Numeric Interpreter::parse_object_query(const Token& name) {
  const std::string n(name.text);
  expect("(", " after '" + n + "'");
  Token id = next();
  const std::shared_ptr<const SceneItem>& item = object_identifier(id, n);
  const Object& object = std::get<Object>(*item);
  if (auto u = unsupported_geometry(object)) fail_unsupported(id, n + "() of " + *u);
  const std::optional<std::string> foreign_shape = shape_outside_parser(object);
  if (n == "inside") {
    accept(",");
    const Vec3 p = parse_vector();
    expect(")", " closing inside()");
    if (!foreign_shape) return Numeric::scalar(inside(object, p, false) ? 1.0 : 0.0);
    if (!options_.object_geometry) fail_unsupported(id, n + "() of " + *foreign_shape);
    return Numeric::scalar(prepared_object(item).inside(p) ? 1.0 : 0.0);
  }
  expect(")", " closing " + n + "()");
  if (auto shape = shape_outside_parser(object, true)) fail_unsupported(id, n + "() of " + *shape);
  if (has_clip_or_bound(object)) fail_unsupported(id, n + "() of an object with clipped_by or bounded_by");
  if (const auto* csg = std::get_if<Csg>(&object.shape); csg && csg->kind != CsgKind::union_ &&
                                                          csg->kind != CsgKind::merge)
    fail_unsupported(id, n + "() of a CSG " + csg_name(csg->kind));
  const ExtentBox box = bounding_box(object);
  return Numeric::vector(n == "min_extent" ? box.lo() : box.max_extent());
}

// trace(O, Start, Direction [, Normal]) (§5, POV-Ray's Parse_Trace): the first intersection of the ray from Start
// along Direction (normalised by the reciprocal of its length, as VNormalizeEq does) with O, or <0, 0, 0> on a
// miss. When a declared vector identifier follows, it receives the surface's raw normal there (reversed on an
// inverted surface), or <0, 0, 0> on a miss; anything else there must be the closing ')'. A zero direction, for
// which POV-Ray traces a NaN ray that meets nothing, gives the miss with a warning.
Numeric Interpreter::parse_trace(const Token& name) {
  expect("(", " after 'trace'");
  Token id = next();
  const std::shared_ptr<const SceneItem>& item = object_identifier(id, "trace");
  const Object& object = std::get<Object>(*item);
  if (auto u = unsupported_geometry(object)) fail_unsupported(id, "trace() of " + *u);
  if (!options_.object_geometry) fail_unsupported(name, "the function 'trace'");   // a parser used without the renderer
  accept(",");
  const Vec3 origin = parse_vector();
  accept(",");
  const Token direction_at = peek();
  const Vec3 direction = parse_vector();
  accept(",");
  std::optional<TracedHit> hit;
  if (const double length2 = dot(direction, direction); length2 > 0 && std::isfinite(length2))
    hit = prepared_object(item).trace(origin, direction * (1.0 / std::sqrt(length2)));
  else
    warn(direction_at.loc, "trace() with a zero or non-finite direction meets nothing (POV-Ray traces a NaN ray)");
  const Vec3 normal = hit ? hit->normal : Vec3{0, 0, 0};
  store_trace_normal(normal);
  expect(")", " closing trace()");
  return Numeric::vector(hit ? hit->point : Vec3{0, 0, 0});
}

// trace()'s optional fourth argument: a declared 3-D vector identifier (or array element) is assigned in place,
// wherever it lives (through macro aliases); other tokens are left for the closing ')'.
void Interpreter::store_trace_normal(Vec3 normal) {
  const Token& ahead = peek_raw();
  if (ahead.kind != TokenKind::identifier || is_reserved_word(ahead.text)) return;
  const Value* v = symbols_.find(std::string(ahead.text));
  if (!v) fail_expected(ahead, "a declared vector identifier to receive trace()'s normal, or ')'");
  if (std::holds_alternative<std::shared_ptr<ArrayValue>>(*v)) {
    const Token name = pop_pushed_back();   // the token peek_raw() looked at
    const auto ref = parse_element_reference(name);
    const auto& element = ref->array->elements[ref->index];
    const auto* n = element ? std::get_if<Numeric>(&*element) : nullptr;
    if (!n || n->terms != 3 || n->colour)
      fail_expected(name, "an element holding a 3-D vector to receive trace()'s normal");
    ref->array->elements[ref->index] = Value(Numeric::vector(normal));
    return;
  }
  const auto* n = std::get_if<Numeric>(v);
  if (!n || n->terms != 3 || n->colour)
    fail_expected(ahead, "a declared 3-D vector identifier to receive trace()'s normal (" +
                             std::string(ahead.text) + " holds a " + value_type_name(*v) + "), or ')'");
  const Token name = pop_pushed_back();   // the token peek_raw() looked at
  symbols_.declare(name.name ? name.name : symbols_.intern(name.text), Value(Numeric::vector(normal)));
}

}  // namespace povtrace::sdl
