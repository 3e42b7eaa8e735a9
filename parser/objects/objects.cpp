// Shapes, CSG and object modifiers (povray-sdl-and-geometry.md §8–§10). Modifiers apply in written order and
// every transform also moves what is already attached (textures) — a texture added after a transform is not
// affected by it (§9, [V sdl_tex_order]).
#include <cmath>

#include "scene/description_transforms.hpp"
#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"
#include "parser/objects/object_transform.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
// The object's own top texture layer, created from the #default texture when the object has none yet
// (object-level pigment/finish on an untextured object, §4 #default).
TextureLayer& own_top_layer(Object& object, const Texture& defaults, const NotesPool& pool) {
  apply_deferred_texture_transforms(object, pool);   // the layer edited is the one the transforms moved
  auto tex = std::make_shared<Texture>(object.texture ? *object.texture : defaults);
  object.texture = tex;
  return tex->layers.back();
}
// POV-Ray's Link_Textures: the new block's layers on top of those `target` has (or the block itself when none).
void link_layers(std::shared_ptr<const Texture>& target, std::shared_ptr<const Texture> added) {
  if (!target) {
    target = std::move(added);
    return;
  }
  auto layered = std::make_shared<Texture>(*target);
  for (const auto& l : added->layers) layered->layers.push_back(l);
  target = std::move(layered);
}
}  // namespace

// A transform moves the object and what is attached to it (scene/description_transforms.cpp), and the parser's notes
// on them (object_transform.cpp).
void ObjectParser::apply_transform(Object& object, const Matrix& m, TransformKind kind) {
  transform_noted(object, m, notes_pool(), kind);
}

bool ObjectParser::try_object_modifier(const Token& t, Object& object) {
  Matrix m;
  if (textures_.try_transform(t, m)) {
    const TransformKind kind = t.is("translate") ? TransformKind::translate
                               : t.is("rotate")  ? TransformKind::rotate
                               : t.is("scale")   ? TransformKind::scale
                                                 : TransformKind::other;
    apply_transform(object, m, kind);
    return true;
  }
  const std::string_view k = t.kind == TokenKind::identifier ? t.text : std::string_view();
  if (k == "texture") {
    auto tex = textures_.parse_texture_block(t);
    // Each texture statement links its layers on top of what the object already has, so consecutive blocks
    // stack as layers; the last written is the top (§11, pipeline §2 "Layers"). Patterned textures take no part in
    // layering (POV-Ray's Link_Textures).
    textures_.refuse_layering(t, object.texture.get(), tex->patterned());
    // the layers below were moved by the deferred transforms, the new ones are not
    if (object.texture) apply_deferred_texture_transforms(object, notes_pool());
    link_layers(object.texture, std::move(tex));
    return true;
  }
  if (k == "interior_texture") {
    // Layers stack on the interior texture as texture blocks do on the texture (POV-Ray's Link_Textures).
    auto tex = textures_.parse_texture_block(t);
    textures_.refuse_layering(t, object.interior_texture.get(), tex->patterned());
    link_layers(object.interior_texture, std::move(tex));
    return true;
  }
  if (k == "double_illuminate") {
    // POV-Ray's Bool_Flag; on a union, merge or intersection it is set (or cleared) through the whole tree.
    set_double_illuminate(object, optional_float(1.0) > 0.0);
    return true;
  }
  if (k == "uv_mapping") {
    if (object.texture) fail_at(t, "uv_mapping must be specified before texture (as in POV-Ray)");
    object.uv_mapping = true;
    return true;
  }
  if (k == "pigment" || k == "normal" || k == "finish") textures_.refuse_layering(t, object.texture.get(), false);
  if (k == "pigment") {
    TextureLayer& layer = own_top_layer(object, default_texture(), notes_pool());
    layer.pigment = textures_.parse_pigment_block(t, layer.pigment);
    return true;
  }
  if (k == "normal") {
    TextureLayer& layer = own_top_layer(object, default_texture(), notes_pool());
    layer.normal =
        std::make_shared<const Normal>(textures_.parse_normal_block(t, textures_.starting_normal(layer.normal.get())));
    taint(object.unsupported, layer.normal->unsupported);
    return true;
  }
  if (k == "finish") {
    TextureLayer& layer = own_top_layer(object, default_texture(), notes_pool());
    layer.finish = textures_.parse_finish_block(t, layer.finish);
    return true;
  }
  if (k == "interior") {
    object.interior = textures_.parse_interior_block(t, object.interior.value_or(Interior{}));
    return true;
  }
  if (k == "material") {
    parse_material_block(t, object);
    return true;
  }
  if (k == "no_shadow") { object.no_shadow = true; return true; }
  // no_image, no_reflection, no_radiosity [bool]: POV-Ray's Bool_Flag, so an explicit false (<= 0) clears a flag
  // the object already had (from a declared object it copies).
  if (k == "no_image") { object.no_image = optional_float(1.0) > 0.0; return true; }
  if (k == "no_reflection") { object.no_reflection = optional_float(1.0) > 0.0; return true; }
  if (k == "no_radiosity") { object.no_radiosity = optional_float(1.0) > 0.0; return true; }
  // radiosity { importance F }: kept on the object; without radiosity in global_settings it changes nothing.
  if (k == "radiosity") {
    if (const std::optional<double> importance = parse_radiosity_importance(t))
      object.radiosity_importance = importance;
    return true;
  }
  if (k == "inverse") {
    if (std::holds_alternative<BicubicPatch>(object.shape))
      warn(t.loc, "cannot invert a patch object (as in POV-Ray, inverse has no effect on a bicubic_patch)");
    invert_object(object);
    return true;
  }
  if (k == "clipped_by") { parse_clip_or_bound(t, object); return true; }
  if (k == "bounded_by") { parse_clip_or_bound(t, object); return true; }
  if (k == "hollow") {
    // hollow [bool]: fog (and media) reach rays inside hollow objects only.
    object.hollow = optional_float(1.0) > 0.0;
    return true;
  }
  if (k == "sturm" && try_sturm_modifier(t, object)) return true;
  if (k == "photons") { parse_object_photons(t, object); return true; }
  if (k == "open")   // POV-Ray reads `open` only right after the parameters of a cylinder, cone, prism or sor
    fail_at(t, "'open' must directly follow the parameters of a cylinder, cone, prism or sor; it is no object "
               "modifier");
  // Real POV-Ray object modifiers povtrace does not render yet: parsed, and the object is tainted.
  static const std::string_view unrendered[] = {
      "sturm", "split_union", "cutaway_textures",
      "hierarchy", "smooth", "water_level", "inside_vector", "uv_vectors", "texture_list"};
  for (auto u : unrendered)
    if (k == u) {
      taint(object.unsupported, skip_unsupported(t, "the object modifier '" + std::string(k) + "'"));
      return true;
    }
  return false;
}

