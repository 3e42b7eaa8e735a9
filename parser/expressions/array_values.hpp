// SDL arrays (docs/parser-split-plan.md step S8, the arrays' part): `array[N][M]… [{ initialisers }]` as a
// right-hand value, the subscripts `[i][j]…` that the reader resolves where an array's name is read (POV-Ray's
// Read_Symbol), element assignment `#declare A[i] = …`, `defined(A[i])` / `#ifdef (A[i])`, dimensions() and
// dimension_size(). Bodies in arrays.cpp. No state of its own: the arrays are Values in the symbol table, which it
// reads and assigns through; the token reader and the expressions come through ParserPart.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "parser/expressions/values.hpp"
#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class SymbolTable;

class ArrayValues : ParserPart {
 public:
  ArrayValues(Interpreter& in, SymbolTable& symbols) : ParserPart(in), symbols_(symbols) {}

  // `[N]… [{ … }]` after the keyword `array`: the new array.
  Value parse_array_declaration(const Token& keyword);
  // The first value stored fixes the array's element type; `at` and `name` are for the message.
  void store_element(ArrayValue& a, std::size_t index, Value value, const Token& at, const std::string& name);
  // `[i][j]…` after an array name: the flat element index. Subscripts are truncated floats (§3). Read by next()
  // where a fresh identifier holding an array is followed by '[' (process_identifier).
  std::size_t parse_subscripts(const ArrayValue& a, const std::string& name, Token& last);
  // `Name[i]…` read raw (an lvalue or #ifdef): the array and element index, or nullopt if Name is no array.
  struct ElementRef {
    std::shared_ptr<ArrayValue> array;
    std::size_t index = 0;
  };
  std::optional<ElementRef> parse_element_reference(const Token& name);
  void directive_declare_element(const Token& name, bool local);   // #declare/#local A[i]… = value
  Numeric parse_dimensions(const Token& name);   // dimensions(A), dimension_size(A, k)
  // defined(Id) / #ifdef (Id): Id may be an array element, defined iff assigned. Reads from after '('.
  bool parse_defined_identifier();

 private:
  void parse_array_initialiser(ArrayValue& a, std::size_t dim, std::size_t base);

  SymbolTable& symbols_;
};

}  // namespace povtrace::sdl
