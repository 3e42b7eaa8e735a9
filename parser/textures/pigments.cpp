// Pigment patterns, their colour/pigment maps and pattern modifiers (povray-sdl-and-geometry.md §11). The
// pattern keywords, defaults and limits follow POV-Ray 3.7's Parse_Pattern, Parse_Blend_List, Parse_Blend_Map and
// Parse_Colour_Map (parser/parstxtr.cpp, parser/express.cpp).
#include <algorithm>
#include <cmath>

#include <cstdio>

#include "runtime/density_file.hpp"
#include "scene/pov_vector_math.hpp"
#include "parser/expressions/int_cast.hpp"
#include "runtime/function_value.hpp"
#include "parser/extents/object_notes.hpp"
#include "parser/interpreter.hpp"
#include "parser/textures/image_location.hpp"
#include "parser/textures/texture_parser.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
// Pattern parameters, map values, frequency and phase are single-precision fields in POV-Ray.
double single(double d) { return static_cast<double>(static_cast<float>(d)); }

// POV-Ray's EPSILON; `mortar M` is stored as M − 2·EPSILON (Parse_Pattern).
constexpr double kPovEpsilon = 1e-10;

// POV-Ray's limit on colour_map/pigment_map entries (MAX_BLEND_MAP_ENTRIES).
constexpr std::size_t kMaxMapEntries = 256;

bool is_list_pattern(PatternKind k) {
  return k == PatternKind::checker || k == PatternKind::hexagon || k == PatternKind::brick ||
         k == PatternKind::object;
}

struct SimplePattern {
  std::string_view keyword;
  PatternKind kind;
};
// Patterns whose keyword takes no argument and changes nothing but the kind (Parse_Pattern).
constexpr SimplePattern kSimplePatterns[] = {
    {"bozo", PatternKind::bozo},         {"spotted", PatternKind::spotted},
    {"granite", PatternKind::granite},   {"leopard", PatternKind::leopard},
    {"onion", PatternKind::onion},       {"radial", PatternKind::radial},
    {"planar", PatternKind::planar},     {"boxed", PatternKind::boxed},
    {"spherical", PatternKind::spherical}, {"cylindrical", PatternKind::cylindrical},
    {"average", PatternKind::average},   {"cells", PatternKind::cells},
    {"bumps", PatternKind::bumps},       {"dents", PatternKind::dents},
    {"wrinkles", PatternKind::wrinkles}, {"ripples", PatternKind::ripples},
    {"waves", PatternKind::waves},
};

struct WaveKeyword {
  std::string_view keyword;
  WaveType wave;
};
constexpr WaveKeyword kWaveKeywords[] = {
    {"ramp_wave", WaveType::ramp},       {"triangle_wave", WaveType::triangle}, {"sine_wave", WaveType::sine},
    {"scallop_wave", WaveType::scallop}, {"cubic_wave", WaveType::cubic},       {"poly_wave", WaveType::poly},
};

// The colours a list pattern gets for entries it does not write (texture/pigment.cpp default maps).
Colour list_default(PatternKind k, std::size_t i) {
  if (k == PatternKind::brick) {
    const Colour brick[2] = {{0.5, 0.5, 0.5, 0, 0}, {single(0.6), single(0.15), single(0.15), 0, 0}};
    return brick[i];
  }
  const Colour blue_green_red[3] = {{0, 0, 1, 0, 0}, {0, 1, 0, 0, 0}, {1, 0, 0, 0, 0}};
  return blue_green_red[i];
}

// POV-Ray's Check_Turb: the classic turbulence, created with its defaults when a turbulence parameter first
// appears.
Turbulence& classic_turbulence(Pigment& p) {
  if (!p.turbulence) p.turbulence = Turbulence{};
  return *p.turbulence;
}

int clamped_octaves(double v) { return std::clamp(static_cast<int>(v), 1, 10); }
}  // namespace

// POV-Ray stores integer parameters (`interpolate N`, fractal iterations) as (int)N: truncated towards zero. C++
// leaves the conversion of a float outside int's range undefined, so such values are clamped first (any of them
// picks tricubic for interpolate, as N % 10 ∉ {0, 1}).
int truncated_int(double v) {
  if (std::isnan(v)) return 0;
  return static_cast<int>(std::clamp(std::trunc(v), -2147483648.0, 2147483647.0));
}

