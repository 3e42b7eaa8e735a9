// POV-Ray's bounding boxes for min_extent() and max_extent() (povray-sdl-and-geometry.md §5). Facts read from
// POV-Ray 3.7's source (source/backend/shape/*.cpp Compute_BBox and Transform, csg.cpp CSG::Compute_BBox,
// parser/parse.cpp Parse_Object_Mods, 3.7-stable):
// - Boxes are single precision (ExtentBox). Quadrics follow quadric_extent.hpp, lathes, sors and prisms
//   sweep_extents.hpp. Most shapes recompute theirs from the shape and the composed transform
//   whenever they are transformed (the box of the 8 transformed corners of an object-space box); a sphere moved by
//   translations, rotations and uniform scales keeps a tight box around its moved centre; a plane's and a poly's
//   box is the huge ±1e10 box (a poly's, once it has been transformed with clip objects, its first clip's box).
// - CSG (and text, a union of glyphs), quadrics, blobs and meshes make their box once, then carry that box itself
//   through every later transform (ObjectNotes::carried_extent): rotations widen it step by step.
// - A union's box encloses its children's (a light source inside has the huge box); an intersection's is the common
//   part of its children's boxes, leaving out inverted children and height fields, taking a plane perpendicular to
//   an axis as a half space, and recomputing its quadrics within the others' common box last. A box wider than 1e6
//   becomes the huge box.
// - At the end of every object's modifiers, the common box of its bounding objects, then of its clip objects
//   (inverted ones left out), replaces the object's box when its volume is smaller.
#include "parser/extents/object_extents.hpp"
#include "parser/extents/object_notes.hpp"
#include "parser/extents/placed_boxes.hpp"
#include "scene/ovus_geometry.hpp"

#include "runtime/quadric_extent.hpp"
#include "runtime/sweep_extents.hpp"

#include <algorithm>
#include <cmath>

