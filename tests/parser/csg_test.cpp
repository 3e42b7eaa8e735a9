// CSG and the object modifiers that combine objects, as the parser describes them (parser/objects/csg_modifiers.cpp,
// objects.cpp): differences as intersections with inverted later children, inverse by De Morgan, clipped_by and
// bounded_by lists (transformed with the object, linked, refused when textured), removal of unnecessary bounds,
// texture inheritance and the #default texture through nested CSG, lights inside CSG, inside() with clips.
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::test;

SceneDescription scene(const std::string& body, Messages* messages = nullptr) {
  return parse("#version 3.7;\n" + body, messages);
}

const Csg& csg_of(const Object& o) { return std::get<Csg>(o.shape); }

TEST(Csg, DifferenceIsAnIntersectionWithTheLaterChildrenInverted) {
  const SceneDescription s = scene("difference { box { -1, 1 } sphere { 0, 0.5 } union { sphere { x, 0.2 } "
                                   "sphere { -x, 0.2 } } }\n");
  const Csg& d = csg_of(s.objects.at(0));
  EXPECT_EQ(d.kind, CsgKind::intersection);
  ASSERT_EQ(d.children.size(), 3u);
  EXPECT_FALSE(d.children[0].inverse);
  EXPECT_TRUE(d.children[1].inverse);
  // An inverted union is the intersection of its inverted children (De Morgan).
  const Csg& u = csg_of(d.children[2]);
  EXPECT_EQ(u.kind, CsgKind::intersection);
  for (const Object& c : u.children) EXPECT_TRUE(c.inverse);
  EXPECT_FALSE(d.children[2].inverse);
}

TEST(Csg, ALightCountsAsTheFirstItemOfADifference) {
  // POV-Ray counts items, lights included: after a light, the first object is inverted too.
  const SceneDescription s = scene("difference { light_source { 0, 1 } sphere { 0, 1 } sphere { x, 1 } }\n");
  const Csg& d = csg_of(s.objects.at(0));
  ASSERT_EQ(d.children.size(), 2u);
  EXPECT_TRUE(d.children[0].inverse);
  EXPECT_TRUE(d.children[1].inverse);
  EXPECT_EQ(s.lights.size(), 1u);
}

TEST(Csg, InverseFollowsDeMorgan) {
  const SceneDescription s = scene(
      "union { sphere { 0, 1 } box { 0, 1 } inverse }\n"
      "intersection { sphere { 0, 1 } box { 0, 1 } inverse }\n"
      "merge { sphere { 0, 1 } box { 0, 1 } inverse }\n"
      "union { sphere { 0, 1 } box { 0, 1 } inverse inverse }\n"
      "difference { sphere { 0, 1 } box { 0, 1 } inverse }\n");
  ASSERT_EQ(s.objects.size(), 5u);
  EXPECT_EQ(csg_of(s.objects[0]).kind, CsgKind::intersection);
  EXPECT_EQ(csg_of(s.objects[1]).kind, CsgKind::merge);
  EXPECT_EQ(csg_of(s.objects[2]).kind, CsgKind::intersection);
  // Twice inverted, a union comes back as a merge with its children as written.
  EXPECT_EQ(csg_of(s.objects[3]).kind, CsgKind::merge);
  for (const Object& c : csg_of(s.objects[3]).children) EXPECT_FALSE(c.inverse);
  // difference { A B } inverted: merge { inverse A, B }.
  const Csg& d = csg_of(s.objects[4]);
  EXPECT_EQ(d.kind, CsgKind::merge);
  EXPECT_TRUE(d.children[0].inverse);
  EXPECT_FALSE(d.children[1].inverse);
  for (const Object& o : s.objects) EXPECT_FALSE(o.inverse);
}

TEST(Csg, InsideOfInvertedCsgAndDifferences) {
  EXPECT_EQ(debug_output("#declare U = union { sphere { 0, 1 } sphere { 3*x, 1 } inverse }\n"
                         "#declare D = difference { box { -2, 2 } sphere { 0, 1 } inverse }\n"
                         "#debug concat(str(inside(U, 0), 0, 0), str(inside(U, 1.5*x), 0, 0), "
                         "str(inside(D, 0), 0, 0), str(inside(D, 1.5*x), 0, 0), str(inside(D, 5*x), 0, 0))\n"),
            "01101");
}