// `density_file df3 "NAME"` (Parse_Pattern): the file is looked for as POV-Ray's Locate_File looks for a DF3 file
// (the name, with .df3 or .DF3 appended, in the working directory and the library paths) and read here, so that a
// missing or malformed file is an error where it is named (POV-Ray: "Cannot read media density file.", "Error
// reading density_file", "Invalid density file size"). A new density_file starts with interpolate 0 again
// (Create_Density_File).
void TextureParser::parse_density_file(Pigment& p) {
  const Token type = next();
  if (!type.is("df3")) fail_expected(type, "'df3' after 'density_file' (the only density file type)");
  const Token name_token = peek();
  const std::string name = parse_string();
  static constexpr std::string_view kExtensions[] = {".df3", ".DF3"};
  const auto path = locate_typed_file(name, kExtensions, library_paths());
  if (!path)
    fail_at(name_token, "cannot find the density file '" + name + "' (looked for it, and for it with .df3 or .DF3 "
                        "appended, in the working directory and the library paths)");
  try {
    p.density_file = std::make_shared<const DensityGrid>(df3::read_density_file(*path));
  } catch (const df3::DensityFileError& e) {
    fail_at(name_token, e.what());
  }
  p.pattern = PatternKind::density_file;
  p.density_interpolation = 0;
}

bool TextureParser::starts_map_expression(const Token& t) const {
  return starts_colour(t) || t.kind == TokenKind::number || t.is("<") || t.is("(") || t.is("-") || t.is("+");
}

// `checker C1, C2` / `hexagon C1, C2, C3` / `brick C1, C2`, or the same with `pigment { }` entries: all colours or
// all pigments, decided by the first token; entries not written take the default colours, or the #default
// pigment when the list is of pigments (Parse_Blend_List).
std::vector<MapEntry> TextureParser::parse_list_entries(PatternKind kind, std::size_t count) {
  std::vector<MapEntry> entries;
  const bool pigments = peek().is("pigment");
  while (entries.size() < count) {
    Token n = peek();
    MapEntry e;
    e.value = static_cast<double>(entries.size());
    if (pigments && n.is("pigment")) {
      Token keyword = next();
      e.pigment = std::make_shared<const Pigment>(parse_pigment_block(keyword, default_pigment()));
    } else if (!pigments && starts_map_expression(n)) {
      e.colour = parse_colour();
    } else {
      break;
    }
    accept(",");
    entries.push_back(std::move(e));
  }
  while (entries.size() < count) {
    MapEntry e;
    e.value = static_cast<double>(entries.size());
    if (pigments) e.pigment = std::make_shared<const Pigment>(default_pigment());
    else e.colour = list_default(kind, entries.size());
    entries.push_back(std::move(e));
  }
  return entries;
}

// The object of an object pattern (POV-Ray's Parse_Bound_Clip): one object or object identifier, untextured and
// no patch. It keeps the coordinates it was written in: the pattern's transforms take the point to it.
std::shared_ptr<const Object> TextureParser::parse_pattern_object() {
  const Token t = next();
  std::optional<SceneItem> item = try_parse_item(t);
  if (!item || !std::holds_alternative<Object>(*item))
    fail_expected(t, "an object or object identifier in the object pattern");
  Object& o = std::get<Object>(*item);
  if (o.texture || std::holds_alternative<BicubicPatch>(o.shape))
    fail_at(t, "an object pattern's object can have no texture and be no bicubic_patch (POV-Ray: \"Illegal "
               "texture or patch in clip, bound or object pattern.\")");
  clear_notes(o);
  return std::make_shared<const Object>(std::move(o));
}

void TextureParser::set_list_pattern(const Token& t, Pigment& p) {
  const PatternKind kind = t.is("checker") ? PatternKind::checker
                           : t.is("hexagon") ? PatternKind::hexagon : PatternKind::brick;
  // A brick pigment edited with `brick` again keeps its size and mortar.
  if (kind == PatternKind::brick && p.pattern != PatternKind::brick) {
    p.brick_size = {8, 3, 4.5};
    p.mortar = single(0.5 - 2 * kPovEpsilon);
  }
  p.pattern = kind;
  p.frequency = 0.0;
}

