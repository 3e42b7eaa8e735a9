// image_map { … } in pigments and bump_map { … } in normals (povray-sdl-and-geometry.md §11). Facts from POV-Ray
// 3.7's parser (source/backend/parser/parstxtr.cpp Parse_Image, Parse_Image_Map, Parse_Bump_Map; support/
// fileutil.cpp for the extensions; 3.7-stable):
// - The file: a type keyword and a string, or a string alone typed by its extension (.png/.PNG, .tga, .jpg …;
//   an unknown extension is an error). povtrace reads PNG files only: the other types, `function` images and names
//   without an extension (POV-Ray would take the render's output type) are refused by name. The file is read when
//   parsed: a missing file is an error there.
// - After the name, `gamma G` / `gamma srgb` (decoding override) and `premultiplied B` (only B = off, PNG's own
//   storage, is accepted).
// - The gamma handling is the scene's at that point: none before an assumed_gamma or a #version ≥ 3.7, the file's
//   chunks or sRGB for 3.7 scenes, the file's chunks or the working gamma for older scenes with assumed_gamma.
// - image_map items in any order: `once`, `interpolate 2|3|4`, `map_type 0|1|2|5`, `use_colour`/`use_index`
//   (no effect on colours), `repeat <u, v>` (both > 0), `offset <u, v>`, `filter|transmit all F` and
//   `filter|transmit N, F` (palette entry N = int(N + 0.01)). bump_map takes `bump_size`, `use_index` and accepts
//   any map_type (unknown ones map planar) but no filter/transmit.
#include <filesystem>

#include "runtime/image_files.hpp"
#include "parser/interpreter.hpp"
#include "parser/textures/texture_parser.hpp"
#include "parser/textures/image_location.hpp"

namespace povtrace::sdl {

namespace {
bool image_extension(std::string_view ext) {
  static constexpr std::string_view known[] = {".tga", ".TGA", ".ppm", ".PPM", ".pgm", ".PGM", ".gif", ".GIF",
                                               ".iff", ".IFF", ".jpg", ".JPG", ".jpeg", ".JPEG", ".tif", ".TIF",
                                               ".tiff", ".TIFF", ".bmp", ".BMP", ".exr", ".EXR", ".hdr", ".HDR"};
  return std::find(std::begin(known), std::end(known), ext) != std::end(known);
}
}  // namespace

// POV-Ray's gamma handling mode at this point of the parse (parse.cpp, tokenize.cpp: #version and assumed_gamma
// set it; a scene without #version counts as 3.62).
ImageGamma TextureParser::current_image_gamma() const {
  ImageGamma g;
  const int version = version_directive_seen() ? language_version() : 362;
  if (assumed_gamma())
    g.mode = version < 370 ? ImageGammaMode::file_or_working : ImageGammaMode::file_or_srgb;
  else
    g.mode = version_directive_seen() && version >= 370 ? ImageGammaMode::file_or_srgb : ImageGammaMode::none;
  g.working = assumed_gamma().value_or(1.0);
  return g;
}

// `[type] "file" [gamma G] [premultiplied B]`: the file located and checked, or `unsupported` set.
void TextureParser::parse_image_file(const Token& keyword, ImageMap& m, Unsupported& unsupported) {
  Token t = next();
  if (t.is("function")) {
    taint(unsupported, skip_unsupported(t, "an image made from a function in " + std::string(keyword.text)));
    return;
  }
  std::string type;
  if (t.kind == TokenKind::identifier && is_image_type_word(t.text)) type = std::string(t.text);
  else unget(t);
  m.file_loc = peek().loc;
  const Token name_token = peek();
  const std::string name = parse_string();
  if (type.empty()) {
    const std::string ext = std::filesystem::path(name).extension().string();
    if (ext == ".png" || ext == ".PNG") type = "png";
    else if (ext.empty()) type = "(the output file type: the name has no extension)";
    else if (image_extension(ext)) type = ext;
    else fail_at(name_token, "could not determine a valid image file type from the extension '" + ext + "'");
  }
  if (type != "png") {
    taint(unsupported, UnsupportedFeature{std::string(keyword.text) + " from a " + type + " image", name_token.loc});
  } else {
    m.file = locate_image_file(name, library_paths());
    std::error_code ec;
    if (!std::filesystem::is_regular_file(m.file, ec))
      fail_at(name_token, "cannot open the image file '" + name + "' (looked in the working directory and the "
                          "library paths)");
  }
  m.gamma = current_image_gamma();
  parse_image_decoding(m, unsupported);
}

void TextureParser::parse_image_decoding(ImageMap& m, Unsupported& unsupported) {
  while (true) {
    Token t = next();
    if (t.is("gamma")) {
      m.gamma.given = true;
      if (peek().is("srgb")) {
        next();
        m.gamma.given_srgb = true;
        continue;
      }
      const double g = parse_float();
      if (g <= 0) fail_at(t, "gamma value must be positive");
      m.gamma.given_gamma = g;
    } else if (t.is("premultiplied")) {
      if (static_cast<int>(parse_float()) != 0)
        taint(unsupported, UnsupportedFeature{"an image read as premultiplied", t.loc});
    } else {
      unget(t);
      return;
    }
  }
}

// `filter|transmit all F` or `filter|transmit N, F` after the keyword.
void TextureParser::parse_image_channel(const Token& keyword, ImageMap& m) {
  ImageChannelSetting s;
  s.transmit = keyword.is("transmit");
  s.loc = keyword.loc;
  if (accept("all")) {
    s.value = parse_float();
  } else {
    s.index = static_cast<int>(parse_float() + 0.01);
    if (s.index < 0)
      fail_at(keyword, std::string(keyword.text) + " color register value out of range (as in POV-Ray)");
    accept(",");
    s.value = parse_float();
  }
  m.channels.push_back(s);
  m.has_filter = true;
}

bool TextureParser::try_image_item(const Token& t, ImageMap& m, bool bump) {
  if (t.is("once")) { m.once = true; return true; }
  if (t.is("use_colour") || t.is("use_color")) { m.use_index = false; return true; }
  if (t.is("use_index")) { m.use_index = true; return true; }
  if (t.is("interpolate")) {
    m.interpolate = static_cast<int>(parse_float());
    if (!bump && m.interpolate != 2 && m.interpolate != 3 && m.interpolate != 4)
      fail_at(t, "invalid interpolate value (image_map takes 2, 3 or 4)");
    return true;
  }
  if (t.is("map_type")) {
    m.map_type = static_cast<int>(parse_float());
    if (!bump && m.map_type != 0 && m.map_type != 1 && m.map_type != 2 && m.map_type != 5)
      fail_at(t, "invalid map_type value (image_map takes 0, 1, 2 or 5)");
    return true;
  }
  if (t.is("repeat")) {
    const auto [u, v] = parse_uv_vector("after 'repeat'");
    if (u <= 0 || v <= 0) fail_at(t, "zero or negative image repeat vector");
    m.repeat_u = u;
    m.repeat_v = v;
    return true;
  }
  if (t.is("offset")) {
    const auto [u, v] = parse_uv_vector("after 'offset'");
    m.offset_u = u;
    m.offset_v = v;
    return true;
  }
  if (!bump && (t.is("filter") || t.is("transmit"))) {
    parse_image_channel(t, m);
    return true;
  }
  if (!bump && t.is("alpha"))
    fail_at(t, "'alpha' is discontinued: use filter (POV-Ray 3.7 refuses it here too)");
  return false;
}

// image_map { … } (the pigment's pattern).
void TextureParser::parse_image_map(const Token& keyword, Pigment& p) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'image_map'");
  auto m = std::make_shared<ImageMap>();
  parse_image_file(keyword, *m, p.unsupported);
  for (Token t = next(); !t.is("}"); t = next())
    if (!try_image_item(t, *m, false))
      fail_expected(t, "once, interpolate, map_type, use_colour, use_index, repeat, offset, filter, transmit or "
                       "'}' in image_map { }");
  p.pattern = PatternKind::image_map;
  p.frequency = 0.0;
  p.entries.clear();
  p.image = std::move(m);
}

