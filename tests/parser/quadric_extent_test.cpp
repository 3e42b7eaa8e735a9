// POV-Ray 3.7's quadric bounding boxes (parser/quadric_extent): the box Parse_Quadric computes from the coefficients
// as written, carried by later transforms; the box recomputed inside a CSG intersection's range or a clipped_by;
// the half spaces axis-aligned planes give; the transformed coefficients.
//
// Every "printed" box below is what POV-Ray 3.7.0.10 printed for the same object: each component of min_extent()
// and max_extent() through str(V, 0, 17), in scenes run as povray +W8 +H8 -D -V -GR -GS -GW. The box is single
// precision, so 17 decimals name one float each; the comparisons are exact, the sign of a zero included.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "runtime/quadric_extent.hpp"

namespace povtrace {
namespace {

constexpr Vec3 kRangeMin{-kBoundHuge, -kBoundHuge, -kBoundHuge};
constexpr Vec3 kRangeMax{kBoundHuge, kBoundHuge, kBoundHuge};

Quadric quadric(Vec3 square, Vec3 mixed, Vec3 linear, double constant) { return {square, mixed, linear, constant}; }

// min_extent() and max_extent() as POV-Ray printed them.
struct Printed {
  Vec3 min, max;
};

// min_extent() is the float lower corner, max_extent() the float sum of corner and lengths (ExtentBox::max_extent).
void expect_printed(const ExtentBox& box, const Printed& printed, const std::string& what) {
  const Vec3 lo = box.lo(), hi = box.max_extent();
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(lo[k], double(static_cast<float>(printed.min[k]))) << what << ": min_extent component " << k;
    EXPECT_EQ(hi[k], double(static_cast<float>(printed.max[k]))) << what << ": max_extent component " << k;
    EXPECT_EQ(std::signbit(lo[k]), std::signbit(printed.min[k])) << what << ": sign of min_extent component " << k;
    EXPECT_EQ(std::signbit(hi[k]), std::signbit(printed.max[k])) << what << ": sign of max_extent component " << k;
  }
}

// One transform as the parser makes it.
struct Step {
  Matrix m;
  TransformKind kind;
};
Step scale(Vec3 v) { return {Matrix::scaling(v), TransformKind::scale}; }
Step rotate(Vec3 degrees) { return {Matrix::rotation(degrees), TransformKind::rotate}; }
Step translate(Vec3 v) { return {Matrix::translation(v), TransformKind::translate}; }
Step matrix(std::array<double, 12> v) {
  Matrix m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) m.m[i][j] = v[3 * i + j];
  return {m, TransformKind::other};
}

// A quadric as POV-Ray holds it after parsing: Parse_Quadric's box, then per transform (Quadric::Transform) the
// coefficients transformed and the box carried along (Recompute_BBox).
struct Placed {
  Quadric q;
  ExtentBox box;
};
Placed place(const Quadric& written, const std::vector<Step>& steps = {}) {
  Placed p{written, parsed_quadric_box(written).box};
  for (const Step& s : steps) {
    p.q = transformed_quadric(p.q, s.m, s.kind);
    p.box = p.box.transformed(s.m);
  }
  return p;
}

// A range a non-quadric child of an intersection (or a clip object) confines the quadric to.
struct Range {
  Vec3 lo, hi;
};
// A box's BBox (Box::Compute_BBox: the corner and the lengths, in float), as Make_min_max_from_BBox reads it back.
Range box_range(Vec3 corner1, Vec3 corner2) {
  const ExtentBox b = ExtentBox::make(corner1, corner2 - corner1);
  return {b.lo(), b.hi()};
}
// A plane moved only by translate, rotate and scale (POV-Ray keeps it in world space).
Range plane_range(Vec3 normal, double distance, const Matrix& world_from_object = Matrix::identity()) {
  Range r;
  plane_min_max(normal, distance, world_from_object, r.lo, r.hi);
  return r;
}
// A plane with a Trans: its normal and distance when the first matrix or transform block reached it, and the
// transforms composed since.
Range trans_plane_range(Vec3 normal, double distance, const Matrix& trans) {
  Range r;
  plane_min_max_with_trans(normal, distance, trans, r.lo, r.hi);
  return r;
}

void narrow(Vec3& lo, Vec3& hi, Vec3 child_lo, Vec3 child_hi) {
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::max(lo[k], child_lo[k]);
    hi[k] = std::min(hi[k], child_hi[k]);
  }
}