bool TextureParser::try_pattern(const Token& t, Pigment& p) {
  if (t.is("image_map")) {
    parse_image_map(t, p);
    return true;
  }
  if (t.is("density_file")) {
    parse_density_file(p);
    return true;
  }
  for (const auto& s : kSimplePatterns)
    if (t.is(s.keyword)) { p.pattern = s.kind; return true; }
  if (t.is("checker") || t.is("hexagon") || t.is("brick")) {
    set_list_pattern(t, p);
    p.entries = parse_list_entries(p.pattern, p.pattern == PatternKind::hexagon ? 3 : 2);
    return true;
  }
  if (t.is("gradient")) {
    const Vec3 v = parse_vector();
    if (length(v) == 0.0) fail_at(t, "the gradient direction must not be the zero vector");
    p.pattern = PatternKind::gradient;
    p.gradient = normalize(v);
    return true;
  }
  if (t.is("marble") || t.is("wood")) {
    p.pattern = t.is("marble") ? PatternKind::marble : PatternKind::wood;
    p.wave = WaveType::triangle;   // POV-Ray's default wave for both
    return true;
  }
  if (t.is("function")) {
    // function { EXPRESSION } of x, y, z (POV-Ray's Parse_Function: the body only, no parameter list).
    if (peek().is("(")) fail_expected(peek(), "'{' after 'function' in a pattern");
    auto fn = parse_function_definition(t);
    if (fn->return_size != 0 || fn->parameter_count != 3)
      fail_at(t, "a function pattern needs a float function of x, y and z");
    if (auto part = unevaluable_part(*fn)) taint(p.unsupported, UnsupportedFeature{"a pattern of " + *part, t.loc});
    p.pattern = PatternKind::function;
    p.function = std::move(fn);
    return true;
  }
  if (t.is("quilted")) {   // POV-Ray resets both controls and skips the wave step's frequency
    p.pattern = PatternKind::quilted;
    p.control0 = p.control1 = 1.0f;
    p.frequency = 0.0;
    return true;
  }
  if (t.is("spiral1") || t.is("spiral2")) {
    p.pattern = t.is("spiral1") ? PatternKind::spiral1 : PatternKind::spiral2;
    // POV-Ray keeps the arm count as a short, converted from the float as written.
    p.arms = static_cast<short>(std::clamp(std::trunc(parse_float()), -32768.0, 32767.0));
    p.wave = WaveType::triangle;   // POV-Ray's default wave for both
    return true;
  }
  if (t.is("crackle")) {   // every crackle keyword resets its parameters (Parse_Pattern)
    p.pattern = PatternKind::crackle;
    p.crackle = CrackleParams{};
    return true;
  }
  if (t.is("mandel") || t.is("julia") || t.is("magnet")) {
    parse_fractal_pattern(t, p);
    return true;
  }
  if (t.is("slope")) {
    parse_slope_pattern(t, p);
    return true;
  }
  if (t.is("image_pattern")) {
    parse_image_pattern(t, p);
    return true;
  }
  if (t.is("pigment_pattern")) {   // a pigment of its own, from plain black (Create_Pigment), not the #default one
    const NestingGuard guard(*this, t);
    expect("{", " after 'pigment_pattern'");
    auto inner = std::make_shared<const Pigment>(parse_pigment_contents(Pigment{}, t.loc, "}"));
    taint(p.unsupported, inner->unsupported);
    p.pattern = PatternKind::pigment_pattern;
    p.pattern_pigment = std::move(inner);
    return true;
  }
  if (t.is("aoi")) {
    p.pattern = PatternKind::aoi;
    return true;
  }
  if (t.is("object")) {   // object { OBJECT [C1, C2 | pigment { } pigment { }] }
    const NestingGuard guard(*this, t);
    const Token open = expect("{", " after 'object' (the object pattern)");
    p.object = parse_pattern_object();
    taint(p.unsupported, p.object->unsupported);
    p.pattern = PatternKind::object;
    p.frequency = 0.0;   // a list pattern (Parse_Pattern sets Frequency 0)
    if (peek().is("normal")) {
      taint(p.unsupported, UnsupportedFeature{"the object pattern with normal entries", peek().loc});
      skip_balanced(open);
      return true;
    }
    p.entries = parse_list_entries(PatternKind::object, 2);
    expect("}", " closing the object pattern");
    return true;
  }
  if (t.is("agate")) {
    p.pattern = PatternKind::agate;
    classic_turbulence(p);   // agate needs the turbulence's octaves, omega and lambda
    p.agate_turb = 1.0;
    return true;
  }
  return false;
}

