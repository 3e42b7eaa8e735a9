// The texture part of the parser (docs/parser-split-plan.md step S9): texture, pigment, finish, normal and interior
// blocks, their patterns, maps and warps, image_map and bump_map, patterned textures, transforms, sky_sphere and
// fog. Its bodies are in this folder:
//   textures.cpp          pigment, finish, texture and interior blocks; transforms; sky_sphere, fog
//   pigments.cpp          pigment patterns, maps and pattern modifiers
//   normals.cpp           normal { } perturbations
//   image_map.cpp         image_map, bump_map
//   media.cpp             media and density blocks
//   texture_patterns.cpp  patterned textures (texture_map, checker/hexagon/brick textures, tiles, uv_mapping)
// It owns no state: what it reads of the scene so far (the #default texture, the language version, assumed_gamma)
// comes through ParserPart, as do the token reader, diagnostics and expressions.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "parser/expressions/values.hpp"
#include "parser/parser_part.hpp"

namespace povtrace::sdl {

// (int)v as POV-Ray converts a parsed float to an integer parameter, with out-of-range values clamped (pigments.cpp).
int truncated_int(double v);

class TextureParser : ParserPart {
 public:
  explicit TextureParser(Interpreter& in) : ParserPart(in) {}

  // The blocks other parts read (objects, #default, #declare's values, functions' pigment patterns) after their
  // keyword; `start` is what the block edits (a layer's own, a declared one, a default).
  std::shared_ptr<const Texture> parse_texture_block(const Token& keyword);
  Pigment parse_pigment_block(const Token& keyword, const Pigment& start);
  Finish parse_finish_block(const Token& keyword, const Finish& start);
  Normal parse_normal_block(const Token& keyword, const Normal& start);
  // The normal a `normal { }` block edits: the layer's own, else the #default texture's, else a new one.
  Normal starting_normal(const Normal* current) const;
  Interior parse_interior_block(const Token& keyword, const Interior& start);
  // media { } and density { } (media.cpp).
  Media parse_media_block(const Token& keyword);
  Pigment parse_density_block(const Token& keyword);
  BlendMapValue parse_density_map(const Token& keyword);
  BlendMapValue parse_blend_map(const Token& keyword, bool weights_optional = false);
  BlendMapValue parse_texture_map(const Token& keyword, bool weights_optional);
  SkySphere parse_sky_sphere(const Token& keyword);
  Fog parse_fog(const Token& keyword);
  Rainbow parse_rainbow(const Token& keyword);   // rainbow.cpp
  bool try_transform(const Token& t, Matrix& m);   // translate/rotate/scale/matrix/transform; composes into m
  Matrix parse_transform_block(const Token& keyword);
  // POV-Ray's Link_Textures checks: nothing over a patterned texture, a patterned one over nothing.
  void refuse_layering(const Token& t, const Texture* existing, bool adding_patterned) const;

 private:
  // ---- textures (textures.cpp) ----
  void parse_finish_reflection(Finish& f);
  void parse_irid(const Token& keyword, Finish& f);
  bool try_pigment_item(const Token& t, Pigment& p);

  // ---- pigment patterns, maps and pattern modifiers (pigments.cpp) ----
  Pigment parse_pigment_contents(const Pigment& start, const SourceLoc& loc, std::string_view closer);
  Pigment default_pigment() const;
  Pigment uv_mapped_pigment(Pigment outer, const SourceLoc& loc, std::string_view closer);
  bool try_pattern(const Token& t, Pigment& p);
  void set_list_pattern(const Token& t, Pigment& p);   // checker/hexagon/brick without their entries
  std::shared_ptr<const Object> parse_pattern_object();   // the object of an object pattern
  MappingWarp parse_mapping_warp(const Token& kind);
  BlackHoleWarp parse_black_hole_warp();
  void check_black_hole(const Token& at, BlackHoleWarp& w) const;
  void parse_density_file(Pigment& p);                  // after `density_file`: df3 "NAME", the file read
  bool try_pattern_modifier(const Token& t, Pigment& p);
  bool try_pattern_parameter(const Token& t, Pigment& p);
  bool starts_map_expression(const Token& t) const;
  std::vector<MapEntry> parse_list_entries(PatternKind kind, std::size_t count);
  void parse_colour_map_entry(std::vector<MapEntry>& entries);
  void parse_pigment_map_entry(std::vector<MapEntry>& entries, bool weights_optional);
  void refuse_map_for_pattern(const Token& t, const Pigment& p, bool pigment_map);
  void parse_warp(const Token& keyword, Pigment& p);
  RepeatWarp parse_repeat_warp(const Token& keyword);

  // ---- fractal and surface patterns (surface_fractal_patterns.cpp) ----
  void parse_fractal_pattern(const Token& keyword, Pigment& p);   // mandel, julia, magnet and their numbers
  void parse_slope_pattern(const Token& keyword, Pigment& p);     // slope V or slope { … }
  bool try_fractal_parameter(const Token& t, Pigment& p);         // exterior, interior, exponent

  // ---- media and density (media.cpp) ----
  Media starting_media() const;
  bool parse_media_item(const Token& t, Media& m);
  void parse_scattering(const Token& keyword, Media& m);
  Pigment parse_density_contents(const SourceLoc& loc, std::string_view closer);

  // ---- normal { } (normals.cpp) ----
  Normal parse_normal_contents(const Token& keyword, const Normal& start, std::string_view closing = "}");
  void parse_normal_list(Normal& n, int count);
  void parse_normal_map(const Token& keyword, Normal& n);
  std::shared_ptr<const Normal> default_normal() const;
  bool try_normal_pattern(const Token& t, Normal& n);
  bool try_normal_modifier(const Token& t, Normal& n);
  std::vector<SlopeEntry> parse_slope_map(const Token& keyword);

  // ---- image_map, bump_map (image_map.cpp) ----
  ImageGamma current_image_gamma() const;
  void parse_image_file(const Token& keyword, ImageMap& m, Unsupported& unsupported);
  void parse_image_decoding(ImageMap& m, Unsupported& unsupported);
  void parse_image_channel(const Token& keyword, ImageMap& m);
  bool try_image_item(const Token& t, ImageMap& m, bool bump);
  void parse_image_map(const Token& keyword, Pigment& p);
  void parse_image_pattern(const Token& keyword, Pigment& p);
  void parse_bump_map(const Token& keyword, Normal& n);

  // ---- patterned textures (texture_patterns.cpp) ----
  std::shared_ptr<const Texture> parse_texture_contents(const SourceLoc& loc, std::string_view closer);
  static bool starts_texture_pattern(const Token& t);
  bool is_list_pattern_word(const Token& t) const;
  std::shared_ptr<const Texture> transformed_patterned_texture(const Texture& declared, Token t,
                                                               std::string_view closer);
  void parse_material_map(const Token& keyword, TexturePattern& pattern);
  std::vector<TextureMapEntry> parse_texture_list(std::size_t count);
  std::vector<TextureMapEntry> parse_tiles(const Token& keyword);
  std::shared_ptr<const Texture> parse_patterned_texture(const Token& first, const SourceLoc& loc,
                                                         std::string_view closer);
  void parse_texture_pattern_modifiers(const Token& first, TexturePattern& pattern, std::string_view closer);
};

}  // namespace povtrace::sdl
