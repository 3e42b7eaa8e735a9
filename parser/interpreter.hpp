// The SDL interpreter, one parse's session: POV-Ray parses and evaluates in one pass (povray-sdl-and-geometry.md
// §1), so this class owns every part of the parser (docs/parser-split-plan.md) — the token reader (TokenReader,
// with the token stream: a stack of source frames), the diagnostics (Diagnostics), the symbol tables, the
// directives with their control-flow stack and the macro calls (DirectiveRunner), the expression and value parts,
// and the statement parsers that fill the SceneDescription (SceneStatements) — builds them in order and runs the
// parse (run). The parts reach each other through ParserPart. They are implemented by area:
//   lexing/token_stream.cpp      the TokenReader part (token_reader.hpp), the reader over TokenStream: next()
//                                hands directives and macro calls to directives_; also the ExpressionParser's
//                                fast_operand, which inlines plain_ahead() and nesting_room() here
//   directives/directives.cpp    DirectiveRunner: #declare #local #undef #include #if… #while #for #macro #debug…
//   directives/macros.cpp        DirectiveRunner: macro calls
//   expressions/expressions.cpp  float/vector/colour/string expressions, Parse_UV_Vect and Allow_Float, and
//   expressions/functions.cpp    the built-in functions: the ExpressionParser (expression_parser.hpp), the
//                                Interpreter's empty base; the programs that replay expressions are the
//                                ExpressionPrograms part (expression_programs.hpp)
//   textures/                    textures, pigments, normals, image maps: the TextureParser part (texture_parser.hpp)
//   objects/                     shapes, CSG, meshes, object modifiers and transforms, text and its fonts: the
//                                ObjectParser part (object_parser.hpp)
//   statements/camera_lights.cpp camera and light sources: the CameraLightParser part (camera_light_parser.hpp)
//   statements/scene.cpp         top-level statements, global_settings, background, #default, #version's effect,
//                                placing objects and lights, the parse's loop: the SceneStatements part
//                                (scene_statements.hpp); also the entry points parse_scene and parse_scene_text
//   statements/values.cpp        right-hand values (#declare's): the ValueReader part (value_reader.hpp)
//   statements/radiosity.cpp     global_settings' radiosity block, radiosity importance, their post-parse checks:
//                                the RadiosityParser part (radiosity_parser.hpp)
//   statements/unsupported.cpp   features parsed but not rendered: the UnsupportedFeatures part
//                                (unsupported_features.hpp)
//   expressions/arrays.cpp       arrays: the ArrayValues part (array_values.hpp)
//   expressions/function_parser.cpp user-defined functions: the FunctionValues part (function_values.hpp)
//   directives/file_io.cpp       DirectiveRunner: #fopen #read #write #fclose, confined to the scene's and working dirs
//   expressions/object_queries.cpp inside(), min_extent(), max_extent(), trace(): the ObjectQueries part
//                                (object_queries.hpp)
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
#include "parser/lexing/nesting_limit.hpp"
#include "parser/lexing/token_stream.hpp"
#include "parser/lexing/token_reader.hpp"
#include "parser/extents/object_extents.hpp"
#include "parser/parse_scene.hpp"
#include "parser/lexing/reserved_words.hpp"
#include "parser/directives/directive_runner.hpp"
#include "parser/directives/symbols.hpp"
#include "parser/expressions/values.hpp"
#include "parser/parser_part.hpp"
#include "parser/expressions/builtins.hpp"
#include "parser/expressions/expression_programs.hpp"
#include "parser/expressions/expression_parser.hpp"
#include "parser/expressions/array_values.hpp"
#include "parser/expressions/function_values.hpp"
#include "parser/expressions/object_queries.hpp"
#include "parser/expressions/spline_values.hpp"
#include "parser/statements/camera_light_parser.hpp"
#include "parser/statements/radiosity_parser.hpp"
#include "parser/statements/scene_statements.hpp"
#include "parser/statements/unsupported_features.hpp"
#include "parser/statements/value_reader.hpp"
#include "parser/objects/object_parser.hpp"
#include "parser/textures/texture_parser.hpp"

namespace povtrace::sdl {

class Interpreter : ExpressionParser {   // its empty base: the expression grammar (expression_parser.hpp)
 public:
  explicit Interpreter(const ParseOptions& options);
  SceneDescription run(std::unique_ptr<SourceFile> main_file) { return statements_.run(std::move(main_file)); }
  // `name` held in the parse's file names (the SceneDescription keeps them: its locations point to them).
  FileName file_name(std::string_view name) { return reader_.stream().file_name(name); }