void TextureParser::refuse_map_for_pattern(const Token& t, const Pigment& p, bool pigment_map) {
  if (p.unsupported) return;   // the pattern may be one povtrace skipped: its kind is unknown here
  const bool solid = p.pattern == PatternKind::solid || p.pattern == PatternKind::image_map;
  const bool average = p.pattern == PatternKind::average;
  if (solid || is_list_pattern(p.pattern) || (average && !pigment_map))
    fail_at(t, "cannot use " + std::string(t.text) + " with this pattern type (as in POV-Ray)");
}

// `[v C]`, `[v, C]`, `[v <r,g,b,f,t>]` or the old two-colour form `[v1, v2 color C1 color C2]`.
void TextureParser::parse_colour_map_entry(std::vector<MapEntry>& entries) {
  MapEntry first;
  first.value = single(parse_float());
  accept(",");
  Token n = peek();
  if (starts_colour(n)) {
    first.colour = parse_colour();
    entries.push_back(first);
    return;
  }
  Numeric e = parse_additive();
  if (e.terms == 5) {
    e.colour = true;
    first.colour = e.stored().as_colour();
    entries.push_back(first);
    return;
  }
  if (e.terms != 1) fail_at(n, "expected a colour or a second value (old-style entry) in the color_map entry");
  MapEntry second;
  second.value = single(e.v[0]);
  first.colour = parse_colour();
  Token c = peek();
  if (!c.is("color") && !c.is("colour")) fail_expected(c, "'color' before the second colour of an old-style entry");
  second.colour = parse_colour();
  entries.push_back(first);
  entries.push_back(second);
}

// `[v pigment-body]`; in an average's map the weight may be left out (1).
void TextureParser::parse_pigment_map_entry(std::vector<MapEntry>& entries, bool weights_optional) {
  MapEntry e;
  const Token n = peek();
  const bool has_value = n.kind == TokenKind::number || n.is("(") || n.is("-") || n.is("+") ||
                         (n.kind == TokenKind::identifier && !is_reserved_word(n.text) && lookup(n) &&
                          std::holds_alternative<Numeric>(*lookup(n)));
  e.value = single(weights_optional && !has_value ? 1.0 : parse_float());
  accept(",");
  e.pigment = std::make_shared<const Pigment>(parse_pigment_contents(default_pigment(), n.loc, "]"));
  entries.push_back(std::move(e));
}

BlendMapValue TextureParser::parse_blend_map(const Token& keyword, bool weights_optional) {
  const NestingGuard guard(*this, keyword);
  BlendMapValue map;
  map.pigments = keyword.is("pigment_map");
  expect("{", " after '" + std::string(keyword.text) + "'");
  Token t = next();
  if (const Value* v = lookup(t); v && std::holds_alternative<BlendMapValue>(*v)) {
    map = std::get<BlendMapValue>(*v);
    if (map.textures || map.pigments != keyword.is("pigment_map"))
      fail_at(t, "this identifier is a " + value_type_name(*v) + ", not a " + std::string(keyword.text));
    expect("}", " after the map identifier");
    return map;
  }
  while (!t.is("}")) {
    if (!t.is("[")) fail_expected(t, "'[' starting a map entry, or '}'");
    if (map.entries.size() >= kMaxMapEntries)
      fail_at(t, "too many entries in the map: POV-Ray allows at most 256");
    if (map.pigments) {
      parse_pigment_map_entry(map.entries, weights_optional);   // reads the closing ']' itself
    } else {
      parse_colour_map_entry(map.entries);
      expect("]", " closing the map entry");
    }
    t = next();
  }
  if (map.entries.empty()) fail_at(keyword, "a map needs at least one entry");
  return map;
}

