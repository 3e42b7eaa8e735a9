// normal { [N_id] [pattern [, amount]] modifiers } (POV-Ray 3.7 parstxtr.cpp Parse_Tnormal and Parse_Pattern with
// NORMAL_TYPE): the normal-only patterns, any pigment pattern used as a normal, the amount after the pattern,
// bump_size, accuracy, no_bump_scale, slope_map, and the pattern modifiers shared with pigments.
#include "parser/interpreter.hpp"
#include "parser/textures/texture_parser.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
struct NormalOnly {
  std::string_view keyword;
  NormalKind kind;
};
constexpr NormalOnly kNormalOnly[] = {
    {"bumps", NormalKind::bumps},       {"dents", NormalKind::dents}, {"wrinkles", NormalKind::wrinkles},
    {"ripples", NormalKind::ripples},   {"waves", NormalKind::waves},
};

double single(double d) { return static_cast<double>(static_cast<float>(d)); }

// POV-Ray sets the sampling distance of the list patterns back to its default when they are (re)selected.
constexpr double kDefaultAccuracy = 0.02;
}  // namespace

// The pattern keyword of a normal: a normal-only pattern, a list pattern (whose entries, when written, are
// normals: refused by name until normal maps are rendered) or any pigment pattern povtrace renders.
bool TextureParser::try_normal_pattern(const Token& t, Normal& n) {
  for (const auto& k : kNormalOnly)
    if (t.is(k.keyword)) {
      n.kind = k.kind;
      n.has_type = true;
      return true;
    }
  if (t.is("facets")) {   // Parse_Pattern's FACETS_TOKEN: its defaults reset each time it is chosen
    n.kind = NormalKind::facets;
    n.facets_size = 0.1;
    n.facets_coords = 0.0;
    n.facets_metric = 2.0;
    n.has_type = true;
    return true;
  }
  if (t.is("quilted")) {   // a normal of its own (POV-Ray's normal.cpp quilted), with the pattern's controls
    try_pattern(t, n.pattern);
    n.kind = NormalKind::quilted;
    n.has_type = true;
    return true;
  }
  if (t.is("checker") || t.is("hexagon") || t.is("brick")) {
    const PatternKind kind = t.is("checker") ? PatternKind::checker
                             : t.is("hexagon") ? PatternKind::hexagon : PatternKind::brick;
    if (kind == PatternKind::brick && n.pattern.pattern != PatternKind::brick) {
      n.pattern.brick_size = {8, 3, 4.5};
      n.pattern.mortar = single(0.5 - 2e-10);
    }
    n.kind = NormalKind::pattern;
    n.pattern.pattern = kind;
    n.pattern.frequency = 0.0;
    n.accuracy = kDefaultAccuracy;
    n.has_type = true;
    parse_normal_list(n, kind == PatternKind::hexagon ? 3 : 2);
    return true;
  }
  if (t.is("average")) {   // the weighted mean of a normal_map's normals (Do_Average_Normals)
    n.kind = NormalKind::average;
    n.has_type = true;
    return true;
  }
  if (t.is("image_map")) fail_at(t, "image_map can only be used in a pigment (as in POV-Ray)");
  if (t.is("bump_map")) {
    parse_bump_map(t, n);
    n.kind = NormalKind::bump_map;
    n.has_type = true;
    return true;
  }
  if (try_pattern(t, n.pattern)) {
    n.kind = NormalKind::pattern;
    n.has_type = true;
    return true;
  }
  return false;
}

// `slope_map { [v, <height, slope>] … }` (Parse_Blend_Map with SLOPE_TYPE). The normal-only patterns ignore it.
std::vector<SlopeEntry> TextureParser::parse_slope_map(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'slope_map'");
  std::vector<SlopeEntry> entries;
  for (Token t = next(); !t.is("}"); t = next()) {
    if (!t.is("[")) fail_expected(t, "'[' starting a slope_map entry, or '}'");
    if (entries.size() >= 256) fail_at(t, "too many entries in the map: POV-Ray allows at most 256");
    SlopeEntry e;
    e.value = single(parse_float());
    accept(",");
    const Token at = peek();
    const Numeric v = parse_additive();
    if (v.terms < 2) fail_at(at, "expected <height, slope> in the slope_map entry");
    e.height = v.v[0];
    e.slope = v.v[1];
    expect("]", " closing the slope_map entry");
    entries.push_back(e);
  }
  if (entries.empty()) fail_at(keyword, "a map needs at least one entry");
  return entries;
}

bool TextureParser::try_normal_modifier(const Token& t, Normal& n) {
  Matrix m;
  if (try_transform(t, m)) {
    n.pattern.world_from_pattern = n.pattern.world_from_pattern * m;
    return true;
  }
  if (t.is("bump_size")) { n.amount = parse_float(); return true; }
  // facets' own items (POV-Ray: "coords" and "size" are only allowed with facets; metric is also crackle's).
  if (t.is("coords") || t.is("size") || (t.is("metric") && n.kind == NormalKind::facets)) {
    if (n.kind != NormalKind::facets) fail_at(t, "'" + std::string(t.text) + "' can only be used with facets");
    if (t.is("coords")) n.facets_coords = parse_float();
    else if (t.is("size")) n.facets_size = parse_float();
    else n.facets_metric = parse_vector().x;   // a vector of which only x counts, as POV-Ray reads it
    return true;
  }
  if (t.is("accuracy")) { n.accuracy = parse_float(); return true; }
  if (t.is("no_bump_scale")) { n.no_bump_scale = true; return true; }
  if (t.is("slope_map")) {
    const PatternKind k = n.pattern.pattern;
    if (n.kind == NormalKind::pattern &&
        (k == PatternKind::checker || k == PatternKind::hexagon || k == PatternKind::brick))
      fail_at(t, "slope_map cannot be used with this normal type (as in POV-Ray)");
    n.slope_map = parse_slope_map(t);
    return true;
  }
  if (t.is("color_map") || t.is("colour_map") || t.is("pigment_map"))
    fail_at(t, "'" + std::string(t.text) + "' can only be used in a pigment");
  if (t.is("normal_map")) {
    parse_normal_map(t, n);
    return true;
  }
  return try_pattern_modifier(t, n.pattern);
}

