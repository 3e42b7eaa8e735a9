// pigment, finish, texture and interior blocks, and the transforms shared with objects
// (povray-sdl-and-geometry.md §9, §11; finish defaults in povray-pixel-pipeline.md §2).
#include <algorithm>
#include <cmath>

#include <atomic>

#include "parser/interpreter.hpp"
#include "parser/textures/texture_parser.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
template <class T> const T* identifier_value(const Value* v) {
  return v && std::holds_alternative<Boxed<T>>(*v) ? &*std::get<Boxed<T>>(*v) : nullptr;
}

void transform_pigment(Pigment& p, const Matrix& m) { p.world_from_pattern = p.world_from_pattern * m; }

bool uses_uv_mapping(const Pigment& p) {
  if (p.pattern == PatternKind::uv_mapping) return true;
  for (const auto& e : p.entries)
    if (e.pigment && uses_uv_mapping(*e.pigment)) return true;
  return false;
}

// A texture's transforms move every layer's pigment and normal (POV-Ray's Transform_Textures).
void transform_layer(TextureLayer& l, const Matrix& m) {
  transform_pigment(l.pigment, m);
  if (l.normal) {
    auto moved = std::make_shared<Normal>(*l.normal);
    transform_pigment(moved->pattern, m);
    l.normal = std::move(moved);
  }
}
}  // namespace

// translate/rotate/scale/matrix/transform: composes into `m` in written order (§9).
bool TextureParser::try_transform(const Token& t, Matrix& m) {
  if (t.is("translate")) { m = m * Matrix::translation(parse_vector()); return true; }
  if (t.is("rotate")) { m = m * Matrix::rotation(parse_vector()); return true; }
  if (t.is("scale")) {
    Vec3 s = parse_vector();
    for (int i = 0; i < 3; ++i)
      if (s[i] == 0.0) {
        warn(t.loc, "scale by 0 is changed to 1 in that axis, as POV-Ray does");
        s[i] = 1.0;
      }
    m = m * Matrix::scaling(s);
    return true;
  }
  if (t.is("matrix")) {
    expect("<", " after 'matrix' (12 values)");
    Matrix r;
    for (int i = 0; i < 12; ++i) {
      if (i > 0) expect(",", " between the 12 matrix values");
      r.m[static_cast<std::size_t>(i / 3)][static_cast<std::size_t>(i % 3)] = parse_float();
    }
    expect(">", " after the 12 matrix values");
    if (r.determinant() == 0.0) fail_at(t, "this matrix is singular (determinant 0): it cannot place an object");
    m = m * r;
    return true;
  }
  if (t.is("transform")) { m = m * parse_transform_block(t); return true; }
  return false;
}

Matrix TextureParser::parse_transform_block(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  Token open = next();
  // The old form `transform T_id` without braces.
  if (const Matrix* id = identifier_value<Matrix>(lookup(open))) return *id;
  if (!open.is("{")) fail_expected(open, "'{' or a transform identifier after 'transform'");
  Matrix m;
  bool inverse = false;
  while (true) {
    Token t = next();
    if (t.is("}")) break;
    if (t.is("inverse")) { inverse = true; continue; }
    if (const Matrix* id = identifier_value<Matrix>(lookup(t))) { m = m * *id; continue; }
    if (try_transform(t, m)) continue;
    fail_expected(t, "translate, rotate, scale, matrix, transform, inverse or '}' in transform { }");
  }
  return inverse ? m.inverse() : m;
}

// One item of a pigment body: a pattern (pigments.cpp), a colour, a transform or a pattern modifier.
bool TextureParser::try_pigment_item(const Token& t, Pigment& p) {
  if (try_pattern(t, p)) return true;
  if (starts_colour(t)) {
    unget(t);
    p.pattern = PatternKind::solid;
    p.colour = parse_colour();
    return true;
  }
  Matrix m;
  if (try_transform(t, m)) { transform_pigment(p, m); return true; }
  return try_pattern_modifier(t, p);
}

Pigment TextureParser::parse_pigment_block(const Token& keyword, const Pigment& start) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'pigment'");
  return parse_pigment_contents(start, keyword.loc, "}");
}

