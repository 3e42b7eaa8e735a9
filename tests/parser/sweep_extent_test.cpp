// min_extent() and max_extent() of lathe, sor and prism: the boxes of runtime/sweep_extents.hpp carried by the
// identity, against the values POV-Ray 3.7.0.10 printed for the same objects. Each object was declared as written
// here (#declare O = ...) in a #version 3.7 scene and printed with
//   #debug concat(str(min_extent(O).x, 0, 17), "\n")   (and so on for each coordinate of both corners)
// rendered with `povray +W8 +H8 -D`. POV-Ray's box is single precision, so every value is a float and must match
// exactly. The cases cover each spline kind, linear and conic prism sweeps, open and closed shapes, profiles whose
// extremes lie inside a segment (so the turning points decide), negative lathe radii, and NaN sor radii.
#include <gtest/gtest.h>

#include <variant>

#include "parse_helpers.hpp"
#include "runtime/sweep_extents.hpp"

namespace povtrace::test {
namespace {

struct ExtentCase {
  const char* sdl;   // the object as declared
  Vec3 min, max;     // min_extent(O), max_extent(O) printed by POV-Ray 3.7.0.10
};

// The one object `sdl` describes.
Object object_of(const std::string& sdl) {
  const SceneDescription scene = parse("#version 3.7;\n" + sdl + "\n");
  EXPECT_EQ(scene.objects.size(), 1u) << sdl;
  return scene.objects.at(0);
}

// Make_BBox of the shape, then Recompute_BBox with the object's transform, as min_extent() sees it.
ExtentBox extent_box(const Object& o) {
  ExtentBox local;
  if (const auto* l = std::get_if<Lathe>(&o.shape)) local = lathe_local_box(*l);
  else if (const auto* s = std::get_if<Sor>(&o.shape)) local = sor_local_box(*s);
  else if (const auto* p = std::get_if<Prism>(&o.shape)) local = prism_local_box(*p);
  else ADD_FAILURE() << "not a lathe, sor or prism";
  return local.transformed(o.world_from_object);
}

// min_extent() and max_extent() of the object `sdl` declares, coordinate by coordinate.
void expect_extents(const std::string& sdl, Vec3 min, Vec3 max) {
  SCOPED_TRACE(sdl);
  const ExtentBox box = extent_box(object_of(sdl));
  EXPECT_EQ(box.lo().x, min.x);
  EXPECT_EQ(box.lo().y, min.y);
  EXPECT_EQ(box.lo().z, min.z);
  EXPECT_EQ(box.max_extent().x, max.x);
  EXPECT_EQ(box.max_extent().y, max.y);
  EXPECT_EQ(box.max_extent().z, max.z);
}

// Untransformed objects: the local box carried by the identity, which POV-Ray applies too.
void expect_povray_extents(const std::vector<ExtentCase>& cases) {
  for (const ExtentCase& c : cases) {
    EXPECT_EQ(object_of(c.sdl).world_from_object, Matrix::identity()) << c.sdl;
    expect_extents(c.sdl, c.min, c.max);
  }
}

TEST(SweepExtents, LatheBoxesMatchPovRay) {
  expect_povray_extents({
    // end points only
    {"lathe { linear_spline 4, <0,0>, <1,0.5>, <0.8,1.5>, <0,2> }",
     {-1.0, 0.0, -1.0},
     {1.0, 2.0, 1.0}},
    // the end points may have x < 0; the box takes the largest x
    {"lathe { linear_spline 4, <-1,-0.25>, <0.6,0.5>, <0.75,1.5>, <-0.3,2.1> }",
     {-0.75, -0.25, -0.75},
     {0.75, 2.09999990463256836, 0.75}},
    // every radius negative: Radius2 < 0 gives negative lengths, turned round by Recompute_BBox
    {"lathe { linear_spline 2, <-1,0.1>, <-0.45,1.3> }",
     {-0.44999998807907104, 0.10000000149011612, -0.44999998807907104},
     {0.44999998807907104, 1.30000007152557373, 0.44999998807907104}},
    {"lathe { quadratic_spline 5, <0,-0.5>, <0.5,0>, <1.2,1>, <0.4,2>, <0,3.1> }",
     {-1.20000004768371582, 0.0, -1.20000004768371582},
     {1.20000004768371582, 3.09999990463256836, 1.20000004768371582}},
    // the height peaks inside the segment (a turning point of y)
    {"lathe { quadratic_spline 4, <0,0>, <1,1>, <1.5,0.2>, <0.5,-0.6> }",
     {-1.5, -0.60000002384185791, -1.5},
     {1.5, 1.00277769565582275, 1.5}},
    // the radius peaks inside the segment (a turning point of x)
    {"lathe { quadratic_spline 4, <-2,-1>, <0.3,0.1>, <0.9,1.1>, <0.2,2.3> }",
     {-0.91838234663009644, 0.10000000149011612, -0.91838234663009644},
     {0.91838234663009644, 2.29999995231628418, 0.91838234663009644}},
    {"lathe { cubic_spline 6, <0,0>,<1,0.2>,<1.5,1>,<0.5,1.7>,<1,2.5>,<0,3> }",
     {-1.51305127143859863, 0.20000000298023224, -1.51305127143859863},
     {1.51305127143859863, 2.5, 1.51305127143859863}},
    // the Catmull-Rom radius overshoots its end points
    {"lathe { cubic_spline 5, <0,-2>, <0.3,0>, <1.7,0.2>, <0.4,0.4>, <0.1,3> }",
     {-1.70019614696502686, 0.0, -1.70019614696502686},
     {1.70019614696502686, 0.40000000596046448, 1.70019614696502686}},
    // negative slope points, radius peak inside
    {"lathe { cubic_spline 4, <-2,0>, <0.5,0.5>, <0.7,1.5>, <-2,2> }",
     {-0.93920648097991943, 0.5, -0.93920648097991943},
     {0.93920648097991943, 1.5, 0.93920648097991943}},
    // all control points count, on the curve or not
    {"lathe { bezier_spline 8, <0,0>,<2,0.3>,<1.5,1.2>,<1,1>, <1,1>,<0.5,0.8>,<1.8,2>,<0,2.2> }",
     {-2.0, 0.0, -2.0},
     {2.0, 2.20000004768371582, 2.0}},
    {"lathe { bezier_spline 4, <-0.5,0>,<0.3,-0.4>,<0.9,1.3>,<-0.1,1.7> }",
     {-0.89999997615814209, -0.40000000596046448, -0.89999997615814209},
     {0.89999997615814209, 1.69999992847442627, 0.89999997615814209}},
    // no segment: the initial ±BOUND_HUGE ranges, clipped to ±1e10
    {"lathe { bezier_spline 0 }",
     {-10000000000.0, -10000000000.0, -10000000000.0},
     {10000000000.0, 10000000000.0, 10000000000.0}},
  });
}

TEST(SweepExtents, SorBoxesMatchPovRay) {
  expect_povray_extents({
    // the radius peaks inside a segment (√r² at a turning point of r²)
    {"sor { 5, <0,0>, <1,0.2>, <0.5,1>, <1.2,2>, <0,3> }",
     {-1.20837152004241943, 0.20000000298023224, -1.20837152004241943},
     {1.20837152004241943, 2.0, 1.20837152004241943}},
    {"sor { 6, <0.2,-1>, <0.8,0>, <0.3,0.5>, <1.5,1.5>, <0.6,2>, <1,3> open }",
     {-1.50125527381896973, 0.0, -1.50125527381896973},
     {1.50125527381896973, 2.0, 1.50125527381896973}},
    {"sor { 4, <2,-1>, <0.9,0>, <0.9,1>, <2,2> }",
     {-0.89999997615814209, 0.0, -0.89999997615814209},
     {0.89999997615814209, 1.0, 0.89999997615814209}},
    // the radius narrows inside a segment (a turning point of r² below both end radii): the box only takes the
    // largest radius
    {"sor { 6, <0,-0.3>, <0.05,0>, <0.9,0.1>, <0.05,0.2>, <0.6,1>, <0,1.2> }",
     {-0.89999997615814209, 0.0, -0.89999997615814209},
     {0.89999997615814209, 1.0, 0.89999997615814209}},
    // r² < 0 at its one turning point: NaN in the first candidate, so the only segment drops out and Radius2 stays
    // −BOUND_HUGE (the box is then clipped to ±1e10)
    {"sor { 4, <20,-0.1>, <0.1,0>, <0.1,1>, <20,1.1> }",
     {-10000000000.0, 0.0, -10000000000.0},
     {10000000000.0, 1.0, 10000000000.0}},
    // r² < 0 at a turning point whose NaN is passed over
    {"sor { 4, <20,-0.1>, <0.1,0>, <0.2,1>, <6,1.1> }",
     {-0.20000000298023224, 0.0, -0.20000000298023224},
     {0.20000000298023224, 1.0, 0.20000000298023224}},
    // as above, in the second segment
    {"sor { 5, <0.5,-1>, <0.3,0>, <0.1,1>, <0.1,1.5>, <12,1.6> }",
     {-0.30000001192092896, 0.0, -0.30000001192092896},
     {0.30000001192092896, 1.5, 0.30000001192092896}},
  });
}

TEST(SweepExtents, PrismBoxesMatchPovRay) {
  expect_povray_extents({
    {"prism { linear_sweep linear_spline 0, 1, 4, <0,0>, <2,0>, <1,1.5>, <0,0> }",
     {0.0, 0.0, 0.0},
     {2.0, 1.0, 1.5}},
    // POV-Ray appends the closing point
    {"prism { -0.5, 2, 3, <-1,-1>, <1.5,-0.5>, <0,2> }",
     {-1.0, -0.5, -1.0},
     {1.5, 2.0, 2.0}},
    // two sub-outlines
    {"prism { 0, 1, 8, <0,0>, <3,0>, <0,3>, <0,0>, <-1,-1>, <-2,-1>, <-1,-2.5>, <-1,-1> open }",
     {-2.0, 0.0, -2.5},
     {3.0, 1.0, 3.0}},
    {"prism { quadratic_spline 0.1, 0.7, 6, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0> }",
     {-1.0, 0.10000000149011612, -1.0},
     {1.0, 0.70000004768371582, 1.0}},
    // the outline bulges inside segments (turning points of x and z)
    {"prism { quadratic_spline -0.2, 0.4, 5, <0.5,1>, <0,-1>, <1.5,0.2>, <0,1>, <0,-1> }",
     {-0.1875, -0.20000000298023224, -1.02499997615814209},
     {1.5, 0.40000003576278687, 1.00000011920928955}},
    {"prism { cubic_spline -1, 1.3, 7, <0.5,-1>, <1,0>, <0.2,0.8>, <-1.1,0.1>, <-0.3,-0.9>, <1,0>, <0.2,0.8> }",
     {-1.10871052742004395, -1.0, -0.90032267570495605},
     {1.0, 1.29999995231628418, 0.80046677589416504}},
    // a prism's Bézier segments run backwards; all control points count
    {"prism { bezier_spline 0, 1, 8, <0,0>, <1.5,-0.6>, <1.6,1.9>, <0.5,1>, <0.5,1>, <-0.7,0.3>, <-0.4,-0.8>, <0,0> }",
     {-0.69999998807907104, 0.0, -0.80000001192092896},
     {1.59999990463256836, 1.0, 1.90000009536743164}},
    // degenerate (never hit), but POV-Ray still computes its box
    {"prism { bezier_spline 0, 1, 4, <0,0>, <1,-1>, <2,1>, <0.5,0.2> }",
     {0.0, 0.0, -1.0},
     {2.0, 1.0, 1.0}},
    // conic: the rectangle scaled by both heights
    {"prism { conic_sweep linear_spline 0.2, 1, 4, <-1,-0.5>, <1.5,0.3>, <0.2,1>, <-1,-0.5> }",
     {-1.0, 0.20000000298023224, -0.5},
     {1.5, 1.0, 1.0}},
    // the heights given in decreasing order are sorted
    {"prism { conic_sweep quadratic_spline 1, 0.25, 6, <0,-1>, <1.3,0>, <0,1>, <-0.7,0>, <0,-1>, <1.3,0> open }",
     {-0.69999998807907104, 0.25, -1.0},
     {1.29999995231628418, 1.0, 1.0}},
    // a negative height flips the scaled rectangle
    {"prism { conic_sweep linear_spline -0.5, 0.75, 4, <0,-1>, <1,1>, <-2,0.5>, <0,-1> }",
     {-1.5, -0.5, -0.75},
     {1.0, 0.75, 0.75}},
    {"prism { conic_sweep cubic_spline 0.5, 2, 6, <-1,-1>, <1,-1>, <1.4,1>, <-1,1>, <1,-1>, <1,-1> open }",
     {-2.00374531745910645, 0.5, -2.0},
     {3.0728919506072998, 2.0, 2.5}},
    {"prism { conic_sweep bezier_spline 0.3, 1.1, 4, <0,0>, <1,-1>, <2,1>, <0,0> }",
     {0.0, 0.30000001192092896, -1.10000002384185791},
     {2.20000004768371582, 1.10000002384185791, 1.10000002384185791}},
  });
}

// The caller carries the local box by the object's transform, as POV-Ray's Recompute_BBox does with Trans (printed
// by POV-Ray 3.7.0.10 in the same way).
TEST(SweepExtents, TransformedBoxesMatchPovRay) {
  const ExtentCase cases[] = {
      {"lathe { cubic_spline 6, <0,0>,<1,0.2>,<1.5,1>,<0.5,1.7>,<1,2.5>,<0,3> rotate <20, 30, 0> "
       "translate <1, -2, 0.5> }",
       {-0.98704040050506592, -2.32955551147460938, -1.4286036491394043},
       {3.44876766204833984, 0.86672544479370117, 3.22833871841430664}},
      {"prism { conic_sweep cubic_spline 0.5, 2, 6, <-1,-1>, <1,-1>, <1.4,1>, <-1,1>, <1,-1>, <1,-1> open "
       "scale <1, 2, 0.5> rotate 40*y }",
       {-2.17774558067321777, 1.0, -2.74126124382019043},
       {3.1574561595916748, 4.0, 2.24553847312927246}},
  };
  for (const ExtentCase& c : cases) expect_extents(c.sdl, c.min, c.max);
}

// Where POV-Ray and povtrace differ. The turning points of a sor's r² are solved by the quadratic povtrace shares
// between parser and renderer (runtime/quadratic_roots.hpp), which returns the root of larger magnitude first;
// POV-Ray's solve_quadratic returns the larger root first. The two orders differ when the roots' sum is negative,
// and the order only matters when r² < 0 at the turning point in range: its NaN radius then lands in the first
// candidate in POV-Ray (the segment drops out; here the only one, so POV-Ray's Radius2 stays −BOUND_HUGE and it
// prints the ±1e10 box, and renders no side surface) but in the second one here (passed over: the end radii give
// the box). Kept so that the renderer's sor rings stay as they were; this test changes with that order.
// r² is negative at the larger turning point, inside the segment: POV-Ray's solve_quadratic returns that root first,
// so its NaN radius poisons the segment's range, which drops out, and the sor keeps the huge box.
TEST(SweepExtents, SorNanAtTheLargerTurningPoint) {
  expect_extents("sor { 4, <6,-0.1>, <0.2,0>, <0.1,1>, <20,1.1> }", {-1e10, 0.0, -1e10}, {1e10, 1.0, 1e10});
}

}  // namespace
}  // namespace povtrace::test
