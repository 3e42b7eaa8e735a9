// height_field (povray-sdl-and-geometry.md §8). Facts from POV-Ray 3.7's parser (source/backend/parser/parse.cpp
// Parse_HField, parstxtr.cpp Parse_Image, 3.7-stable):
// - height_field { [FILE_TYPE] "file" [gamma G] [premultiplied B] [smooth] [water_level W]… modifiers }: the file
//   type keyword is optional when the name has an extension; `smooth` and `water_level` may come in any order
//   before the object modifiers (water_level is divided by 256 before #version 2.0).
// - The image is read without gamma correction (a height field's values are data), so `gamma 1.0` changes nothing;
//   another gamma would decode the values, which povtrace does not do (refused by name).
// - `hierarchy [B]` only changes POV-Ray's internal bounding blocks, never the image: accepted and ignored.
// The parser keeps the file's path (found in the working directory or a +L library path, else as written); the
// renderer reads the image when it builds the scene. Only PNG images are read (other types are refused by name),
// and `function W, H { … }` height fields are refused by name.
#include <filesystem>

#include "parser/image_files.hpp"
#include "parser/interpreter.hpp"

namespace povtrace::sdl {

std::string Interpreter::locate_image_file(const std::string& name) const {
  const std::filesystem::path p(name);
  if (p.is_absolute()) return name;
  std::vector<std::filesystem::path> dirs{std::filesystem::current_path()};
  for (const auto& d : options_.library_paths) dirs.push_back(d);
  for (const auto& d : dirs) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(d / p, ec)) return (d / p).string();
  }
  return name;
}

// The image part of a height field: the type keyword (optional), the name, gamma and premultiplied.
void Interpreter::parse_height_field_image(const Token& keyword, HeightField& h, Object& o) {
  Token t = next();
  std::string type;
  if (t.is("function")) {   // function W, H { … }: skipped up to its block's end
    taint(o.unsupported, skip_unsupported(t, "a height_field made from a function"));
    return;
  }
  if (t.kind == TokenKind::identifier && is_image_type_word(t.text)) type = std::string(t.text);
  else unget(t);
  h.file_loc = peek().loc;
  const std::string name = parse_string();
  if (type.empty() && lower_extension(name) != ".png") type = "'" + std::filesystem::path(name).extension().string() + "'";
  if (!type.empty() && type != "png")
    taint(o.unsupported, UnsupportedFeature{"a height_field read from a " + type + " image", keyword.loc});
  h.file = locate_image_file(name);
  while (true) {
    t = next();
    if (t.is("gamma")) {
      const double g = parse_float();
      if (g != 1.0) taint(o.unsupported, UnsupportedFeature{"a height_field image decoded with a gamma", t.loc});
    } else if (t.is("premultiplied")) {
      parse_float();   // only the alpha channel's storage, which heights ignore
    } else {
      unget(t);
      return;
    }
  }
}

Object Interpreter::parse_height_field(const Token& keyword) {
  expect("{", " after 'height_field'");
  Object o;
  o.loc = keyword.loc;
  HeightField h;
  parse_height_field_image(keyword, h, o);
  while (true) {
    Token t = next();
    if (t.is("smooth")) {
      h.smooth = true;
    } else if (t.is("water_level")) {
      h.water_level = parse_float();
      if (scene_.language_version < 200) h.water_level /= 256.0;
    } else if (t.is("hierarchy")) {
      const Token n = peek();
      if (n.kind == TokenKind::number || n.is("on") || n.is("off") || n.is("true") || n.is("false") ||
          n.is("yes") || n.is("no") || n.is("("))
        parse_float();
    } else {
      unget(t);
      break;
    }
  }
  o.shape = h;
  parse_object_modifiers(o);
  return o;
}

}  // namespace povtrace::sdl
