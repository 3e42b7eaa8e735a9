// min_extent() and max_extent() of every kind of object, through the parser with the renderer's geometry (a height
// field's samples are the renderer's to read). The expected lines are POV-Ray 3.7.0.10's own output for the same
// scenes (vstr(3, V, ",", 0, 9)): single-precision boxes made, carried through later transforms, narrowed by clip
// and bounding objects and combined by CSG as POV-Ray does (parser/extents/object_extents.cpp).
#include <string>

#include <gtest/gtest.h>

#include "renderer/object_geometry.hpp"
#include "tests/parser/parse_helpers.hpp"

namespace povtrace::test {
namespace {

std::string extents(const std::string& body) {
  Messages m;
  ParseOptions o = options_into(m);
  o.object_geometry = std::make_shared<render::RendererGeometry>();
  parse_scene_text("#version 3.7;\n#macro V(S, P) #debug concat(S, \" \", vstr(3, P, \",\", 0, 9), \"\\n\") #end\n"
                   "#macro E(S, O) V(concat(S, \" min\"), min_extent(O)) V(concat(S, \" max\"), max_extent(O)) #end\n" +
                       body,
                   "extents.pov", o);
  std::string out;
  for (const auto& item : m.items)
    if (item.find("warning") == std::string::npos) out += item;
  return out;
}

// Superellipsoid and isosurface (their cube and container carried by the whole transform), blobs (the spheres
// bounding their elements of positive strength, made after the blob's own modifiers, then carried), meshes and
// unions carried through two rotations, intersections (planes as half spaces, inverted children left out),
// differences, clip and bounding objects, polys (huge; a clipped one moved takes its clip's box), text, a light
// source in a union, an inverted intersection.
TEST(Extents, OfEveryShapeAsPovRayComputesThem) {
  EXPECT_EQ(extents(
                  "#declare SE = superellipsoid { <0.5, 2> scale <1,2,3> rotate 30*y translate x };\n"
                  "E(\"se\", SE)\n"
                  "#declare IS1 = isosurface { function { x*x+y*y+z*z-1 } contained_by { box { <-1,-2,-3>, <1,2,3> } } rotate 45*z };\n"
                  "E(\"is1\", IS1)\n"
                  "#declare IS2 = isosurface { function { x } contained_by { sphere { <1,2,3>, 0.7 } } };\n"
                  "E(\"is2\", IS2)\n"
                  "#declare BL1 = blob { threshold 0.5 sphere { <0,0,0>, 1, 1 } sphere { <2,0,0>, 0.5, -1 } sphere { <0,1,0>, 0.8, 2 translate z rotate 20*x } };\n"
                  "E(\"bl1\", BL1)\n"
                  "#declare BL2 = blob { sphere { 0, 1, 1 scale <1,2,1> rotate 30*z } cylinder { <0,0,0>, <1,2,3>, 0.5, 1 } scale 2 };\n"
                  "E(\"bl2\", BL2)\n"
                  "#declare BL3 = object { BL2 rotate 30*y rotate 40*x };\n"
                  "E(\"bl3\", BL3)\n"
                  "#declare M1 = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,2> } triangle { <1,1,1>, <2,-1,0>, <0,3,1> } };\n"
                  "E(\"m1\", M1)\n"
                  "#declare M2 = object { M1 rotate 30*y rotate 40*x };\n"
                  "E(\"m2\", M2)\n"
                  "#declare U1 = union { sphere { 0, 1 } box { 0, <3,0.5,0.5> } };\n"
                  "#declare U2 = object { U1 rotate 30*y rotate 40*x };\n"
                  "E(\"u2\", U2)\n"
                  "#declare I1 = intersection { box { -1, 1 } sphere { x, 1.5 } plane { y, 0.5 } plane { -x, 0.25 } };\n"
                  "E(\"i1\", I1)\n"
                  "#declare I2 = intersection { sphere { 0, 2 } box { 0, 3 inverse } plane { z, 1 rotate 90*x } };\n"
                  "E(\"i2\", I2)\n"
                  "#declare D1 = difference { box { -2, 2 } sphere { 0, 1 } box { 0, 5 } };\n"
                  "E(\"d1\", D1)\n"
                  "#declare C1 = sphere { 0, 2 clipped_by { box { -1, <1, 0.5, 3> } } };\n"
                  "E(\"c1\", C1)\n"
                  "#declare C2 = box { -3, 3 bounded_by { sphere { x, 1 } } clipped_by { sphere { -x, 1.5 } } };\n"
                  "E(\"c2\", C2)\n"
                  "#declare C3 = object { C1 rotate 45*z };\n"
                  "E(\"c3\", C3)\n"
                  "#declare UC = union { sphere { 0, 1 } sphere { 2*x, 1 } clipped_by { box { <-0.5,-2,-2>, <5, 0.25, 2> } } rotate 10*z };\n"
                  "E(\"uc\", UC)\n"
                  "#declare PO = poly { 2, <1,0,0,0,1,0,0,1,0,-1> };\n"
                  "E(\"po\", PO)\n"
                  "#declare PO2 = quartic { <1,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,-1> clipped_by { sphere { 0, 2 } } };\n"
                  "E(\"po2\", PO2)\n"
                  "#declare PO3 = object { PO2 translate x };\n"
                  "E(\"po3\", PO3)\n"
                  "#declare TX = text { internal 1 \"Hi\" 0.2, 0 rotate 30*x rotate 20*y };\n"
                  "E(\"tx\", TX)\n"
                  "#declare UL = union { sphere { 0, 1 } light_source { <5,5,5> color 1 } };\n"
                  "E(\"ul\", UL)\n"
                  "#declare INV = intersection { sphere { 0, 1 } sphere { x, 1 } inverse };\n"
                  "E(\"inv\", INV)\n"
                  "#declare II = intersection { union { sphere { 0, 1 } sphere { 3*x, 1 } inverse } sphere { x, 1.2 } };\n"
                  "E(\"ii\", II)\n"),
                  "se min -1.366262078,-2.000200033,-3.098386049\n"
                  "se max 3.366261959,2.000200033,3.098386049\n"
                  "is1 min -2.121320248,-2.121320248,-3.000000000\n"
                  "is1 max 2.121320248,2.121320248,3.000000000\n"
                  "is2 min 0.300000012,1.299999952,2.299999952\n"
                  "is2 max 1.700000048,2.699999809,3.699999809\n"
                  "bl1 min -1.000000000,-1.000000000,-1.000000000\n"
                  "bl1 max 1.000000000,1.397672415,2.081712723\n"
                  "bl2 min -5.210590363,-4.464101791,-4.464101791\n"
                  "bl2 max 7.210590363,8.210590363,9.210590363\n"
                  "bl3 min -6.744554520,-10.221614838,-8.592832565\n"
                  "bl3 max 10.849849701,11.092149734,13.383871078\n"
                  "m1 min 0.000000000,-1.000000000,0.000000000\n"
                  "m1 max 2.000000000,3.000000000,2.000000000\n"
                  "m2 min 0.000000000,-1.879385352,-1.408832073\n"
                  "m2 max 2.732050896,2.940920830,3.255190849\n"
                  "u2 min -1.366025448,-1.644108653,-2.455268145\n"
                  "u2 max 3.098076344,2.286896229,1.689224005\n"
                  "i1 min -0.250000000,-1.000000000,-1.000000000\n"
                  "i1 max 1.000000000,0.500000000,1.000000000\n"
                  "i2 min -2.000000000,-1.000000000,-2.000000000\n"
                  "i2 max 2.000000000,2.000000000,2.000000000\n"
                  "d1 min -2.000000000,-2.000000000,-2.000000000\n"
                  "d1 max 2.000000000,2.000000000,2.000000000\n"
                  "c1 min -1.000000000,-1.000000000,-1.000000000\n"
                  "c1 max 1.000000000,0.500000000,3.000000000\n"
                  "c2 min 0.000000000,-1.000000000,-1.000000000\n"
                  "c2 max 2.000000000,1.000000000,1.000000000\n"
                  "c3 min -1.060660124,-1.414213538,-1.000000000\n"
                  "c3 max 1.414213657,1.060660243,3.000000000\n"
                  "uc min -1.158455968,-1.158455968,-1.000000000\n"
                  "uc max 3.128071308,1.505752206,1.000000000\n"
                  "po min -10000000000.000000000,-10000000000.000000000,-10000000000.000000000\n"
                  "po max 10000000000.000000000,10000000000.000000000,10000000000.000000000\n"
                  "po2 min -2.000000000,-2.000000000,-2.000000000\n"
                  "po2 max 2.000000000,2.000000000,2.000000000\n"
                  "po3 min -1.000000000,-2.000000000,-2.000000000\n"
                  "po3 max 3.000000000,2.000000000,2.000000000\n"
                  "tx min -0.000017421,-0.100009598,-0.338275582\n"
                  "tx max 1.107628703,0.602777719,0.489795536\n"
                  "ul min -10000000000.000000000,-10000000000.000000000,-10000000000.000000000\n"
                  "ul max 10000000000.000000000,10000000000.000000000,10000000000.000000000\n"
                  "inv min 0.000000000,-1.000000000,-1.000000000\n"
                  "inv max 1.000000000,1.000000000,1.000000000\n"
                  "ii min -0.200000003,-1.200000048,-1.200000048\n"
                  "ii max 2.200000048,1.200000048,1.200000048\n");
}

// Height fields: the samples' range (above the water level) scaled into the unit cube; clip objects written inside
// a height field or a blob do not narrow its box until a later object { } ends; in a union a height field counts,
// in an intersection it does not; planes moved by translate, rotate and scale bound an intersection.
TEST(Extents, OfHeightFieldsAndLateClipsAsPovRayComputesThem) {
  EXPECT_EQ(extents(
                  "#declare H1 = height_field { function 20, 10 { 0.2 + 0.5*x*y } scale <2,3,4> rotate 10*y };\n"
                  "E(\"h1\", H1)\n"
                  "#declare H2 = height_field { function 8, 8 { x } water_level 0.3 clipped_by { box { 0, 0.5 } } };\n"
                  "E(\"h2\", H2)\n"
                  "#declare H3 = object { H2 };\n"
                  "E(\"h3\", H3)\n"
                  "#declare H4 = union { height_field { function 5, 5 { 0.5 } } sphere { -x, 0.5 } };\n"
                  "E(\"h4\", H4)\n"
                  "#declare H5 = intersection { height_field { function 5, 5 { 0.5 } } sphere { -x, 0.5 } };\n"
                  "E(\"h5\", H5)\n"
                  "#declare B4 = blob { sphere { 0, 1, 1 } clipped_by { box { 0, 0.5 } } };\n"
                  "E(\"b4\", B4)\n"
                  "#declare B5 = object { B4 };\n"
                  "E(\"b5\", B5)\n"
                  "#declare MP = intersection { sphere { 0, 3 } plane { y, 1 scale <1,2,1> translate 0.5 } plane { -z, 1 rotate 180*y } };\n"
                  "E(\"mp\", MP)\n"),
                  "h1 min 0.000000000,0.599990785,-0.347296357\n"
                  "h1 max 2.664208174,2.099945068,3.939230919\n"
                  "h2 min 0.000000000,0.299999982,0.000000000\n"
                  "h2 max 1.000000000,0.999984741,1.000000000\n"
                  "h3 min 0.000000000,0.000000000,0.000000000\n"
                  "h3 max 0.500000000,0.500000000,0.500000000\n"
                  "h4 min -1.500000000,-0.500000000,-0.500000000\n"
                  "h4 max 1.000000000,0.500000000,1.000000000\n"
                  "h5 min -1.500000000,-0.500000000,-0.500000000\n"
                  "h5 max -0.500000000,0.500000000,0.500000000\n"
                  "b4 min -1.000000000,-1.000000000,-1.000000000\n"
                  "b4 max 1.000000000,1.000000000,1.000000000\n"
                  "b5 min 0.000000000,0.000000000,0.000000000\n"
                  "b5 max 0.500000000,0.500000000,0.500000000\n"
                  "mp min -3.000000000,-3.000000000,-3.000000000\n"
                  "mp max 3.000000000,2.500000000,1.000000000\n");
}

// Quadrics: a written ellipsoid's box carried by its transforms; clipped_by recomputing the box within the clip
// objects (planes as half spaces); shapes.inc's unbounded quadrics bounded inside intersections and differences,
// where they are recomputed within the other children's common box; an inverted quadric left out.
TEST(Extents, OfQuadricsAsPovRayComputesThem) {
  EXPECT_EQ(extents(
                  "#include \"shapes.inc\"\n"
                  "#declare Q1 = quadric { <1,2,3>, <0,0,0>, <0,0,0>, -1 scale 2 rotate 30*y };\n"
                  "E(\"q1\", Q1)\n"
                  "#declare Q2 = quadric { <1,0,1>, <0,0,0>, <0,0,0>, -1 clipped_by { box { -2, 2 } } };\n"
                  "E(\"q2\", Q2)\n"
                  "#declare Q3 = intersection { object { Cylinder_Y } box { <-3,-1,-3>, <3,2,3> } };\n"
                  "E(\"q3\", Q3)\n"
                  "#declare Q4 = intersection { object { QCone_Y scale 2 } plane { y, 1 } plane { -y, 0 } };\n"
                  "E(\"q4\", Q4)\n"
                  "#declare Q5 = object { Q4 rotate 20*z };\n"
                  "E(\"q5\", Q5)\n"
                  "#declare Q6 = difference { box { -1, 1 } object { Cylinder_Z scale 0.5 } };\n"
                  "E(\"q6\", Q6)\n"
                  "#declare Q7 = intersection { object { Paraboloid_Y } sphere { 0, 3 } translate x };\n"
                  "E(\"q7\", Q7)\n"
                  "#declare Q8 = quadric { <1,1,0>, <0,0,0>, <0,0,0>, -1 translate <1,2,3> clipped_by { plane { z, 1 } plane { -z, 1 } } };\n"
                  "E(\"q8\", Q8)\n"
                  "#declare Q9 = intersection { quadric { <1,1,1>, <0,0,0>, <0,0,0>, -4 inverse } box { -3, 3 } };\n"
                  "E(\"q9\", Q9)\n"),
            "q1 min -2.309401035,-1.414213538,-2.000000000\n"
            "q1 max 2.309401035,1.414213538,2.000000000\n"
            "q2 min -1.000000000,-2.000000000,-1.000000000\n"
            "q2 max 1.000000000,2.000000000,1.000000000\n"
            "q3 min -1.000000000,-1.000000000,-1.000000000\n"
            "q3 max 1.000000000,2.000000000,1.000000000\n"
            "q4 min -1.000000000,-0.000000000,-1.000000000\n"
            "q4 max 1.000000000,1.000000000,1.000000000\n"
            "q5 min -1.281712770,-0.342020154,-1.000000000\n"
            "q5 max 0.939692497,1.281712770,1.000000000\n"
            "q6 min -1.000000000,-1.000000000,-1.000000000\n"
            "q6 max 1.000000000,1.000000000,1.000000000\n"
            "q7 min -0.732050776,0.000000000,-1.732050776\n"
            "q7 max 2.732050896,3.000000000,1.732050776\n"
            "q8 min 0.000000000,1.000000000,-1.000000000\n"
            "q8 max 2.000000000,3.000000000,1.000000000\n"
            "q9 min -3.000000000,-3.000000000,-3.000000000\n"
            "q9 max 3.000000000,3.000000000,3.000000000\n");
}

// Lathe, sor and prism: their profile's extent (sweep_extents.hpp) carried by the transforms, alone and in a union.
TEST(Extents, OfSweptShapesAsPovRayComputesThem) {
  EXPECT_EQ(extents(
                  "#declare L1 = lathe { cubic_spline 6, <0,0>,<1,0.2>,<1.5,1>,<0.5,1.7>,<1,2.5>,<0,3> rotate 30*x translate y };\n"
                  "E(\"l1\", L1)\n"
                  "#declare S1 = sor { 5, <0,0>, <1,0.2>, <0.5,1>, <1.2,2>, <0,3> scale <1,2,1> rotate 20*z };\n"
                  "E(\"s1\", S1)\n"
                  "#declare P1 = prism { conic_sweep linear_spline 0.5, 1, 4, <1,1>, <-1,1>, <-1,-1>, <1,-1> rotate 45*y };\n"
                  "E(\"p1\", P1)\n"
                  "#declare U = union { object { L1 } object { P1 } rotate 10*x };\n"
                  "E(\"u\", U)\n"),
            "l1 min -1.513051271,0.416679442,-1.210340858\n"
            "l1 max 1.513051271,3.921589136,2.560340881\n"
            "s1 min -2.503578424,-0.037410345,-1.208371520\n"
            "s1 max 0.998689651,4.172058105,1.208371520\n"
            "p1 min -1.414213538,0.500000000,-1.414213538\n"
            "p1 max 1.414213538,1.000000000,1.414213538\n"
            "u min -1.513051271,-0.034249362,-1.320372820\n"
            "u max 1.513051271,4.107587337,3.202420473\n");
}

// Planes moved by matrix or transform (POV-Ray's other half-space formula), in intersections, a difference and a
// quadric's clips; spheres turned into ellipsoids by a transform block or a non-uniform scale (their cube as it
// was then, carried by the transforms since); an inverted quadric (its coefficients negated); clip boxes whose
// upper corners POV-Ray sums in float before a union carries them.
TEST(Extents, OfMatrixPlanesEllipsoidsAndInvertedQuadricsAsPovRayComputesThem) {
  EXPECT_EQ(extents(
                  "#declare PM1 = intersection { sphere { 0, 5 } plane { y, 1 transform { scale 2 } } };\n"
                  "E(\"pm1\", PM1)\n"
                  "#declare PM2 = intersection { sphere { 0, 5 } plane { z, 0.5 translate 0.2*z transform { rotate 90*x } translate y } };\n"
                  "E(\"pm2\", PM2)\n"
                  "#declare PM3 = difference { sphere { 0, 5 } plane { -x, 1 matrix <1,0,0, 0,1,0, 0,0,1, 0.5,0,0> } };\n"
                  "E(\"pm3\", PM3)\n"
                  "#declare PM4 = quadric { <1,0,1>, <0,0,0>, <0,0,0>, -1 clipped_by { plane { y, 2 matrix <1,0,0, 0,1,0, 0,0,1, 0,1,0> } plane { -y, 1 } } };\n"
                  "E(\"pm4\", PM4)\n"
                  "#declare SP1 = sphere { 0, 1 transform { rotate 45*y } };\n"
                  "E(\"sp1\", SP1)\n"
                  "#declare SP2 = sphere { 0, 1 scale <1,2,1> scale <1,0.5,1> rotate 45*y };\n"
                  "E(\"sp2\", SP2)\n"
                  "#declare SP3 = sphere { <1,0,0>, 1 rotate 45*y scale <1,2,1> translate x };\n"
                  "E(\"sp3\", SP3)\n"
                  "#declare QI = quadric { <0,1,1>, <0,0,0>, <0,0,0>, -1 inverse clipped_by { box { -2, 2 } } };\n"
                  "E(\"qi\", QI)\n"
                  "#declare CU = union { sphere { 0, 1 clipped_by { box { <-2,-2,-0.5>, <2,2,0.5> } } } sphere { 3*x, 1 } translate y };\n"
                  "E(\"cu\", CU)\n"
                  "#declare CL = sphere { 0, 2 clipped_by { box { -1, 1 } translate <0.3, 0.2, 0.1> } };\n"
                  "E(\"cl\", CL)\n"
                  "#declare FS = sphere { 0, 100 clipped_by { box { <-2.1938,2.0846,1.5826>, <-0.911,4.5668,3.8356> } } };\n"
                  "#declare FU = union { object { FS } object { FS } scale 1234.567 };\n"
                  "E(\"fu\", FU)\n"),
            "pm1 min -5.000000000,-5.000000000,-5.000000000\n"
            "pm1 max 5.000000000,0.000000000,5.000000000\n"
            "pm2 min -5.000000000,-5.000000000,-5.000000000\n"
            "pm2 max 5.000000000,1.699999809,5.000000000\n"
            "pm3 min -5.000000000,-5.000000000,-5.000000000\n"
            "pm3 max -0.500000000,5.000000000,5.000000000\n"
            "pm4 min -1.000000000,-1.000000000,-1.000000000\n"
            "pm4 max 1.000000000,3.000000000,1.000000000\n"
            "sp1 min -1.414213538,-1.000000000,-1.414213538\n"
            "sp1 max 1.414213538,1.000000000,1.414213538\n"
            "sp2 min -1.414213538,-1.000000000,-1.414213538\n"
            "sp2 max 1.414213538,1.000000000,1.414213538\n"
            "sp3 min 0.707106769,-2.000000000,-1.707106829\n"
            "sp3 max 2.707106829,2.000000000,0.292893171\n"
            "qi min -2.000000000,-2.000000000,-2.000000000\n"
            "qi max 2.000000000,2.000000000,2.000000000\n"
            "cu min -1.000000000,0.000000000,-1.000000000\n"
            "cu max 4.000000000,2.000000000,1.000000000\n"
            "cl min -0.699999988,-0.800000012,-0.899999976\n"
            "cl max 1.299999952,1.200000048,1.100000024\n"
            "fu min -2708.393066406,2573.578369141,1953.825683594\n"
            "fu max -1124.690551758,5638.020507812,4735.304687500\n");
}

}  // namespace
}  // namespace povtrace::test