// `warp { turbulence V [octaves N] [omega W] [lambda L] }`; other warps are refused by name.
void TextureParser::parse_warp(const Token& keyword, Pigment& p) {
  const NestingGuard guard(*this, keyword);
  const Token open = expect("{", " after 'warp'");
  Token kind = next();
  if (kind.is("repeat")) {
    PatternWarp w;
    w.repeat = parse_repeat_warp(kind);
    w.before = p.world_from_pattern;
    p.world_from_pattern = Matrix::identity();
    p.warps.push_back(w);
    return;
  }
  if (kind.is("planar") || kind.is("cylindrical") || kind.is("spherical") || kind.is("toroidal") ||
      kind.is("cubic") || kind.is("black_hole")) {
    PatternWarp w;
    if (kind.is("black_hole")) w.black_hole = parse_black_hole_warp();
    else w.mapping = parse_mapping_warp(kind);
    expect("}", " closing the warp (one warp per warp { })");
    w.before = p.world_from_pattern;
    p.world_from_pattern = Matrix::identity();
    p.warps.push_back(w);
    return;
  }
  if (!kind.is("turbulence")) {
    taint(p.unsupported, UnsupportedFeature{"the warp '" + std::string(kind.text) + "'", kind.loc});
    unget(kind);
    skip_balanced(open);
    return;
  }
  PatternWarp w;
  w.turbulence.amount = parse_vector();
  while (true) {
    Token t = next();
    if (t.is("octaves")) w.turbulence.octaves = clamped_octaves(parse_float());
    else if (t.is("omega")) w.turbulence.omega = static_cast<float>(parse_float());
    else if (t.is("lambda")) w.turbulence.lambda = static_cast<float>(parse_float());
    else if (t.is("}")) break;
    else fail_expected(t, "octaves, omega, lambda or '}' in warp { turbulence … }");
  }
  // Warps and transforms apply in written order: the transforms so far belong before this warp.
  w.before = p.world_from_pattern;
  p.world_from_pattern = Matrix::identity();
  p.warps.push_back(w);
}

// planar [V [,] D] | cylindrical | spherical | toroidal [orientation V] [dist_exp F] [major_radius R] | cubic
// (Parse_Warp): the orientation normalised by its reciprocal length, as VNormalizeEq does.
MappingWarp TextureParser::parse_mapping_warp(const Token& kind) {
  MappingWarp w;
  if (kind.is("cubic")) {
    w.kind = MappingWarpKind::cubic;
    return w;
  }
  if (kind.is("planar")) {
    w.kind = MappingWarpKind::planar;
    if (!peek().is("}")) {   // the orientation and the (then mandatory) distance
      w.orientation = pov_normalized(parse_vector());
      accept(",");
      w.offset = parse_float();
    }
    return w;
  }
  w.kind = kind.is("cylindrical") ? MappingWarpKind::cylindrical
           : kind.is("spherical") ? MappingWarpKind::spherical : MappingWarpKind::toroidal;
  while (true) {
    const Token t = peek();
    if (t.is("orientation")) { next(); w.orientation = pov_normalized(parse_vector()); }
    else if (t.is("dist_exp")) { next(); w.dist_exp = parse_float(); }
    else if (t.is("major_radius") && w.kind == MappingWarpKind::toroidal) { next(); w.major_radius = parse_float(); }
    else return w;
  }
}

// black_hole <centre> [,] radius [strength S] [falloff F] [inverse] [type T] [repeat V] [turbulence V] (Parse_Warp),
// the centre and repeat vector adjusted at each repeat and turbulence as Check_BH_Parameters does.
BlackHoleWarp TextureParser::parse_black_hole_warp() {
  BlackHoleWarp w;
  w.centre = parse_vector();
  accept(",");
  w.radius = parse_float();
  while (true) {
    const Token t = peek();
    if (t.is("strength")) { next(); w.strength = parse_float(); }
    else if (t.is("falloff")) { next(); w.falloff = parse_float(); }
    else if (t.is("inverse")) { next(); w.inverse = true; }
    else if (t.is("type")) { next(); w.type = saturating_cast<int>(parse_float()); }
    else if (t.is("repeat")) {
      next();
      w.repeat_vector = parse_vector();
      w.repeat = true;
      check_black_hole(t, w);
    } else if (t.is("turbulence")) {
      next();
      w.uncertainty = parse_vector();
      w.uncertain = true;
      check_black_hole(t, w);
    } else return w;
  }
}

