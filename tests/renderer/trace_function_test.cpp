// trace() and inside() at parse time through the renderer's geometry (scene/object_geometry.hpp,
// renderer/object_geometry.cpp). The expected values are POV-Ray 3.7.0.10's own: the same scene lines run through
// `povray` printed them with vstr(3, V, ",", 0, 17).
#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "renderer/object_geometry.hpp"
#include "tests/parser/parse_helpers.hpp"

namespace povtrace::test {
namespace {

ParseOptions with_geometry(Messages& messages) {
  ParseOptions o = options_into(messages);
  o.object_geometry = std::make_shared<render::RendererGeometry>();
  return o;
}

// The #debug output of `body` after a few shared declarations, with the renderer's geometry.
std::string traced(const std::string& body, Messages* warnings = nullptr) {
  Messages m;
  const std::string scene = "#version 3.7;\n#include \"shapes.inc\"\n#declare N = <0,0,0>;\n"
                            "#macro Show(P, N) #debug concat(vstr(3,P,\",\",0,17), \" \", vstr(3,N,\",\",0,17), \"\\n\") #end\n" +
                            body;
  parse_scene_text(scene, "trace.pov", with_geometry(m));
  std::string out;
  for (const auto& item : m.items) {
    if (item.find("warning") != std::string::npos) {
      if (warnings) warnings->items.push_back(item);
    } else {
      out += item;
    }
  }
  return out;
}

// Six numbers "x,y,z x,y,z" (point and normal) from one line of Show().
std::array<double, 6> numbers(const std::string& line) {
  std::array<double, 6> v{};
  std::string s = line;
  for (char& c : s)
    if (c == ',') c = ' ';
  std::istringstream in(s);
  for (double& x : v) in >> x;
  return v;
}

// Point and normal equal to POV-Ray's to `tolerance` (its output has 17 digits).
void expect_trace(const std::string& body, const std::array<double, 6>& povray, double tolerance = 1e-12) {
  const std::array<double, 6> got = numbers(traced(body));
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(got[i], povray[i], tolerance) << body << " value " << i;
}

TEST(TraceFunction, SphereHitPointAndOutwardNormal) {
  expect_trace("#declare S = sphere { <0,1,0>, 1 }\n#declare P = trace(S, <0,5,0>, -y, N); Show(P, N)\n",
               {0, 2, 0, 0, 1, 0}, 0.0);
}

TEST(TraceFunction, DirectionIsNormalisedAndTransformsApply) {
  expect_trace("#declare T = torus { 2, 0.5 rotate 30*x translate <0.3,0.2,0.1> }\n"
               "#declare P = trace(T, <2.1,5,0.3>, <0.1,-1,0.05>, N); Show(P, N)\n",
               {2.55612699273473343, 0.43873007265266573, 0.52806349636736671, 0.53684841454795040,
                0.69890457777435799, 0.47257398464515449},
               1e-11);
}

TEST(TraceFunction, ADifferenceGivesTheInvertedChildsNormalReversed) {
  expect_trace("#declare D = difference { box { -1, 1 } sphere { <0,1,0>, 0.8 } }\n"
               "#declare P = trace(D, <0.1,5,0.2>, -y, N); Show(P, N)\n",
               {0.10000000000000001, 0.23188542521313948, 0.20000000000000001, -0.125, 0.96014321848357564, -0.25});
}

TEST(TraceFunction, AMissGivesZeroPointAndZeroNormal) {
  expect_trace("#declare N = <7,7,7>;\n#declare D = box { -1, 1 }\n#declare P = trace(D, <3,5,0.2>, -y, N); Show(P, N)\n",
               {0, 0, 0, 0, 0, 0}, 0.0);
}

TEST(TraceFunction, HitsCloserThanMinIsectDepthAreIgnored) {
  // From a point on the surface: outward meets nothing, inward the far side.
  expect_trace("#declare S = sphere { 0, 1 }\n#declare P = trace(S, <0,0,-1>, -z, N); Show(P, N)\n",
               {0, 0, 0, 0, 0, 0}, 0.0);
  expect_trace("#declare S = sphere { 0, 1 }\n#declare P = trace(S, <0,0,-1>, z, N); Show(P, N)\n",
               {0, 0, 1, 0, 0, 1}, 0.0);
}

TEST(TraceFunction, InverseObjectsReverseTheNormal) {
  expect_trace("#declare Inv = sphere { 0, 2 inverse }\n#declare P = trace(Inv, <0.5,0.2,0>, <1,1,1>, N); Show(P, N)\n",
               {1.40293736993728757, 1.10293736993728753, 0.90293736993728757, -0.70146868496864379,
                -0.55146868496864376, -0.45146868496864379});
  expect_trace("#declare Inv = sphere { 0, 2 inverse }\n#declare P = trace(Inv, <0,0,-5>, z, N); Show(P, N)\n",
               {0, 0, -2, 0, 0, 1}, 0.0);
}

TEST(TraceFunction, MeshesPlanesAndSmoothTriangles) {
  const std::string mesh = "#declare M = mesh { triangle { <-1,0,-1>, <1,0,-1>, <0,0,1> } smooth_triangle { <-1,0,-1>, "
                           "<0,1,0>, <1,0,-1>, <0.3,1,0>, <0,0.5,-2>, <0,1,0.2> } translate y }\n";
  expect_trace(mesh + "#declare P = trace(M, <0.1,5,0.2>, -y, N); Show(P, N)\n", {0.1, 1, 0.2, 0, 1, 0}, 1e-15);
  // POV-Ray keeps a mesh's vertex normals in single precision: its interpolated normal differs from the
  // double-precision one in the ninth digit.
  expect_trace(mesh + "#declare P = trace(M, <0.1,5,-1.2>, -y, N); Show(P, N)\n",
               {0.10000000000000001, 1.09999999999999964, -1.19999999999999996, 0.13108449665645319,
                0.99057346778065813, 0.03976254098175421},
               1e-8);
  expect_trace("#declare Pl = plane { y, -1 rotate 10*z }\n"
               "#declare P = trace(Pl, <0.3,5,0.2>, <0.1,-1,0.3>, N); Show(P, N)\n",
               {0.88592147530012832, -0.85921475300128414, 1.95776442590038524, -0.17364817766693033,
                0.98480775301220802, 0});
}

TEST(TraceFunction, CsgClipsAndUnions) {
  expect_trace("#declare Cl = sphere { 0, 1 clipped_by { plane { y, 0.5 } } }\n"
               "#declare P = trace(Cl, <0.1,5,0.1>, -y, N); Show(P, N)\n",
               {0.10000000000000001, -0.98994949366116458, 0.10000000000000001, 0.10000000000000001,
                -0.98994949366116458, 0.10000000000000001});
  expect_trace("#declare U = union { sphere { <-1,0,0>, 0.7 } box { <0.5,-0.5,-0.5>, <1.5,0.5,0.5> } scale 2 "
               "rotate 20*y }\n#declare P = trace(U, <2,5,0>, -y, N); Show(P, N)\n",
               {2, 1, 0, 0, 1, 0});
  expect_trace("#declare I = intersection { sphere { 0, 1 } cylinder { -2*z, 2*z, 0.5 } }\n"
               "#declare P = trace(I, <0.2,5,0.1>, -y, N); Show(P, N)\n",
               {0.20000000000000001, 0.45825756949558460, 0.10000000000000001, 0.39999999999999941,
                0.91651513899116821, -0.00000000000000011});
}

// A height field's inside goes on below its bottom, so a cylinder clipped by one keeps its wall there; POV-Ray's
// box for the clipped cylinder is the height field's (its volume is the smaller), which this ray meets.
TEST(TraceFunction, AShapeClippedByAHeightFieldKeepsItsSurfaceBelowTheBottom) {
  expect_trace("#declare C = cylinder { -10*y, 10*y, 1 clipped_by { height_field { png \"plasma2.png\" "
               "translate <-0.5,0,-0.5> scale <6,2,6> } } }\n"
               "#declare P = trace(C, <0,6,-6>, <0,-6.5,5>, N); Show(P, N)\n",
               {0, -0.5, -1, 0, 0, -1});
}

TEST(TraceFunction, SolidsAndSweeps) {
  expect_trace("#declare B = blob { threshold 0.5 sphere { 0, 1, 1 } sphere { <0.7,0,0>, 1, 1 } }\n"
               "#declare P = trace(B, <0.3,5,0.1>, -y, N); Show(P, N)\n",
               {0.29999999999999999, 0.60516650957635587, 0.10000000000000001, -0.04143954627662923,
                0.98577313554589108, 0.16289287657969989});
  expect_trace("#declare Iso = isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } } "
               "max_gradient 4 }\n#declare P = trace(Iso, <0.3,5,0.1>, -y, N); Show(P, N)\n",
               {0.29999999999999999, 0.94824218750000000, 0.10000000000000001, 0.30042306574429484,
                0.94849928974948983, 0.10047426990783534});
  expect_trace("#declare L = lathe { linear_spline 3, <0,0>, <1,1>, <0,2> }\n"
               "#declare P = trace(L, <5,0.5,0.1>, -x, N); Show(P, N)\n",
               {0.48989794855663416, 0.5, 0.10000000000000001, 0.69282032302755081, -0.70710678118654757,
                0.14142135623730992});
  expect_trace("#declare Sq = superellipsoid { <0.5, 0.3> rotate 10*x }\n"
               "#declare P = trace(Sq, <0.2,5,0.1>, -y, N); Show(P, N)\n",
               {0.20000000000000001, 0.99738749453462461, 0.10000000000000001, 0.00800935665948276,
                0.98477623669652148, 0.17364220064183111});
  expect_trace("#declare Tx = text { ttf \"timrom.ttf\" \"H\" 1, 0 }\n"
               "#declare P = trace(Tx, <0.1,0.3,-5>, z, N); Show(P, N)\n",
               {0.10000000000000001, 0.29999999999999999, 0.00000349053665705, -0.00001745359713116,
                0.00001745298789898, -0.99999999969538256});
}

TEST(TraceFunction, TheNormalGoesIntoArrayElementsAndThroughMacroAliases) {
  expect_trace("#declare S = sphere { <0,1,0>, 1 }\n#declare A = array[2] { <0,0,0>, <0,0,0> }\n"
               "#declare P = trace(S, <0,5,0>, -y, A[1]); Show(P, A[1])\n",
               {0, 2, 0, 0, 1, 0}, 0.0);
  // shapes.inc's IsectN passes a #local through trace() and returns it through its parameters.
  expect_trace("#declare S = sphere { 0, 1 }\n#declare Q = <9,9,9>;\n"
               "#if (IsectN(<0,0,-5>, z, S, Q, N)) Show(Q, N) #end\n",
               {0, 0, -1, 0, 0, -1}, 0.0);
  expect_trace("#declare S = sphere { 0, 1 }\n#declare Q = <9,9,9>;\n#declare N = <1,2,3>;\n"
               "#if (IsectN(<0,3,-5>, z, S, Q, N)) #else Show(Q, N) #end\n",
               {9, 9, 9, 1, 2, 3}, 0.0);
}

TEST(TraceFunction, AZeroDirectionMeetsNothingWithAWarning) {
  Messages warnings;
  const std::string out =
      traced("#declare S = sphere { 0, 1 }\n#declare P = trace(S, <0,0,-3>, 0, N); Show(P, N)\n", &warnings);
  const std::array<double, 6> v = numbers(out);
  for (double x : v) EXPECT_EQ(x, 0.0);
  ASSERT_EQ(warnings.items.size(), 1u);
  EXPECT_NE(warnings.items[0].find("trace.pov:6:33: warning: trace() with a zero or non-finite direction"),
            std::string::npos)
      << warnings.items[0];
}

TEST(TraceFunction, TheFourthArgumentMustBeAVectorIdentifier) {
  ParseOptions o;
  o.object_geometry = std::make_shared<render::RendererGeometry>();
  const ParseError f = parse_error("#declare S = sphere { 0, 1 }\n#declare F = 1;\n#declare P = trace(S, 5*y, -y, F);\n", o);
  EXPECT_EQ(f.location().line, 3);
  EXPECT_EQ(f.location().column, 32);
  EXPECT_NE(f.bare_message().find("a declared 3-D vector identifier to receive trace()'s normal (F holds a float)"),
            std::string::npos)
      << f.bare_message();
  const ParseError u = parse_error("#declare S = sphere { 0, 1 }\n#declare P = trace(S, 5*y, -y, Undeclared);\n", o);
  EXPECT_EQ(u.location().column, 32);
  const ParseError notobject = parse_error("#declare V = <1,2,3>;\n#declare P = trace(V, 5*y, -y);\n", o);
  EXPECT_NE(notobject.bare_message().find("an object identifier in trace()"), std::string::npos);
}

TEST(TraceFunction, UnsupportedGeometryIsRefusedByName) {
  ParseOptions o;
  o.object_geometry = std::make_shared<render::RendererGeometry>();
  const ParseError e = parse_error("#declare B = sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, 1 }\n"
                                   "#declare P = trace(B, 5*y, -y);\n",
                                   o);
  EXPECT_NE(e.bare_message().find("trace() of the shape 'sphere_sweep'"), std::string::npos) << e.bare_message();
}

// A flat bicubic_patch in z = 0 over [0, 3]²: trace() meets it where the ray crosses the plane, normal ±z.
TEST(TraceFunction, BicubicPatch) {
  const std::string out = traced(
      "#declare B = bicubic_patch { type 1 u_steps 2 v_steps 2 "
      "<0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>,<0,1,0>,<1,1,0>,<2,1,0>,<3,1,0>,"
      "<0,2,0>,<1,2,0>,<2,2,0>,<3,2,0>,<0,3,0>,<1,3,0>,<2,3,0>,<3,3,0> }\n"
      "#declare N = <0, 0, 0>;\n#declare P = trace(B, <1.25, 0.5, 5>, -z, N);\n"
      "#debug concat(vstr(3, P, \",\", 0, 3), \" \", str(abs(N.z), 0, 3), \"\\n\")\n");
  EXPECT_EQ(out, "1.250,0.500,0.000 1.000\n");
}

TEST(InsideFunction, ShapesThatOnlyTheRendererTestsAskItsGeometry) {
  const std::string out = traced(
      "#declare Cy = cylinder { 0, y, 1 scale <1,2,0.5> }\n#declare To = torus { 1, 0.25 }\n"
      "#debug concat(str(inside(Cy, <0.1,1,0.1>),0,0), str(inside(Cy, <0.1,1,0.6>),0,0), "
      "str(inside(To, <1,0,0>),0,0), str(inside(To, <0,0,0>),0,0), \"\\n\")\n");
  EXPECT_EQ(out, "1010\n");   // POV-Ray prints the same
}

}  // namespace
}  // namespace povtrace::test