// CSG::Compute_BBox of an intersection (every child here non-inverted): the range from ±BOUND_HUGE narrowed by
// the other children first, then each quadric child's box recomputed within the range so far (it replaces the
// child's box) and the range narrowed by that. The intersection (starting from the huge box) takes the range if it
// is not empty and its volume is smaller; wider than CRITICAL_LENGTH it is the huge box.
ExtentBox intersection_box(const std::vector<Range>& others, std::vector<Placed>& quadrics) {
  Vec3 lo = kRangeMin, hi = kRangeMax;
  for (const Range& r : others) narrow(lo, hi, r.lo, r.hi);
  for (Placed& p : quadrics) {
    p.box = quadric_box(p.q, lo, hi, p.box).box;
    narrow(lo, hi, p.box.lo(), p.box.hi());
  }
  const ExtentBox initial = ExtentBox::huge();
  if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return initial;
  if (!((hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z) < initial.volume())) return initial;
  const ExtentBox box = ExtentBox::from_min_max(lo, hi);
  return box.wider_than_critical() ? ExtentBox::huge() : box;
}
ExtentBox intersection_box(const std::vector<Range>& others, Placed quadric) {
  std::vector<Placed> quadrics{quadric};
  return intersection_box(others, quadrics);
}

// A quadric with clipped_by (Parse_Object_Mods): Compute_BBox from ±BOUND_HUGE narrowed by the clip objects, with
// the coefficients and box as they are at that point.
ExtentBox clipped_box(const Placed& p, const std::vector<Range>& clips) {
  Vec3 lo = kRangeMin, hi = kRangeMax;
  for (const Range& r : clips) narrow(lo, hi, r.lo, r.hi);
  return quadric_box(p.q, lo, hi, p.box).box;
}

const Quadric kSphere = quadric({1, 1, 1}, {}, {}, -1);
// shapes.inc (shapes_old.inc) quadrics. (Its Ellipsoid and Sphere are spheres, not quadrics.)
const Quadric kCylinderX = quadric({0, 1, 1}, {}, {}, -1);
const Quadric kCylinderY = quadric({1, 0, 1}, {}, {}, -1);
const Quadric kCylinderZ = quadric({1, 1, 0}, {}, {}, -1);
const Quadric kQConeX = quadric({-1, 1, 1}, {}, {}, 0);
const Quadric kQConeY = quadric({1, -1, 1}, {}, {}, 0);
const Quadric kQConeZ = quadric({1, 1, -1}, {}, {}, 0);
const Quadric kParaboloidX = quadric({0, 1, 1}, {}, {-1, 0, 0}, 0);
const Quadric kParaboloidY = quadric({1, 0, 1}, {}, {0, -1, 0}, 0);
const Quadric kParaboloidZ = quadric({1, 1, 0}, {}, {0, 0, -1}, 0);
const Quadric kHyperboloid = quadric({-1, 0, 1}, {}, {0, 1, 0}, 0);   // a saddle, y = x² - z²
const Quadric kHyperboloidY = quadric({1, -1, 1}, {}, {}, -1);

TEST(QuadricExtent, InitialBoxIsTheHugeBox) {
  const ExtentBox b = initial_quadric_box();
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(b.lower[k], -1e10f);
    EXPECT_EQ(b.lengths[k], 2e10f);
  }
}