TEST(ClippedBy, ObjectsAreTransformedWithTheObject) {
  const SceneDescription s = scene(
      "sphere { 0, 1 clipped_by { plane { y, 0 } box { -1, 1 } translate x } translate 2*y }\n");
  const Object& o = s.objects.at(0);
  ASSERT_EQ(o.clipped_by.size(), 2u);
  // The clip's own translate x, then the object's translate 2*y.
  EXPECT_EQ(o.clipped_by[1].world_from_object.point({0, 0, 0}).x, 1.0);
  EXPECT_EQ(o.clipped_by[1].world_from_object.point({0, 0, 0}).y, 2.0);
  EXPECT_EQ(o.clipped_by[0].world_from_object.point({0, 0, 0}).y, 2.0);
  EXPECT_TRUE(o.bounded_by.empty());
}

TEST(ClippedBy, InsideRequiresTheClips) {
  EXPECT_EQ(debug_output("#declare C = sphere { 0, 1 clipped_by { plane { y, 0 } } }\n"
                         "#debug concat(str(inside(C, -0.5*y), 0, 0), str(inside(C, 0.5*y), 0, 0))\n"),
            "10");
}

TEST(ClippedBy, LinkingSharesTheList) {
  Messages m;
  const SceneDescription s = scene(
      "union { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { -1, 2 } } clipped_by { bounded_by } }\n", &m);
  const Object& o = s.objects.at(0);
  EXPECT_EQ(o.clipped_by.size(), 1u);
  EXPECT_EQ(o.bounded_by.size(), 1u);   // a union keeps its bounds
  EXPECT_TRUE(o.clips_are_bounds);
}

TEST(BoundedBy, RemovedFromPlacedPrimitivesAndSplitUnionChildren) {
  Messages m;
  const SceneDescription s = scene(
      "sphere { 0, 1 bounded_by { box { -1, 1 } } }\n"
      "union { sphere { 0, 1 bounded_by { box { -1, 1 } } } sphere { x, 1 } }\n"
      "intersection { sphere { 0, 1 bounded_by { box { -1, 1 } } } sphere { x, 1 } bounded_by { sphere { 0, 3 } } }\n"
      "sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } }\n",
      &m);
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_TRUE(s.objects[0].bounded_by.empty());
  EXPECT_EQ(s.objects[0].removed_bounds.size(), 1u);   // its bounding box stays (POV-Ray's BBox)
  EXPECT_TRUE(csg_of(s.objects[1]).children[0].bounded_by.empty());
  EXPECT_EQ(csg_of(s.objects[1]).children[0].removed_bounds.size(), 1u);
  // Inside CSG, and on CSG, bounds stay.
  EXPECT_EQ(csg_of(s.objects[2]).children[0].bounded_by.size(), 1u);
  EXPECT_EQ(s.objects[2].bounded_by.size(), 1u);
  EXPECT_TRUE(s.objects[2].removed_bounds.empty());
  // A removed bound that was also the clip leaves the clip.
  EXPECT_TRUE(s.objects[3].bounded_by.empty());
  EXPECT_EQ(s.objects[3].clipped_by.size(), 1u);
  int warnings = 0;
  for (const auto& item : m.items) warnings += item.find("unnecessary bounding object removed") != std::string::npos;
  EXPECT_EQ(warnings, 3);
}

// POV-Ray 3.7.0.10's warnings for the same scene: a text is a union and keeps its bounds ("CSG union unnecessarily
// bounded"); quadrics without a mixed term lose theirs (their box was computed: Automatic_Bounds); one with a mixed
// term keeps them, silently.
TEST(BoundedBy, TextsKeepThemQuadricsWithAComputedBoxLoseThem) {
  Messages m;
  const SceneDescription s = scene(
      "text { internal 1 \"Hi\" 0.2, 0 bounded_by { box { -1, 2 } } }\n"
      "quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 bounded_by { box { -1, 2 } } }\n"
      "quadric { <1,1,0>, <0,0,0>, <0,0,0>, -1 bounded_by { box { -1, 2 } } }\n"
      "quadric { <1,1,0>, <1,0,0>, <0,0,0>, -1 bounded_by { box { -1, 2 } } }\n"
      "union { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { -1, 2 } } }\n"
      "union { sphere { 0, 1 } plane { y, 0 } bounded_by { box { -1, 2 } } }\n",
      &m);
  ASSERT_EQ(s.objects.size(), 6u);
  EXPECT_EQ(s.objects[0].bounded_by.size(), 1u);
  EXPECT_TRUE(s.objects[1].bounded_by.empty());
  EXPECT_TRUE(s.objects[2].bounded_by.empty());
  EXPECT_EQ(s.objects[3].bounded_by.size(), 1u);
  std::string warnings;   // line 1 is the #version the helper writes
  for (const auto& item : m.items) warnings += item;
  EXPECT_NE(warnings.find("2:1: warning: CSG union unnecessarily bounded"), std::string::npos);
  EXPECT_NE(warnings.find("3:1: warning: unnecessary bounding object removed"), std::string::npos);
  EXPECT_NE(warnings.find("4:1: warning: unnecessary bounding object removed"), std::string::npos);
  EXPECT_EQ(warnings.find("5:1: warning"), std::string::npos);
  EXPECT_NE(warnings.find("6:1: warning: CSG union unnecessarily bounded"), std::string::npos);
  EXPECT_EQ(warnings.find("7:1: warning"), std::string::npos);   // a plane child is not finite
}