namespace povtrace::sdl {

namespace {
bool is_identity(const Matrix& m) { return m == Matrix::identity(); }

// Per component as std::min and std::max, which POV-Ray's box code calls: the first argument wins a tie, which
// decides between a -0 and a +0.
Vec3 std_min(Vec3 a, Vec3 b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
Vec3 std_max(Vec3 a, Vec3 b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }

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


// POV-Ray's INVERTED_FLAG: a CSG node's own flag, a leaf's inverse — except for planes, which Plane::Invert turns
// over instead, and triangles and polygons, which ignore inverse.
bool inverted(const Object& o) {
  if (const auto* csg = std::get_if<Csg>(&o.shape)) return csg->inverted;
  if (std::holds_alternative<Plane>(o.shape) || std::holds_alternative<Triangle>(o.shape) ||
      std::holds_alternative<Polygon>(o.shape))
    return false;
  return o.inverse;
}

// The min/max corners of a box, as Make_min_max_from_BBox gives them.
struct MinMax {
  Vec3 lo{kBoundHuge, kBoundHuge, kBoundHuge}, hi{-kBoundHuge, -kBoundHuge, -kBoundHuge};
  void enclose(const ExtentBox& b) {
    lo = std_min(lo, b.lo());
    hi = std_max(hi, b.hi());
  }
  void narrow(Vec3 l, Vec3 h) {
    lo = std_max(lo, l);
    hi = std_min(hi, h);
  }
  void narrow(const ExtentBox& b) { narrow(b.lo(), b.hi()); }
  void enclose_point(Vec3 p) {   // the min/max in double, before any rounding to float
    lo = std_min(lo, p);
    hi = std_max(hi, p);
  }
  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  double volume() const { return (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z); }
  static MinMax everything() {
    MinMax m;
    std::swap(m.lo, m.hi);
    return m;
  }
};

// The end of CSG::Compute_BBox: the new box replaces the old one when it is not degenerate and its volume is
// smaller, and becomes the huge box when wider than CRITICAL_LENGTH.
ExtentBox csg_result(const MinMax& m, const ExtentBox& old) {
  if (m.empty() || !(m.volume() < old.volume())) return old;
  const ExtentBox b = ExtentBox::from_min_max(m.lo, m.hi);
  return b.wider_than_critical() ? ExtentBox::huge() : b;
}

// Mesh::Compute_BBox: the box of the vertices of its triangles, in object space (the mesh's transforms carry it).
ExtentBox mesh_box(const MeshData& data) {
  MinMax m;
  for (const std::uint32_t v : data.faces) {
    m.lo = std_min(m.lo, data.vertex(v));
    m.hi = std_max(m.hi, data.vertex(v));
  }
  return ExtentBox::from_min_max(m.lo, m.hi);
}

// A plane as a CSG intersection or a quadric's clip sees it (Quadric::Compute_Plane_Min_Max): a half space when it
// is perpendicular to an axis. POV-Ray's Plane::Invert turns the plane over instead of flagging it, so an inverted
// plane counts, turned. A plane moved by matrix or transform has POV-Ray's other formula (quadric_extent.hpp).
void narrow_by_plane(MinMax& m, const Plane& plane, const Object& o) {
  const double side = o.inverse ? -1.0 : 1.0;
  Vec3 lo, hi;
  if (const auto& frame = notes_of(o).matrix_frame)
    plane_min_max_with_trans(side * frame->normal, side * frame->distance, frame->since, lo, hi);
  else
    plane_min_max(side * plane.normal, side * plane.distance, o.world_from_object, lo, hi);
  m.narrow(lo, hi);
}

// The sphere bounding one blob element (get_element_bounding_sphere), added to the running box. Elements with a
// transform (ellipsoids, cylinders) take the centre through it and, for the radius, the longest side of the box of
// the transformed cube (0, 0, 0)–(r, r, r), squared plus EPSILON.
void enclose_element_sphere(MinMax& m, Vec3 centre, double radius2, const Matrix* element) {
  if (element) {
    const double r = std::sqrt(radius2);
    centre = element->point(centre);
    const ExtentBox cube = ExtentBox::make({0, 0, 0}, {r, r, r}).transformed(*element);
    const double side = std::max({std::fabs(double(cube.lengths[0])), std::fabs(double(cube.lengths[1])),
                                  std::fabs(double(cube.lengths[2]))});
    radius2 = side * side + kEpsilon;
  }
  const double r = std::sqrt(radius2);
  m.lo = std_min(m.lo, centre - Vec3{r, r, r});
  m.hi = std_max(m.hi, centre + Vec3{r, r, r});
}

// Blob::Compute_BBox, run when the blob is made (after its own modifiers): the spheres bounding its elements of
// positive strength — a cylinder component is three elements, the cylinder and its two end hemispheres, in the
// frame that takes the unit z axis onto it — then the blob's transform, if it has one.
ExtentBox blob_box(const Blob& blob, const Matrix& world_from_object) {
  MinMax m;
  for (const BlobComponent& c : *blob.components) {
    if (!(c.strength > 0.0)) continue;
    if (c.kind == BlobComponentKind::sphere) {
      enclose_element_sphere(m, c.centre, c.radius2, nullptr);
    } else if (c.kind == BlobComponentKind::ellipsoid) {
      enclose_element_sphere(m, c.centre, c.radius2, &c.transform);
    } else {
      const double len = length(c.apex - c.centre);
      const Matrix frame = canonical_to_shape(c.centre, (c.apex - c.centre) / len, 1.0, 1.0) * c.transform;
      enclose_element_sphere(m, {0, 0, 0.5 * len}, c.radius2 + 0.25 * len * len, &frame);
      enclose_element_sphere(m, {0, 0, 0}, c.radius2, &frame);
      enclose_element_sphere(m, {0, 0, len}, c.radius2, &frame);
    }
  }
  const ExtentBox b = ExtentBox::from_min_max(m.lo, m.hi);
  return is_identity(world_from_object) ? b : b.transformed(world_from_object);
}
// The union of the glyphs' boxes as POV-Ray builds it (TrueType::Compute_BBox: the header box in em units,
// z from −1e-6 to thickness + 1e-6, carried by the glyph's translation; CSG::Compute_BBox), when the text is made.
ExtentBox text_box(const Text& text) {
  constexpr double kTextTolerance = 1e-6;   // truetype.cpp TTF_Tolerance
  Vec3 lo{kBoundHuge, kBoundHuge, kBoundHuge}, hi{-kBoundHuge, -kBoundHuge, -kBoundHuge};
  for (const TextGlyph& g : text.glyphs) {
    const GlyphOutline& outline = *g.outline;
    const double funit = 1.0 / outline.units_per_em;
    const Vec3 min{outline.x_min * funit, outline.y_min * funit, -kTextTolerance};
    const Vec3 max{outline.x_max * funit, outline.y_max * funit, text.thickness + kTextTolerance};
    const ExtentBox b = ExtentBox::make(min, max - min).transformed(Matrix::translation({g.x, g.y, 0.0}));
    lo = std_min(lo, b.lo());
    hi = std_max(hi, b.hi());
  }
  ExtentBox box = ExtentBox::huge();
  if (lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z) {
    box = ExtentBox::from_min_max(lo, hi);
    for (int i = 0; i < 3; ++i)
      if (box.lengths[i] > kCriticalLength) box = ExtentBox::huge();
  }
  return box;
}

}  // namespace

// The box of a shape whose box is remade from the shape and its composed transform (its Compute_BBox), before the
// narrowing by bounding and clip objects. The carried shapes come here when they are made (or, built in code
// without a carried box, each time).
ExtentBox ObjectExtents::shape_box(const Object& o) const {
  struct Box_ {
    const ObjectExtents& self;
    const Object& o;
    const Matrix& m = o.world_from_object;
    // Sphere::Compute_BBox: the cube around the centre and radius POV-Ray moves itself while the sphere stays a
    // sphere (translations, rotations, uniform scales); an ellipsoid's cube as it was when it became one, carried
    // by the transforms since.
    ExtentBox operator()(const Sphere& s) const {
      auto cube = [](Vec3 c, double r) { return ExtentBox::make(c - Vec3{r, r, r}, {2 * r, 2 * r, 2 * r}); };
      if (const auto& frame = notes_of(o).ellipsoid_frame; s.ellipsoid && frame)
        return cube(frame->centre, frame->radius).transformed(frame->since);
      if (const double k = similarity_scale(m); k > 0 && !s.ellipsoid) return cube(m.point(s.centre), s.radius * k);
      return cube(s.centre, s.radius).transformed(m);   // an ellipsoid built in code, all in one transform
    }
    ExtentBox operator()(const Box& b) const {
      const ExtentBox local = ExtentBox::make(b.corner1, b.corner2 - b.corner1);
      return is_identity(m) ? local : local.transformed(m);
    }
    ExtentBox operator()(const Plane&) const { return ExtentBox::huge(); }
    // Triangle::Compute_BBox: the box of the world corners grown by EPSILON.
    ExtentBox operator()(const Triangle& t) const {
      MinMax b;
      for (const Vec3& c : t.corners) b.enclose(ExtentBox::make(m.point(c), {0, 0, 0}));
      const Vec3 e{kEpsilon, kEpsilon, kEpsilon};
      return ExtentBox::from_min_max(b.lo - e, b.hi + e);
    }
    // Polygon::Compute_BBox: the box of its points carried to world space.
    ExtentBox operator()(const Polygon& poly) const {
      MinMax b;
      for (const auto& q : poly.points) {
        const Vec3 w = (poly.world_from_plane * m).point({q[0], q[1], 0});
        b.lo = povtrace::min(b.lo, w);
        b.hi = povtrace::max(b.hi, w);
      }
      return ExtentBox::from_min_max(b.lo, b.hi);
    }
    ExtentBox operator()(const Mesh& mesh) const {
      const ExtentBox b = mesh_box(*mesh.data);
      return is_identity(m) ? b : b.transformed(m);
    }
    ExtentBox operator()(const Csg&) const { throw std::logic_error("a CSG box is made by csg_box"); }
    // Parse_Cone and Parse_Cylinder read the first end point as the apex, the second as the base.
    ExtentBox operator()(const Cylinder& c) const { return cone_box(c.end2, c.radius, c.end1, c.radius, m); }
    ExtentBox operator()(const Cone& c) const { return cone_box(c.end2, c.radius2, c.end1, c.radius1, m); }
    // Disc::Compute_BBox: the unit disc's square, SMALL_TOLERANCE thick, scaled by the outer radius, placed by the
    // disc's canonical transform (radius and length 1) and the object's.
    ExtentBox operator()(const Disc& d) const {
      const double r = d.radius;
      return ExtentBox::make({-r, -r, -kSmallTolerance}, {2 * r, 2 * r, 2 * kSmallTolerance})
          .transformed(canonical_to_shape(d.centre, d.normal, 1.0, 1.0) * m);
    }
    // Torus::Compute_BBox: the box of radius R + r around the centre, r high, carried by the torus's transform.
    ExtentBox operator()(const Torus& t) const {
      const double r1 = t.minor, r2 = t.major + t.minor;
      return ExtentBox::make({-r2, -r1, -r2}, {2.0 * r2, 2.0 * r1, 2.0 * r2}).transformed(m);
    }
    // Poly::Compute_BBox: the huge box, or the first clip object's box once a transform has run it with clips.
    ExtentBox operator()(const Poly&) const {
      if (notes_of(o).box_from_first_clip && !o.clipped_by.empty()) return self.box(o.clipped_by.front());
      return ExtentBox::huge();
    }
    ExtentBox operator()(const Quadric&) const { throw std::logic_error("a quadric's box is carried"); }
    // Superellipsoid::Compute_BBox: the cube ±1.0001, carried by the transform.
    ExtentBox operator()(const Superellipsoid&) const {
      return ExtentBox::make({-1.0001, -1.0001, -1.0001}, {2.0002, 2.0002, 2.0002}).transformed(m);
    }
    // Ovus::Compute_BBox, carried by the transform.
    ExtentBox operator()(const Ovus& v) const {
      const double w = ovus_box_half_width(v);
      return ExtentBox::make({-w, -v.bottom_radius, -w}, {2.0 * w, 2.0 * v.bottom_radius + v.top_radius, 2.0 * w})
          .transformed(m);
    }
    ExtentBox operator()(const HeightField& h) const { return self.height_field_box(o, h); }
    ExtentBox operator()(const Blob& b) const { return blob_box(b, m); }
    ExtentBox operator()(const Text& text) const { return text_box(text); }
    ExtentBox operator()(const Lathe& sweep) const { return lathe_local_box(sweep).transformed(m); }
    ExtentBox operator()(const Prism& sweep) const { return prism_local_box(sweep).transformed(m); }
    ExtentBox operator()(const Sor& sweep) const { return sor_local_box(sweep).transformed(m); }
    // Fractal::Compute_BBox: the cube around its bounding sphere, radius 1 + |c| (plus 1e-7, at most 2) for
    // quaternions and 4 for hypercomplex numbers, carried by the transform.
    ExtentBox operator()(const JuliaFractal& j) const {
      double r = 4.0;
      if (j.algebra == JuliaAlgebra::quaternion) {
        const auto& c = j.julia;
        r = std::min(2.0, 1.0 + std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2] + c[3] * c[3]) + 1e-7);
      }
      const ExtentBox local = ExtentBox::make({-r, -r, -r}, {2 * r, 2 * r, 2 * r});
      return is_identity(m) ? local : local.transformed(m);
    }
    // BicubicPatch::Compute_BBox: the box of its 16 control points, where its transforms have put them.
    ExtentBox operator()(const BicubicPatch& b) const {
      MinMax box;
      for (const Vec3& p : b.points) box.enclose_point(p);
      return ExtentBox::from_min_max(box.lo, box.hi);
    }
    // IsoSurface::Compute_BBox: the container's box (a sphere's cube), carried by the transform.
    ExtentBox operator()(const Isosurface& iso) const {
      const ExtentBox local =
          iso.sphere_container
              ? ExtentBox::make(iso.centre - Vec3{iso.radius, iso.radius, iso.radius},
                                {iso.radius * 2, iso.radius * 2, iso.radius * 2})
              : ExtentBox::make(iso.corner1, iso.corner2 - iso.corner1);
      return is_identity(m) ? local : local.transformed(m);
    }
  };
  return std::visit(Box_{*this, o}, o.shape);
}