// Parse_Quadric's box of the coefficients as written: finite only for ellipsoids (moved or not); every unbounded
// quadric — cylinders, cones, hyperboloids, paraboloids, a two-sheet hyperboloid, a quadric with a cross term —
// keeps or ends with the huge box.
TEST(QuadricExtent, ParsedBoxAsPovRayPrintsIt) {
  struct Case {
    const char* name;
    Quadric q;
    Printed printed;
  };
  const Case cases[] = {
      {"sphere", kSphere, {{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}},
      {"ellipsoid <1,4,9>",
       quadric({1, 4, 9}, {}, {}, -1),
       {{-1.0, -0.5, -0.3333333432674408}, {1.0, 0.5, 0.3333333432674408}}},
      {"ellipsoid <2,3,5> J -7",
       quadric({2, 3, 5}, {}, {}, -7),
       {{-1.87082874774932861, -1.52752518653869629, -1.18321597576141357},
        {1.87082874774932861, 1.52752518653869629, 1.18321597576141357}}},
      {"ellipsoid with A negative",
       quadric({-1, -4, -9}, {}, {}, 2),
       {{-1.41421353816986084, -0.70710676908493042, -0.47140452265739441},
        {1.41421353816986084, 0.70710676908493042, 0.47140452265739441}}},
      {"Cylinder_X", kCylinderX, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"Cylinder_Y", kCylinderY, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"Cylinder_Z", kCylinderZ, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"elliptic cylinder y", quadric({4, 0, 9}, {}, {}, -2), {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"QCone_X", kQConeX, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"QCone_Y", kQConeY, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"QCone_Z", kQConeZ, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"hyperboloid x", quadric({1, -1, -1}, {}, {}, 1), {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"Hyperboloid_Y", kHyperboloidY, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"hyperboloid z", quadric({1, 1, -1}, {}, {}, -1), {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"two-sheet hyperboloid z", quadric({1, 1, -1}, {}, {}, 1), {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"Paraboloid_X", kParaboloidX, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"Paraboloid_Y", kParaboloidY, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"Paraboloid_Z", kParaboloidZ, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"paraboloid y opening down", quadric({1, 0, 1}, {}, {0, 1, 0}, 0), {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"Hyperboloid (saddle)", kHyperboloid, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"mixed term", quadric({1, 1, 1}, {1, 0, 0}, {}, -1), {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"mixed term below EPSILON", quadric({1, 1, 1}, {1e-11, 0, 0}, {}, -1), {{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}},
      {"square term below EPSILON", quadric({1, 1, 1e-11}, {}, {}, -1), {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"sphere moved by linear terms", quadric({1, 1, 1}, {}, {-2, 4, 0}, 4), {{0.0, -3.0, -1.0}, {2.0, -1.0, 1.0}}},
      {"ellipsoid moved by linear terms",
       quadric({2, 3, 1}, {}, {-1.2, -4.2, 0.2}, 0.18 + 1.47 + 0.01 - 2),
       {{-0.69999998807907104, -0.11649657785892487, -1.51421356201171875},
        {1.29999995231628418, 1.51649665832519531, 1.31421351432800293}}},
      {"cylinder z moved by linear terms",
       quadric({1, 4, 0}, {}, {1, -2, 0}, -0.5),
       {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"paraboloid y moved by linear terms",
       quadric({1, 0, 1}, {}, {-2, -1, 0}, 3),
       {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
  };
  for (const Case& c : cases) expect_printed(parsed_quadric_box(c.q).box, c.printed, c.name);
}

// Later transforms only carry Parse_Quadric's box along.
TEST(QuadricExtent, TransformsCarryTheParsedBox) {
  struct Case {
    const char* name;
    Quadric q;
    std::vector<Step> steps;
    Printed printed;
  };
  const Quadric moved_ellipsoid = quadric({2, 3, 1}, {}, {-1.2, -4.2, 0.2}, 0.18 + 1.47 + 0.01 - 2);
  const Case cases[] = {
      {"sphere scale 2 rotate 30*y",
       kSphere,
       {scale({2, 2, 2}), rotate({0, 30, 0})},
       {{-2.73205089569091797, -2.0, -2.73205089569091797}, {2.73205089569091797, 2.0, 2.73205089569091797}}},
      {"ellipsoid rotate <10,20,30> translate <1,2,3>",
       quadric({1, 4, 9}, {}, {}, -1),
       {rotate({10, 20, 30}), translate({1, 2, 3})},
       {{-0.16045653820037842, 1.08286213874816895, 2.26791977882385254},
        {2.16045665740966797, 2.91713762283325195, 3.73208045959472656}}},
      {"moved ellipsoid scale <1,2,3>",
       moved_ellipsoid,
       {scale({1, 2, 3})},
       {{-0.69999998807907104, -0.23299315571784973, -4.54264068603515625},
        {1.29999995231628418, 3.03299331665039062, 3.94264030456542969}}},
      {"ellipsoid matrix",
       quadric({1, 4, 9}, {}, {}, -1),
       {matrix({1, 0.5, 0, 0, 1, 0, 0.25, 0, 2, 1, -1, 0.5})},
       {{-0.0833333358168602, -2.0, -0.16666668653488159}, {2.08333349227905273, 0.0, 1.16666674613952637}}},
      {"Cylinder_X rotate 45*z", kCylinderX, {rotate({0, 0, 45})}, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
      {"Cylinder_X translate <1,2,3>", kCylinderX, {translate({1, 2, 3})}, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}},
  };
  for (const Case& c : cases) expect_printed(place(c.q, c.steps).box, c.printed, c.name);
}

// intersection { quadric { … } box { … } }: the quadric's box recomputed within the box's range.
TEST(QuadricExtent, IntersectionWithBoxRecomputesTheQuadricBox) {
  struct Case {
    const char* name;
    Placed quadric;
    Vec3 corner1, corner2;
    Printed printed;
  };
  const Case cases[] = {
      {"Cylinder_Y", place(kCylinderY), {-1.5, -2, -0.5}, {0.5, 3, 3}, {{-1.0, -2.0, -0.5}, {0.5, 3.0, 1.0}}},
      {"QCone_Y", place(kQConeY), {-2, -1, -2}, {2, 3, 2}, {{-2.0, -1.0, -2.0}, {2.0, 3.0, 2.0}}},
      {"QCone_Y in a wide box", place(kQConeY), {-5, 0.5, -5}, {5, 2, 5}, {{-2.0, 0.5, -2.0}, {2.0, 2.0, 2.0}}},
      {"elliptic cone x",
       place(quadric({-1, 4, 9}, {}, {}, 0)),
       {-3, -5, -5},
       {1, 5, 5},
       {{-3.0, -1.5, -1.0}, {1.0, 1.5, 1.0}}},
      {"QCone_Z",
       place(kQConeZ),
       {-5, -5, -0.7},
       {5, 5, 1.3},
       {{-1.29999995231628418, -1.29999995231628418, -0.69999998807907104},
        {1.29999995231628418, 1.29999995231628418, 1.29999995231628418}}},
      {"Hyperboloid_Y",
       place(kHyperboloidY),
       {-5, -1, -5},
       {5, 2, 5},
       {{-2.2360680103302002, -1.0, -2.2360680103302002}, {2.2360680103302002, 2.0, 2.2360680103302002}}},
      {"hyperboloid x",
       place(quadric({1, -1, -1}, {}, {}, 1)),
       {-2, -5, -5},
       {1, 5, 5},
       {{-2.0, -2.2360680103302002, -2.2360680103302002}, {1.0, 2.2360680103302002, 2.2360680103302002}}},
      {"hyperboloid z",
       place(quadric({1, 4, -1}, {}, {}, -1)),
       {-5, -5, -3},
       {5, 5, 0.5},
       {{-3.1622776985168457, -1.58113884925842285, -3.0}, {3.1622776985168457, 1.58113884925842285, 0.5}}},
      // POV-Ray takes the hyperboloid's constant as -1 whatever it is: radius √(1 + y²), not √(4 + y²) — a box
      // narrower than the surface.
      {"hyperboloid y with J -4",
       place(quadric({1, -1, 1}, {}, {}, -4)),
       {-5, -1, -5},
       {5, 2, 5},
       {{-2.2360680103302002, -1.0, -2.2360680103302002}, {2.2360680103302002, 2.0, 2.2360680103302002}}},
      {"Paraboloid_Y",
       place(kParaboloidY),
       {-3, -1, -3},
       {3, 2, 3},
       {{-1.41421353816986084, 0.0, -1.41421353816986084}, {1.41421353816986084, 2.0, 1.41421353816986084}}},
      {"paraboloid y opening down",
       place(quadric({1, 0, 1}, {}, {0, 1, 0}, 0)),
       {-3, -2, -3},
       {3, 1, 3},
       {{-1.41421353816986084, -2.0, -1.41421353816986084}, {1.41421353816986084, 0.0, 1.41421353816986084}}},
      {"Paraboloid_X",
       place(kParaboloidX),
       {-1, -3, -3},
       {2, 3, 3},
       {{0.0, -1.41421353816986084, -1.41421353816986084}, {2.0, 1.41421353816986084, 1.41421353816986084}}},
      {"paraboloid x, negative square terms",
       place(quadric({0, -1, -1}, {}, {-1, 0, 0}, 0)),
       {-2, -3, -3},
       {1, 3, 3},
       {{-2.0, -1.41421353816986084, -1.41421353816986084}, {0.0, 1.41421353816986084, 1.41421353816986084}}},
      {"Paraboloid_Z",
       place(kParaboloidZ),
       {-3, -3, -1},
       {3, 3, 2},
       {{-1.41421353816986084, -1.41421353816986084, 0.0}, {1.41421353816986084, 1.41421353816986084, 2.0}}},
      {"paraboloid z opening down",
       place(quadric({1, 1, 0}, {}, {0, 0, 1}, 0)),
       {-3, -3, -1},
       {3, 3, 2},
       {{-1.0, -1.0, -1.0}, {1.0, 1.0, 0.0}}},
      {"mixed term: the range itself",
       place(quadric({1, 1, 1}, {1, 0, 0}, {}, -1)),
       {-1, -2, -3},
       {1, 2, 3},
       {{-1.0, -2.0, -3.0}, {1.0, 2.0, 3.0}}},
      {"sphere", place(kSphere), {-0.5, -2, -2}, {2, 0.25, 2}, {{-0.5, -1.0, -1.0}, {1.0, 0.25, 1.0}}},
      {"cone y moved by linear terms",
       place(quadric({1, -1, 1}, {}, {-2, 2, 0}, 0)),
       {-4, -1, -4},
       {4, 2.5, 4},
       {{-1.0, -1.0, -2.0}, {3.0, 2.5, 2.0}}},
      // Transformed coefficients: the translation appears as linear terms, the rotation's cos 90° terms fall
      // below EPSILON, and a rotated ellipsoid has cross terms (its carried box stays, being smaller).
      {"Cylinder_Y scale <2,1,3> translate <1,0,-1>",
       place(kCylinderY, {scale({2, 1, 3}), translate({1, 0, -1})}),
       {-5, -1, -5},
       {5, 1, 5},
       {{-1.0, -1.0, -4.0}, {3.0, 1.0, 2.0}}},
      {"Cylinder_Y rotate 90*x",
       place(kCylinderY, {rotate({90, 0, 0})}),
       {-5, -5, -1},
       {5, 5, 2},
       {{-1.0, -1.0, -1.0}, {1.0, 1.0, 2.0}}},
      {"QCone_Y scale <1,2,1> rotate 90*z translate 0.5*y",
       place(kQConeY, {scale({1, 2, 1}), rotate({0, 0, 90}), translate({0, 0.5, 0})}),
       {-1, -5, -5},
       {3, 5, 5},
       {{-1.0, -1.0, -1.5}, {3.0, 2.0, 1.5}}},
      {"ellipsoid rotate 30*y",
       place(quadric({1, 4, 9}, {}, {}, -1), {rotate({0, 30, 0})}),
       {-0.5, -5, -5},
       {5, 5, 5},
       {{-0.5, -0.5, -0.78867512941360474}, {1.0326920747756958, 0.5, 0.78867512941360474}}},
      {"ellipsoid matrix",
       place(quadric({1, 4, 9}, {}, {}, -1), {matrix({2, 0, 0, 0, 1, 0, 0, 0, 0.5, 1, -1, 0.5})}),
       {-5, -5, -5},
       {5, -0.5, 5},
       {{-1.0, -1.5, 0.3333333432674408}, {3.0, -0.5, 0.66666668653488159}}},
  };
  for (const Case& c : cases)
    expect_printed(intersection_box({box_range(c.corner1, c.corner2)}, c.quadric), c.printed, c.name);
}

// The shapes.inc quadrics alone (all the huge box) and in intersection { object { Q } box { <-2,-1.5,-1>,
// <1,2.5,3> } }. Paraboloid_Z's max x shows the float rounding of the intersection's lengths.
TEST(QuadricExtent, ShapesIncQuadrics) {
  struct Case {
    const char* name;
    Quadric q;
    Printed alone, boxed;
  };
  const Case cases[] = {
      {"Cylinder_X", kCylinderX, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}, {{-2.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}},
      {"Cylinder_Y", kCylinderY, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}, {{-1.0, -1.5, -1.0}, {1.0, 2.5, 1.0}}},
      {"Cylinder_Z", kCylinderZ, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}, {{-1.0, -1.0, -1.0}, {1.0, 1.0, 3.0}}},
      {"QCone_X", kQConeX, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}, {{-2.0, -1.5, -1.0}, {1.0, 2.0, 2.0}}},
      {"QCone_Y", kQConeY, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}, {{-2.0, -1.5, -1.0}, {1.0, 2.5, 2.5}}},
      {"QCone_Z", kQConeZ, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}, {{-2.0, -1.5, -1.0}, {1.0, 2.5, 3.0}}},
      {"Paraboloid_X", kParaboloidX, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}, {{0.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}},
      {"Paraboloid_Y",
       kParaboloidY,
       {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}},
       {{-1.58113884925842285, 0.0, -1.0}, {1.0, 2.5, 1.58113884925842285}}},
      {"Paraboloid_Z",
       kParaboloidZ,
       {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}},
       {{-1.73205077648162842, -1.5, 0.0}, {1.00000011920928955, 1.73205089569091797, 3.0}}},
      {"Hyperboloid", kHyperboloid, {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}}, {{-2.0, -1.5, -1.0}, {1.0, 2.5, 3.0}}},
      {"Hyperboloid_Y",
       kHyperboloidY,
       {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}},
       {{-2.0, -1.5, -1.0}, {1.0, 2.5, 2.69258236885070801}}},
  };
  for (const Case& c : cases) {
    expect_printed(parsed_quadric_box(c.q).box, c.alone, c.name);
    expect_printed(intersection_box({box_range({-2, -1.5, -1}, {1, 2.5, 3})}, place(c.q)), c.boxed,
                   std::string(c.name) + " in the box");
  }
}

// A paraboloid whose range lies wholly on its empty side: its box gets a negative length (POV-Ray keeps it, the
// volume being negative), the intersection's range is empty, and the intersection keeps its initial huge box.
TEST(QuadricExtent, EmptyRangeGivesNegativeLengthsAndAHugeIntersection) {
  const Range box = box_range({-3, -2, -3}, {3, -1, 3});
  const ExtentBox q = quadric_box(kParaboloidY, box.lo, box.hi, initial_quadric_box()).box;
  EXPECT_EQ(q.lower[1], 0.0f);
  EXPECT_EQ(q.lengths[1], -1.0f);
  expect_printed(intersection_box({box}, place(kParaboloidY)), {{-1e10, -1e10, -1e10}, {1e10, 1e10, 1e10}},
                 "Paraboloid_Y below 0");
}

// Two quadrics: the second is recomputed within the range the first narrowed.
TEST(QuadricExtent, IntersectionOfTwoQuadrics) {
  std::vector<Placed> quadrics{place(kCylinderY), place(kQConeY)};
  expect_printed(intersection_box({box_range({-3, -0.5, -3}, {3, 2, 3})}, quadrics),
                 {{-1.0, -0.5, -1.0}, {1.0, 2.0, 1.0}}, "Cylinder_Y, QCone_Y and a box");
}

// Planes as intersection children (Compute_Plane_Min_Max).
TEST(QuadricExtent, IntersectionWithPlanes) {
  expect_printed(intersection_box({plane_range({0, 1, 0}, 2), plane_range({0, -1, 0}, 1)}, place(kCylinderY)),
                 {{-1.0, -1.0, -1.0}, {1.0, 2.0, 1.0}}, "plane { y, 2 } plane { -y, 1 }");
  expect_printed(intersection_box({plane_range({0, 1, 0}, 1, Matrix::translation({0, 0.5, 0})),
                                   plane_range({0, 1, 0}, 1, Matrix::rotation({180, 0, 0}))},
                                  place(kQConeY)),
                 {{-1.5, -1.0, -1.5}, {1.5, 1.5, 1.5}}, "plane { y, 1 translate 0.5*y } plane { y, 1 rotate 180*x }");
  expect_printed(intersection_box({plane_range({1, 0, 0}, 1, Matrix::scaling({2, 2, 2})), plane_range({-1, 0, 0}, 0.5)},
                                  place(kCylinderX)),
                 {{-0.5, -1.0, -1.0}, {2.0, 1.0, 1.0}}, "plane { x, 1 scale 2 } plane { -x, 0.5 }");
  // difference { Cylinder_Y plane { y, -1 } plane { -y, -2 } }: the planes are inverted (normal and distance
  // negated) yet still count, as Plane::Invert sets no INVERTED_FLAG.
  expect_printed(intersection_box({plane_range({0, -1, 0}, 1), plane_range({0, 1, 0}, 2)}, place(kCylinderY)),
                 {{-1.0, -1.0, -1.0}, {1.0, 2.0, 1.0}}, "difference { Cylinder_Y plane { y, -1 } plane { -y, -2 } }");
}

// Planes with a Trans (a matrix or transform block): POV-Ray's formula, which is not the moved plane's half space.
TEST(QuadricExtent, IntersectionWithTransformedPlanesAsPovRayHasThem) {
  // plane { y, 1 transform { scale 2 } }: the plane is y = 2, POV-Ray bounds y by 0.
  expect_printed(
      intersection_box({trans_plane_range({0, 1, 0}, 1, Matrix::scaling({2, 2, 2})), plane_range({0, -1, 0}, 1)},
                       place(kCylinderY)),
      {{-1.0, -1.0, -1.0}, {1.0, 0.0, 1.0}}, "plane { y, 1 transform { scale 2 } }");
  // plane { y, 1 scale 2 transform { translate y } }: the Trans starts after the scale (y, 2); right here: y ≤ 3.
  expect_printed(
      intersection_box({trans_plane_range({0, 1, 0}, 2, Matrix::translation({0, 1, 0})), plane_range({0, -1, 0}, 1)},
                       place(kCylinderY)),
      {{-1.0, -1.0, -1.0}, {1.0, 3.0, 1.0}}, "plane { y, 1 scale 2 transform { translate y } }");
  // plane { z, 0.5 transform { rotate 90*x } }: the plane is y = -0.5 bounding from below; POV-Ray's normal turns
  // the other way, and the bound is y ≤ 1.5.
  expect_printed(
      intersection_box({trans_plane_range({0, 0, 1}, 0.5, Matrix::rotation({90, 0, 0})), plane_range({0, -1, 0}, 1)},
                       place(kCylinderY)),
      {{-1.0, -1.0, -1.0}, {1.0, 1.5, 1.0}}, "plane { z, 0.5 transform { rotate 90*x } }");
  expect_printed(intersection_box({trans_plane_range({0, 0, 1}, 1, matrix({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0.25}).m),
                                   plane_range({0, 0, -1}, 1)},
                                  place(kCylinderZ)),
                 {{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.25}}, "plane { z, 1 matrix <…, 0,0,0.25> }");
}

// clipped_by on a quadric: the box recomputed from the coefficients at that point within the clip objects' range;
// an inverted clip object does not narrow it; later transforms carry the result.
TEST(QuadricExtent, ClippedBy) {
  expect_printed(clipped_box(place(kParaboloidY), {box_range({-3, -1, -3}, {3, 2, 3})}),
                 {{-1.41421353816986084, 0.0, -1.41421353816986084}, {1.41421353816986084, 2.0, 1.41421353816986084}},
                 "Paraboloid_Y clipped_by a box");
  expect_printed(clipped_box(place(kCylinderY), {plane_range({0, 1, 0}, 1), plane_range({0, -1, 0}, 1)}),
                 {{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}, "Cylinder_Y clipped_by two planes");
  expect_printed(clipped_box(place(kCylinderY, {scale({2, 1, 0.5}), translate({0.25, 0, 0})}),
                             {box_range({-5, -1, -5}, {5, 3, 5})}),
                 {{-1.75, -1.0, -0.5}, {2.25, 3.0, 0.5}},
                 "Cylinder_Y scale <2,1,0.5> translate 0.25*x clipped_by a box");
  expect_printed(
      clipped_box(place(kSphere), {box_range({-5, -0.5, -5}, {5, 3, 5})}).transformed(Matrix::scaling({2, 2, 2})),
      {{-2.0, -1.0, -2.0}, {2.0, 2.0, 2.0}}, "sphere clipped_by a box, then scale 2");
  expect_printed(clipped_box(place(kSphere), {}), {{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}},
                 "sphere clipped_by an inverted box");
}

// Automatic_Bounds: set whenever the computed box is used, which is every quadric without a cross term in
// Parse_Quadric's huge range (even those left with the huge box). POV-Ray 3.7.0.10 showed it by removing a
// bounded_by ("Unnecessary bounding object removed") from the sphere, Cylinder_Y, the two-sheet hyperboloid, the
// saddle and the plane 2y = 0, and keeping it on the sphere with a cross term.
TEST(QuadricExtent, AutomaticBounds) {
  const std::pair<Quadric, bool> cases[] = {
      {kSphere, true},      {quadric({1, 1, 1}, {1, 0, 0}, {}, -1), false},
      {kCylinderY, true},   {quadric({1, 1, -1}, {}, {}, 1), true},
      {kHyperboloid, true}, {quadric({0, 0, 0}, {}, {0, 1, 0}, 0), true},
  };
  for (const auto& [q, automatic] : cases) {
    EXPECT_EQ(parsed_quadric_box(q).computed, automatic);
  }
}

// The plane rule itself: only axis-aligned planes bound, on the side their normal points to.
TEST(QuadricExtent, PlaneMinMax) {
  Vec3 lo, hi;
  plane_min_max({0, 1, 0}, 2, Matrix::identity(), lo, hi);
  EXPECT_EQ(lo, (Vec3{-1e10, -1e10, -1e10}));
  EXPECT_EQ(hi, (Vec3{1e10, 2, 1e10}));
  plane_min_max({0, 0, -1}, 1, Matrix::identity(), lo, hi);
  EXPECT_EQ(lo, (Vec3{-1e10, -1e10, -1}));
  EXPECT_EQ(hi, (Vec3{1e10, 1e10, 1e10}));
  plane_min_max(normalize({1, 1, 0}), 1, Matrix::identity(), lo, hi);   // tilted: no bound
  EXPECT_EQ(lo, (Vec3{-1e10, -1e10, -1e10}));
  EXPECT_EQ(hi, (Vec3{1e10, 1e10, 1e10}));
  plane_min_max({1, 0, 0}, 1, Matrix::rotation({0, 0, 90}), lo, hi);   // x = 1 turned to y = 1
  EXPECT_EQ(hi.y, 1.0);
  EXPECT_EQ(hi.x, 1e10);
  plane_min_max({1, 0, 0}, 1, Matrix::translation({-3, 0, 0}) * Matrix::scaling({0.5, 1, 1}), lo, hi);
  EXPECT_EQ(hi.x, -1.0);   // x = -2, then halved
  // With a Trans: a translation along the normal comes out right, a scale does not (y = 3 bounded at y ≤ 1).
  plane_min_max_with_trans({0, 1, 0}, 1, Matrix::translation({0, 2, 0}), lo, hi);
  EXPECT_EQ(hi.y, 3.0);
  plane_min_max_with_trans({0, 1, 0}, 1, Matrix::scaling({3, 3, 3}), lo, hi);
  EXPECT_EQ(hi.y, -1.0);
}

// The coefficients after a transform: exact for translations and scales of simple quadrics, the surface moved
// with the transform in general.
TEST(QuadricExtent, TransformedCoefficients) {
  Quadric t = transformed_quadric(kSphere, Matrix::translation({1, 2, 3}), TransformKind::translate);
  EXPECT_EQ(t.square, (Vec3{1, 1, 1}));
  EXPECT_EQ(t.mixed, (Vec3{0, 0, 0}));
  EXPECT_EQ(t.linear, (Vec3{-2, -4, -6}));
  EXPECT_EQ(t.constant, 13.0);
  t = transformed_quadric(kSphere, Matrix::scaling({2, 4, 0.5}), TransformKind::scale);
  EXPECT_EQ(t.square, (Vec3{0.25, 0.0625, 4}));
  EXPECT_EQ(t.constant, -1.0);
  // Cylinder_X turned 90° about z is a cylinder along y (the cos 90° residue aside).
  t = transformed_quadric(kCylinderX, Matrix::rotation({0, 0, 90}), TransformKind::rotate);
  EXPECT_NEAR(t.square.x, 1, 1e-15);
  EXPECT_NEAR(t.square.y, 0, 1e-15);
  EXPECT_NEAR(t.square.z, 1, 1e-15);
  EXPECT_NEAR(t.mixed.x, 0, 1e-15);
  // x² turned 45° about z: x²/2 + y²/2 and a cross term of magnitude 1.
  t = transformed_quadric(quadric({1, 0, 0}, {}, {}, 0), Matrix::rotation({0, 0, 45}), TransformKind::rotate);
  EXPECT_NEAR(t.square.x, 0.5, 1e-15);
  EXPECT_NEAR(t.square.y, 0.5, 1e-15);
  EXPECT_NEAR(std::fabs(t.mixed.x), 1, 1e-15);
  // In general: the transformed quadric at a moved point equals the quadric at the original point.
  const Quadric q = quadric({1, -2, 3}, {0.5, -1, 0.25}, {1, 2, -3}, -4);
  const Matrix m = matrix({1, 0.5, 0, 0.2, 1, 0, 0.25, 0, 2, 1, -1, 0.5}).m;
  const Matrix composed =
      Matrix::scaling({2, 1, 0.5}) * Matrix::rotation({10, 20, 30}) * Matrix::translation({1, 2, 3});
  auto value = [](const Quadric& c, Vec3 p) {
    return c.square.x * p.x * p.x + c.square.y * p.y * p.y + c.square.z * p.z * p.z + c.mixed.x * p.x * p.y +
           c.mixed.y * p.x * p.z + c.mixed.z * p.y * p.z + c.linear.x * p.x + c.linear.y * p.y + c.linear.z * p.z +
           c.constant;
  };
  for (const Matrix& x : {m, composed}) {
    const Quadric moved = transformed_quadric(q, x);
    for (const Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 2, 3}, Vec3{-0.5, 0.25, 4}})
      EXPECT_NEAR(value(moved, x.point(p)), value(q, p), 1e-12);
  }
  // The kind only chooses how the inverse is computed.
  const Quadric by_kind = transformed_quadric(q, Matrix::scaling({3, 5, 7}), TransformKind::scale);
  const Quadric by_inverse = transformed_quadric_by_inverse(q, Matrix::scaling({1.0 / 3, 1.0 / 5, 1.0 / 7}));
  EXPECT_EQ(by_kind.square, by_inverse.square);
  EXPECT_EQ(by_kind.mixed, by_inverse.mixed);
  EXPECT_EQ(by_kind.linear, by_inverse.linear);
  EXPECT_EQ(by_kind.constant, by_inverse.constant);
}

}   // namespace
}   // namespace povtrace
