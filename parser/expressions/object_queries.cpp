// Geometric queries the SDL evaluates at parse time on declared objects (povray-sdl-and-geometry.md §5, §8, §10):
// inside(O, P), min_extent(O), max_extent(O). Parser-side only — no renderer code: the inside tests of the
// shapes povtrace describes (sphere, box, plane, CSG); the others ask the renderer's geometry.
//
// Why these inside tests are not routed through ObjectGeometry::prepare(...)->inside() (issue 17 asked): the
// parser has no geometry when it runs without the renderer (ParseOptions::object_geometry null: the parser tests,
// a parse-only tool), and there inside() of spheres, boxes, planes, meshes, texts and CSG must still answer. And
// the two are not the same function at the edges: a plane here is tested in world space with its unit normal and
// POV-Ray's 1e-10 band in world units, as POV-Ray keeps a transformed plane (the renderer's plane measures the band
// in object units, so `plane { y, 0 scale <1, 0.5, 1> }` at y = 0.7e-10 is inside here and outside there); a
// mesh counts its crossings by brute force at POV-Ray's depths (1e-6, 1e7) along the normalised inside_vector
// (mesh_inside), the renderer through its triangle BVH and its own ray-triangle test. Answers agree away from such
// edges (every inside() case of the parser tests gives the same through both). Routing through the renderer would
// change parse-time results at those edges; unifying needs the renderer's plane made POV-Ray's first.
//
// The bounding boxes themselves are made in object_extents.cpp.
#include <cmath>

#include <stdexcept>

#include "parser/expressions/array_values.hpp"
#include "parser/expressions/object_queries.hpp"
#include "parser/extents/placed_boxes.hpp"
#include "parser/interpreter.hpp"