// POV-Ray's Parse_Object_Id: every shape block, CSG included, takes a declared object as its whole body and makes
// a copy of it with the modifiers that follow (of whatever shape it is); another object after it is an error
// (povray: "No matching } in 'intersection', sphere found instead").
TEST(Csg, ADeclaredObjectAsTheWholeBodyIsACopyOfIt) {
  const SceneDescription s = scene("#declare A = sphere { 0, 1 }\nunion { A translate x }\nbox { A scale 2 }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<Sphere>(s.objects[0].shape));
  EXPECT_EQ(s.objects[0].world_from_object.point({0, 0, 0}).x, 1.0);
  EXPECT_TRUE(std::holds_alternative<Sphere>(s.objects[1].shape));
  const std::string error =
      parse_error("#version 3.7;\n#declare A = sphere { 0, 1 }\nintersection { A sphere { x, 1 } }\n").what();
  EXPECT_NE(error.find("3:18"), std::string::npos) << error;
}

TEST(Csg, TexturesInheritThroughNestedCsgAndTheDefaultFillsTheRest) {
  const SceneDescription s = scene(
      "#default { pigment { rgb <0, 0, 1> } }\n"
      "difference {\n"
      "  intersection { box { -1, 1 } sphere { 0, 1.4 } pigment { rgb <1, 0, 0> } }\n"
      "  union { sphere { 0, 0.5 } box { 0, 1 pigment { rgb <0, 1, 0> } } }\n"
      "}\n"
      "intersection { sphere { 0, 1 } box { 0, 1 pigment { rgb <0, 1, 0> } } pigment { rgb <1, 1, 0> } }\n");
  const Csg& d = csg_of(s.objects.at(0));
  const Csg& inner = csg_of(d.children[0]);
  for (const Object& c : inner.children) EXPECT_EQ(c.texture->layers.back().pigment.colour.r, 1.0);
  const Csg& cutters = csg_of(d.children[1]);
  // The untextured union (and its untextured child) falls back to the #default texture, blue.
  EXPECT_EQ(cutters.children[0].texture->layers.back().pigment.colour.b, 1.0);
  EXPECT_EQ(cutters.children[1].texture->layers.back().pigment.colour.g, 1.0);
  const Csg& second = csg_of(s.objects.at(1));
  EXPECT_EQ(second.children[0].texture->layers.back().pigment.colour.g, 1.0);   // inherits yellow <1,1,0>
  EXPECT_EQ(second.children[0].texture->layers.back().pigment.colour.r, 1.0);
  EXPECT_EQ(second.children[1].texture->layers.back().pigment.colour.r, 0.0);   // keeps its own green
}

TEST(Csg, NoShadowAndLightsPropagate) {
  const SceneDescription s = scene(
      "intersection { sphere { 0, 1 } difference { box { -1, 1 } light_source { <0, 5, 0>, 1 } sphere { 0, 0.5 } } "
      "no_shadow translate x }\n");
  const Csg& i = csg_of(s.objects.at(0));
  for (const Object& c : i.children) EXPECT_TRUE(c.no_shadow);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].location.x, 1.0);   // moved with the CSG
}