// The normals of a list pattern (Parse_Blend_List with NORMAL_TYPE): `checker normal { … }, normal { … }`. With none
// written the pattern is an ordinary pattern normal; otherwise the entries take the values 0, 1, 2 and those not
// written are the #default normal (none: the surface normal is left as it is).
void TextureParser::parse_normal_list(Normal& n, int count) {
  std::vector<NormalMapEntry> entries;
  while (static_cast<int>(entries.size()) < count && peek().is("normal")) {
    const Token entry = next();
    entries.push_back({0, std::make_shared<const Normal>(parse_normal_block(entry, starting_normal(nullptr)))});
    taint(n.unsupported, entries.back().normal->unsupported);
    accept(",");
  }
  if (entries.empty()) return;
  while (static_cast<int>(entries.size()) < count) entries.push_back({0, default_normal()});
  for (std::size_t i = 0; i < entries.size(); ++i) entries[i].value = static_cast<double>(i);
  n.map = std::move(entries);
}

// `normal_map { [value NORMAL_BODY] … }` (Parse_Blend_Map with NORMAL_TYPE): each entry's normal starts from the
// #default normal. An average's entries take an optional weight (1 when left out) and keep their written order.
void TextureParser::parse_normal_map(const Token& keyword, Normal& n) {
  const NestingGuard guard(*this, keyword);
  if (n.kind != NormalKind::pattern && n.kind != NormalKind::average)
    fail_unsupported(keyword, "'normal_map' with a normal-only pattern");
  expect("{", " after 'normal_map'");
  std::vector<NormalMapEntry> entries;
  for (Token t = next(); !t.is("}"); t = next()) {
    if (!t.is("[")) fail_expected(t, "'[' starting a normal_map entry, or '}'");
    if (entries.size() >= 256) fail_at(t, "too many entries in the map: POV-Ray allows at most 256");
    NormalMapEntry e;
    e.value = single(n.kind == NormalKind::average ? optional_float(1.0) : parse_float());
    accept(",");
    const Normal start = starting_normal(nullptr);
    e.normal = std::make_shared<const Normal>(parse_normal_contents(t, start, "]"));
    taint(n.unsupported, e.normal->unsupported);
    entries.push_back(std::move(e));
  }
  if (entries.empty()) fail_at(keyword, "a map needs at least one entry");
  n.map = std::move(entries);
}

// The #default normal as a map entry: null when there is none (the entry then leaves the normal as it is).
std::shared_ptr<const Normal> TextureParser::default_normal() const { return default_texture().layers.back().normal; }

Normal TextureParser::parse_normal_block(const Token& keyword, const Normal& start) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'normal'");
  return parse_normal_contents(keyword, start);
}

// The inside of normal { … } up to its '}'. `uv_mapping NORMAL_BODY`: the rest of the block is a normal (from the
// #default one) evaluated at the hit's <u, v, 0> (POV-Ray's UV_MAP_PATTERN in Parse_Pattern).
Normal TextureParser::parse_normal_contents(const Token& keyword, const Normal& start, std::string_view closing) {
  Normal n = start;
  n.loc = keyword.loc;
  Token t = next();
  if (const Value* v = lookup(t); v && std::holds_alternative<Boxed<Normal>>(*v)) {
    n = *std::get<Boxed<Normal>>(*v);
    t = next();
  }
  if (t.is("uv_mapping")) {
    const NestingGuard guard(*this, t);   // `uv_mapping uv_mapping …` nests
    auto inner = std::make_shared<const Normal>(parse_normal_contents(keyword, starting_normal(nullptr), closing));
    n.kind = NormalKind::uv_mapping;
    n.has_type = true;
    n.unsupported = inner->unsupported;
    n.uv_normal = std::move(inner);
    return n;
  }
  if (try_normal_pattern(t, n)) {
    accept(",");
    n.amount = optional_float(n.amount);
    t = next();
  }
  while (!t.is(closing)) {
    if (try_normal_modifier(t, n)) { t = next(); continue; }
    if (t.kind == TokenKind::identifier && is_reserved_word(t.text)) {
      taint(n.unsupported, skip_unsupported(t, "the normal item '" + std::string(t.text) + "'"));
      // An unrendered pattern with a block (pigment_pattern { … }, image_pattern { … }) may carry the amount.
      if (accept(",") || peek().kind == TokenKind::number) n.amount = parse_float();
      t = next();
      continue;
    }
    fail_expected(t, "a normal pattern, bump_size, accuracy, a transform or '" + std::string(closing) +
                         (closing == "]" ? "' closing the normal_map entry" : "' in normal { }"));
  }
  if (n.kind == NormalKind::average && n.map.empty())
    fail_at(keyword, "an average normal needs a normal_map giving the normals it averages");
  taint(n.unsupported, n.pattern.unsupported);
  // A normal without a type is legal until an object uses it (POV-Ray's Post_Tnormal: `#default { normal {
  // bump_size 2 } }` is fine when every object names its pattern): see Interpreter::check_normal_types.
  return n;
}

Normal TextureParser::starting_normal(const Normal* current) const {
  if (current) return *current;
  const auto& defaults = default_texture().layers.back().normal;
  return defaults ? *defaults : Normal{};
}

}  // namespace povtrace::sdl
