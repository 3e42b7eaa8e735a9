// text { ttf "font" "string" thickness, offset modifiers } and text { internal N … } (povray-sdl-and-geometry.md
// §8). Facts from POV-Ray 3.7's parser (source/backend/parser/parse.cpp Parse_TrueType; shape/truetype.cpp
// OpenFontFile; support/fileutil.cpp Locate_File; base/fileinputoutput.cpp IMemStream; 3.7-stable):
// - After `ttf` a file name, or after `internal` a float (truncated) naming a built-in font: 1 timrom, 2 cyrvetic,
//   3 crystal, anything else povlogo. POV-Ray compiles in byte-for-byte copies of the four .ttf files it ships;
//   povtrace reads those files from the library path instead (the POV-Ray include folder).
// - Then the string, the extrusion thickness and the offset vector (a float is promoted), commas optional.
// - The font file is searched like an include file with the extensions .ttf/.TTF: the exact name first when it
//   ends in one of them, the working directory, then each library path.
// - Fonts stay open for the whole parse, found again by the name the scene writes compared with the name the
//   file was found under (so only fonts found in the working directory, or named by their full path, are shared
//   between text objects, glyph cache included). Built-in fonts are never shared. A font is read with the string
//   encoding (global_settings { charset }) in force when it is first opened.
// - Before the object modifiers the whole text is rotated by <0.001, 0.001, 0.001> degrees ("to fix cracks in text
//   that lies along an axis"): textures attached later are not affected, the bounding box is.
#include <filesystem>
#include <fstream>
#include <iterator>

#include "parser/expressions/int_cast.hpp"
#include "parser/objects/object_transform.hpp"
#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"

namespace povtrace::sdl {

namespace {
namespace fs = std::filesystem;

constexpr double kAntiCrackRotation = 0.001;   // degrees about x, y and z (Parse_TrueType)

// FindFile's candidate names for a font: the exact name first if it ends in .ttf/.TTF, then with each extension.
std::vector<std::string> font_candidates(const std::string& name) {
  const auto dot = name.find_last_of('.');
  const bool has_ext = dot != std::string::npos && (name.substr(dot) == ".ttf" || name.substr(dot) == ".TTF");
  if (has_ext) return {name, name + ".ttf", name + ".TTF"};
  return {name + ".ttf", name + ".TTF", name};
}

struct FoundFont {
  std::string name;   // as POV-Ray's front end reports it: as written in the working directory, else dir/name
  fs::path path;
};

std::optional<FoundFont> find_font(const std::string& name, const std::vector<fs::path>& library_paths) {
  for (const auto& candidate : font_candidates(name)) {
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return FoundFont{candidate, candidate};
    if (fs::path(candidate).is_absolute()) continue;
    for (const auto& dir : library_paths)
      if (fs::is_regular_file(dir / candidate, ec)) return FoundFont{(dir / candidate).string(), dir / candidate};
  }
  return std::nullopt;
}

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ttf::FontError("cannot open the file");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const char* internal_font_file(int id) {
  switch (id) {
    case 1: return "timrom.ttf";
    case 2: return "cyrvetic.ttf";
    case 3: return "crystal.ttf";
    default: return "povlogo.ttf";
  }
}
}  // namespace

ttf::Font& ObjectParser::font_for_text(const Token& at, const std::string& name) {
  for (auto& [found_as, font] : fonts_)
    if (found_as == name) return *font;
  const auto found = find_font(name, library_paths());
  if (!found) {
    std::string searched = "the working directory";
    for (const auto& d : library_paths()) searched += ", " + d.string();
    fail_at(at, "cannot find font file \"" + name + "\" (searched " + searched + ", also with .ttf and .TTF)");
  }
  try {
    fonts_.emplace_back(found->name, std::make_unique<ttf::Font>(read_bytes(found->path), string_encoding_));
  } catch (const ttf::FontError& e) {
    fail_at(at, "cannot read TrueType font file \"" + found->path.string() + "\": " + e.what());
  }
  return *fonts_.back().second;
}

// A built-in font is opened afresh for every text object (POV-Ray keeps no cache entry for it).
ttf::Font& ObjectParser::internal_font(const Token& at, int id) {
  const std::string file = internal_font_file(id);
  const auto found = find_font(file, library_paths());
  if (!found)
    fail_at(at, "internal font " + std::to_string(id) + " is POV-Ray's built-in copy of " + file +
                    ", which povtrace reads from the POV-Ray include folder; it is not in the library path");
  try {
    fonts_.emplace_back(std::string(), std::make_unique<ttf::Font>(read_bytes(found->path), string_encoding_));
  } catch (const ttf::FontError& e) {
    fail_at(at, "cannot read TrueType font file \"" + found->path.string() + "\": " + e.what());
  }
  return *fonts_.back().second;
}

Object ObjectParser::parse_text(const Token& keyword) {
  expect("{", " after 'text'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  const Token kind = next();
  const Token font_at = peek();
  ttf::Font* font = nullptr;
  if (kind.is("ttf")) font = &font_for_text(font_at, parse_string());
  else if (kind.is("internal")) font = &internal_font(font_at, saturating_cast<int>(parse_float()));
  else fail_expected(kind, "ttf or internal after 'text {'");
  accept(",");
  const Token string_at = peek();
  const std::string string = parse_string();
  accept(",");
  const double thickness = parse_float();
  accept(",");
  const Vec3 offset = parse_vector();
  Text text;
  try {
    text = ttf::lay_out_text(*font, ttf::character_codes(string, string_encoding_, language_version()), thickness,
                             offset);
  } catch (const ttf::FontError& e) {
    fail_at(string_at, "cannot lay out this text with the font: " + std::string(e.what()));
  }
  const Matrix anti_crack = Matrix::rotation({kAntiCrackRotation, kAntiCrackRotation, kAntiCrackRotation});
  o.shape = std::move(text);
  extents().made(o);
  transform_noted(o, anti_crack, notes_pool());   // POV-Ray turns the new text (and its box) by the anti-crack rotation
  parse_object_modifiers(o);
  return o;
}

}  // namespace povtrace::sdl
