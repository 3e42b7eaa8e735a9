// The lexical level (povray-sdl-and-geometry.md §2): token kinds, texts, number values and positions, comments,
// string escapes, and the exact position and wording of lexical errors.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parser/lexing/lexer.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {
namespace {

FileNames& test_file_names() {   // lives through the test program, as the files made below do
  static FileNames names;
  return names;
}

SourceFile make_file(const std::string& text) {
  SourceFile f;
  f.name = test_file_names().intern("lex.pov");
  f.path = "lex.pov";
  f.text = text;
  return f;
}

// Every token of the file, the final end_of_input included.
std::vector<Token> lex_all(const SourceFile& file) {
  std::vector<Token> tokens;
  LexPosition at;
  while (true) {
    Token t = lex_token(file, at);
    tokens.push_back(t);
    if (t.kind == TokenKind::end_of_input) return tokens;
    EXPECT_GT(t.end.offset, at.offset) << "the lexer must make progress";
    at = t.end;
  }
}

// The error a malformed input raises (fails the test if it lexes).
ParseError lex_error(const std::string& text) {
  const SourceFile file = make_file(text);
  try {
    lex_all(file);
  } catch (const ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a lexical error for: " << text;
  return ParseError(SourceLoc{}, "<no error>");
}

const char* kind_name(TokenKind k) {
  switch (k) {
    case TokenKind::end_of_input: return "end";
    case TokenKind::number: return "number";
    case TokenKind::string: return "string";
    case TokenKind::identifier: return "identifier";
    case TokenKind::symbol: return "symbol";
  }
  return "?";
}

// ---- One token per input: kind, text, value, position ------------------------------------------------------
struct SingleToken {
  std::string input;
  TokenKind kind;
  std::string text;
  double number;
  int line, column;
};

class LexSingleToken : public ::testing::TestWithParam<SingleToken> {};

TEST_P(LexSingleToken, KindTextValueAndPosition) {
  const SingleToken& c = GetParam();
  const SourceFile file = make_file(c.input);
  const auto tokens = lex_all(file);
  ASSERT_EQ(tokens.size(), 2u) << "input: " << c.input;
  const Token& t = tokens[0];
  EXPECT_EQ(kind_name(t.kind), std::string(kind_name(c.kind))) << c.input;
  EXPECT_EQ(t.text, c.text) << c.input;
  if (c.kind == TokenKind::number) {
    EXPECT_DOUBLE_EQ(t.number, c.number) << c.input;
  }
  EXPECT_EQ(t.loc.line, c.line) << c.input;
  EXPECT_EQ(t.loc.column, c.column) << c.input;
  EXPECT_EQ(t.begin.line, c.line);
  EXPECT_EQ(t.begin.column, c.column);
  EXPECT_EQ(t.end.offset - t.begin.offset, c.text.size()) << "the token spans its text";
  EXPECT_EQ(*t.loc.file, "lex.pov");
}

INSTANTIATE_TEST_SUITE_P(
    Table, LexSingleToken,
    ::testing::Values(
        // Number forms (§2, [V sdl_lex]).
        SingleToken{"1", TokenKind::number, "1", 1, 1, 1},
        SingleToken{"1.", TokenKind::number, "1.", 1, 1, 1},
        SingleToken{".5", TokenKind::number, ".5", 0.5, 1, 1},
        SingleToken{"1e-3", TokenKind::number, "1e-3", 1e-3, 1, 1},
        SingleToken{"2E+2", TokenKind::number, "2E+2", 200, 1, 1},
        SingleToken{"3e2", TokenKind::number, "3e2", 300, 1, 1},
        SingleToken{"1.e3", TokenKind::number, "1.e3", 1000, 1, 1},
        SingleToken{"12.25", TokenKind::number, "12.25", 12.25, 1, 1},
        SingleToken{"007", TokenKind::number, "007", 7, 1, 1},
        // Identifiers and keywords are both identifier tokens at this level.
        SingleToken{"sphere", TokenKind::identifier, "sphere", 0, 1, 1},
        SingleToken{"Sphere", TokenKind::identifier, "Sphere", 0, 1, 1},
        SingleToken{"sphere2", TokenKind::identifier, "sphere2", 0, 1, 1},
        SingleToken{"_u", TokenKind::identifier, "_u", 0, 1, 1},
        SingleToken{"red_x", TokenKind::identifier, "red_x", 0, 1, 1},
        // Strings keep their quotes; an escaped quote does not end them; comment markers inside are text.
        SingleToken{"\"abc\"", TokenKind::string, "\"abc\"", 0, 1, 1},
        SingleToken{"\"a\\\"b\"", TokenKind::string, "\"a\\\"b\"", 0, 1, 1},
        SingleToken{"\"/* not a comment */\"", TokenKind::string, "\"/* not a comment */\"", 0, 1, 1},
        SingleToken{"\"\"", TokenKind::string, "\"\"", 0, 1, 1},
        // A literal line break inside a string is part of it, as in POV-Ray.
        SingleToken{"\n \"a\nb\"", TokenKind::string, "\"a\nb\"", 0, 2, 2},
        // Two-character operators.
        SingleToken{"<=", TokenKind::symbol, "<=", 0, 1, 1},
        SingleToken{">=", TokenKind::symbol, ">=", 0, 1, 1},
        SingleToken{"!=", TokenKind::symbol, "!=", 0, 1, 1},
        // POV-Ray has tokens for these too; they are syntax errors only later (povray: "@ found instead").
        SingleToken{"@", TokenKind::symbol, "@", 0, 1, 1},
        SingleToken{"$", TokenKind::symbol, "$", 0, 1, 1},
        // Blanks and comments before the token move its position.
        SingleToken{"   x", TokenKind::identifier, "x", 0, 1, 4},
        SingleToken{"\tx", TokenKind::identifier, "x", 0, 1, 2},
        SingleToken{"\n\n  x", TokenKind::identifier, "x", 0, 3, 3},
        SingleToken{"\r\nx", TokenKind::identifier, "x", 0, 2, 1},
        SingleToken{"// line comment\n  7", TokenKind::number, "7", 7, 2, 3},
        SingleToken{"// comment at the end of the file\nx", TokenKind::identifier, "x", 0, 2, 1},
        SingleToken{"/* block */ 7", TokenKind::number, "7", 7, 1, 13},
        SingleToken{"/* outer /* nested */ still comment */ 7", TokenKind::number, "7", 7, 1, 40},
        SingleToken{"/* a\n/* b\n*/\n*/x", TokenKind::identifier, "x", 0, 4, 3},
        SingleToken{"/* // */ 7", TokenKind::number, "7", 7, 1, 10},
        SingleToken{"// /* not opened\n7", TokenKind::number, "7", 7, 2, 1},
        // NUL and Ctrl-Z are blanks, as in POV-Ray.
        SingleToken{std::string("\0\x1a y", 4), TokenKind::identifier, "y", 0, 1, 4}));

// ---- Token sequences --------------------------------------------------------------------------------------
struct Sequence {
  std::string input;
  std::vector<std::string> texts;
};

class LexSequence : public ::testing::TestWithParam<Sequence> {};

TEST_P(LexSequence, SplitsIntoTheseTokens) {
  const SourceFile file = make_file(GetParam().input);
  const auto tokens = lex_all(file);
  std::vector<std::string> texts;
  for (std::size_t i = 0; i + 1 < tokens.size(); ++i) texts.emplace_back(tokens[i].text);
  EXPECT_EQ(texts, GetParam().texts) << GetParam().input;
}

INSTANTIATE_TEST_SUITE_P(
    Table, LexSequence,
    ::testing::Values(
        Sequence{"a<=b>=c!=d", {"a", "<=", "b", ">=", "c", "!=", "d"}},
        Sequence{"< = > =", {"<", "=", ">", "="}},
        Sequence{"!!=", {"!", "!="}},
        // A '.' not followed by a digit is the dot operator.
        Sequence{"V.x", {"V", ".", "x"}},
        Sequence{"1.x", {"1.", "x"}},
        Sequence{"<1,2>.y", {"<", "1", ",", "2", ">", ".", "y"}},
        // No sign in numbers: unary minus is an operator; '1e' without digits is a number then an identifier.
        Sequence{"-1", {"-", "1"}},
        Sequence{"1e", {"1", "e"}},
        Sequence{"2e+", {"2", "e", "+"}},
        Sequence{"#declare X=1;", {"#", "declare", "X", "=", "1", ";"}},
        Sequence{"#  debug", {"#", "debug"}},
        Sequence{"a/*c*/b//d\ne", {"a", "b", "e"}},
        Sequence{"1/2", {"1", "/", "2"}},
        Sequence{"{}()[],;:?&|*+", {"{", "}", "(", ")", "[", "]", ",", ";", ":", "?", "&", "|", "*", "+"}},
        Sequence{"\"a\"\"b\"", {"\"a\"", "\"b\""}},
        Sequence{"\"a\n//b\" c", {"\"a\n//b\"", "c"}},
        Sequence{"", {}},
        Sequence{"  // only a comment", {}},
        Sequence{"/* only /* nested */ comments */", {}}));

TEST(Lexer, EndOfInputIsRepeatableAndPositionedAfterTheText) {
  const SourceFile file = make_file("x\n  ");
  const auto tokens = lex_all(file);
  ASSERT_EQ(tokens.size(), 2u);
  const Token& end = tokens[1];
  EXPECT_EQ(end.kind, TokenKind::end_of_input);
  EXPECT_EQ(end.begin.offset, 4u);
  EXPECT_EQ(end.loc.line, 2);
  EXPECT_EQ(end.loc.column, 3);
  const Token again = lex_token(file, end.end);
  EXPECT_EQ(again.kind, TokenKind::end_of_input);
}

TEST(Lexer, PositionsAfterAMultiLineString) {
  const SourceFile file = make_file("\"one\ntwo\" x");
  const auto tokens = lex_all(file);
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[0].end.line, 2);
  EXPECT_EQ(tokens[1].text, "x");
  EXPECT_EQ(tokens[1].loc.line, 2);
  EXPECT_EQ(tokens[1].loc.column, 6);
}

TEST(Lexer, ReadsFromAnyPositionWithTheGivenLineAndColumn) {
  // Re-entrancy: macros and loops restart the lexer in the middle of a file.
  const SourceFile file = make_file("alpha\n  beta gamma");
  const auto tokens = lex_all(file);
  ASSERT_EQ(tokens.size(), 4u);
  const Token again = lex_token(file, tokens[1].begin);
  EXPECT_EQ(again.text, "beta");
  EXPECT_EQ(again.loc.line, 2);
  EXPECT_EQ(again.loc.column, 3);
  const Token next = lex_token(file, again.end);
  EXPECT_EQ(next.text, "gamma");
  EXPECT_EQ(next.loc.column, 8);
}

TEST(Lexer, ReservedWordsAreCaseSensitive) {
  EXPECT_TRUE(is_reserved_word("sphere"));
  EXPECT_TRUE(is_reserved_word("red"));
  EXPECT_TRUE(is_reserved_word("rgbft"));
  EXPECT_TRUE(is_reserved_word("vaxis_rotate"));
  EXPECT_FALSE(is_reserved_word("Sphere"));
  EXPECT_FALSE(is_reserved_word("Red"));
  EXPECT_FALSE(is_reserved_word("sphere2"));
  EXPECT_FALSE(is_reserved_word("red_x"));
  EXPECT_FALSE(is_reserved_word("tau"));   // not in 3.7
}

// ---- String escapes ------------------------------------------------------------------------------------------
struct Escape {
  std::string literal;   // the string token as written
  bool decode;
  std::string value;
};

class StringValue : public ::testing::TestWithParam<Escape> {};

TEST_P(StringValue, Decodes) {
  const SourceFile file = make_file(GetParam().literal);
  const Token t = lex_token(file, {});
  ASSERT_EQ(t.kind, TokenKind::string);
  EXPECT_EQ(string_value(t, file, GetParam().decode), GetParam().value) << GetParam().literal;
}

INSTANTIATE_TEST_SUITE_P(
    Table, StringValue,
    ::testing::Values(Escape{R"("plain")", true, "plain"},
                      Escape{R"("tab[\t] quote[\"] backslash[\\] apos[\'] u[\u0041]")", true,
                             "tab[\t] quote[\"] backslash[\\] apos['] u[A]"},
                      Escape{R"("a\nb")", true, "a\nb"},
                      Escape{"\"two\nlines\"", true, "two\nlines"},
                      Escape{R"("\a\b\f\r\v")", true, "\a\b\f\r\v"},
                      Escape{R"("\u00e9")", true, " "},   // non-ASCII becomes a space
                      // File names are taken verbatim, except the lexer-level \".
                      Escape{R"("dir\new\file.inc")", false, "dir\\new\\file.inc"},
                      Escape{R"("say \"hi\"")", false, "say \"hi\""}));