// material { [M_id] texture{} interior{} transforms } (§9): a texture and an interior together.
void ObjectParser::parse_material_block(const Token& keyword, Object& object) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'material'");
  Object holder;   // collects the material's parts with the object-modifier rules, then hands them over
  Token t = next();
  if (const Value* v = lookup(t)) {
    if (v && std::holds_alternative<Boxed<MaterialValue>>(*v)) {
      const auto& m = *std::get<Boxed<MaterialValue>>(*v);
      holder.texture = m.texture;
      holder.interior_texture = m.interior_texture;
      holder.interior = m.interior;
      t = next();
    }
  }
  while (!t.is("}")) {
    Matrix m;
    if (t.is("texture") || t.is("interior_texture") || t.is("interior") || t.is("pigment") || t.is("normal") ||
        t.is("finish"))
      try_object_modifier(t, holder);
    else if (textures_.try_transform(t, m)) {
      transform_texture(holder.texture, m);
      if (holder.interior) transform_media(holder.interior->media, m);   // POV-Ray's Interior::Transform
    } else if (t.kind == TokenKind::identifier && is_reserved_word(t.text))
      taint(holder.unsupported, skip_unsupported(t, "the material item '" + std::string(t.text) + "'"));
    else fail_expected(t, "texture, interior, a transform or '}' in material { }");
    t = next();
  }
  if (holder.texture) {
    object.texture = holder.texture;
    drop_deferred_texture_transforms(object, notes_pool());   // they belonged to the texture replaced
  }
  if (holder.interior_texture) object.interior_texture = holder.interior_texture;
  if (holder.interior) object.interior = holder.interior;
  taint(object.unsupported, holder.unsupported);
}

