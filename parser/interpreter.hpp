// The SDL interpreter: POV-Ray parses and evaluates in one pass (povray-sdl-and-geometry.md §1), so this class
// owns the token stream (TokenStream: a stack of source frames), the diagnostics (Diagnostics), the symbol tables,
// the directives with their control-flow stack and the macro calls (DirectiveRunner), and the statement parsers
// that fill the SceneDescription
// (docs/parser-split-plan.md splits it further). Its member functions are implemented by area:
//   lexing/token_stream.cpp      the reader over TokenStream: next() hands directives and macro calls to directives_
//   directives/directives.cpp    DirectiveRunner: #declare #local #undef #include #if… #while #for #macro #debug…
//   directives/macros.cpp        DirectiveRunner: macro calls
//   expressions/expressions.cpp  float/vector/colour/string expressions and built-in functions
//   textures/                    textures, pigments, normals, image maps: the TextureParser part (texture_parser.hpp)
//   objects/objects.cpp          shapes, CSG, object modifiers and transforms
//   statements/camera_lights.cpp camera and light sources: the CameraLightParser part (camera_light_parser.hpp)
//   statements/scene.cpp         top-level statements, global_settings, background, post-processing, entry points
//   expressions/arrays.cpp       arrays: the ArrayValues part (array_values.hpp)
//   expressions/function_parser.cpp user-defined functions: the FunctionValues part (function_values.hpp)
//   directives/file_io.cpp       DirectiveRunner: #fopen #read #write #fclose, confined to the scene's and working dirs
//   expressions/object_queries.cpp inside(), min_extent(), max_extent(), trace(): the ObjectQueries part
//                                (object_queries.hpp)
//   objects/quadric_shapes.cpp   cylinder, cone, disc, torus and the modifiers only they take (open, sturm)
//   objects/implicit_shapes.cpp  superellipsoid, blob
//   objects/height_field.cpp     height_field
//   objects/text.cpp             text (fonts read by runtime/truetype*.cpp, laid out by runtime/text_layout.cpp)
//   objects/csg_modifiers.cpp    inverse (De Morgan), clipped_by, bounded_by, removal of unnecessary bounds
//   objects/sweep_shapes.cpp     lathe, prism, sor
//   objects/isosurface.cpp       isosurface
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/description_transforms.hpp"
#include "parser/lexing/lexer.hpp"
#include "parser/lexing/diagnostics.hpp"
#include "parser/lexing/token_stream.hpp"
#include "parser/extents/object_extents.hpp"
#include "parser/parse_scene.hpp"
#include "parser/lexing/reserved_words.hpp"
#include "parser/directives/directive_runner.hpp"
#include "parser/directives/symbols.hpp"
#include "runtime/truetype.hpp"
#include "parser/expressions/values.hpp"
#include "parser/parser_part.hpp"
#include "parser/expressions/array_values.hpp"
#include "parser/expressions/function_values.hpp"
#include "parser/expressions/object_queries.hpp"
#include "parser/expressions/spline_values.hpp"
#include "parser/statements/camera_light_parser.hpp"
#include "parser/textures/texture_parser.hpp"