namespace povtrace::sdl {

namespace {
constexpr double kInsideEpsilon = 1e-10;

// Features of an object that change its geometry, which povtrace does not model (the first found is named): an
// unsupported shape or object modifier anywhere in its tree. The harmless ones (appearance, flags) are ignored. (A
// parsed object records only its first unsupported feature; a later clipped_by behind a harmless one goes unseen.)
std::optional<std::string> unsupported_geometry(const Object& o) {
  if (o.unsupported) {
    const std::string& n = o.unsupported->name;
    static const char* const harmless[] = {
        "'normal { }' perturbation", "the object modifier 'double_illuminate'",
        "the object modifier 'sturm'", "the object modifier 'interior_texture'", "the object modifier 'uv_mapping'",
        "the object modifier 'photons'", "the object modifier 'split_union'",
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

// The shapes whose inside test the parser does not carry itself (the renderer has them): the first one in the
// object's tree, or nothing.
std::optional<std::string> shape_outside_parser(const Object& o) {
  if (const auto* csg = std::get_if<Csg>(&o.shape))
    for (const auto& c : csg->children)
      if (auto u = shape_outside_parser(c)) return u;
  for (const auto* list : {&o.clipped_by, &o.bounded_by})
    for (const auto& c : *list)
      if (auto u = shape_outside_parser(c)) return u;
  struct Name {
    std::optional<std::string> operator()(const Sphere&) const { return {}; }
    std::optional<std::string> operator()(const Plane&) const { return {}; }
    std::optional<std::string> operator()(const Box&) const { return {}; }
    std::optional<std::string> operator()(const Csg&) const { return {}; }
    std::optional<std::string> operator()(const Triangle&) const { return {}; }
    std::optional<std::string> operator()(const Polygon&) const { return {}; }
    std::optional<std::string> operator()(const Mesh&) const { return {}; }
    std::optional<std::string> operator()(const Text&) const { return {}; }
    std::optional<std::string> operator()(const Cylinder&) const { return "the shape 'cylinder'"; }
    std::optional<std::string> operator()(const Cone&) const { return "the shape 'cone'"; }
    std::optional<std::string> operator()(const Disc&) const { return "the shape 'disc'"; }
    std::optional<std::string> operator()(const Torus&) const { return "the shape 'torus'"; }
    std::optional<std::string> operator()(const Poly&) const { return "the shape 'poly'"; }
    std::optional<std::string> operator()(const Quadric&) const { return "the shape 'quadric'"; }
    std::optional<std::string> operator()(const Superellipsoid&) const { return "the shape 'superellipsoid'"; }
    std::optional<std::string> operator()(const Ovus&) const { return "the shape 'ovus'"; }
    std::optional<std::string> operator()(const HeightField&) const { return "the shape 'height_field'"; }
    std::optional<std::string> operator()(const Blob&) const { return "the shape 'blob'"; }
    std::optional<std::string> operator()(const Lathe&) const { return "the shape 'lathe'"; }
    std::optional<std::string> operator()(const Prism&) const { return "the shape 'prism'"; }
    std::optional<std::string> operator()(const Sor&) const { return "the shape 'sor'"; }
    std::optional<std::string> operator()(const Isosurface&) const { return "the shape 'isosurface'"; }
    std::optional<std::string> operator()(const JuliaFractal&) const { return "the shape 'julia_fractal'"; }
    std::optional<std::string> operator()(const BicubicPatch&) const { return "the shape 'bicubic_patch'"; }
  };
  return std::visit(Name{}, o.shape);
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
    bool operator()(const Ovus&) const { throw std::logic_error("inside() of an ovus"); }
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
    bool operator()(const JuliaFractal&) const { throw std::logic_error("inside() of a julia_fractal"); }
    bool operator()(const BicubicPatch&) const { throw std::logic_error("inside() of a bicubic_patch"); }
  };
  return std::visit(Test{o, p, invert}, o.shape);
}

}  // namespace

// The object an identifier token names, for inside(), trace(), min_extent() and max_extent() (§5: they take an
// object identifier).
const std::shared_ptr<const SceneItem>& ObjectQueries::object_identifier(const Token& id, std::string_view function) {
  const Value* v = lookup(id);
  const auto* item = v ? std::get_if<std::shared_ptr<const SceneItem>>(v) : nullptr;
  if (!item || !std::holds_alternative<Object>(**item))
    fail_expected(id, "an object identifier in " + std::string(function) + "()");
  return *item;
}

// The renderer's form of a declared object, made once per declared value and noise generator: scenes trace the
// same object in loops. The cache keeps the values it was made from alive, so an address is never reused for
// another object; it is emptied when it grows past a few hundred objects (a loop declaring and tracing a new object
// each time).
const PreparedObject& ObjectQueries::prepared_object(const std::shared_ptr<const SceneItem>& item) {
  constexpr std::size_t kMaxPreparedObjects = 256;
  const int generator = noise_generator();
  if (auto found = prepared_objects_.find(item.get()); found != prepared_objects_.end()) {
    if (found->second.noise_generator == generator) return *found->second.prepared;
    prepared_objects_.erase(found);
  }
  if (prepared_objects_.size() >= kMaxPreparedObjects) prepared_objects_.clear();
  // Prepared as if placed: the renderer culls the rays of a placed object by POV-Ray's box of it, as POV-Ray's
  // trace() tests the object's own box first.
  Object placed = std::get<Object>(*item);
  set_placed_boxes(placed, extents());
  PreparedEntry entry{item, options_.object_geometry->prepare(placed, generator), generator};
  return *prepared_objects_.emplace(item.get(), std::move(entry)).first->second.prepared;
}

// inside(O, P) → 1 or 0; min_extent(O), max_extent(O) → the corners of O's bounding box. O must be an object
// identifier (§5). inside() of shapes the parser does not test itself asks the renderer's geometry.
Numeric ObjectQueries::parse_object_query(const Token& name) {
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
  try {
    const ExtentBox box = extents().box(object);
    return Numeric::vector(n == "min_extent" ? box.lo() : box.max_extent());
  } catch (const ExtentUnavailable& e) {
    fail_unsupported(id, n + "() of " + e.what());
  }
}

// trace(O, Start, Direction [, Normal]) (§5, POV-Ray's Parse_Trace): the first intersection of the ray from Start
// along Direction (normalised by the reciprocal of its length, as VNormalizeEq does) with O, or <0, 0, 0> on a
// miss. When a declared vector identifier follows, it receives the surface's raw normal there (reversed on an
// inverted surface), or <0, 0, 0> on a miss; anything else there must be the closing ')'. A zero direction, for
// which POV-Ray traces a NaN ray that meets nothing, gives the miss with a warning.
Numeric ObjectQueries::parse_trace(const Token& name) {
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
void ObjectQueries::store_trace_normal(Vec3 normal) {
  const Token& ahead = peek_raw();
  if (ahead.kind != TokenKind::identifier || is_reserved_word(ahead.text)) return;
  const Value* v = symbols_.find(std::string(ahead.text));
  if (!v) fail_expected(ahead, "a declared vector identifier to receive trace()'s normal, or ')'");
  if (std::holds_alternative<std::shared_ptr<ArrayValue>>(*v)) {
    const Token name = pop_pushed_back();   // the token peek_raw() looked at
    const auto ref = arrays_.parse_element_reference(name);
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