// HField::Compute_BBox: x and z over the sample grid, y from the samples' range, all scaled into the unit cube
// (Parse_HField's scaling by 1/(width − 1), 1/65536, 1/(depth − 1)), then the object's transforms.
ExtentBox ObjectExtents::height_field_box(const Object& o, const HeightField& h) const {
  if (!geometry_) throw ExtentUnavailable(ExtentGap::height_field_samples);
  const HeightFieldExtent e = geometry_->height_field_extent(h, noise_generator_);
  const Vec3 lower{0, e.bottom, 0}, upper{e.width - 1.0, e.top, e.depth - 1.0};
  const Matrix unit = Matrix::scaling({1.0 / (e.width - 1.0), 1.0 / 65536.0, 1.0 / (e.depth - 1.0)});
  return ExtentBox::make(lower, upper - lower).transformed(unit * o.world_from_object);
}

// CSG::Compute_BBox when the CSG is made, from its children's boxes as they are then (see the top of this file).
ExtentBox ObjectExtents::csg_box(Object& o) const {
  auto& csg = std::get<Csg>(o.shape);
  const ExtentBox old = ExtentBox::huge();
  if (csg.kind == CsgKind::union_ || csg.kind == CsgKind::merge) {
    MinMax m;
    for (const Object& child : csg.children) m.enclose(box(child));
    if (!csg.lights.empty()) m.enclose(ExtentBox::huge());   // a light source keeps the initial huge box
    return csg_result(m, old);
  }
  MinMax m = MinMax::everything();
  std::vector<Object*> quadrics;
  for (Object& child : csg.children) {
    if (inverted(child) || std::holds_alternative<HeightField>(child.shape)) continue;
    if (std::holds_alternative<Quadric>(child.shape)) quadrics.push_back(&child);
    else if (const auto* plane = std::get_if<Plane>(&child.shape)) narrow_by_plane(m, *plane, child);
    else m.narrow(box(child));
  }
  for (Object* q : quadrics) {
    recompute_quadric(*q, m.lo, m.hi);
    m.narrow(box(*q));
  }
  return csg_result(m, old);
}