namespace povtrace::sdl {

// The float arguments of a built-in call, on the stack (expressions in loops call built-ins millions of times).
struct CallArguments {
  static constexpr std::size_t kMax = 64;   // the most any built-in takes (min, max, bitwise_*)
  std::array<double, kMax> values;
  std::size_t count = 0;
  std::size_t size() const { return count; }
  const double* begin() const { return values.data(); }
  const double* end() const { return values.data() + count; }
  double operator[](std::size_t i) const { return values[i]; }
  void push_back(double v) { values[count++] = v; }   // callers stop at max_args ≤ kMax
};

// Which of POV-Ray's argument checks a built-in float function has (functions.cpp domain_error): known with the
// function, so that a call need not compare its name against each checked one.
enum class FloatDomain : std::uint8_t {
  any,             // no check
  non_negative,    // sqrt
  positive,        // ln, log
  not_both_zero,   // pow, atan2
  divisor,         // mod, div: the second argument is not 0
  unit             // acos, asin: |x| > 1 warns and is clamped
};

// A built-in float function (functions.cpp): its argument counts, its value and its argument check.
struct FloatFunction {
  std::size_t min_args, max_args;
  double (*eval)(const CallArguments&);   // a plain function: no std::function call per evaluation
  FloatDomain domain = FloatDomain::any;
};
const FloatFunction* find_float_function(std::string_view name);   // nullptr: no such built-in
// What parse_function_call gives for the built-in `name` with these arguments, or nullopt where it would report
// an error or warn instead (a domain error, acos(2), an infinite result): the expression programs call through here.
std::optional<double> quiet_float_call(const FloatFunction& f, const CallArguments& args);

class Interpreter {
 public:
  explicit Interpreter(const ParseOptions& options);
  SceneDescription run(std::unique_ptr<SourceFile> main_file);
  // `name` held in the parse's file names (the SceneDescription keeps them: its locations point to them).
  FileName file_name(std::string_view name) { return stream_.file_name(name); }

 private:
  // ---- token stream (token_stream.cpp) ----
  // The frames and kept tokens are the TokenStream's (lexing/token_stream.hpp); the functions below of the same
  // names forward to it. It is the first data member: its address is the Interpreter's, so that the hot paths
  // keep no second pointer around their calls into it (measured: 0.4-1.2% more instructions in the parse benchmarks
  // otherwise).
  TokenStream stream_;
  using Frame = TokenStream::Frame;
  Token raw() { return stream_.raw(); }   // next token of the frame stack, no directive processing
  const LexedToken& lexed(FileTokens& tokens, std::size_t index) { return stream_.lexed(tokens, index); }
  Token make_token(const FileTokens& tokens, const LexedToken& t) const { return stream_.make_token(tokens, t); }
  bool ahead_is(std::string_view symbol) { return stream_.ahead_is(symbol); }
  bool frame_ahead_is(std::string_view symbol) { return stream_.frame_ahead_is(symbol); }
  bool reserved(const Token& t) const { return sdl::reserved(symbols_, t); }
  Token next();                  // next token after directives and macro calls
  // `#declare`, `#local` and `#end` — the directives loops run — read from the kept tokens, neither the '#' nor
  // the word made a Token unless an error needs it. False, having read nothing, where next() takes the full path:
  // a token limit, a cancel check due, the nesting limit near, another directive, a pushed-back token.
  bool quick_directive();
  const Token& peek();   // valid until the next token is read
  // The next token *without* running a directive or macro call it may be (POV-Ray's Ok_To_Declare look-ahead
  // at the end of a #declare): a following `#declare`/`#end` must run only after the current one is finished.
  const Token& peek_raw();   // valid until the next token is read
  // Kind and text of what peek_raw() would return, without making a Token of it when the frame's next token is
  // plain (not '#', not the end of a file): the look for an operator after every operand.
  struct Ahead {
    TokenKind kind;
    std::string_view text;
    bool is(std::string_view s) const {
      // Length and first byte first, as Token::is: asked after every operand, mostly of one-byte symbols.
      return (kind == TokenKind::symbol || kind == TokenKind::identifier) && text.size() == s.size() &&
             (text.empty() || text[0] == s[0]) && text == s;
    }
  };
  // Inline for the frame's next plain token (asked after every operand, by every level of the expression grammar);
  // out of line where a token was pushed back, a frame ends or a directive may follow.
  Ahead raw_ahead() {
    if (!stream_.has_pushed_back()) {
      const Frame& f = stream_.frame();
      const LexedToken& k = lexed(*f.tokens, f.index);
      const std::string_view text(f.file->text.data() + k.offset, k.length());
      if (k.kind() != TokenKind::end_of_input && !(text.size() == 1 && text[0] == '#')) return {k.kind(), text};
    }
    return raw_ahead_full();
  }
  Ahead raw_ahead_full();
  // Whether a directive ahead of a complete operand waits until the value is finished (§1 item 6, POV-Ray's
  // Ok_To_Declare off): in the value of a #declare or #local, a macro argument, an array initialiser and the
  // condition of #if/#elseif/#while/#switch/#case/#range — where POV-Ray reads '#' there as a plain token and
  // reports it. Elsewhere (object, pigment, transform arguments, #debug) POV-Ray's Get_Token runs the directive
  // while it looks for an operator: `pigment { M() * 0.5 }` with M's value inside an #if … #end goes on with `* 0.5`
  // after the directives and the macro's #end (advanced/isocacti.pov).
  bool raw_operator_look_ = false;
  class RawOperatorLook {
   public:
    explicit RawOperatorLook(Interpreter& in, bool raw = true) : in_(in), saved_(in.raw_operator_look_) {
      in_.raw_operator_look_ = raw;
    }
    ~RawOperatorLook() { in_.raw_operator_look_ = saved_; }
    RawOperatorLook(const RawOperatorLook&) = delete;
    RawOperatorLook& operator=(const RawOperatorLook&) = delete;