// image_pattern { [type] "file" [gamma G] once map_type interpolate use_colour use_index use_alpha repeat offset }
// (POV-Ray's Parse_Image_Pattern): a pattern whose value is the image's grey (or with use_alpha its alpha, or red
// without an alpha channel), read without gamma handling as a bump_map's image; the pattern's map, modifiers and
// wave follow as for any pattern.
void TextureParser::parse_image_pattern(const Token& keyword, Pigment& p) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'image_pattern'");
  auto m = std::make_shared<ImageMap>();
  parse_image_file(keyword, *m, p.unsupported);
  m->gamma.mode = ImageGammaMode::none;
  m->gamma.working = 1.0;
  for (Token t = next(); !t.is("}"); t = next()) {
    if (t.is("use_alpha")) {
      m->use_alpha = true;
      continue;
    }
    if (t.is("use_colour") || t.is("use_color") || t.is("use_index")) m->use_alpha = false;
    if (t.is("interpolate")) {   // 1 and values beyond 4 leave POV-Ray's weights undefined
      m->interpolate = static_cast<int>(parse_float());
      if (m->interpolate < 0 || m->interpolate == 1 || m->interpolate > 4)
        taint(p.unsupported, UnsupportedFeature{"image_pattern interpolate " + std::to_string(m->interpolate), t.loc});
      continue;
    }
    if (!try_image_item(t, *m, true))
      fail_expected(t, "once, interpolate, map_type, use_colour, use_index, use_alpha, repeat, offset or '}' in "
                       "image_pattern { }");
  }
  p.pattern = PatternKind::image_pattern;
  p.frequency = 0.0;   // Parse_Pattern sets Frequency 0 for it
  p.image = std::move(m);
}

// bump_map { … } (the normal's pattern): the image is read without gamma handling unless `gamma` is given, and
// then decoded with that gamma alone (Parse_Image's GammaCorrect off for bump maps).
void TextureParser::parse_bump_map(const Token& keyword, Normal& n) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'bump_map'");
  auto m = std::make_shared<ImageMap>();
  parse_image_file(keyword, *m, n.unsupported);
  m->gamma.mode = ImageGammaMode::none;
  m->gamma.working = 1.0;
  for (Token t = next(); !t.is("}"); t = next()) {
    if (t.is("bump_size")) {
      n.amount = parse_float();
      continue;
    }
    if (t.is("interpolate")) {   // 1 and values beyond 4 leave POV-Ray's weights undefined
      m->interpolate = static_cast<int>(parse_float());
      if (m->interpolate < 0 || m->interpolate == 1 || m->interpolate > 4)
        taint(n.unsupported, UnsupportedFeature{"bump_map interpolate " + std::to_string(m->interpolate), t.loc});
      continue;
    }
    if (!try_image_item(t, *m, true))
      fail_expected(t, "once, interpolate, map_type, bump_size, use_colour, use_index, repeat, offset or '}' in "
                       "bump_map { }");
  }
  n.pattern.pattern = PatternKind::image_map;
  n.pattern.frequency = 0.0;
  n.pattern.image = std::move(m);
}

}  // namespace povtrace::sdl