struct BadEscape {
  std::string literal;
  int column;
  std::string fragment;
};

class BadStringValue : public ::testing::TestWithParam<BadEscape> {};

TEST_P(BadStringValue, NamesTheEscapeAndItsColumn) {
  const SourceFile file = make_file("  " + GetParam().literal);
  const Token t = lex_token(file, {});
  try {
    string_value(t, file, true);
    ADD_FAILURE() << "expected an error for " << GetParam().literal;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.location().line, 1);
    EXPECT_EQ(e.location().column, GetParam().column) << e.what();
    EXPECT_NE(e.bare_message().find(GetParam().fragment), std::string::npos) << e.bare_message();
  }
}

INSTANTIATE_TEST_SUITE_P(Table, BadStringValue,
                         ::testing::Values(BadEscape{R"("ab\q")", 6, "unknown escape sequence '\\q'"},
                                           BadEscape{R"("\u00")", 5, "four hexadecimal digits"},
                                           BadEscape{R"("x\uZZZZ")", 6, "four hexadecimal digits"}));

// ---- Lexical errors: exact position and wording -----------------------------------------------------------
struct LexError {
  std::string name;
  std::string input;
  int line, column;
  std::string fragment;
};

class LexErrors : public ::testing::TestWithParam<LexError> {};