// Quadric::Compute_BBox(ClipMin, ClipMax) with the quadric's current coefficients, within its clip objects and the
// given range; the quadric keeps the new box when it is smaller.
void ObjectExtents::recompute_quadric(Object& o, Vec3 clip_lo, Vec3 clip_hi) const {
  MinMax range;
  range.lo = clip_lo;
  range.hi = clip_hi;
  for (const Object& clip : o.clipped_by) {
    if (inverted(clip)) continue;
    if (const auto* plane = std::get_if<Plane>(&clip.shape)) narrow_by_plane(range, *plane, clip);
    else range.narrow(box(clip));
  }
  // The coefficients POV-Ray holds now: the written ones carried by the composed transform (POV-Ray transforms
  // them at each transform; the two agree to rounding).
  // Quadric::Invert negates every coefficient, which the box computation sees when x² has none to make positive.
  const Quadric& q = std::get<Quadric>(o.shape);
  Quadric current = transformed_quadric(q, o.world_from_object);
  if (o.inverse) {
    current.square = -1.0 * current.square;
    current.mixed = -1.0 * current.mixed;
    current.linear = -1.0 * current.linear;
    current.constant = -current.constant;
  }
  const ExtentBox old = notes_of(o).carried_extent.value_or(initial_quadric_box());
  const QuadricBox b = quadric_box(current, range.lo, range.hi, old);
  ObjectNotes& notes = edit_notes(o, notes_);
  notes.carried_extent = b.box;
  notes.automatic_bounds = notes.automatic_bounds || b.computed;
}