// irid { AMOUNT [thickness T] [turbulence V] } (Parse_Finish's IRID_TOKEN): single-precision fields; the turbulence
// is a vector of which only x counts. Items after the amount may repeat, the last one wins.
void TextureParser::parse_irid(const Token& keyword, Finish& f) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'irid'");
  f.irid = static_cast<float>(parse_float());
  for (Token t = next(); !t.is("}"); t = next()) {
    if (t.is("thickness")) f.irid_thickness = static_cast<float>(parse_float());
    else if (t.is("turbulence")) f.irid_turbulence = static_cast<float>(parse_vector().x);
    else fail_expected(t, "thickness, turbulence or '}' in irid { }");
  }
}

Finish TextureParser::parse_finish_block(const Token& keyword, const Finish& start) {
  expect("{", " after 'finish'");
  Finish f = start;
  f.loc = keyword.loc;
  Token t = next();
  if (const Finish* id = identifier_value<Finish>(lookup(t))) {
    f = *id;
    t = next();
  }
  // Plain RGB parameters accept floats as greys (§5 "Colours").
  auto rgb_parameter = [this]() {
    Token at = peek();
    Numeric n = parse_additive();
    // Finish colours are stored in single precision like every POV-Ray colour.
    const auto single = [](double d) { return static_cast<double>(static_cast<float>(d)); };
    if (n.terms == 1) return Colour{single(n.v[0]), single(n.v[0]), single(n.v[0]), 0, 0};
    if (n.terms < 3) fail_at(at, "expected a float or a colour");
    return Colour{single(n.v[0]), single(n.v[1]), single(n.v[2]), 0, 0};
  };
  auto colour_parameter = [&]() {
    Token n = peek();
    if (starts_colour(n)) { Colour c = parse_colour(); c.f = c.t = 0; return c; }
    return rgb_parameter();
  };
  // `albedo` forms are rescaled once the whole block is read (pipeline §2: they use the block's brilliance,
  // phong_size and roughness, wherever those are written).
  bool diffuse_albedo = false, phong_albedo = false, specular_albedo = false;
  while (!t.is("}")) {
    const std::string_view k = t.kind == TokenKind::identifier ? t.text : std::string_view();
    if (k == "ambient") f.ambient = colour_parameter();
    else if (k == "emission") f.emission = colour_parameter();
    else if (k == "diffuse") {
      diffuse_albedo = accept("albedo");
      f.diffuse = parse_float();
      // POV-Ray's Parse_Comma then Allow_Float(0): the comma is optional and an unwritten back value is 0, so
      // `diffuse D` in a finish copied from an identifier clears that finish's back value.
      accept(",");
      f.diffuse_back = optional_float(0.0);
    } else if (k == "brilliance") f.brilliance = parse_float();
    else if (k == "phong") {
      phong_albedo = accept("albedo");
      f.phong = parse_float();
    } else if (k == "phong_size") f.phong_size = parse_float();
    else if (k == "specular") {
      specular_albedo = accept("albedo");
      f.specular = parse_float();
    } else if (k == "roughness") {
      f.roughness = parse_float();
      if (f.roughness == 0) fail_at(t, "roughness must not be 0 (the highlight exponent is 1/roughness)");
    } else if (k == "metallic") {
      // `metallic` alone means 1 (§2 defaults); `metallic on` and any float expression give their value
      // (POV-Ray's Allow_Float).
      f.metallic = optional_float(1.0);
    } else if (k == "reflection") {
      parse_finish_reflection(f);
    } else if (k == "reflection_exponent") {
      f.reflection_exponent = parse_float();
    } else if (k == "conserve_energy") {
      f.conserve_energy = true;
    } else if (k == "ior") {
      // Pre-3.1 syntax: POV-Ray warns and moves the value into the object's interior when it is placed.
      f.legacy_ior = parse_float();
      warn(t.loc, "the index of refraction should be given in 'interior { ior … }'");
    } else if (k == "refraction") {
      f.legacy_refraction = parse_float();
      warn(t.loc, "'refraction' is not needed to turn refraction on; to attenuate, use fade_power and "
                  "fade_distance in 'interior { }'");
    } else if (k == "caustics") {
      // Pre-3.1 syntax: POV-Ray warns and moves the value, unscaled, into the object's interior when it is placed.
      f.legacy_caustics = parse_float();
      warn(t.loc, "the caustics value should be given in 'interior { caustics … }'");
    } else if (k == "crand") {
      f.crand = parse_float();
    } else if (k == "irid") {
      parse_irid(t, f);
    } else if (!k.empty() && is_reserved_word(k)) {
      taint(f.unsupported, skip_unsupported(t, "the finish item '" + std::string(k) + "'"));
    } else {
      fail_expected(t, "a finish item (ambient, emission, diffuse, brilliance, phong, phong_size, specular, "
                       "roughness, metallic, reflection, conserve_energy) or '}'");
    }
    t = next();
  }
  // Radiosity uses the values before this block's albedo rescaling (POV-Ray's RawDiffuse, set at the end of every
  // finish block from what the block holds, rescaled or not).
  f.diffuse_raw = f.diffuse;
  f.diffuse_back_raw = f.diffuse_back;
  if (diffuse_albedo) {
    f.diffuse *= (f.brilliance + 1.0) / 2.0;
    f.diffuse_back *= (f.brilliance + 1.0) / 2.0;   // both values, as POV-Ray's Parse_Finish rescales them
  }
  if (phong_albedo) f.phong *= (f.phong_size + 1.0) / 2.0;
  if (specular_albedo) {
    const double n = 1.0 / f.roughness;
    f.specular *= (n + 2.0) / (4.0 * (2.0 - std::pow(2.0, -n / 2.0)));
  }
  return f;
}