TEST_P(LexErrors, PositionAndMessage) {
  const LexError& c = GetParam();
  const ParseError e = lex_error(c.input);
  EXPECT_EQ(e.location().line, c.line) << e.what();
  EXPECT_EQ(e.location().column, c.column) << e.what();
  EXPECT_NE(e.bare_message().find(c.fragment), std::string::npos) << e.bare_message();
  const std::string prefix = "lex.pov:" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": error: ";
  EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
}

// lex_quick, the hand-written reader of common tokens, reads what lex_token reads wherever it reads anything, and
// leaves to it everything else (comments, strings, the end, errors, numbers from_chars does not take).
TEST(LexQuick, AgreesWithTheGrammarOnEveryTokenItReads) {
  const std::string text =
      "#declare Value_12 = <1 * 0.5, 2. + .25, -3e2, 4E+1, 5e-1, 6e, 7e+, 8.e3> * 2;\n"
      "  \t\r\v\f\x1a x<=y>=z!=w x<y>z!w a/b /* c */ d // e\n f \"s\" {}()[],;:?=+-*.&|#%^@$'~`\\ _a9 "
      "1.5.x 9 1e-999 .x .";
  const SourceFile file = make_file(std::string(text) + '\0' + " g");
  LexPosition at;
  int quick = 0;
  while (true) {
    const Token t = lex_token(file, at);
    if (QuickToken q; lex_quick(file, at, q)) {
      ++quick;
      EXPECT_EQ(q.kind, t.kind) << t.text;
      EXPECT_EQ(q.begin.offset, t.begin.offset) << t.text;
      EXPECT_EQ(q.begin.line, t.begin.line) << t.text;
      EXPECT_EQ(q.begin.column, t.begin.column) << t.text;
      EXPECT_EQ(q.length, t.text.size()) << t.text;
      if (t.kind == TokenKind::number) {
        EXPECT_EQ(q.number, t.number) << t.text;
      }
    } else {
      EXPECT_TRUE(t.kind == TokenKind::end_of_input || t.kind == TokenKind::string || t.text == "1e-999" ||
                  t.text == "d" || t.text == "f")
          << "left to lex_token: " << t.text;
    }
    if (t.kind == TokenKind::end_of_input) break;
    at = t.end;
  }
  EXPECT_GT(quick, 60);
}

