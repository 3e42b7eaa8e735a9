// Geometric queries on declared objects at parse time (docs/parser-split-plan.md step S8, the queries' part):
// inside(O, P), min_extent(O), max_extent(O) and trace(O, Start, Dir [, Normal]), POV-Ray's Parse_Inside,
// Parse_Min/Max_Extent and Parse_Trace. Bodies in object_queries.cpp, which says why the parser keeps its own inside
// tests. It owns the declared objects made ready for the renderer's geometry (prepared_objects_); the bounding boxes
// and the noise generator come through ParserPart, trace()'s normal into an array element through ArrayValues.
#pragma once

#include <memory>
#include <string_view>
#include <unordered_map>

#include "parser/expressions/values.hpp"
#include "parser/parse_scene.hpp"
#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class ArrayValues;
class SymbolTable;

class ObjectQueries : ParserPart {
 public:
  ObjectQueries(Interpreter& in, const ParseOptions& options, SymbolTable& symbols, ArrayValues& arrays)
      : ParserPart(in), options_(options), symbols_(symbols), arrays_(arrays) {}

  Numeric parse_object_query(const Token& name);   // inside(O, P), min_extent(O), max_extent(O)
  Numeric parse_trace(const Token& name);          // trace(O, Start, Dir [, Normal])

 private:
  void store_trace_normal(Vec3 normal);
  const std::shared_ptr<const SceneItem>& object_identifier(const Token& id, std::string_view function);
  const PreparedObject& prepared_object(const std::shared_ptr<const SceneItem>& item);

  const ParseOptions& options_;   // object_geometry: the renderer's geometry, null without the renderer
  SymbolTable& symbols_;
  ArrayValues& arrays_;
  // Declared objects made ready for trace() and inside() by ParseOptions::object_geometry (object_queries.cpp).
  struct PreparedEntry {
    std::shared_ptr<const SceneItem> item;   // keeps the key's object alive
    std::unique_ptr<const PreparedObject> prepared;
    int noise_generator;   // the scene's when it was prepared (its isosurfaces' functions read it)
  };
  std::unordered_map<const SceneItem*, PreparedEntry> prepared_objects_;
};

}  // namespace povtrace::sdl