// sky_sphere { [S_id] pigment { … }… emission C transforms } (POV-Ray's Parse_Skysphere): pigments are added in
// order, transforms compose into the sky's own matrix (they do not move the pigments), and an empty sky_sphere is
// an error.
SkySphere TextureParser::parse_sky_sphere(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'sky_sphere'");
  SkySphere sky;
  sky.loc = keyword.loc;
  Token t = next();
  if (const Value* v = lookup(t); v && std::holds_alternative<Boxed<SkySphere>>(*v)) {
    sky = *std::get<Boxed<SkySphere>>(*v);
    t = next();
  }
  for (; !t.is("}"); t = next()) {
    Matrix m;
    if (t.is("pigment")) {
      sky.pigments.push_back(parse_pigment_block(t, Pigment{}));
      // A miss has no surface and no uv: POV-Ray stops the render there ("The 'uv_mapping' pattern cannot be used
      // as part of a pigment function!").
      if (uses_uv_mapping(sky.pigments.back()))
        fail_at(t, "the 'uv_mapping' pattern cannot be used in a sky_sphere (there is no surface to take uv from)");
      taint(sky.unsupported, sky.pigments.back().unsupported);
    } else if (t.is("emission")) {
      const Colour c = parse_colour();
      sky.emission = Colour{static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b), 0, 0};
    } else if (try_transform(t, m)) {
      sky.world_from_sky = sky.world_from_sky * m;
    } else {
      fail_expected(t, "pigment, emission, a transform or '}' in sky_sphere { }");
    }
  }
  if (sky.pigments.empty()) fail_at(keyword, "a sky_sphere needs at least one pigment");
  return sky;
}

// fog { [colour] [distance D | D] [fog_type 1|2] [fog_alt] [fog_offset] [turb_depth] [up V] [turbulence V octaves
// omega lambda] [rotate scale matrix transform] } (POV-Ray's Parse_Fog): transforms turn only the up vector (a translate
// warns and does nothing), which is normalised at the end.
Fog TextureParser::parse_fog(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'fog'");
  Fog fog;
  fog.loc = keyword.loc;
  auto turbulence = [&fog]() -> Turbulence& {
    if (!fog.turbulence) fog.turbulence = Turbulence{};
    return *fog.turbulence;
  };
  for (Token t = next(); !t.is("}"); t = next()) {
    Matrix m;
    if (starts_colour(t)) {
      unget(t);
      fog.colour = parse_colour();
    } else if (t.is("distance")) {
      fog.distance = parse_float();
    } else if (t.is("fog_type")) {
      const double type = parse_float();
      if (type != 1 && type != 2) warn(t.loc, "unknown fog_type (1 is constant fog, 2 ground fog)");
      fog.type = static_cast<int>(type);
    } else if (t.is("fog_alt")) {
      fog.alt = parse_float();
    } else if (t.is("fog_offset")) {
      fog.offset = parse_float();
    } else if (t.is("turb_depth")) {
      fog.turb_depth = parse_float();
    } else if (t.is("up")) {
      fog.up = parse_vector();
    } else if (t.is("turbulence")) {
      turbulence().amount = parse_vector();
    } else if (t.is("octaves")) {
      turbulence().octaves = std::clamp(static_cast<int>(parse_float()), 1, 10);
    } else if (t.is("omega")) {
      turbulence().omega = static_cast<float>(parse_float());
    } else if (t.is("lambda")) {
      turbulence().lambda = static_cast<float>(parse_float());
    } else if (t.is("translate")) {
      parse_vector();
      warn(t.loc, "a fog's up vector cannot be translated: the translate does nothing");
    } else if (try_transform(t, m)) {
      fog.up = m.vector(fog.up);
    } else if (t.kind == TokenKind::number || t.is("(") || t.is("-")) {
      unget(t);
      warn(t.loc, "the fog distance should be written with the 'distance' keyword");
      fog.distance = parse_float();
    } else {
      fail_expected(t, "a fog item (a colour, distance, fog_type, fog_alt, fog_offset, turb_depth, up, turbulence, "
                       "octaves, omega, lambda, a transform) or '}'");
    }
  }
  const double l = length(fog.up);
  if (l > 0) fog.up = fog.up / l;
  return fog;
}

