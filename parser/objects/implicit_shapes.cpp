// superellipsoid and blob (povray-sdl-and-geometry.md §8). Facts from POV-Ray 3.7's parser
// (source/backend/parser/parse.cpp Parse_Superellipsoid, express.cpp Parse_UV_Vect, 3.7-stable):
// - superellipsoid { <e, n> modifiers }: the exponents are a UV vector (a float stands for both; three or more
//   components are an error). The shape is |x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1; the renderer derives the
//   powers.
// - blob { [threshold T] components… [sturm] modifiers } (Parse_Blob, Parse_Blob_Element_Mods): threshold defaults
//   to 1 and may come between components; components are `sphere { C, R, [strength] S mods }`,
//   `cylinder { B, A, R, [strength] S mods }` and the old `component S, R, C`. Commas are optional. A cylinder whose
//   ends are closer than 1e-10 is an error. A sphere component keeps its centre and radius through translate,
//   rotate and a uniform scale (centre scaled, radius² by the square); a non-uniform scale, matrix or transform turns
//   it into an ellipsoid placed by its own transform. A component may have its own texture, moved by its transforms.
#include <algorithm>

#include "scene/description_transforms.hpp"
#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"

namespace povtrace::sdl {

Object ObjectParser::parse_superellipsoid(const Token& keyword) {
  expect("{", " after 'superellipsoid'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Superellipsoid s;
  std::tie(s.e, s.n) = parse_uv_vector("<e, n> of the superellipsoid");
  o.shape = s;
  parse_object_modifiers(o);
  return o;
}

// ovus { BOTTOM, TOP } (Parse_Ovus): negative radii are an error; a top radius of twice the bottom one or more
// makes the sphere it would equal (POV-Ray's warning), at <0, BOTTOM, 0> with radius TOP. The box is computed
// before the modifiers, which carry it.
Object ObjectParser::parse_ovus(const Token& keyword) {
  expect("{", " after 'ovus'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Ovus v;
  v.bottom_radius = parse_float();
  accept(",");
  v.top_radius = parse_float();
  if (v.top_radius < 0 || v.bottom_radius < 0) fail_at(keyword, "both ovus radii must be positive (as in POV-Ray)");
  if (v.top_radius < 2.0 * v.bottom_radius) {
    o.shape = v;
  } else {
    warn(keyword.loc, "the ovus' second radius should be less than twice its first: a sphere is used instead, "
                      "identical and simpler (as POV-Ray does)");
    o.shape = Sphere{Vec3{0, v.bottom_radius, 0}, v.top_radius, false};
  }
  parse_object_modifiers(o);
  return o;
}

namespace {
bool is_uniform_scaling(const Matrix& m) {
  return m == Matrix::scaling({m.m[0][0], m.m[0][0], m.m[0][0]});
}
}  // namespace

// A component's transforms move it and the texture it has so far (POV-Ray's Translate_Blob_Element and friends
// call Transform_Textures); its texture, pigment, normal and finish build its own texture as an object's do
// (Parse_Blob_Element_Mods: texture blocks stack as layers, a pigment, normal or finish edits the top layer of the
// texture so far, or of a copy of the #default texture).
void ObjectParser::parse_blob_component_modifiers(BlobComponent& c, std::shared_ptr<const Texture>& texture,
                                                   Object& blob) {
  while (true) {
    const Token t = next();
    if (t.is("}")) return;
    Matrix m;
    if (textures_.try_transform(t, m)) {
      if (c.kind == BlobComponentKind::sphere && (t.is("translate") || t.is("rotate") ||
                                                  (t.is("scale") && is_uniform_scaling(m)))) {
        c.centre = m.point(c.centre);
        if (t.is("scale")) c.radius2 *= m.m[0][0] * m.m[0][0];
      } else {
        if (c.kind == BlobComponentKind::sphere) c.kind = BlobComponentKind::ellipsoid;
        c.transform = c.transform * m;
      }
      transform_texture(texture, m);
    } else if (t.is("texture")) {
      auto tex = textures_.parse_texture_block(t);
      textures_.refuse_layering(t, texture.get(), tex->patterned());
      if (!texture) {
        texture = std::move(tex);
      } else {
        auto layered = std::make_shared<Texture>(*texture);
        for (const auto& l : tex->layers) layered->layers.push_back(l);
        texture = std::move(layered);
      }
    } else if (t.is("pigment") || t.is("finish") || t.is("normal")) {
      textures_.refuse_layering(t, texture.get(), false);
      auto own = std::make_shared<Texture>(texture ? *texture : default_texture());
      TextureLayer& layer = own->layers.back();
      if (t.is("pigment")) {
        layer.pigment = textures_.parse_pigment_block(t, layer.pigment);
      } else if (t.is("finish")) {
        layer.finish = textures_.parse_finish_block(t, layer.finish);
      } else {
        layer.normal = std::make_shared<const Normal>(
            textures_.parse_normal_block(t, textures_.starting_normal(layer.normal.get())));
        taint(blob.unsupported, layer.normal->unsupported);
      }
      texture = std::move(own);
    } else {
      fail_expected(t, "a transform, texture, pigment, normal, finish or '}' in a blob component");
    }
  }
}

// sphere { C, R, [strength] S … } or the old `component S, R, C`.
BlobComponent ObjectParser::parse_blob_sphere(bool old_syntax) {
  BlobComponent c;
  if (old_syntax) {
    c.strength = parse_float();
    accept(",");
    const double r = parse_float();
    accept(",");
    c.radius2 = r * r;
    c.centre = parse_vector();
    return c;
  }
  expect("{", " after 'sphere' in a blob");
  c.centre = parse_vector();
  accept(",");
  const double r = parse_float();
  c.radius2 = r * r;
  accept(",");
  accept("strength");
  c.strength = parse_float();
  return c;
}

BlobComponent ObjectParser::parse_blob_cylinder(const Token& keyword) {
  expect("{", " after 'cylinder' in a blob");
  BlobComponent c;
  c.kind = BlobComponentKind::cylinder;
  c.centre = parse_vector();
  accept(",");
  c.apex = parse_vector();
  accept(",");
  const double r = parse_float();
  c.radius2 = r * r;
  accept(",");
  accept("strength");
  c.strength = parse_float();
  if (length(c.apex - c.centre) < 1e-10) fail_at(keyword, "degenerate cylindrical component in blob");
  return c;
}

Object ObjectParser::parse_blob(const Token& keyword) {
  expect("{", " after 'blob'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Blob b;
  auto components = std::make_shared<std::vector<BlobComponent>>();
  std::vector<std::shared_ptr<const Texture>> textures;   // one per component
  while (true) {
    const Token t = next();
    if (t.is("threshold")) {
      b.threshold = parse_float();
    } else if (t.is("component")) {
      components->push_back(parse_blob_sphere(true));
      textures.emplace_back();
    } else if (t.is("sphere")) {
      components->push_back(parse_blob_sphere(false));
      parse_blob_component_modifiers(components->back(), textures.emplace_back(), o);
    } else if (t.is("cylinder")) {
      components->push_back(parse_blob_cylinder(t));
      parse_blob_component_modifiers(components->back(), textures.emplace_back(), o);
    } else {
      unget(t);
      break;
    }
  }
  if (components->empty()) fail_at(keyword, "a blob needs at least one component (POV-Ray refuses it too)");
  b.components = std::move(components);
  if (std::any_of(textures.begin(), textures.end(), [](const auto& t) { return t != nullptr; }))
    b.textures = std::move(textures);
  o.shape = b;
  parse_object_modifiers(o);
  extents().made(o);   // Make_Blob computes the box after the blob's own modifiers
  return o;
}

}  // namespace povtrace::sdl