   private:
    Interpreter& in_;
    bool saved_;
  };
  // Reading without making Tokens, where next() would return the frame's next kept token unchanged: nothing is
  // pushed back, and that token is neither '#', nor the end of a file, nor an identifier that runs something or
  // resolves to something else when read (a macro call, an array that subscripts may follow, a deprecated name).
  // The kept token then; nullptr where only next() may read on. A look: nothing is run or consumed.
  const LexedToken* plain_ahead();
  // Consumes the token plain_ahead() or raw_ahead() (when not pushed back) just returned: a symbol, counted
  // against the token limit as next() would count it.
  void consume_plain();
  void skip_ahead();   // consumes the symbol raw_ahead() just returned, pushed back or not
  std::string_view text_of(const LexedToken& k) const { return stream_.text_of(k); }
  bool plain_symbol(const LexedToken* k, char c) const { return stream_.plain_symbol(k, c); }
  // expect() where its Token is not needed: a plain `symbol` ahead is consumed without making one.
  void skip_expected(char symbol, std::string_view context);
  // A number or a numeric identifier as a whole operand, read from the kept tokens without a Token (most operands
  // are one); false, having read nothing, where the full parse_unary() must run.
  bool fast_operand(Numeric& out);
  bool nesting_room() const;   // whether NestingGuard would let one more level in
  void unget(const Token& t) { stream_.unget(t); }
  Token pop_pushed_back() { return stream_.pop_pushed_back(); }
  Token expect(std::string_view symbol, std::string_view context);
  bool accept(std::string_view symbol);   // consumes the token if it is `symbol`
  std::string expect_identifier_raw(std::string_view context);
  [[noreturn]] void fail(const SourceLoc& loc, const std::string& message) const;
  [[noreturn]] void fail_at(const Token& t, const std::string& message) const;
  // The scene's noise generator in force now (POV-Ray's: 1 before #version 3.5, 2 from then on, unless
  // global_settings set it), which functions evaluated during the parse read.
  int noise_generator() const {
    return scene_.settings.noise_generator.value_or(scene_.language_version < 350 ? 1 : 2);
  }
  [[noreturn]] void fail_expected(const Token& t, std::string_view expected) const;
  [[noreturn]] void fail_unsupported(const Token& t, std::string_view what) const;
  void warn(const SourceLoc& loc, const std::string& message) const;
  std::string reached_from() const { return stream_.reached_from(); }
  std::string describe(const Token& t) const;
  const SourceFile& file_of(const SourceLoc& loc) const { return stream_.file_of(loc); }
  bool is_macro_call(const Token& t) const;
  // The value an identifier token stands for: an array element's value (Token::element), else the symbol
  // visible under its name; nullptr for anything else. Every identifier lookup goes through here.
  const Value* lookup(const Token& t) const;
  // next() on a fresh identifier: the deprecation warning, and `A[i]…` resolved to its element.
  void process_identifier(Token& t, const Value* v);

