// height_field (povray-sdl-and-geometry.md §8). Facts from POV-Ray 3.7's parser (source/backend/parser/parse.cpp
// Parse_HField, parstxtr.cpp Parse_Image, 3.7-stable):
// - height_field { [FILE_TYPE] "file" [gamma G] [premultiplied B] [smooth] [water_level W]… modifiers }: the file
//   type keyword is optional when the name has an extension; `smooth` and `water_level` may come in any order
//   before the object modifiers (water_level is divided by 256 before #version 2.0).
// - The image is read without gamma correction (a height field's values are data), so `gamma 1.0` changes nothing;
//   another gamma would decode the values, which povtrace does not do (refused by name).
// - `hierarchy [B]` only changes POV-Ray's internal bounding blocks, never the image: accepted and ignored.
// The parser keeps the file's path (found in the working directory or a +L library path, else as written); the
// renderer reads the image when it builds the scene. Only PNG images are read (other types are refused by name).
// `function W, H { … }` is sampled here, as POV-Ray's Make_Pattern_Image does while parsing.
#include <cmath>
#include <cstdint>
#include <filesystem>

#include "runtime/function_value.hpp"
#include "runtime/image_files.hpp"
#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"
#include "parser/textures/image_location.hpp"

namespace povtrace::sdl {

// `function W, H { FLOAT_FUNCTION }` (Parse_Image with FUNCTION_TOKEN, Make_Pattern_Image): a W × H image whose
// pixel (column j, row i from the top) is f(j / (W − 1), i / (H − 1), 0); W and H are rounded to integers. The
// image's bottom row is the height field's z = 0, as for a file. image_height_at reads the grey back as
// unsigned short(grey · 65535), in float.
void ObjectParser::parse_height_field_function(const Token& keyword, HeightField& h, Object& o) {
  const Token width_at = peek();
  const double w = std::floor(parse_float() + 0.5);
  accept(",");
  const double d = std::floor(parse_float() + 0.5);
  if (!(w >= 2 && d >= 2 && w <= 16384 && d <= 16384))
    fail_at(width_at, "a height_field function needs a size of 2 to 16384 samples each way");
  const Token open = peek();
  if (!open.is("{")) fail_expected(open, "'{' after the size of the height_field function");
  const auto fn = parse_function_definition(keyword);
  const int width = static_cast<int>(w), depth = static_cast<int>(d);
  h.file_loc = keyword.loc;
  if (fn->kind == FunctionValue::Kind::pigment && fn->pigment) {
    // A 16-bit RGBA image of the pigment's colours at the same points, made by the renderer (render_height_field).
    if (fn->pigment->unsupported) taint(o.unsupported, fn->pigment->unsupported);
    h.pigment_function = fn->pigment;
    h.noise_generator = noise_generator();
    h.samples_width = width;
    h.samples_depth = depth;
    return;
  }
  if (fn->return_size != 0) {
    taint(o.unsupported, UnsupportedFeature{"a height_field made from a vector function", keyword.loc});
    return;
  }
  if (auto part = unevaluable_part(*fn)) {
    taint(o.unsupported, UnsupportedFeature{"a height_field made from " + *part, keyword.loc});
    return;
  }
  auto samples = std::make_shared<std::vector<std::uint16_t>>(static_cast<std::size_t>(width) * depth);
  double args[3] = {0, 0, 0}, out[5];
  std::uint64_t* const budget = function_budget();   // the fuzzer's bound on function work, shared with SDL calls
  try {
    for (int i = 0; i < depth; ++i) {
      args[1] = static_cast<double>(i) / (d - 1);
      for (int j = 0; j < width; ++j) {
        args[0] = static_cast<double>(j) / (w - 1);
        const double value =
            evaluate_function(*fn, args, out, noise_generator(), budget);
        (*samples)[static_cast<std::size_t>(depth - 1 - i) * width + j] =
            static_cast<std::uint16_t>(function_image_value(value) * 65535.0f);
      }
    }
  } catch (const FunctionError& e) {
    fail_at(keyword, e.what());
  }
  h.samples = std::move(samples);
  h.samples_width = width;
  h.samples_depth = depth;
}

// The image part of a height field: the type keyword (optional), the name, gamma and premultiplied.
void ObjectParser::parse_height_field_image(const Token& keyword, HeightField& h, Object& o) {
  Token t = next();
  std::string type;
  if (t.is("function")) {
    parse_height_field_function(t, h, o);
    return;
  }
  if (t.kind == TokenKind::identifier && is_image_type_word(t.text)) type = std::string(t.text);
  else unget(t);
  h.file_loc = peek().loc;
  const std::string name = parse_string();
  // PNG and JPEG files are read (the renderer tells them apart by their first bytes).
  const std::string extension = lower_extension(name);
  if (type.empty() && extension != ".png" && extension != ".jpg" && extension != ".jpeg")
    type = "'" + std::filesystem::path(name).extension().string() + "'";
  if (!type.empty() && type != "png" && type != "jpeg")
    taint(o.unsupported, UnsupportedFeature{"a height_field read from a " + type + " image", keyword.loc});
  h.file = locate_image_file(name, library_paths());
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

Object ObjectParser::parse_height_field(const Token& keyword) {
  expect("{", " after 'height_field'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
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
      if (language_version() < 200) h.water_level /= 256.0;
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
  edit_notes(o, notes_pool()).box_skips_clips = true;   // Parse_HField computes the box after its own modifiers
  return o;
}

}  // namespace povtrace::sdl
