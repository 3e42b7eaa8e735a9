// The object part of the parser (docs/parser-split-plan.md step S10): shapes, CSG, object { } copies, the object
// modifiers and transforms, bounded_by/clipped_by and inverse (povray-sdl-and-geometry.md §8-§10). Its bodies are in
// this folder:
//   objects.cpp          shapes, CSG, object modifiers and transforms
//   quadric_shapes.cpp   cylinder, cone, disc, torus and the modifiers only they take (open, sturm)
//   poly_shapes.cpp      poly, cubic, quartic, quadric
//   meshes.cpp           triangle, smooth_triangle, polygon, mesh (with the literal mesh scanner)
//   mesh2.cpp            mesh2
//   csg_modifiers.cpp    inverse (De Morgan), clipped_by, bounded_by, removal of unnecessary bounds
//   implicit_shapes.cpp  superellipsoid, blob
//   sweep_shapes.cpp     lathe, prism, sor
//   isosurface.cpp       isosurface
//   height_field.cpp     height_field
//   text.cpp             text (fonts read by runtime/truetype*.cpp, laid out by runtime/text_layout.cpp)
// It owns the font cache (the fonts read so far and the string encoding of global_settings { charset }). The mesh
// scanners read the kept tokens straight from the TokenStream and ask the DirectiveRunner whether a loop of the
// frame is open, so the part holds those two by reference rather than every part reaching them through ParserPart;
// transforms and textures come from the TextureParser, lights inside CSG from the CameraLightParser. The rest (the
// token reader, diagnostics, expressions, the scene's settings, placing an object, the notes pool and the objects'
// boxes) comes through ParserPart.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "parser/lexing/token_stream.hpp"
#include "parser/parser_part.hpp"
#include "runtime/truetype.hpp"

namespace povtrace::sdl {

class CameraLightParser;
class DirectiveRunner;
class TextureParser;

class ObjectParser : ParserPart {
 public:
  ObjectParser(Interpreter& in, TextureParser& textures, CameraLightParser& camera_lights, TokenStream& stream,
               const DirectiveRunner& directives)
      : ParserPart(in), textures_(textures), camera_lights_(camera_lights), stream_(stream), directives_(directives) {}

  // The shape, CSG, object { } or light_source whose keyword `t` is, read to its end, or a copy of the declared
  // object `t` names; nullopt for anything else (the statements, #declare's values and looks_like ask).
  std::optional<SceneItem> try_parse_item(const Token& t);   // sphere, plane, box, csg, object, light_source
  // A statement `object { … }`: a declared object is copied once and moved into the scene once (not passed up
  // through SceneItem and optional, two more moves of a large struct per placed copy).
  void place_object_block(const Token& keyword);
  void parse_object_modifiers(Object& object);   // up to and with the closing '}'
  void apply_transform(Object& object, const Matrix& m, TransformKind kind = TransformKind::other);
  void parse_material_block(const Token& keyword, Object& object);
  void remove_unnecessary_bounds(Object& object);             // Link_To_Frame's Remove_Bounds, when placed
  // global_settings { charset }: how the strings of text objects made from now on are read (the encoding is read
  // when a font is first loaded and when a text's string is decoded, text.cpp).
  void set_string_encoding(ttf::StringEncoding encoding) { string_encoding_ = encoding; }

 private:
  // ---- objects (objects.cpp) ----
  Object parse_sphere(const Token& keyword);
  Object parse_plane(const Token& keyword);
  Object parse_box(const Token& keyword);
  Object parse_csg(const Token& keyword, CsgKind kind);
  SceneItem parse_object_block(const Token& keyword);
  SceneItem parse_object_block_rest(const Token& keyword, const Token& first);   // after `object {` and its first token
  bool try_object_modifier(const Token& t, Object& object);
  static std::string csg_name(CsgKind kind);