TEST(LexQuick, LeavesErrorsToTheGrammar) {
  for (const char* text : {"1.2.3", "1e999", "\x01", "\"open"}) {
    QuickToken q;
    EXPECT_FALSE(lex_quick(make_file(text), {}, q)) << text;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, LexErrors,
    ::testing::Values(
        // Unterminated comments and strings are reported at their opening '/*' or '"'.
        LexError{"UnterminatedComment", "x\n  /* never closed\n\n", 2, 3, "unterminated block comment"},
        LexError{"UnterminatedAfterClosedComments", "/* ok */ // line\n /* fine /* nested */ */ /* open", 2,
                 26, "expected '*/' before the end of the file"},
        // The inner comment is closed; the outer one is not.
        LexError{"UnterminatedNestedComment", "/* outer /* inner */ still open", 1, 1, "expected '*/'"},
        LexError{"UnterminatedString", "#debug \"abc\n", 1, 8, "unterminated string"},
        LexError{"StringAtEndOfFile", "  \"abc", 1, 3, "expected '\"' before the end of the file"},
        LexError{"StringEndingInAnEscapedQuote", "\"abc\\\"", 1, 1, "unterminated string"},
        LexError{"SecondDecimalPoint", "#declare A = 1.2.3;", 1, 17, "a second '.'"},
        LexError{"ControlCharacter", "#declare A = 1;\n\x01", 2, 1, "illegal character 0x01"},
        LexError{"HighByte", "ab \xff", 1, 4, "illegal character 0xFF"}),
    [](const auto& p) { return p.param.name; });

}  // namespace
}  // namespace povtrace::sdl