ExtentBox ObjectExtents::box(const Object& o) const {
  const ObjectNotes& notes = notes_of(o);
  if (notes.carried_extent) return *notes.carried_extent;
  if (notes.extent_gap != ExtentGap::none) throw ExtentUnavailable(notes.extent_gap);
  if (std::holds_alternative<Csg>(o.shape)) {   // a CSG built in code, never made by the parser
    Object copy = o;
    return csg_box(copy);
  }
  if (const auto* q = std::get_if<Quadric>(&o.shape)) return parsed_quadric_box(*q).box.transformed(o.world_from_object);
  const ExtentBox b = shape_box(o);
  return notes.box_skips_clips ? b : narrowed(o, b);
}

// The end of Parse_Object_Mods: the common box of the bounding objects, then of the clip objects, each left out
// when inverted, replaces the box when its volume is smaller.
ExtentBox ObjectExtents::narrowed(const Object& o, ExtentBox b) const {
  const std::vector<Object>& bounds = o.bounded_by.empty() ? o.removed_bounds : o.bounded_by;
  for (const std::vector<Object>* list : {&bounds, &o.clipped_by}) {
    if (list->empty()) continue;
    MinMax m = MinMax::everything();
    for (const Object& sib : *list) {
      if (inverted(sib)) continue;
      const ExtentBox s = box(sib);
      m.narrow(s.lo(), s.max_extent());   // Parse_Object_Mods adds the float corner and lengths in float
    }
    const ExtentBox common = ExtentBox::from_min_max(m.lo, m.hi);
    if (common.volume() < b.volume()) b = common;
  }
  return b;
}