  // ---- cylinder, cone, disc, torus (quadric_shapes.cpp) ----
  Object parse_cylinder(const Token& keyword);
  Object parse_cone(const Token& keyword);
  Object parse_disc(const Token& keyword);
  Object parse_torus(const Token& keyword);
  bool accept_open();
  void check_cone_axis(const Token& keyword, Vec3 end1, Vec3 end2);
  // `sturm [bool]` as an object modifier: legal only on a torus, poly, blob, lathe, prism or sor among the rendered
  // shapes (POV-Ray's STURM_OK_OBJECT); false when the object is not one of them (another shape decides).
  bool try_sturm_modifier(const Token& t, Object& object);
  // poly (order 0: read from the block), cubic (3), quartic (4) — poly_shapes.cpp.
  Object parse_poly(const Token& keyword, int order);
  Object parse_quadric(const Token& keyword);
  // ---- triangles, polygons and meshes (meshes.cpp, mesh2.cpp) ----
  struct MeshBuilder;
  std::optional<Object> parse_declared_object_body();   // `shape { Declared_Id modifiers }`
  Object parse_triangle(const Token& keyword, bool smooth);
  Object parse_polygon(const Token& keyword);
  Object parse_mesh(const Token& keyword);
  void parse_mesh_triangle(const Token& keyword, bool smooth, MeshBuilder& mesh);
  // A mesh triangle as read (either way): normals checked and normalised, degenerate ones counted, then added.
  void add_mesh_triangle(const SourceLoc& keyword, bool smooth, std::array<Vec3, 3> p, std::array<Vec3, 3> n,
                         const std::array<std::int32_t, 3>& tex, const std::optional<std::array<double, 6>>& uv,
                         MeshBuilder& mesh);
  // Literal mesh items read straight from the source text (mesh_scan.hpp): TokenStream::literal_scan_start.
  using LiteralScanStart = TokenStream::LiteralScanStart;
  std::optional<LiteralScanStart> literal_scan_start();   // with whether a loop of this frame is open
  void literal_scan_commit(const LiteralScanStart& start, const LexPosition& to, std::uint64_t tokens) {
    stream_.literal_scan_commit(start, to, tokens);
  }
  bool literal_scan_allows(std::uint64_t tokens, std::size_t items, const LexPosition& at, std::size_t scan_begin) {
    return stream_.literal_scan_allows(tokens, items, at, scan_begin);
  }
  void scan_mesh_triangles(MeshBuilder& mesh);
  // Up to `max_items` items `<n1, …, nN> [,]` of a mesh2 section, each handed to take(values), which may refuse
  // it (false: it is then read the ordinary way, which reports what is wrong with it); returns how many it took.
  template <std::size_t N, class Take>
  std::size_t scan_mesh2_items(std::size_t max_items, Take&& take);
  std::array<std::int32_t, 3> parse_mesh_triangle_textures(MeshBuilder& mesh);
  std::optional<Vec3> parse_inside_vector();
  Object parse_mesh2(const Token& keyword);
  std::size_t parse_mesh2_count(const Token& keyword, bool zero_allowed);
  void check_mesh2_item(const Token& keyword, std::size_t index, std::size_t count, const std::string& items);
  void expect_mesh2_section_end(const Token& keyword, std::size_t count, const std::string& items);
  std::vector<float> parse_mesh2_vectors(const Token& keyword, bool normals);
  std::vector<double> parse_mesh2_uv_vectors(const Token& keyword);
  std::array<std::uint32_t, 3> mesh2_index_triple(const Token& at, const Numeric& value, std::size_t limit,
                                                  const std::string& what);
  std::vector<std::uint32_t> parse_mesh2_indices(const Token& keyword, std::size_t count, std::size_t limit,
                                                 const std::string& what);
  void parse_mesh2_faces(const Token& keyword, std::size_t vertex_count, std::size_t texture_count, MeshData& data);
  // ---- inverse, clipped_by, bounded_by (csg_modifiers.cpp) ----
  static void invert_object(Object& object);                  // De Morgan for CSG (§10)
  static void set_double_illuminate(Object& object, bool on);
  Object parse_light_group(const Token& keyword);
  static void set_no_global_lights(Object& object, bool no_global);
  void parse_clip_or_bound(const Token& keyword, Object& object);
  void parse_object_photons(const Token& keyword, Object& object);   // object_photons.cpp
  std::vector<Object> parse_bound_clip_objects(const Token& keyword);
  bool all_children_finite(const Csg& csg) const;

  // ---- superellipsoid, blob (implicit_shapes.cpp) ----
  Object parse_superellipsoid(const Token& keyword);
  Object parse_ovus(const Token& keyword);
  Object parse_blob(const Token& keyword);
  BlobComponent parse_blob_sphere(bool old_syntax);
  BlobComponent parse_blob_cylinder(const Token& keyword);
  void parse_blob_component_modifiers(BlobComponent& c, std::shared_ptr<const Texture>& texture, Object& blob);

  // ---- lathe, prism, sor (sweep_shapes.cpp) ----
  Object parse_lathe(const Token& keyword);
  Object parse_prism(const Token& keyword);
  Object parse_sor(const Token& keyword);
  SplineKind parse_spline_keywords(bool* conic);   // conic: also the prism's sweep keywords
  long parse_profile_count(const std::string& shape, SplineKind spline, const long minimum[3]);
  std::vector<ProfilePoint> parse_profile_points(
      long count, const std::function<void(long, const std::vector<ProfilePoint>&, const Token&)>& check);
  void close_prism_outline(const Token& keyword, Prism& prism, std::vector<ProfilePoint>& points);

  // ---- isosurface (isosurface.cpp) ----
  // ---- julia_fractal, bicubic_patch (fractal_patch.cpp) ----
  Object parse_julia_fractal(const Token& keyword);
  std::array<double, 4> parse_vector4(std::string_view what);
  static bool is_julia_item(const Token& t);
  void parse_julia_item(const Token& t, JuliaFractal& j, std::optional<Token>& function_at);
  void parse_julia_slice(JuliaFractal& j);
  Object parse_bicubic_patch(const Token& keyword);
  void parse_patch_items(BicubicPatch& b);
  Object parse_isosurface(const Token& keyword);
  void parse_isosurface_function(Isosurface& iso, Object& o);
  void parse_isosurface_container(Isosurface& iso);
  bool try_isosurface_item(const Token& t, Isosurface& iso);
  void correct_isosurface_values(const Token& keyword, Isosurface& iso);
  // ---- height_field (height_field.cpp) ----
  Object parse_height_field(const Token& keyword);
  void parse_height_field_image(const Token& keyword, HeightField& h, Object& o);
  void parse_height_field_function(const Token& keyword, HeightField& h, Object& o);

  // ---- text (text.cpp) ----
  Object parse_text(const Token& keyword);
  ttf::Font& font_for_text(const Token& at, const std::string& name);
  ttf::Font& internal_font(const Token& at, int id);


  TextureParser& textures_;
  CameraLightParser& camera_lights_;
  TokenStream& stream_;                 // the mesh scanners' kept tokens
  const DirectiveRunner& directives_;   // loop_in_frame, for the mesh scanners

  // ---- the font cache (text.cpp) ----
  // Fonts read so far, by the name POV-Ray's cache compares with, and the string encoding set by
  // global_settings { charset }.
  std::vector<std::pair<std::string, std::unique_ptr<ttf::Font>>> fonts_;
  ttf::StringEncoding string_encoding_ = ttf::StringEncoding::ascii;
};

}  // namespace povtrace::sdl
