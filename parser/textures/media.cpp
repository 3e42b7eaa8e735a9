// media { … } and density { … } (POV-Ray 3.7's Parse_Media and Parse_Media_Density_Pattern, parser/parstxtr.cpp).
// A density is a pigment whose maps are density maps: its colour scales the media's coefficients at a point.
#include "parser/interpreter.hpp"
#include "parser/lexing/reserved_words.hpp"
#include "parser/textures/texture_parser.hpp"
#include "scene/description_transforms.hpp"

namespace povtrace::sdl {

namespace {
// POV-Ray keeps media colours in single precision (RGBColour).
Colour single_rgb(const Colour& c) {
  return Colour{static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b), 0, 0};
}
}  // namespace

Media TextureParser::starting_media() const {
  Media m;
  if (language_version() < 350) {   // before 3.5 the default was method 1 with 10 intervals of 1 sample
    m.method = 1;
    m.intervals = 10;
    m.min_samples = m.max_samples = 1;
  }
  return m;
}

Media TextureParser::parse_media_block(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'media'");
  Media m = starting_media();
  Token t = next();
  if (const Value* v = lookup(t); v && std::holds_alternative<Boxed<Media>>(*v)) {
    m = *std::get<Boxed<Media>>(*v);
    t = next();
  }
  m.loc = keyword.loc;
  for (; !t.is("}"); t = next()) {
    if (parse_media_item(t, m)) continue;
    Matrix tr;
    if (try_transform(t, tr)) {   // moves the densities written so far (POV-Ray's Transform_Density)
      for (Pigment& d : m.densities) transform_pattern(d, tr);
      continue;
    }
    fail_expected(t, "absorption, emission, scattering, density, method, intervals, samples, a transform or '}' "
                     "in media { }");
  }
  return m;
}

bool TextureParser::parse_media_item(const Token& t, Media& m) {
  if (t.is("intervals")) {
    m.intervals = static_cast<int>(parse_float());
    if (m.intervals < 1) fail_at(t, "at least one interval is needed in media (as in POV-Ray)");
  } else if (t.is("samples")) {
    m.min_samples = static_cast<int>(parse_float());
    accept(",");
    m.max_samples = static_cast<int>(optional_float(m.min_samples));
    if (m.min_samples < 1) fail_at(t, "at least one sample per interval is needed in media (as in POV-Ray)");
    if (m.max_samples < m.min_samples)
      fail_at(t, "the maximum number of media samples is smaller than the minimum (as in POV-Ray)");
  } else if (t.is("method")) {
    m.method = static_cast<int>(parse_float());
    if (m.method < 1 || m.method > 3) fail_at(t, "media sample method choices are 1, 2 or 3 (as in POV-Ray)");
  } else if (t.is("jitter")) {
    m.jitter = parse_float();
  } else if (t.is("aa_threshold")) {
    m.aa_threshold = parse_float();
    if (m.aa_threshold <= 0) fail_at(t, "aa_threshold in media must be greater than zero (as in POV-Ray)");
  } else if (t.is("aa_level")) {
    m.aa_level = static_cast<int>(parse_float());
    if (m.aa_level < 1) fail_at(t, "aa_level in media must be at least one (as in POV-Ray)");
  } else if (t.is("collect")) {
    m.collect = optional_float(1.0) > 0.0;
  } else if (t.is("absorption")) {
    m.absorption = single_rgb(parse_colour());
  } else if (t.is("emission")) {
    m.emission = single_rgb(parse_colour());
  } else if (t.is("scattering")) {
    parse_scattering(t, m);
  } else if (t.is("confidence")) {
    m.confidence = parse_float();
    if (m.confidence < 0.0 || m.confidence >= 1.0)
      fail_at(t, "the media confidence must be at least 0 and below 1 (as in POV-Ray)");
  } else if (t.is("variance")) {
    m.variance = parse_float();
  } else if (t.is("ratio")) {
    m.ratio = parse_float();
  } else if (t.is("density")) {
    m.densities.push_back(parse_density_block(t));
    taint(m.unsupported, m.densities.back().unsupported);
  } else {
    return false;
  }
  return true;
}