// Check_BH_Parameters: on each repeated axis the centre is at least the radius and the repeat at least the hole's
// far side plus its jitter (a warning when it grows); a repeat below EPSILON is dropped with a warning.
void TextureParser::check_black_hole(const Token& at, BlackHoleWarp& w) const {
  if (!w.repeat) return;
  const auto general = [](double v) {   // printf's %g, as POV-Ray's warning prints the value
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return std::string(text);
  };
  static const char* const axis_names[3] = {"X", "Y", "Z"};
  for (int a = 0; a < 3; ++a) {
    double& repeat = w.repeat_vector[a];
    if (!(repeat > 0.0)) continue;
    double& centre = w.centre[a];
    if (centre < w.radius) centre = w.radius;
    const double needed = (centre + w.radius) + w.uncertainty[a];
    if (repeat < needed) {
      repeat = needed;
      warn(at.loc, std::string("Black Hole repeat vector ") + axis_names[a] + " too small; increased to " +
                       general(repeat));
    }
    if (repeat < kPovEpsilon) {
      warn(at.loc, std::string("Black Hole repeat vector ") + axis_names[a] + " is less than 0.000000; ignored");
      repeat = 0.0;
    }
  }
}

// `repeat V [offset O] [flip F] }` (Parse_Warp): V must name exactly one axis.
RepeatWarp TextureParser::parse_repeat_warp(const Token& keyword) {
  RepeatWarp r;
  const Vec3 v = parse_vector();
  int axes = 0;
  for (int i = 0; i < 3; ++i)
    if (v[i] != 0.0) {
      r.axis = i;
      ++axes;
    }
  if (axes > 1) fail_at(keyword, "can only repeat along 1 axis");
  if (axes == 0) fail_at(keyword, "no axis specified in repeat");
  r.width = v[r.axis];
  for (Token t = next(); !t.is("}"); t = next()) {
    if (t.is("offset")) r.offset = parse_vector();
    else if (t.is("flip")) {
      const Vec3 f = parse_vector();
      r.flip = {f.x != 0.0 ? -1.0 : 1.0, f.y != 0.0 ? -1.0 : 1.0, f.z != 0.0 ? -1.0 : 1.0};
    } else fail_expected(t, "offset, flip or '}' in warp { repeat … }");
  }
  return r;
}

bool TextureParser::try_pattern_modifier(const Token& t, Pigment& p) {
  if (t.is("color_map") || t.is("colour_map") || t.is("pigment_map")) {
    const bool pigment_map = t.is("pigment_map");
    refuse_map_for_pattern(t, p, pigment_map);
    p.entries = parse_blend_map(t, p.pattern == PatternKind::average).entries;
    return true;
  }
  for (const auto& w : kWaveKeywords)
    if (t.is(w.keyword)) {
      p.wave = w.wave;
      // poly_wave's exponent is optional (Allow_Float): the previous one stays.
      if (w.wave == WaveType::poly && starts_map_expression(peek()) && !starts_colour(peek()))
        p.exponent = single(parse_float());
      return true;
    }
  if (t.is("frequency")) { p.frequency = single(parse_float()); return true; }
  if (t.is("phase")) { p.phase = single(parse_float()); return true; }
  if (t.is("turbulence")) { classic_turbulence(p).amount = parse_vector(); return true; }
  if (t.is("octaves")) { classic_turbulence(p).octaves = clamped_octaves(parse_float()); return true; }
  if (t.is("omega")) { classic_turbulence(p).omega = static_cast<float>(parse_float()); return true; }
  if (t.is("lambda")) { classic_turbulence(p).lambda = static_cast<float>(parse_float()); return true; }
  if (t.is("warp")) { parse_warp(t, p); return true; }
  if (t.is("noise_generator")) {   // this pattern's own generator (POV-Ray's NOISE_FLAGS); 0: the scene's
    const double g = parse_float();
    const int n = static_cast<int>(g);
    if (!(g > -1.0 && g < 4.0)) fail_at(t, "Value for noise_generator must be 0, 1, 2, or 3.");
    // POV-Ray ORs the value into the pattern's flags, so a second noise_generator combines with the first.
    p.noise_generator |= n;
    return true;
  }
  return try_pattern_parameter(t, p) || try_fractal_parameter(t, p);
}