  // ---- directives (directive_runner.hpp) ----
  // The directives and macro calls are the DirectiveRunner's (directives_); it reads through the services below
  // (directive_services.hpp forwards to them). #version's effect is the scene's: it stays here (scene.cpp).
  friend class DirectiveRunner;
  void directive_version(const Token& at);

  // ---- expressions (expressions.cpp) ----
  Numeric parse_expression();            // full level: ?:, & |, comparisons, + -
  Numeric parse_additive();              // parameter level (Parse_Rel_Factor)
  Numeric parse_multiplicative();
  // The rest of an additive expression whose first operand the caller has already read (a call of a function or
  // spline it held, the identifier of which may no longer resolve): its postfix, then * / and + - as usual.
  Numeric parse_additive_after(Numeric first_operand);
  Numeric parse_additive_rest(Numeric value);         // + - after the operand `value`
  Numeric parse_multiplicative_rest(Numeric value);   // * / after the operand `value`
  Numeric parse_unary();
  Numeric parse_postfix(Numeric value);
  Numeric parse_primary(const Token& t);   // t: the operand's first token, already read
  Numeric parse_vector_literal(const Token& open);
  Numeric parse_colour_keyword_form(const Token& keyword);
  Numeric parse_function_call(const Token& name);
  double parse_float();
  double parse_float_full();             // a float at the full level (inside parentheses semantics)
  Vec3 parse_vector();
  Colour parse_colour();                 // Parse_Colour: optional colour keyword, forms, overrides
  bool starts_colour(const Token& t) const;
  std::string parse_string();
  std::string parse_datetime();
  Numeric compare_strings();   // "a" < "b" and the other comparisons of two strings
  static int strcmp_value(const std::string& a, const std::string& b);   // POV-Ray's strcmp(): a char difference
  bool starts_string(const Token& t) const;
  bool string_ahead();   // starts_string() of what comes next, made a Token only where needed
  class ExpressionStart;
  double to_float(const Numeric& n, const Token& at) const;
  CallArguments parse_call_arguments(const Token& name, std::size_t min_args, std::size_t max_args);
  // Loops and macro bodies read the same expressions over and over from the same kept tokens. The first time one
  // is met again it is translated into a program (numbers, numeric identifiers, + - * / unary ! comparisons & |,
  // parentheses, vector literals, pure built-in float calls), which later readings run instead of parsing it:
  // the grammar decides the program from the tokens alone, and the values are checked as it runs. Anything the
  // program does not cover — a '#' or the end of a file on the way, a string, a macro, an identifier that holds
  // no number when read, an error or warning the parse would give — leaves it to the full parse, which starts
  // from the same token and reports it (nothing is consumed before the program has its value).
  struct ExpressionOp {
    enum class Code : std::uint8_t {
      number, name, neg, not_, add, sub, mul, div, compare, and_, or_, vector, call
    } code = Code::number;
    std::uint8_t arg = 0;       // compare: the Comparison; vector, call: the component or argument count
    std::uint32_t name = 0;     // name: the NameId
    double number = 0;          // number: the value
    const FloatFunction* function = nullptr;   // call: the built-in
  };
  struct ExpressionProgram {
    std::uint32_t first_op = 0, op_count = 0;   // in program_ops_
    std::uint32_t end = 0;                      // token index just after the expression
    bool usable = false;                        // false: the grammar took something no program covers
  };
  class ProgramCompiler;
  // The expression at the frame's next token at the full level (parse_expression) or the parameter level
  // (parse_additive), run as a program where one exists or can be made; false, having read nothing, elsewhere.
  bool run_expression_program(bool full, Numeric& out);
  bool replaying() const;   // inside a macro body or a #while/#for loop: where expressions are read again
  // Found through the note (FileTokens::note) of the expression's first token and level: 0 not tried yet, 1 no
  // program, else programs_[note - 2]. A note is an index, not a hash lookup: asked at every expression.
  std::vector<ExpressionProgram> programs_;
  std::vector<ExpressionOp> program_ops_;

  // ---- arrays (expressions/array_values.hpp) ----
  ArrayValues arrays_{*this, symbols_};