// The box a later transform leaves to be carried, as POV-Ray's Transform handles each shape: a carried box itself;
// a box remade from the shape, without the narrowing by clip objects a transform drops (ObjectNotes::box_skips_clips),
// where a sphere that is still a sphere becomes an ellipsoid holding its moved centre and radius (Sphere::Transform);
// a clipped poly's first clip's (Poly::Compute_BBox). Unset: the huge box whatever the transform. A uniform scaling
// by a power of two carries this box exactly as the remade one (every product scales exactly), except a triangle's
// EPSILON margin, which POV-Ray adds after the transform (1e-10 in a float box: below a float's precision but at
// coordinates within 1e-3 of zero).
std::optional<ExtentBox> ObjectExtents::moved_box(const Object& o) const {
  const ObjectNotes& notes = notes_of(o);
  if (notes.carried_extent) return *notes.carried_extent;
  if (notes.extent_gap != ExtentGap::none) throw ExtentUnavailable(notes.extent_gap);
  if (std::holds_alternative<Plane>(o.shape)) return std::nullopt;
  if (std::holds_alternative<Poly>(o.shape)) {
    if (o.clipped_by.empty()) return std::nullopt;
    return moved_box(o.clipped_by.front());
  }
  if (const auto* s = std::get_if<Sphere>(&o.shape); s && !s->ellipsoid) {
    const Matrix& m = o.world_from_object;
    const double r = s->radius * length(Vec3{m.m[0][0], m.m[0][1], m.m[0][2]});   // as carry_sphere_frame scales it
    return ExtentBox::make(m.point(s->centre) - Vec3{r, r, r}, {2 * r, 2 * r, 2 * r});
  }
  if (std::holds_alternative<Csg>(o.shape) || std::holds_alternative<Quadric>(o.shape)) return box(o);   // from code
  return shape_box(o);
}

PlacedBox ObjectExtents::placed(const Object& o) const {
  try {
    return PlacedBox{true, box(o), moved_box(o)};
  } catch (const ExtentUnavailable&) {
    return PlacedBox{};
  }
}

// The renderer culls by this box only what it builds as a CSG node (renderer/csg_build.cpp needs_csg_node): CSG and
// objects with clip, bounding or removed bounding objects; it bounds every other shape by the shape's own bounds.
// So only these get one: 100,000 placed spheres would otherwise cost 100,000 box computations for nothing (8 % of
// bench's parse_objects parse).
bool culled_by_placed_box(const Object& o) {
  return std::holds_alternative<Csg>(o.shape) || !o.clipped_by.empty() || !o.bounded_by.empty() ||
         !o.removed_bounds.empty();
}

void set_placed_boxes(Object& o, const ObjectExtents& extents) {
  if (culled_by_placed_box(o)) o.placed_box = extents.placed(o);
  auto* csg = std::get_if<Csg>(&o.shape);
  if (csg && csg->kind == CsgKind::union_ && o.clipped_by.empty() && o.bounded_by.empty())
    for (Object& child : csg->children) set_placed_boxes(child, extents);
}

namespace {
// The box is unset for good: later boxes hang on it (ObjectNotes::extent_gap).
void record_gap(Object& o, ExtentGap gap, const NotesPool& pool) {
  ObjectNotes& notes = edit_notes(o, pool);
  notes.carried_extent.reset();
  notes.extent_gap = gap;
}
}  // namespace

void ObjectExtents::made(Object& o) const {
  try {
    ExtentBox b;
    bool computed_quadric_box = false;
    if (std::holds_alternative<Csg>(o.shape)) b = csg_box(o);
    else if (const auto* q = std::get_if<Quadric>(&o.shape)) {
      const QuadricBox parsed = parsed_quadric_box(*q);
      b = parsed.box;
      computed_quadric_box = parsed.computed;
    } else b = shape_box(o);
    ObjectNotes& notes = edit_notes(o, notes_);
    notes.carried_extent = b;
    notes.automatic_bounds = notes.automatic_bounds || computed_quadric_box;
  } catch (const ExtentUnavailable& e) {
    record_gap(o, e.gap, notes_);
  }
}

void ObjectExtents::quadric_clipped(Object& o) const {
  try {
    recompute_quadric(o, MinMax::everything().lo, MinMax::everything().hi);
  } catch (const ExtentUnavailable& e) {
    record_gap(o, e.gap, notes_);
  }
}

void ObjectExtents::modifiers_ended(Object& o) const {
  if (notes_of(o).box_skips_clips) edit_notes(o, notes_).box_skips_clips = false;   // no notes made for nothing
  const std::optional<ExtentBox> carried = notes_of(o).carried_extent;
  if (!carried || (o.clipped_by.empty() && o.bounded_by.empty())) return;
  try {
    const ExtentBox b = narrowed(o, *carried);
    edit_notes(o, notes_).carried_extent = b;
  } catch (const ExtentUnavailable& e) {
    record_gap(o, e.gap, notes_);
  }
}

}  // namespace povtrace::sdl