// `reflection C` (old form: min = max = C, falloff 1, no fresnel) or `reflection { Cmin [, Cmax] [fresnel [B]]
// [falloff F] [exponent E] [metallic [M]] }` (pipeline §4). In the block, a single colour is both min and max,
// except that `fresnel` without a second colour makes min 0 so that the fresnel term has an effect.
void TextureParser::parse_finish_reflection(Finish& f) {
  auto reflection_colour = [this] {
    Colour c = parse_colour();
    c = Colour{static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b), 0, 0};
    return c;
  };
  if (!accept("{")) {
    f.reflection_max = f.reflection_min = reflection_colour();
    f.reflection_falloff = 1.0;
    f.reflection_fresnel = false;
    return;
  }
  f.reflection_min = reflection_colour();
  accept(",");
  bool second_colour = false;
  if (const Token n = peek(); !n.is("}") && !n.is("fresnel") && !n.is("falloff") && !n.is("exponent") &&
                              !n.is("metallic")) {
    f.reflection_max = reflection_colour();
    second_colour = true;
  } else {
    f.reflection_max = f.reflection_min;
  }
  for (Token t = next(); !t.is("}"); t = next()) {
    if (t.is("fresnel")) {
      const double on = optional_float(1.0);
      if (on != 0.0 && on != 1.0) fail_at(t, "fresnel must be true or false");
      f.reflection_fresnel = on != 0.0;
      if (!second_colour && f.reflection_fresnel) f.reflection_min = Colour{};
    } else if (t.is("falloff")) {
      f.reflection_falloff = parse_float();
    } else if (t.is("exponent")) {
      f.reflection_exponent = parse_float();
    } else if (t.is("metallic")) {
      f.reflection_metallic = optional_float(1.0);
    } else {
      fail_expected(t, "fresnel, falloff, exponent, metallic or '}' in reflection { }");
    }
  }
}

Interior TextureParser::parse_interior_block(const Token& keyword, const Interior& start) {
  (void)keyword;
  expect("{", " after 'interior'");
  Interior in = start;
  Token t = next();
  if (const Interior* id = identifier_value<Interior>(lookup(t))) {
    in = *id;
    t = next();
  }
  while (!t.is("}")) {
    if (t.is("ior")) in.ior = parse_float();
    else if (t.is("fade_distance")) in.fade_distance = parse_float();
    else if (t.is("fade_power")) in.fade_power = parse_float();
    else if (t.is("fade_color") || t.is("fade_colour")) {
      const Colour c = parse_colour();
      in.fade_colour = Colour{static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b), 0, 0};
    } else if (t.is("refraction")) {
      // POV-Ray accepts it here but overwrites it with the finish's (legacy) refraction when the object is
      // placed, so it never has an effect.
      parse_float();
      warn(t.loc, "'refraction' is not needed to turn refraction on; to attenuate, use fade_power and "
                  "fade_distance in 'interior { }'");
    } else if (t.is("caustics")) {
      in.caustics = parse_float() * 45.0;   // POV-Ray's Parse_Interior scales it so
    } else if (t.is("media")) {
      auto media = in.media ? std::make_shared<std::vector<Media>>(*in.media) : std::make_shared<std::vector<Media>>();
      media->push_back(parse_media_block(t));
      taint(in.unsupported, media->back().unsupported);
      in.media = std::move(media);
      // Identity only, never part of an image: any value unique in the process will do.
      static std::atomic<std::uint64_t> next_media_id{0};
      in.media_id = ++next_media_id;
    } else if (t.kind == TokenKind::identifier && is_reserved_word(t.text))
      taint(in.unsupported, skip_unsupported(t, "the interior item '" + std::string(t.text) + "'"));
    else fail_expected(t, "ior, fade_distance, fade_power, fade_color, caustics, media or '}' in interior { }");
    t = next();
  }
  return in;
}