// Post_Process: a CSG parent's no_image, no_reflection and no_radiosity are set on every child, nested CSG
// included; a child's own flags stay; nothing is cleared.
TEST(Csg, RayFlagsPropagateToChildren) {
  const SceneDescription s = scene(
      "union { sphere { 0, 1 no_reflection } merge { box { -1, 1 } sphere { x, 1 } } no_image }\n"
      "merge { sphere { 0, 1 no_image } sphere { x, 1 } no_reflection no_radiosity }\n"
      "intersection { sphere { 0, 1 no_image } sphere { x, 1 } }\n");
  const Csg& u = csg_of(s.objects.at(0));
  EXPECT_TRUE(s.objects[0].no_image);
  EXPECT_FALSE(s.objects[0].no_reflection);
  EXPECT_TRUE(u.children[0].no_image);
  EXPECT_TRUE(u.children[0].no_reflection);   // its own
  EXPECT_TRUE(u.children[1].no_image);
  for (const Object& c : csg_of(u.children[1]).children) {
    EXPECT_TRUE(c.no_image);
    EXPECT_FALSE(c.no_reflection);
  }
  const Csg& m = csg_of(s.objects.at(1));
  EXPECT_TRUE(m.children[0].no_image);
  EXPECT_FALSE(m.children[1].no_image);
  for (const Object& c : m.children) {
    EXPECT_TRUE(c.no_reflection);
    EXPECT_TRUE(c.no_radiosity);
  }
  const Csg& i = csg_of(s.objects.at(2));
  EXPECT_FALSE(s.objects[2].no_image);   // a child's flag does not reach its parent
  EXPECT_TRUE(i.children[0].no_image);
  EXPECT_FALSE(i.children[1].no_image);
  for (const Object& o : s.objects) EXPECT_FALSE(o.unsupported);
}

TEST(ClipAndBound, PovRaysErrors) {
  auto message = [](const std::string& text) { return std::string(parse_error("#version 3.7;\n" + text).what()); };
  EXPECT_NE(message("sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } clipped_by { box { 0, 1 } "
                    "} }\n")
                .find("cannot add clips after linking bounds and clips"),
            std::string::npos);
  EXPECT_NE(message("sphere { 0, 1 clipped_by { box { -1, 1 } } bounded_by { box { 0, 1 } } clipped_by { "
                    "bounded_by } }\n")
                .find("cannot link bounds with previous clips"),
            std::string::npos);
  EXPECT_NE(message("sphere { 0, 1 clipped_by { box { -1, 1 pigment { rgb 1 } } } }\n")
                .find("illegal texture in a clipping or bounding object"),
            std::string::npos);
  EXPECT_NE(message("sphere { 0, 1 clipped_by { } }\n").find("expected an object in clipped_by { }"),
            std::string::npos);
}

}  // namespace

// interior_texture (POV-Ray's Interior_Texture): kept beside the texture, layered by repeated blocks, moved by the
// object's transforms, inherited by CSG children without one (with uv_mapping), and carried by a material.
TEST(InteriorTexture, ParsedInheritedAndMoved) {
  const SceneDescription s = scene(
      "union { sphere { 0, 1 pigment { rgb 1 } interior_texture { pigment { rgb x } } } sphere { x, 1 }\n"
      "        pigment { rgb 1 } interior_texture { pigment { checker } } translate y }\n"
      "sphere { 0, 1 pigment { rgb 1 } interior_texture { pigment { rgb y } } interior_texture { pigment { rgbf 1 } "
      "} }\n"
      "#declare M = material { texture { pigment { rgb 1 } } interior_texture { pigment { rgb z } } }\n"
      "sphere { 0, 1 material { M } }\n");
  const Csg& u = csg_of(s.objects.at(0));
  ASSERT_TRUE(u.children[0].interior_texture);
  EXPECT_EQ(u.children[0].interior_texture->layers.back().pigment.colour.r, 1.0);   // its own
  ASSERT_TRUE(u.children[1].interior_texture);
  EXPECT_EQ(u.children[1].interior_texture, s.objects[0].interior_texture);         // the parent's
  EXPECT_EQ(u.children[1].interior_texture->layers.back().pigment.pattern, PatternKind::checker);
  // the translate moved the checker with the object
  EXPECT_EQ(u.children[1].interior_texture->layers.back().pigment.world_from_pattern.point(Vec3{0, 0, 0}).y, 1.0);
  ASSERT_TRUE(s.objects.at(1).interior_texture);
  EXPECT_EQ(s.objects[1].interior_texture->layers.size(), 2u);   // layered
  ASSERT_TRUE(s.objects.at(2).interior_texture);
  EXPECT_EQ(s.objects[2].interior_texture->layers.back().pigment.colour.b, 1.0);
  for (const Object& o : s.objects) EXPECT_FALSE(o.unsupported);
}

