// The right-hand values (docs/parser-split-plan.md step S11): what #declare, #local, array initialisers and macro
// arguments read after their '=' (POV-Ray's Parse_RValue: a number, vector, colour, string, texture, object,
// function, array…). Its bodies are in values.cpp. It owns no state: it calls the parts that parse each kind of
// value, which it holds, and reads the reader and the symbols through ParserPart (token_stream(), symbol_table():
// both reached from the one Interpreter pointer, which numeric_ahead and call_macros_ahead, run at every #declare,
// load once; a reference of the symbols' own cost call_macros_ahead 5 instructions more a call in parse_while).
//
// Public interface: try_parse_rvalue (the parts, through ParserPart), numeric_ahead and call_macros_ahead (the
// DirectiveRunner's #declare path, parse_declares and parse_while: the common numeric values taken without a Token).
#pragma once

#include <optional>

#include "parser/lexing/token_stream.hpp"
#include "parser/parse_scene.hpp"
#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class DirectiveRunner;
class ExpressionParser;
class TextureParser;
class CameraLightParser;
class ObjectParser;
class ArrayValues;
class SplineValues;
class FunctionValues;

class ValueReader : ParserPart {
 public:
  ValueReader(Interpreter& in, const ParseOptions& options, DirectiveRunner& directives,
              ExpressionParser& expressions, TextureParser& textures, CameraLightParser& camera_lights,
              ObjectParser& objects, ArrayValues& arrays, SplineValues& splines, FunctionValues& functions)
      : ParserPart(in), options_(options), directives_(directives), expressions_(expressions),
        textures_(textures), camera_lights_(camera_lights), objects_(objects), arrays_(arrays), splines_(splines),
        functions_(functions) {}

  std::optional<Value> try_parse_rvalue(const Token& first);
  // Whether a plain token ahead starts what try_parse_rvalue() reads as a numeric expression: a number, a
  // symbol, or an identifier holding a number (the common right-hand sides, taken without making a Token).
  bool numeric_ahead();
  // Runs the macro calls that start a value (`#declare S = Add(S, I);`) as next() would, so that a numeric body
  // is then read by numeric_ahead()'s path: next() would hand its first token over as a Token, which keeps the
  // expression from running as a compiled program.
  void call_macros_ahead();

 private:
  using Frame = TokenStream::Frame;
  const ParseOptions& options_;
  DirectiveRunner& directives_;
  ExpressionParser& expressions_;
  TextureParser& textures_;
  CameraLightParser& camera_lights_;
  ObjectParser& objects_;
  ArrayValues& arrays_;
  SplineValues& splines_;
  FunctionValues& functions_;
};

}  // namespace povtrace::sdl