void ObjectParser::parse_object_modifiers(Object& object) {
  while (true) {
    if (plain_symbol(plain_ahead(), '}') && !object.interior_texture) {   // the closing brace, without its Token
      consume_plain();
      extents().modifiers_ended(object);
      return;
    }
    Token t = next();
    if (t.is("}")) {
      // POV-Ray's Parse_Object_Mods: the #default texture is given only later, so it does not count.
      if (object.interior_texture && !object.texture)
        fail_at(t, "interior_texture needs a texture (pigment, normal or finish) on the same object (POV-Ray: "
                   "\"Interior texture requires an exterior texture\")");
      extents().modifiers_ended(object);
      return;
    }
    if (try_object_modifier(t, object)) continue;
    // Any other keyword here (often the next object after a missing '}') is a syntax error.
    fail_expected(t, "an object modifier (translate, rotate, scale, matrix, transform, texture, pigment, finish, "
                     "interior, no_shadow, inverse) or '}'");
  }
}

Object ObjectParser::parse_sphere(const Token& keyword) {
  skip_expected('{', " after 'sphere'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Sphere s;
  s.centre = parse_vector();
  accept(",");   // commas between object parameters are optional (§8 Parse_Comma)
  s.radius = parse_float();
  o.shape = s;
  parse_object_modifiers(o);
  return o;
}

Object ObjectParser::parse_plane(const Token& keyword) {
  skip_expected('{', " after 'plane'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Plane p;
  Token at = peek();
  const Vec3 n = parse_vector();
  if (length(n) == 0) fail_at(at, "the plane's normal is the zero vector (expected a direction)");
  accept(",");   // commas between object parameters are optional (§8 Parse_Comma)
  // The normal is normalised first; the distance is measured along the unit normal ([V sdl_plane_side]).
  p.normal = normalize(n);
  p.distance = parse_float();
  o.shape = p;
  parse_object_modifiers(o);
  return o;
}

Object ObjectParser::parse_box(const Token& keyword) {
  skip_expected('{', " after 'box'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  const Vec3 a = parse_vector();
  accept(",");   // commas between object parameters are optional (§8 Parse_Comma)
  const Vec3 b = parse_vector();
  o.shape = Box{min(a, b), max(a, b)};   // corners sorted per axis ([V sdl_promote])
  parse_object_modifiers(o);
  return o;
}

std::string ObjectParser::csg_name(CsgKind kind) {
  switch (kind) {
    case CsgKind::union_: return "'union'";
    case CsgKind::merge: return "'merge'";
    case CsgKind::intersection: return "'intersection'";
    case CsgKind::difference: return "'difference'";
  }
  return "CSG";
}

// union/merge/intersection/difference { objects… modifiers } (§10). A difference becomes an intersection whose
// items after the first are inverted as they are added (a light source counts as an item, as in POV-Ray).
Object ObjectParser::parse_csg(const Token& keyword, CsgKind kind) {
  const NestingGuard guard(*this, keyword);
  if (const Token open = next(); !open.is("{"))   // not expect(): its message would be built every time
    fail_expected(open, "'{' after '" + std::string(keyword.text) + "'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Csg csg;
  csg.kind = kind;
  Token t = next();
  for (std::size_t items = 1;; ++items) {
    auto item = try_parse_item(t);
    if (!item) break;
    if (auto* light = std::get_if<Light>(&*item)) {
      csg.lights.push_back(std::move(*light));
    } else {
      Object& child = std::get<Object>(*item);
      if ((kind == CsgKind::intersection || kind == CsgKind::difference) &&
          std::holds_alternative<BicubicPatch>(child.shape))   // Parse_CSG's warning; the patch is still added
        warn(t.loc, "patch objects are not allowed in an intersection (a bicubic_patch has no inside)");
      if (kind == CsgKind::difference && items > 1) invert_object(child);
      csg.children.push_back(std::move(child));
    }
    t = next();
  }
  if (kind == CsgKind::difference) csg.kind = CsgKind::intersection;
  unget(t);
  if (csg.children.size() + csg.lights.size() < 2)
    warn(keyword.loc, "a CSG " + csg_name(kind) + " should have at least two objects");
  o.shape = std::move(csg);
  extents().made(o);
  parse_object_modifiers(o);
  return o;
}

// object { Id modifiers } — a deep copy of a declared object (or light) with modifiers applied.
SceneItem ObjectParser::parse_object_block(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  skip_expected('{', " after 'object'");
  return parse_object_block_rest(keyword, next());
}

void ObjectParser::place_object_block(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  skip_expected('{', " after 'object'");
  const Token t = next();
  if (const Value* v = lookup(t); v && std::holds_alternative<std::shared_ptr<const SceneItem>>(*v))
    if (const auto* declared = std::get_if<Object>(std::get<std::shared_ptr<const SceneItem>>(*v).get())) {
      Object o = *declared;   // before the modifiers, which may redeclare the name
      parse_object_modifiers(o);
      place_object(std::move(o), keyword.loc);
      return;
    }
  SceneItem item = parse_object_block_rest(keyword, t);
  if (auto* light = std::get_if<Light>(&item)) place_light(std::move(*light), keyword.loc);
  else place_object(std::move(std::get<Object>(item)), keyword.loc);
}

SceneItem ObjectParser::parse_object_block_rest(const Token& keyword, const Token& first) {
  const Token& t = first;
  std::optional<SceneItem> item;
  if (const Value* v = lookup(t)) {
    if (v && std::holds_alternative<std::shared_ptr<const SceneItem>>(*v))
      item = *std::get<std::shared_ptr<const SceneItem>>(*v);
  }
  if (!item) item = try_parse_item(t);
  if (!item) fail_expected(t, "an object identifier or an object inside object { }");
  if (auto* light = std::get_if<Light>(&*item)) {
    while (true) {
      Token m = next();
      if (m.is("}")) break;
      if (!camera_lights_.try_light_modifier(m, *light)) fail_expected(m, "a light_source modifier or '}'");
    }
    return std::move(*item);
  }
  Object& o = std::get<Object>(*item);
  (void)keyword;
  parse_object_modifiers(o);
  return std::move(*item);   // not a copy: an object is large
}

std::optional<SceneItem> ObjectParser::try_parse_item(const Token& t) {
  if (t.kind != TokenKind::identifier) return std::nullopt;
  const std::string_view k = t.text;
  if (k == "sphere") return parse_sphere(t);
  if (k == "plane") return parse_plane(t);
  if (k == "box") return parse_box(t);
  if (k == "object") return parse_object_block(t);
  if (k == "light_source") return camera_lights_.parse_light(t);
  if (k == "poly") return parse_poly(t, 0);
  if (k == "quadric") return parse_quadric(t);
  if (k == "cubic") return parse_poly(t, 3);
  if (k == "quartic") return parse_poly(t, 4);
  if (k == "union") return parse_csg(t, CsgKind::union_);
  if (k == "merge") return parse_csg(t, CsgKind::merge);
  if (k == "intersection") return parse_csg(t, CsgKind::intersection);
  if (k == "difference") return parse_csg(t, CsgKind::difference);
  if (k == "cylinder") return parse_cylinder(t);
  if (k == "cone") return parse_cone(t);
  if (k == "disc") return parse_disc(t);
  if (k == "torus") return parse_torus(t);
  if (k == "triangle") return parse_triangle(t, false);
  if (k == "smooth_triangle") return parse_triangle(t, true);
  if (k == "polygon") return parse_polygon(t);
  if (k == "mesh") return parse_mesh(t);
  if (k == "mesh2") return parse_mesh2(t);
  if (k == "superellipsoid") return parse_superellipsoid(t);
  if (k == "ovus") return parse_ovus(t);
  if (k == "height_field") return parse_height_field(t);
  if (k == "blob") return parse_blob(t);
  if (k == "text") return parse_text(t);
  if (k == "lathe") return parse_lathe(t);
  if (k == "prism") return parse_prism(t);
  if (k == "sor") return parse_sor(t);
  if (k == "isosurface") return parse_isosurface(t);
  if (k == "julia_fractal") return parse_julia_fractal(t);
  if (k == "light_group") return parse_light_group(t);
  if (k == "bicubic_patch") return parse_bicubic_patch(t);
  static const std::string_view shapes[] = {
      "sphere_sweep", "parametric", "lemon",
      "polynomial"};
  for (auto s : shapes)
    if (k == s) {
      Object o;
      o.loc = t.loc;
      o.unsupported = skip_unsupported(t, "the shape '" + std::string(k) + "'");
      return o;
    }
  if (const Value* v = lookup(t)) {
    if (v && std::holds_alternative<std::shared_ptr<const SceneItem>>(*v))
      return *std::get<std::shared_ptr<const SceneItem>>(*v);
  }
  return std::nullopt;
}

}  // namespace povtrace::sdl
