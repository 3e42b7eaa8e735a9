// The object modifiers that combine objects (povray-sdl-and-geometry.md §9, §10): `inverse` (De Morgan for CSG),
// `clipped_by { objects }`, `bounded_by { objects }`, the inversion of a difference's later children, and the
// removal of unnecessary bounds when an object is placed.
//
// POV-Ray behaviour reproduced (facts read from source/backend/parser/parse.cpp and shape/csg.cpp, 3.7-stable):
// - Inverting a CSG inverts each child (CSG children recursively) and turns a union or merge into an
//   intersection and an intersection into a merge; its clip objects are not inverted. So `inverse inverse` on a
//   union leaves a merge. A difference is an intersection whose items after the first were inverted as they were
//   added (a light source counts as an item there).
// - clipped_by / bounded_by take one or more objects, then optional transforms that move all of them, then '}'.
//   Objects with a texture are refused. `clipped_by { bounded_by }` and `bounded_by { clipped_by }` reuse the
//   other list (it is copied here; later transforms move both the same way, so a copy behaves identically).
// - When a finished object is placed in the scene (Link_To_Frame), with Remove_Bounds on (the default), the
//   bounding objects of anything but a union, merge, intersection, poly (cubic, quartic) or quadric are dropped
//   with the warning "Unnecessary bounding object removed."; a union that will be split into its children (no
//   clip, no bound) gets the same treatment for each child. Objects inside CSG keep their bounds. A text is a
//   union in POV-Ray and keeps them; a quadric keeps them only when its box computation did not find a box itself
//   (Quadric::Automatic_Bounds, see quadric_extent.hpp).
// - A bounded union (text included) kept whole although all its children are finite gets the warning "CSG union
//   unnecessarily bounded" (POV-Ray would only split it with Split_Unions on, which is off by default).
// - A removed bound leaves behind the bounding box it gave the object (Parse_Object_Mods sets the object's box to
//   the bounds' box when that is smaller, and Link_To_Frame does not recompute it), so it is kept as
//   removed_bounds for the renderer.
#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"