  // ---- bounding boxes (extents/object_extents.hpp) ----
  // POV-Ray's bounding boxes of objects as they are made and modified (object_extents.cpp).
  ObjectExtents extents() const {
    return ObjectExtents(options_.object_geometry.get(), noise_generator(), notes_pool_);
  }

  // ---- the parser's components (parser_part.hpp): they reach the services above through ParserPart ----
  friend class ParserPart;
  template <class> friend class PartNestingGuard;
  template <class> friend class PartRawOperatorLook;

  // ---- textures (textures/texture_parser.hpp) ----
  TextureParser textures_{*this};
  // POV-Ray's Allow_Float: a float expression if one follows, else `fallback` (object modifiers, finishes, maps).
  double optional_float(double fallback);
  static bool is_float_function(std::string_view name);   // abs, sin, … (the built-ins that return a float)
  const Texture& default_texture() const { return default_texture_; }

  // ---- objects (objects.cpp) ----
  std::optional<SceneItem> try_parse_item(const Token& t);   // sphere, plane, box, csg, object, light_source
  Object parse_sphere(const Token& keyword);
  Object parse_plane(const Token& keyword);
  Object parse_box(const Token& keyword);
  Object parse_csg(const Token& keyword, CsgKind kind);
  SceneItem parse_object_block(const Token& keyword);
  SceneItem parse_object_block_rest(const Token& keyword, const Token& first);   // after `object {` and its first token
  // A statement `object { … }`: a declared object is copied once and moved into the scene once (not passed up
  // through SceneItem and optional, two more moves of a large struct per placed copy).
  void place_object_block(const Token& keyword);
  void parse_object_modifiers(Object& object);
  bool try_object_modifier(const Token& t, Object& object);
  void apply_transform(Object& object, const Matrix& m, TransformKind kind = TransformKind::other);
  void parse_material_block(const Token& keyword, Object& object);
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
  void parse_clip_or_bound(const Token& keyword, Object& object);
  std::vector<Object> parse_bound_clip_objects(const Token& keyword);
  bool all_children_finite(const Csg& csg) const;
  void remove_unnecessary_bounds(Object& object);             // Link_To_Frame's Remove_Bounds, when placed

  // ---- superellipsoid, blob (implicit_shapes.cpp) ----
  std::pair<double, double> parse_uv_vector(std::string_view context);   // POV-Ray's Parse_UV_Vect
  Object parse_superellipsoid(const Token& keyword);
  Object parse_blob(const Token& keyword);
  BlobComponent parse_blob_sphere(bool old_syntax);
  BlobComponent parse_blob_cylinder(const Token& keyword);
  void parse_blob_component_modifiers(BlobComponent& c, Object& blob);

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
  Object parse_isosurface(const Token& keyword);
  void parse_isosurface_function(Isosurface& iso, Object& o);
  void parse_isosurface_container(Isosurface& iso);
  bool try_isosurface_item(const Token& t, Isosurface& iso, Object& o);
  void correct_isosurface_values(const Token& keyword, Isosurface& iso);
  // ---- height_field (height_field.cpp) ----
  Object parse_height_field(const Token& keyword);
  void parse_height_field_image(const Token& keyword, HeightField& h, Object& o);
  void parse_height_field_function(const Token& keyword, HeightField& h, Object& o);

  // ---- text (text.cpp) ----
  Object parse_text(const Token& keyword);
  ttf::Font& font_for_text(const Token& at, const std::string& name);
  ttf::Font& internal_font(const Token& at, int id);

  // ---- spline values (expressions/spline_values.hpp) ----
  SplineValues splines_{*this};

  // ---- camera and lights (statements/camera_light_parser.hpp) ----
  CameraLightParser camera_lights_{*this, textures_};

  // ---- features parsed but not rendered yet (unsupported.cpp) ----
  UnsupportedFeature skip_unsupported(const Token& keyword, const std::string& what);
  void skip_balanced(const Token& open);
  bool continues_arguments(const Token& t);
  void refuse_if_unsupported(const Unsupported& u, const SourceLoc& placed_at, std::string_view what) const;
  static void taint(Unsupported& slot, const Unsupported& feature) {
    if (!slot && feature) slot = feature;   // the first one found is the one reported
  }