// POV-Ray refuses an interior_texture on an object without a texture of its own (the #default does not count).
TEST(InteriorTexture, NeedsAnExteriorTexture) {
  const std::string message =
      parse_error("#version 3.7;\nsphere { 0, 1\n  interior_texture { pigment { rgb 1 } }\n}\n").what();
  EXPECT_NE(message.find("interior_texture needs a texture"), std::string::npos) << message;
  EXPECT_NE(message.find(":4:1"), std::string::npos) << message;
}

// double_illuminate [bool]: on a union, merge or intersection it is set through the whole tree (Set_CSG_Tree_Flag);
// `off` on a copy clears it the same way.
TEST(DoubleIlluminate, SetThroughTheCsgTree) {
  const SceneDescription s = scene(
      "#declare U = union { sphere { 0, 1 } intersection { sphere { 0, 1 } box { -1, 1 } } double_illuminate }\n"
      "object { U }\n"
      "object { U double_illuminate off }\n"
      "sphere { 0, 1 double_illuminate 1 }\n");
  const Csg& on = csg_of(s.objects.at(0));
  EXPECT_TRUE(on.children[0].double_illuminate);
  for (const Object& c : csg_of(on.children[1]).children) EXPECT_TRUE(c.double_illuminate);
  const Csg& off = csg_of(s.objects.at(1));
  EXPECT_FALSE(off.children[0].double_illuminate);
  for (const Object& c : csg_of(off.children[1]).children) EXPECT_FALSE(c.double_illuminate);
  EXPECT_TRUE(s.objects.at(2).double_illuminate);
  for (const Object& o : s.objects) EXPECT_FALSE(o.unsupported);
}

// light_group (Parse_Light_Group, Promote_Local_Lights): its lights are no scene lights, its objects see them and
// (with global_lights) the scene's; a nested group with lights and objects keeps its objects to its own lights; each
// placement of a declared group is a group of its own.
TEST(LightGroup, LightsAndObjectsOfEachGroup) {
  const SceneDescription s = scene(
      "light_source { <0, 9, 0> rgb 1 }\n"
      "#declare G = light_group { sphere { 0, 1 } light_source { <0, 5, 0> rgb 1 }\n"
      "  light_group { box { -1, 1 } light_source { x, rgb 1 } } translate x }\n"
      "object { G }\nobject { G }\n"
      "light_group { sphere { 0, 1 } light_source { y, rgb 1 } global_lights on }\n");
  ASSERT_EQ(s.lights.size(), 6u);   // the scene light, two per copy of G, one in the last group
  EXPECT_EQ(s.lights[0].group, -1);
  const Object& first = s.objects.at(0);
  const Csg& g = csg_of(first);
  EXPECT_TRUE(g.light_group);
  ASSERT_EQ(g.children.size(), 2u);
  const Object& sphere = g.children[0];
  const Object& box = csg_of(g.children[1]).children.at(0);
  EXPECT_TRUE(sphere.no_global_lights);
  EXPECT_TRUE(box.no_global_lights);
  ASSERT_EQ(sphere.light_groups.size(), 1u);
  ASSERT_EQ(box.light_groups.size(), 1u);   // the inner group's lights only
  EXPECT_NE(sphere.light_groups[0], box.light_groups[0]);
  // the second copy's groups are other groups
  const Object& second_sphere = csg_of(s.objects.at(1)).children.at(0);
  ASSERT_EQ(second_sphere.light_groups.size(), 1u);
  EXPECT_NE(second_sphere.light_groups[0], sphere.light_groups[0]);
  // lights moved with the group, tagged with its id
  int tagged = 0;
  for (const Light& l : s.lights)
    if (l.group == sphere.light_groups[0]) {
      ++tagged;
      EXPECT_EQ(l.location, (Vec3{1, 5, 0}));
    }
  EXPECT_EQ(tagged, 1);
  const Object& lit = csg_of(s.objects.at(2)).children.at(0);
  EXPECT_FALSE(lit.no_global_lights);
  EXPECT_EQ(lit.light_groups.size(), 1u);
}