// scattering { type, colour [eccentricity g] [extinction e] }
void TextureParser::parse_scattering(const Token& keyword, Media& m) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'scattering'");
  m.scattering_type = static_cast<int>(parse_float());
  if (m.scattering_type < 1 || m.scattering_type > 5)   // POV-Ray warns and scatters isotropically
    warn(keyword.loc, "unknown media scattering type " + std::to_string(m.scattering_type) +
                          " (1 to 5): scattering isotropically, as POV-Ray does");
  accept(",");
  m.scattering = single_rgb(parse_colour());
  for (Token t = next(); !t.is("}"); t = next()) {
    if (t.is("eccentricity")) {
      if (m.scattering_type != 5)
        fail_at(t, "eccentricity can only be used with scattering type 5 (Henyey-Greenstein), as in POV-Ray");
      m.eccentricity = parse_float();
    } else if (t.is("extinction")) {
      m.extinction = parse_float();
    } else {
      fail_expected(t, "eccentricity, extinction or '}' in scattering { }");
    }
  }
}

Pigment TextureParser::parse_density_block(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'density'");
  return parse_density_contents(keyword.loc, "}");
}

// The inside of density { } or of a density_map entry, up to `closer`: a pigment body whose map may be a
// density_map (entries are densities) and which may start with a density identifier.
Pigment TextureParser::parse_density_contents(const SourceLoc& loc, std::string_view closer) {
  Pigment d;   // POV-Ray's Create_Pigment: a plain black density until a colour or pattern is given
  d.loc = loc;
  Token t = next();
  if (const Value* v = lookup(t); v && std::holds_alternative<Boxed<DensityValue>>(*v)) {
    d = std::get<Boxed<DensityValue>>(*v)->density;
    t = next();
  }
  for (; !t.is(closer); t = next()) {
    if (t.is("density_map")) {
      refuse_map_for_pattern(t, d, false);
      d.entries = parse_density_map(t).entries;
      continue;
    }
    if (t.is("pigment_map")) fail_at(t, "pigment_map is only allowed in a pigment; a density uses density_map");
    if (t.is("uv_mapping")) fail_at(t, "uv_mapping cannot be used in a density (media have no surface)");
    if (try_pigment_item(t, d)) continue;
    if (t.kind == TokenKind::identifier && is_reserved_word(t.text)) {
      taint(d.unsupported, skip_unsupported(t, "the density item '" + std::string(t.text) + "'"));
      continue;
    }
    fail_expected(t, closer == "}" ? "a colour, a pattern, density_map, a transform or '}' in density { }"
                                   : "a colour, a pattern, a transform or ']' in the density_map entry");
  }
  if (d.pattern == PatternKind::average && d.entries.empty())
    fail_at(t, "an average density needs a density_map (as in POV-Ray)");
  for (const auto& e : d.entries)
    if (e.pigment) taint(d.unsupported, e.pigment->unsupported);
  return d;
}

// density_map { [v density-body] … } or a declared one.
BlendMapValue TextureParser::parse_density_map(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  BlendMapValue map;
  map.densities = true;
  expect("{", " after 'density_map'");
  Token t = next();
  if (const Value* v = lookup(t); v && std::holds_alternative<BlendMapValue>(*v)) {
    map = std::get<BlendMapValue>(*v);
    if (!map.densities) fail_at(t, "this identifier is a " + value_type_name(*v) + ", not a density_map");
    expect("}", " after the map identifier");
    return map;
  }
  for (; !t.is("}"); t = next()) {
    if (!t.is("[")) fail_expected(t, "'[' starting a density_map entry, or '}'");
    if (map.entries.size() >= 256) fail_at(t, "too many entries in the map: POV-Ray allows at most 256");
    MapEntry e;
    const Token at = peek();
    e.value = static_cast<double>(static_cast<float>(parse_float()));
    accept(",");
    e.pigment = std::make_shared<const Pigment>(parse_density_contents(at.loc, "]"));
    map.entries.push_back(std::move(e));
  }
  if (map.entries.empty()) fail_at(keyword, "a map needs at least one entry");
  return map;
}

}  // namespace povtrace::sdl