  // ---- scene (scene.cpp) ----
  void parse_statement(const Token& t);
  void parse_global_settings(const Token& keyword);
  void parse_background(const Token& keyword);
  void parse_default(const Token& keyword);
  std::optional<Value> try_parse_rvalue(const Token& first);
  // Whether a plain token ahead starts what try_parse_rvalue() reads as a numeric expression: a number, a
  // symbol, or an identifier holding a number (the common right-hand sides, taken without making a Token).
  bool numeric_ahead();
  // Runs the macro calls that start a value (`#declare S = Add(S, I);`) as next() would, so that a numeric body
  // is then read by numeric_ahead()'s path: next() would hand its first token over as a Token, which keeps the
  // expression from running as a compiled program.
  void call_macros_ahead();
  void place_object(Object&& object, const SourceLoc& at);   // finished in place, then moved into the scene once
  void place_light(Light light, const SourceLoc& at);
  void add_light(Light light);
  void post_process(Object& object);
  void placed(Object& object);   // the last step before the object joins scene_.objects

  const ParseOptions& options_;
  NotesPool notes_pool_;   // where the objects' notes are made (ObjectNotes); before the members holding objects
  // True while run() reads the next statement's first token: a directive then run at nesting level 0 stands
  // between statements, where nothing holds a kept token (FileTokens::release_before).
  bool between_statements_ = false;
  SymbolTable symbols_;
  // The directives and macro calls, with their control stack (directive_runner.hpp). Built here, where the directive
  // words it interns were interned before.
  DirectiveRunner directives_{*this, options_, stream_, symbols_, diagnostics_};
  // fail(), fail_at(), fail_expected(), fail_unsupported(), warn() and describe() forward to it.
  Diagnostics diagnostics_{options_, stream_, symbols_};
  SceneDescription scene_;
  Texture default_texture_;
  std::shared_ptr<const Texture> placed_default_texture_;   // shared by untextured objects until #default changes
  bool camera_seen_ = false;
  bool statement_seen_ = false;
  // The scene's noise generator as functions see it when they run (POV-Ray's f_noise3d reads the scene's current
  // setting): updated at #version, at global_settings and once more when the parse ends, so that functions
  // evaluated while rendering see the final one.
  bool version_directive_seen_ = false;   // POV-Ray's languageVersionSet: any #version so far
  std::vector<std::uint32_t> rand_streams_;
  // ---- object queries (expressions/object_queries.hpp): after options_, which they hold ----
  ObjectQueries object_queries_{*this, options_, symbols_, arrays_};
  // ---- user-defined functions (expressions/function_values.hpp): after options_, which they hold ----
  FunctionValues functions_{*this, options_, symbols_, textures_, splines_};
  // Fonts read so far, by the name POV-Ray's cache compares with (text.cpp), and the string encoding set by
  // global_settings { charset }.
  std::vector<std::pair<std::string, std::unique_ptr<ttf::Font>>> fonts_;
  ttf::StringEncoding string_encoding_ = ttf::StringEncoding::ascii;

  // Input nested deeper than this (parentheses, vectors, unary operators, object { object { … } }, transform
  // blocks) is refused with an error instead of overflowing the C++ stack. POV-Ray itself crashes there.
  static constexpr int kMaxNesting = 500;
  int nesting_ = 0;
  class NestingGuard {
   public:
    NestingGuard(Interpreter& in, const Token& at);
    // One more level where nesting_room() has just said there is room: nothing to report, so no Token needed.
    struct RoomChecked {};
    NestingGuard(Interpreter& in, RoomChecked) : in_(in) { ++in_.nesting_; }
    ~NestingGuard() { --in_.nesting_; }
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;

   private:
    Interpreter& in_;
  };
};

}  // namespace povtrace::sdl

// The parts' forwarders, now that the Interpreter is complete.
#include "parser/parser_part_forwarders.hpp"
