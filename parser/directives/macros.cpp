// Macro calls (povray-sdl-and-geometry.md §4 #macro): the arguments of a call read and bound, the body's frame
// pushed; the return (DirectiveRunner::return_from_macro) pops both at the macro's #end or #break.
#include <string>

#include "parser/directives/directive_services.hpp"

namespace povtrace::sdl {

namespace {
constexpr std::size_t kMaxMacroDepth = 256;     // runaway recursion guard
}  // namespace

// A macro call: arguments are bound in a new symbol table, then the body's tokens continue the stream until
// its #end, which returns to just after the call's ')' (§1 item 4, §4 #macro).
void DirectiveRunner::call_macro(const Token& name) {
  // The shared definition, not a copy: a call needs no allocation for it (and keeps it alive should the call
  // redefine the macro).
  const Boxed<MacroDefinition> boxed = std::get<Boxed<MacroDefinition>>(*lookup(name));
  const MacroDefinition& macro = *boxed;
  if (stream_.count(Frame::Kind::macro) >= kMaxMacroDepth)
    fail_at(name, "macro calls nested too deeply (more than " + std::to_string(kMaxMacroDepth) +
                      " levels: runaway recursion in '" + std::string(name.text) + "'?)");
  // Checked here rather than with expect(): its message would be built on every call. A plain '(' is taken
  // where it stands.
  if (plain_symbol(plain_ahead(), '(')) consume_plain();
  else if (const Token open = next(); !open.is("("))
    fail_expected(open, "'(' after the macro name '" + std::string(name.text) + "'");
  // The values go on a stack kept by the interpreter (a call allocates nothing for them); a call in an argument
  // pushes its own above them and takes them off again.
  const std::size_t base = macro_arguments_.size();
  struct Unwind {
    std::vector<std::pair<SymbolTable::NameId, Value>>& stack;
    std::size_t base;
    ~Unwind() { stack.resize(base); }
  } unwind{macro_arguments_, base};
  for (std::size_t i = 0; i < macro.parameters.size(); ++i) {
    if (i > 0) accept(",");
    // The common argument, a declared variable's name alone, read from the kept tokens: what the lines below
    // do with it, without making its Token (plain_ahead() leaves out macros, arrays and deprecated names).
    if (const LexedToken* k = plain_ahead(); k && !options_.max_tokens && k->kind() == TokenKind::identifier &&
                                             !symbols_.is_reserved(k->payload)) {
      const Frame& f = stream_.frame();
      const LexedToken& after = lexed(*f.tokens, f.index + 1);
      if (plain_symbol(&after, ',') || plain_symbol(&after, ')'))
        if (const auto level = symbols_.level_of(k->payload)) {
          stream_.step();
          macro_arguments_.emplace_back(macro.parameter_ids[i], Alias{*level, k->payload});
          continue;
        }
    }
    Token first = next();
    // A lone identifier naming an outer variable binds by alias (§4): writes go through to the caller. The look
    // at the token after it has no side effects: if `first` is the result of a macro (`P(Fact(5))`), the #end
    // of that macro must not run, and drop its locals, before `first` is evaluated.
    if (first.kind == TokenKind::identifier && !first.element && !reserved(first)) {
      const bool alone = ahead_is(",") || ahead_is(")");   // lexed first, as the token after it always was
      auto level = first.name ? symbols_.level_of(first.name) : symbols_.level_of(first.text);
      if (level && alone) {
        macro_arguments_.emplace_back(
            macro.parameter_ids[i],
            Alias{*level, first.name ? first.name : symbols_.id_of(first.text)});
        continue;
      }
    }
    std::optional<Value> value;
    {
      const RawOperatorLook raw_look(*this);   // POV-Ray's Ok_To_Declare is off in a macro's arguments
      value = try_parse_rvalue(first);
    }
    if (!value) fail_expected(first, "a value for macro parameter '" + macro.parameters[i] + "'");
    macro_arguments_.emplace_back(macro.parameter_ids[i], std::move(*value));
  }
  if (plain_symbol(plain_ahead(), ')')) consume_plain();
  else if (Token close = next(); !close.is(")"))
    fail_expected(close, "')' closing the call of macro '" + std::string(name.text) + "' (it takes " +
                             std::to_string(macro.parameters.size()) + " parameters)");
  symbols_.push_scope();
  for (std::size_t i = base; i < macro_arguments_.size(); ++i)
    symbols_.bind(macro_arguments_[i].first, std::move(macro_arguments_[i].second));
  stream_.push_macro(macro, name);
  Control c;
  c.kind = Control::Kind::macro_call;
  c.frame = stream_.depth() - 1;
  c.loc = name.loc;
  controls_.push_back(c);
}

}  // namespace povtrace::sdl