// texture { … } (POV-Ray's Parse_Texture).
std::shared_ptr<const Texture> TextureParser::parse_texture_block(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after '" + std::string(keyword.text) + "'");   // texture or interior_texture
  return parse_texture_contents(keyword.loc, "}");
}

// The inside of texture { … } or of a texture_map entry [v …], up to `closer`: [T_id] then pigment{} normal{}
// finish{} transforms (a plain texture, editing the id's top layer or a copy of the #default texture); or, with
// no id and nothing of these first, a patterned texture (texture_patterns.cpp). A declared pigment/finish starts
// from the current #default (§4 #default).
std::shared_ptr<const Texture> TextureParser::parse_texture_contents(const SourceLoc& loc, std::string_view closer) {
  Texture tex;
  tex.loc = loc;
  Token t = next();
  bool edited = false;   // POV-Ray's Modified_Pnf: a texture id or a pigment/normal/finish/transform was read
  if (const Value* v = lookup(t); v && std::holds_alternative<std::shared_ptr<const Texture>>(*v)) {
    const auto declared = std::get<std::shared_ptr<const Texture>>(*v);
    t = next();
    // `texture { T }` unchanged shares the declared texture: textures are immutable once built, and scenes
    // that place thousands of objects with a few textures must not copy them.
    if (t.is(closer)) return declared;
    if (declared->patterned()) return transformed_patterned_texture(*declared, t, closer);
    tex = *declared;
    edited = true;
  }
  if (tex.layers.empty()) tex.layers.push_back(default_texture().layers.front());
  TextureLayer& layer = tex.layers.back();
  // POV-Ray still takes `texture { P N F … }` with pigment, normal and finish identifiers written bare before
  // anything else (old syntax), each replacing the layer's own; scenes before #version 1.5 get its warning.
  for (;; t = next(), edited = true) {
    const Value* v = t.kind == TokenKind::identifier ? lookup(t) : nullptr;
    std::string kind;
    if (v && std::holds_alternative<Boxed<Pigment>>(*v)) layer.pigment = *std::get<Boxed<Pigment>>(*v), kind = "pigment";
    else if (v && std::holds_alternative<Boxed<Normal>>(*v))
      layer.normal = std::make_shared<const Normal>(*std::get<Boxed<Normal>>(*v)), kind = "normal";
    else if (v && std::holds_alternative<Boxed<Finish>>(*v)) layer.finish = *std::get<Boxed<Finish>>(*v), kind = "finish";
    else break;
    if (language_version() < 150)
      warn(t.loc, "Found '" + kind + " identifier' that should be in '" + kind + "' statement.");
  }
  for (; !t.is(closer); t = next(), edited = true) {
    Matrix m;
    if (t.is("pigment")) layer.pigment = parse_pigment_block(t, layer.pigment);
    else if (t.is("finish")) layer.finish = parse_finish_block(t, layer.finish);
    else if (try_transform(t, m))
      for (auto& l : tex.layers) transform_layer(l, m);
    else if (t.is("normal"))
      layer.normal = std::make_shared<const Normal>(parse_normal_block(t, starting_normal(layer.normal.get())));
    else if (!edited && starts_texture_pattern(t)) return parse_patterned_texture(t, loc, closer);
    else if (t.kind == TokenKind::identifier && is_reserved_word(t.text))
      taint(tex.unsupported, skip_unsupported(t, "the texture item '" + std::string(t.text) + "'"));
    else fail_expected(t, "pigment, normal, finish, a transform or '" + std::string(closer) + "' in texture { }");
  }
  for (const auto& l : tex.layers) {
    taint(tex.unsupported, l.pigment.unsupported);
    taint(tex.unsupported, l.finish.unsupported);
    if (l.normal) taint(tex.unsupported, l.normal->unsupported);
  }
  return std::make_shared<const Texture>(std::move(tex));
}

}  // namespace povtrace::sdl