namespace povtrace::sdl {

void ObjectParser::invert_object(Object& object) {
  // A bicubic_patch has no inside to invert (BicubicPatch::Invert does nothing).
  if (std::holds_alternative<BicubicPatch>(object.shape)) return;
  auto* csg = std::get_if<Csg>(&object.shape);
  if (!csg) {
    object.inverse = !object.inverse;
    return;
  }
  csg->inverted = !csg->inverted;
  if (csg->kind == CsgKind::difference) {   // only in descriptions built in code: parse_csg converts differences
    for (std::size_t i = 1; i < csg->children.size(); ++i) invert_object(csg->children[i]);
    csg->kind = CsgKind::intersection;
  }
  for (auto& child : csg->children) invert_object(child);
  csg->kind = csg->kind == CsgKind::intersection ? CsgKind::merge : CsgKind::intersection;
}

// double_illuminate on a union, merge, intersection or difference reaches every object of its tree (POV-Ray's
// Set_CSG_Tree_Flag), so that the leaves a ray hits carry it.
void ObjectParser::set_double_illuminate(Object& object, bool on) {
  object.double_illuminate = on;
  if (auto* csg = std::get_if<Csg>(&object.shape))
    for (auto& child : csg->children) set_double_illuminate(child, on);
}

// light_group { objects and light_source { }s  transforms  [global_lights [B]]  [photons { … }] } (POV-Ray's
// Parse_Light_Group): a union whose lights are no scene lights; only its objects see them, and the scene's lights only
// with `global_lights` (set on every object of the group when the group ends, Set_CSG_Children_Flag). The group ids
// are given when the group is placed (SceneStatements::assign_light_groups).
Object ObjectParser::parse_light_group(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'light_group'");
  Object o;
  o.loc = keyword.loc;
  Csg csg;
  csg.kind = CsgKind::union_;
  csg.light_group = true;
  Token t = next();
  while (auto item = try_parse_item(t)) {
    if (auto* light = std::get_if<Light>(&*item)) csg.lights.push_back(std::move(*light));
    else csg.children.push_back(std::move(std::get<Object>(*item)));
    t = next();
  }
  o.shape = std::move(csg);
  extents().made(o);
  bool global_lights = false;
  for (;; t = next()) {
    Matrix m;
    if (t.is("}")) break;
    if (textures_.try_transform(t, m)) {
      apply_transform(o, m, t.is("translate") ? TransformKind::translate
                            : t.is("rotate")  ? TransformKind::rotate
                            : t.is("scale")   ? TransformKind::scale
                                              : TransformKind::other);
    } else if (t.is("global_lights")) {
      global_lights = optional_float(1.0) > 0.5;
    } else if (t.is("photons")) {
      parse_object_photons(t, o);
    } else {
      fail_expected(t, "an object, a light_source, a transform, global_lights, photons or '}' in light_group");
    }
  }
  set_no_global_lights(o, !global_lights);
  extents().modifiers_ended(o);
  return o;
}

// Set_CSG_Children_Flag: the objects of a CSG tree (not the CSG nodes in it) take the flag.
void ObjectParser::set_no_global_lights(Object& object, bool no_global) {
  object.no_global_lights = no_global;
  if (auto* csg = std::get_if<Csg>(&object.shape))
    for (auto& child : csg->children) set_no_global_lights(child, no_global);
}

std::vector<Object> ObjectParser::parse_bound_clip_objects(const Token& keyword) {
  std::vector<Object> objects;
  Token t = next();
  while (auto item = try_parse_item(t)) {
    auto* object = std::get_if<Object>(&*item);
    if (!object) fail_at(t, "a light source cannot be a clipping or bounding object");
    if (object->texture) fail_at(t, "illegal texture in a clipping or bounding object");
    objects.push_back(std::move(*object));
    t = next();
  }
  if (objects.empty()) fail_expected(t, "an object in " + std::string(keyword.text) + " { }");
  Matrix m;
  while (textures_.try_transform(t, m)) t = next();
  if (!t.is("}")) fail_expected(t, "a transform or '}' closing " + std::string(keyword.text) + " { }");
  if (!(m == Matrix::identity()))
    for (auto& o : objects) apply_transform(o, m);
  return objects;
}

void ObjectParser::parse_clip_or_bound(const Token& keyword, Object& object) {
  const NestingGuard guard(*this, keyword);
  if (const Token open = next(); !open.is("{")) fail_expected(open, "'{' after '" + std::string(keyword.text) + "'");
  const bool clip = keyword.is("clipped_by");
  std::vector<Object>& list = clip ? object.clipped_by : object.bounded_by;
  const std::string_view other = clip ? "bounded_by" : "clipped_by";
  // POV-Ray's parse errors once the two lists are one.
  if (!list.empty() && object.clips_are_bounds)
    fail_at(keyword, clip ? "cannot add clips after linking bounds and clips"
                          : "cannot add bounds after linking bounds and clips");
  if (peek().is(other)) {
    const Token link = next();
    if (!list.empty())
      fail_at(link, clip ? "cannot link bounds with previous clips" : "cannot link clips with previous bounds");
    expect("}", " after '" + std::string(other) + "' in " + std::string(keyword.text) + " { }");
    list = clip ? object.bounded_by : object.clipped_by;
    object.clips_are_bounds = !list.empty();
    return;
  }
  std::vector<Object> objects = parse_bound_clip_objects(keyword);
  for (auto& o : objects) list.push_back(std::move(o));
  if (clip && std::holds_alternative<Quadric>(object.shape)) extents().quadric_clipped(object);
}

// Link_To_Frame's test before it keeps a bounded union whole: every child's box has a volume of at most BOUND_HUGE.
bool ObjectParser::all_children_finite(const Csg& csg) const {
  if (!csg.lights.empty()) return false;   // a light source is a child with the huge box
  try {
    for (const Object& child : csg.children)
      if (extents().box(child).volume() > kBoundHuge) return false;
  } catch (const ExtentUnavailable&) {
    return false;
  }
  return true;
}

void ObjectParser::remove_unnecessary_bounds(Object& object) {
  const auto* csg = std::get_if<Csg>(&object.shape);
  if (!csg) {
    // A text is a CSG union in POV-Ray; a quadric keeps its bounds unless its box computation found one itself.
    const auto* quadric = std::get_if<Quadric>(&object.shape);
    const bool kept = std::holds_alternative<Poly>(object.shape) || std::holds_alternative<Text>(object.shape) ||
                      (quadric && !notes_of(object).automatic_bounds);
    // Its glyphs are finite; a clipped text is placed before that test, an inverted one is an intersection.
    if (!object.bounded_by.empty() && std::holds_alternative<Text>(object.shape) && object.clipped_by.empty() &&
        !object.inverse)
      warn(object.loc, "CSG union unnecessarily bounded");
    if (!object.bounded_by.empty() && !kept) {
      object.removed_bounds = std::move(object.bounded_by);
      object.bounded_by.clear();
      object.clips_are_bounds = false;
      warn(object.loc, "unnecessary bounding object removed");
    }
    return;
  }
  // A union without clip or bound is split into its children, each placed as if on its own.
  if (csg->kind == CsgKind::union_ && object.clipped_by.empty() && object.bounded_by.empty())
    for (auto& child : std::get<Csg>(object.shape).children) remove_unnecessary_bounds(child);
  if (csg->kind == CsgKind::union_ && object.clipped_by.empty() && !object.bounded_by.empty() &&
      all_children_finite(*csg))
    warn(object.loc, "CSG union unnecessarily bounded");
}

}  // namespace povtrace::sdl