// Parameters that belong to one pattern; POV-Ray refuses them with any other (Not_With).
bool TextureParser::try_pattern_parameter(const Token& t, Pigment& p) {
  auto require = [&](PatternKind kind, std::string_view name) {
    if (p.pattern != kind)
      fail_at(t, "'" + std::string(t.text) + "' cannot be used with a non-" + std::string(name) + " pattern");
  };
  if (t.is("control0") || t.is("control1")) {
    if (p.pattern != PatternKind::quilted)
      fail_at(t, "Keyword '" + std::string(t.text) + "' cannot be used with this pattern (only with quilted).");
    (t.is("control0") ? p.control0 : p.control1) = static_cast<float>(parse_float());
    return true;
  }
  if (t.is("agate_turb")) {
    require(PatternKind::agate, "agate");
    p.agate_turb = single(parse_float());
    classic_turbulence(p);
    return true;
  }
  if (t.is("brick_size")) {
    require(PatternKind::brick, "brick");
    p.brick_size = parse_vector();
    return true;
  }
  if (t.is("metric")) {   // a vector for backward compatibility: only its x is used
    require(PatternKind::crackle, "crackle");
    p.crackle.metric = parse_vector().x;
    return true;
  }
  if (t.is("form")) {
    require(PatternKind::crackle, "crackle");
    p.crackle.form = parse_vector();
    return true;
  }
  if (t.is("offset")) {
    require(PatternKind::crackle, "crackle");
    p.crackle.offset = parse_float();
    return true;
  }
  if (t.is("solid")) {
    require(PatternKind::crackle, "crackle");
    p.crackle.solid = true;
    return true;
  }
  if (t.is("mortar")) {
    require(PatternKind::brick, "brick");
    p.mortar = single(parse_float() - 2 * kPovEpsilon);
    return true;
  }
  if (t.is("interpolate")) {
    require(PatternKind::density_file, "density_file");
    p.density_interpolation = truncated_int(parse_float());
    return true;
  }
  return false;
}

// `uv_mapping PIGMENT_BODY`: the rest of the block is a pigment (from the #default one) evaluated at the hit's
// <u, v, 0> (POV-Ray's UV_MAP_PATTERN, Parse_Item_Into_Blend_List); what came before stays but has no effect.
Pigment TextureParser::uv_mapped_pigment(Pigment outer, const SourceLoc& loc, std::string_view closer) {
  MapEntry e;
  e.pigment = std::make_shared<const Pigment>(parse_pigment_contents(default_pigment(), loc, closer));
  outer.pattern = PatternKind::uv_mapping;
  outer.entries = {e};
  outer.image.reset();
  taint(outer.unsupported, e.pigment->unsupported);
  return outer;
}

Pigment TextureParser::default_pigment() const { return default_texture().layers.back().pigment; }

// The inside of `pigment { … }` or of a pigment_map entry `[v …]`, up to `closer`: an optional pigment
// identifier, then a pattern or colour and modifiers.
Pigment TextureParser::parse_pigment_contents(const Pigment& start, const SourceLoc& loc, std::string_view closer) {
  Pigment p = start;
  p.loc = loc;
  Token t = next();
  if (const Value* v = lookup(t); v && std::holds_alternative<Boxed<Pigment>>(*v)) {
    p = *std::get<Boxed<Pigment>>(*v);
    t = next();
  }
  while (!t.is(closer)) {
    if (t.is("uv_mapping")) {
      const NestingGuard guard(*this, t);   // `uv_mapping uv_mapping …` nests
      return uv_mapped_pigment(p, loc, closer);
    }
    if (try_pigment_item(t, p)) { t = next(); continue; }
    if (t.is("quick_color") || t.is("quick_colour")) {
      // Shown instead of the pigment in draft renders (+Q5 and below, BuildOptions::quick_colours).
      const Colour q = parse_colour();
      if (q.r != -1.0 && q.g != -1.0 && q.b != -1.0) p.quick_colour = q;
      else p.quick_colour.reset();
      t = next();
      continue;
    }
    if (t.kind == TokenKind::identifier && is_reserved_word(t.text)) {
      taint(p.unsupported, skip_unsupported(t, "the pigment item '" + std::string(t.text) + "'"));
      t = next();
      continue;
    }
    fail_expected(t, closer == "}" ? "a colour, a pattern, a transform or '}' in pigment { }"
                                   : "a colour, a pattern, a transform or ']' in the pigment_map entry");
  }
  if (p.pattern == PatternKind::average && p.entries.empty())
    fail_at(t, "an average pigment needs a pigment_map (as in POV-Ray)");
  for (const auto& e : p.entries)
    if (e.pigment) taint(p.unsupported, e.pigment->unsupported);
  return p;
}

}  // namespace povtrace::sdl