 private:
  // ---- token reader (lexing/token_reader.hpp) ----
  // The reader owns the token stream and the reader's state. It is the first data member: its address (and its
  // stream's) is the Interpreter's, so that the hot paths keep no second pointer around their calls into it
  // (measured: 0.4-1.2% more instructions in the parse benchmarks otherwise). The parts reach it through
  // ParserPart. The ExpressionParser, an empty base, is at the same address, so the grammar reaches the reader
  // with no load either.
  TokenReader reader_;

  // ---- directives (directive_runner.hpp) ----
  // The directives and macro calls are the DirectiveRunner's (directives_); it reads through the services below
  // (directive_services.hpp forwards to them). #version's effect and #default are the SceneStatements'.
  friend class DirectiveRunner;
  // ---- expressions (expressions/expression_parser.hpp) ----
  // The ExpressionParser is the Interpreter's empty base (so that it reaches the reader with no load): the parts
  // call it through ParserPart or hold it as expressions(). Its state, and the value parts it calls, are members
  // below.
  friend class ExpressionParser;
  ExpressionParser& expressions() { return *this; }

  // ---- arrays (expressions/array_values.hpp) ----
  ArrayValues arrays_{*this, symbols_};

  // ---- bounding boxes (extents/object_extents.hpp) ----
  // POV-Ray's bounding boxes of objects as they are made and modified (object_extents.cpp).
  ObjectExtents extents() const {
    return ObjectExtents(options_.object_geometry.get(), statements_.noise_generator(), notes_pool_);
  }

  // ---- the parser's components (parser_part.hpp): they reach the services above through ParserPart ----
  friend class ParserPart;
  template <class> friend class PartNestingGuard;
  template <class> friend class PartRawOperatorLook;

  // ---- textures (textures/texture_parser.hpp) ----
  TextureParser textures_{*this};

  // ---- spline values (expressions/spline_values.hpp) ----
  SplineValues splines_{*this};

  // ---- camera and lights (statements/camera_light_parser.hpp) ----
  CameraLightParser camera_lights_{*this, textures_};

  // ---- objects (objects/object_parser.hpp) ----
  // It holds the stream and the directive runner (built later: it reads them only while parsing) for the mesh
  // scanners, which read the kept tokens straight from the source text.
  ObjectParser objects_{*this, textures_, camera_lights_, reader_.stream(), directives_};

  const ParseOptions& options_;
  NotesPool notes_pool_;   // where the objects' notes are made (ObjectNotes); before the members holding objects
  SymbolTable symbols_;
  // The directives and macro calls, with their control stack (directive_runner.hpp). Built here, where the directive
  // words it interns were interned before.
  DirectiveRunner directives_{*this, options_, reader_.stream(), symbols_, diagnostics_, values_};
  // ParserPart's fail(), fail_at(), fail_expected(), fail_unsupported() and warn() go to it.
  Diagnostics diagnostics_{options_, reader_.stream(), symbols_};
  ExpressionPrograms programs_{options_, reader_.stream(), symbols_, directives_};   // of replayed expressions (S6)
  // ---- radiosity's settings and importance (statements/radiosity_parser.hpp) ----
  RadiosityParser radiosity_{*this};
  // ---- the scene statements and the scene they fill (statements/scene_statements.hpp) ----
  SceneStatements statements_{*this,        options_,  symbols_, reader_,       directives_, expressions(),
                              textures_, camera_lights_, objects_, unsupported_, radiosity_};
  // ---- object queries (expressions/object_queries.hpp): after options_, which they hold ----
  ObjectQueries object_queries_{*this, options_, symbols_, arrays_};
  // ---- user-defined functions (expressions/function_values.hpp): after options_, which they hold ----
  FunctionValues functions_{*this, options_, symbols_, textures_, splines_};
  // ---- the ExpressionParser's state (expressions/expression_parser.hpp): after options_ ----
  // ParseOptions::max_tokens set: next() counts every token, so the fast paths that read kept tokens are off. Read
  // once (an options reference read per operand cost instructions on the parse benchmarks).
  const bool token_limit_ = options_.max_tokens != 0;
  std::vector<std::uint32_t> rand_streams_;   // seed() and rand(): POV-Ray's streams, by the number seed() returns
  // ---- right-hand values (statements/value_reader.hpp): after the parts it calls ----
  ValueReader values_{*this,    options_,  directives_, expressions(), textures_,
                      camera_lights_, objects_, arrays_,  splines_,    functions_};
  // ---- features parsed but not rendered yet (statements/unsupported_features.hpp) ----
  UnsupportedFeatures unsupported_{*this};
};

}  // namespace povtrace::sdl

// The parts' forwarders, now that the Interpreter is complete.
#include "parser/parser_part_forwarders.hpp"
