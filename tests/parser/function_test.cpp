// The function { } sub-language (povray-sdl-and-geometry.md §6; parser/function_*.cpp): precedence, parameters,
// captured constants, sum/prod/select, the built-ins, POV-Ray's constant folding, internal(N) functions, vector
// (transform, pigment) functions, calls from SDL, errors with their positions, deep nesting and long chains, and
// the standard includes that need functions (math.inc, functions.inc, transforms.inc, shapes.inc).
//
// Every expected value is POV-Ray 3.7.0's own output for the same scene, printed with str(…, 0, 20): the results
// must agree to the last bit (POV-Ray evaluates x/10 as x*0.1, pow(x,3) as x*x*x, folds x+0.1+0.2 into x+0.3…).
#include <chrono>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

struct ValueCase {
  std::string name;
  std::string prelude;
  std::string expression;
  std::string expected;   // POV-Ray's str(expression, 0, 20)
};

class FunctionValues : public ::testing::TestWithParam<ValueCase> {};

TEST_P(FunctionValues, MatchesPovRayToTheLastDigit) {
  const ValueCase& c = GetParam();
  const std::string out =
      debug_output("#version 3.7;\n" + c.prelude + "\n#debug str(" + c.expression + ", 0, 20)\n");
  EXPECT_EQ(out, c.expected) << c.prelude << "\n" << c.expression;
}

INSTANTIATE_TEST_SUITE_P(
    Povray, FunctionValues,
    ::testing::Values(
        ValueCase{"PrecedenceMulOverAdd", "#declare F = function { 1 + x*3 }",
                  "F(2,0,0)", "7.00000000000000000000"},
        ValueCase{"SubtractionIsLeftAssociative", "#declare F = function { x - y - z }",
                  "F(10,4,3)", "3.00000000000000000000"},
        ValueCase{"AndBindsTighterThanOr", "#declare F = function { x | y & z }",
                  "F(1,0,0)", "1.00000000000000000000"},
        ValueCase{"ComparisonsBelowAddition", "#declare F = function { x + 1 < y * 2 }",
                  "F(2,2,0)", "1.00000000000000000000"},
        ValueCase{"UnaryMinusOnOperand", "#declare F = function { -x*y - -2 }",
                  "F(2,3,0)", "-4.00000000000000000000"},
        ValueCase{"SignAfterOperator", "#declare F = function { x * -y }",
                  "F(2,3,0)", "-6.00000000000000000000"},
        ValueCase{"LogicalResults", "#declare F = function { (x | y & z) + 10*(x = y) + 100*(x != y) }",
                  "F(1,0,0)", "101.00000000000000000000"},
        ValueCase{"ConstantChainFoldsLikePovRay", "#declare F = function { x < 1 < 2 }",
                  "F(5,0,0)", "0.00000000000000000000"},
        ValueCase{"ParenthesesOverridePrecedence", "#declare F = function { (x + 1) * 3 }",
                  "F(2,0,0)", "9.00000000000000000000"},
        ValueCase{"DefaultParametersXYZ", "#declare F = function { x + 10*y + 100*z }",
                  "F(1,2,3)", "321.00000000000000000000"},
        ValueCase{"NamedParameters", "#declare F = function(a, b) { a*10 + b }",
                  "F(4,2)", "42.00000000000000000000"},
        ValueCase{"XWithoutSuchParameterIsZero", "#declare F = function(a, b) { x + a*10 + b }",
                  "F(1,2)", "12.00000000000000000000"},
        ValueCase{"UAndVAreXAndY", "#declare F = function(u, v) { x + y*10 + u*100 + v*1000 }",
                  "F(1,2)", "2121.00000000000000000000"},
        ValueCase{"ParameterNamedXAmongOthers", "#declare F = function(x, y, z, w) { x + w }",
                  "F(1,2,3,4)", "5.00000000000000000000"},
        ValueCase{"CapturedConstant", "#declare K = 2;\n#declare F = function { x*K }\n#declare K = 10;",
                  "F(3,0,0)", "6.00000000000000000000"},
        ValueCase{"PiAndClock", "#declare F = function { pi*x + clock }",
                  "F(2,0,0)", "6.28318530717958623200"},
        ValueCase{"Sum", "#declare F = function { sum(i, 1, 4, i*x) }",
                  "F(2,0,0)", "20.00000000000000000000"},
        ValueCase{"Prod", "#declare F = function { prod(i, 1, 4, i) + y }",
                  "F(0,3,0)", "27.00000000000000000000"},
        ValueCase{"NestedSum", "#declare F = function { sum(i, 1, 3, sum(j, 1, i, j)) }",
                  "F(0,0,0)", "10.00000000000000000000"},
        ValueCase{"SumFractionalBounds", "#declare F = function { sum(i, 0.5, 2, i) }",
                  "F(0,0,0)", "2.00000000000000000000"},
        ValueCase{"Select3", "#declare F = function { select(x, 1, 2) }",
                  "F(-1,0,0)*10 + F(0,0,0)", "12.00000000000000000000"},
        ValueCase{"Select4", "#declare F = function { select(x, 10, 20, 30) }",
                  "F(-1,0,0)*100 + F(0,0,0)*10 + F(1,0,0)", "1230.00000000000000000000"},
        ValueCase{"IntDivMod", "#declare F = function { int(x) + div(x, 2)*100 + mod(x, 3)*10000 }",
                  "F(-7.5,0,0)", "-15307.00000000000000000000"},
        ValueCase{"MinMaxAbs", "#declare F = function { min(x,y,z) + 10*max(x,y,z) + 100*abs(x) }",
                  "F(-1,2,3)", "129.00000000000000000000"},
        ValueCase{"ExpLnLog", "#declare F = function { exp(x) + ln(y) + log(z) }",
                  "F(1,2,3)", "3.88855026373865308997"},
        ValueCase{"Trigonometry", "#declare F = function { sin(x) + cos(y)*2 + tan(z)*3 + atan2(x, y)*4 }",
                  "F(0.3,0.4,0.5)", "6.35055409937161918776"},
        ValueCase{"Hyperbolic", "#declare F = function { sinh(x) + cosh(x)*2 + tanh(x)*3 + asinh(x)*4 + acosh(y)*5 + atanh(x)*6 }",
                  "F(0.3,1.5,0)", "11.12106322512803124880"},
        ValueCase{"RadiansDegrees", "#declare F = function { radians(x) + degrees(x) }",
                  "F(0.7,0,0)", "40.11926296392157809123"},
        ValueCase{"FloorCeilSqrtPow", "#declare F = function { floor(x) + ceil(x)*10 + sqrt(y)*100 + pow(y, 0.5)*1000 }",
                  "F(-2.5,2,0)", "1532.63491861040461117227"},
        ValueCase{"IntOutOfRangeIsIntMin", "#declare F = function { int(x) + 1000*div(x, 0.001) }",
                  "F(3e9,0,0)", "-2149631131648.00000000000000000000"},
        ValueCase{"DivisionByAConstantIsAMultiplication", "#declare F = function { x/10 }",
                  "F(3,0,0)", "0.30000000000000004441"},
        ValueCase{"PowByAConstantMultiplies", "#declare F = function { pow(x, 3) }",
                  "F(1.3,0,0)", "2.19700000000000050804"},
        ValueCase{"PowInALaterArgumentIsNotFolded", "#declare F = function { max(1, pow(x, 3)) }",
                  "F(1.3,0,0)", "2.19700000000000006395"},
        ValueCase{"PowerSequences", "#declare F = function { pow(x, 3.5) + pow(x, 7) + pow(x,6) + pow(x,5) }",
                  "F(1.3,0,0)", "17.31955610894280894740"},
        ValueCase{"ConstantsAddedFirst", "#declare F = function { 0.1 * 0.2 * x + 1 - 0.3 - 0.4 }",
                  "F(0.7,0,0)", "0.31399999999999994582"},
        ValueCase{"MultiplicationNotReassociatedAfterAVariable", "#declare F = function { x * 2 * 3 + 2 * 3 * x }",
                  "F(0.1,0,0)", "1.20000000000000017764"},
        ValueCase{"NaNComparisons", "#declare F = function { (sqrt(x) > 1) + 2*(sqrt(x) >= 1) + 4*(sqrt(x) != 1) + 8*(sqrt(x) < 1) + 16*(sqrt(x) <= 1) + 32*(sqrt(x) = 1) }",
                  "F(-1,0,0)", "7.00000000000000000000"},
        ValueCase{"DivisionByZeroAtRunTimeIsInfinite", "#declare F = function { x/y }",
                  "(F(1,0,0) > 1e300)", "1.00000000000000000000"},
        ValueCase{"CallOfAnotherFunction", "#declare G = function(a) { a*a }\n#declare F = function { G(x) + G(y) }",
                  "F(3,4,0)", "25.00000000000000000000"},
        ValueCase{"CallInSdlExpression", "#declare F = function { x + y*z }",
                  "F(1, 2, 3) * 2 + 1", "15.00000000000000000000"},
        ValueCase{"SdlCallCommasOptional", "#declare F = function { x + 10*y + 100*z }",
                  "F(1 2 3)", "321.00000000000000000000"},
        ValueCase{"CopiedFunction", "#declare F = function { x*2 }\n#declare G = F;",
                  "G(4,0,0)", "8.00000000000000000000"},
        ValueCase{"FunctionAsMacroArgument", "#macro Twice(Fn, V) Fn(V, 0, 0)*2 #end",
                  "Twice(function { x + 1 }, 3)", "8.00000000000000000000"},
        ValueCase{"FunctionInArray", "#declare A = array[2];\n#declare A[0] = function { x + 1 }\n#declare A[1] = function { A[0](x, y, z) * 10 }",
                  "A[1](2, 0, 0)", "30.00000000000000000000"},
        ValueCase{"TransformFunction", "#declare T = function { transform { rotate y*90 translate <1,2,3> } }",
                  "T(1,0,0).x + T(1,0,0).y*10 + T(1,0,0).z*100", "221.00000000000000000000"},
        ValueCase{"TransformFunctionInAFunction", "#declare T = function { transform { rotate y*90 translate <1,2,3> } }\n#declare F = function { T(x,y,z).x + T(x,y,z).y*10 }",
                  "F(1,0,0)", "21.00000000000000000000"},
        ValueCase{"ColourPigmentFunction", "#declare P = function { pigment { rgb <0.2, 0.4, 0.6> } }",
                  "P(0,0,0).green", "0.40000000596046447754"},
        ValueCase{"Internal_f_sphere", "#include \"functions.inc\"",
                  "f_sphere(1, 2, 3, 1)", "2.74165738677394132949"},
        ValueCase{"Internal_f_torus", "#include \"functions.inc\"",
                  "f_torus(1, 0.5, 0.2, 1, 0.25)", "0.25039204086684485606"},
        ValueCase{"Internal_f_rounded_box", "#include \"functions.inc\"",
                  "f_rounded_box(1, 2, 0.5, 0.1, 0.5, 0.5, 0.5)", "1.61172327686236904754"},
        ValueCase{"Internal_f_superellipsoid", "#include \"functions.inc\"",
                  "f_superellipsoid(0.3, 0.4, 0.5, 0.5, 0.7)", "0.40506700316754706837"},
        ValueCase{"Internal_f_helix1", "#include \"functions.inc\"",
                  "f_helix1(0.3, -0.7, 1.1, 0.8, 1.3, 1.0, 0.3, 30.0, 0.7, 2.0)", "-0.15701111504697262689"},
        ValueCase{"Internal_f_helical_torus", "#include \"functions.inc\"",
                  "f_helical_torus(1.7, 0.4, -0.25, 1.5, 0.6, 0.0, 0.2, 0.0, 2.0, 45.0, 0.9, 0.4, 1.2)", "1.21828402774395816444"},
        ValueCase{"Internal_f_boy_surface", "#include \"functions.inc\"",
                  "f_boy_surface(0.3, -0.7, 1.1, 0.8, 1.3)", "-10.00000000000000000000"},
        ValueCase{"Internal_f_dupin_cyclid", "#include \"functions.inc\"",
                  "f_dupin_cyclid(-0.45, 1.3, 0.6, 2.0, 1.1, 1.0, 0.0, 15.0, 1.0)", "-10.00000000000000000000"},
        ValueCase{"Internal_f_enneper", "#include \"functions.inc\"",
                  "f_enneper(0.3, -0.7, 0.1, 0.8)", "0.39465480603566549522"},
        ValueCase{"Internal_f_mesh1", "#include \"functions.inc\"",
                  "f_mesh1(1.7, 0.4, -0.25, 1.5, 0.6, 0.0, 0.2, 0.0)", "0.00000000000000000000"},
        ValueCase{"Internal_f_spiral", "#include \"functions.inc\"",
                  "f_spiral(-0.45, 1.3, 0.6, 2.0, 1.1, 1.0, 0.0, 15.0, 1.0)", "0.50083310198036334882"},
        ValueCase{"Internal_f_kampyle_of_eudoxus_2d", "#include \"functions.inc\"",
                  "f_kampyle_of_eudoxus_2d(0.3, -0.7, 1.1, 0.8, 1.3, 1.0, 0.3, 30.0, 0.7)", "10.00000000000000000000"},
        ValueCase{"Internal_f_hex_y", "#include \"functions.inc\"",
                  "f_hex_y(1.7, 0.4, -0.25, 1.5)", "0.17224318643354574743"},
        ValueCase{"Internal_f_polytubes", "#include \"functions.inc\"",
                  "f_polytubes(-0.45, 1.3, 0.6, 5, 1.1, 1.0, 0.0, 15.0, 1.0)", "37.60019127606483380077"},
        ValueCase{"Internal_f_quantum", "#include \"functions.inc\"",
                  "f_quantum(0.3, -0.7, 1.1, 0.8)", "1.17247727744226959423"},
        ValueCase{"Internal_f_sine_wave", "#include \"functions.inc\"",
                  "f_sine_wave(0.3, 0.4, 0.5)", "0.18159619989581871069"},
        ValueCase{"InternalCalledFromAFunction", "#include \"functions.inc\"\n#declare F = function { f_sphere(x, y, z, 1) * 2 }",
                  "F(1, 2, 3)", "5.48331477354788265899"},
        ValueCase{"InternalPatternWithoutPatternIsZero", "#declare F = function { internal(77) }",
                  "F(1, 2, 3)", "0.00000000000000000000"}),
    [](const ::testing::TestParamInfo<ValueCase>& p) { return p.param.name; });

// ---- Errors, with their positions -------------------------------------------------------------------------------
struct ErrorCase {
  std::string name;
  std::string text;
  int line, column;
  std::string fragment;
};

class FunctionErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(FunctionErrors, NamesThePosition) {
  const ErrorCase& c = GetParam();
  const ParseError e = parse_error("#version 3.7;\n" + c.text);
  EXPECT_EQ(e.location().line, c.line + 1) << e.what();
  EXPECT_EQ(e.location().column, c.column) << e.what();
  EXPECT_NE(e.bare_message().find(c.fragment), std::string::npos) << e.bare_message();
}

INSTANTIATE_TEST_SUITE_P(
    Povray, FunctionErrors,
    ::testing::Values(
        ErrorCase{"UndefinedParameter", "#declare F = function(a, b) { a + c }\n", 1, 35,
                  "'c' is neither a parameter of this function (a, b) nor a declared float"},
        ErrorCase{"UndeclaredFunction", "#declare F = function { f_sphere(x, y, z, 1) }\n", 1, 25,
                  "'f_sphere' is not a declared function (the f_… functions are declared in functions.inc)"},
        ErrorCase{"DeclaredParameterName", "#declare r = 1;\n#declare F = function(r) { r }\n", 2, 23,
                  "expected a parameter name (an undeclared identifier, or x, y, z, u, v), found the float "
                  "identifier 'r'"},
        ErrorCase{"TrailingCommaInParameters", "#declare F = function(a,) { a }\n", 1, 25,
                  "expected a parameter name"},
        ErrorCase{"VectorIdentifierInBody", "#declare V = <1,2,3>;\n#declare F = function { V }\n", 2, 25,
                  "expected an operand"},
        ErrorCase{"TooFewArgumentsInABody", "#declare F = function(a, b) { a }\n#declare G = function { F(x) }\n", 2,
                  25, "the function 'F' takes 2 parameter(s), found 1"},
        ErrorCase{"TooFewArgumentsInSdl", "#declare F = function(a, b) { a }\n#declare V = F(1);\n", 2, 17,
                  "the function 'F' takes 2 argument(s), found 1"},
        ErrorCase{"TooManyArgumentsInSdl", "#declare F = function(a, b) { a }\n#declare V = F(1, 2, 3);\n", 2, 20,
                  "the function 'F' takes only 2 argument(s)"},
        ErrorCase{"FunctionWithoutCall", "#declare F = function { x }\n#declare V = 1 + F;\n", 2, 19,
                  "expected '(' after the function 'F' (a function is used by calling it), found ';'"},
        ErrorCase{"IncompleteCallAsValue", "#declare F = function { x }\n#declare V = F + 1;\n", 2, 16,
                  "expected '(' and the arguments of the function 'F' (an incomplete function call), found '+'"},
        ErrorCase{"BuiltinArgumentCount", "#declare F = function { atan2(x) }\n", 1, 25,
                  "'atan2' takes two parameters, found 1"},
        ErrorCase{"SelectArgumentCount", "#declare F = function { select(x, 1) }\n", 1, 25,
                  "'select' takes three or four parameters, found 2"},
        ErrorCase{"SumVariableMustBeANewName", "#declare i = 1;\n#declare F = function { sum(i, 1, 3, x) }\n", 2,
                  29, "the name of the sum() variable"},
        ErrorCase{"SdlOnlyBuiltin", "#declare F = function { bitwise_and(x, 3) }\n", 1, 25,
                  "'bitwise_and' cannot be used inside a function"},
        ErrorCase{"NoSecondSign", "#declare F = function { --x }\n", 1, 26, "expected an operand"},
        ErrorCase{"NoMemberOnParentheses", "#declare F = function { (x).x }\n", 1, 28, "expected an operator"},
        ErrorCase{"MissingOperator", "#declare F = function(a, b) { a b }\n", 1, 33, "expected an operator"},
        ErrorCase{"DivisionByConstantZero", "#declare F = function { x/0 }\n", 1, 26, "division by zero"},
        ErrorCase{"InternalOutOfRange", "#declare F = function { internal(79) }\n", 1, 34,
                  "function 'internal(79)' does not exist"},
        ErrorCase{"VectorFunctionNeedsAMember",
                  "#declare T = function { transform { scale 2 } }\n#declare F = function { T(x, y, z) }\n", 2, 36,
                  "expected '.' and a component"},
        ErrorCase{"MemberBeyondTheResult",
                  "#declare T = function { transform { scale 2 } }\n#declare F = function { T(x, y, z).t }\n", 2,
                  36, "'.t' selects a component that the 3-component result of 'T' does not have"},
        ErrorCase{"ParametersOnATransformFunction", "#declare T = function(a) { transform { scale 2 } }\n", 1, 28,
                  "function parameters are not allowed for transform functions"},
        ErrorCase{"RedeclaringAFunction", "#declare F = function { x }\n#declare F = function { y }\n", 2, 10,
                  "redeclaring the function 'F' is not allowed: #undef it first"},
        ErrorCase{"RedeclaringAFunctionAsAFloat", "#declare F = function { x }\n#declare F = 1;\n", 2, 10,
                  "redeclaring the function 'F' is not allowed"},
        ErrorCase{"RedefiningAFloatAsAFunction", "#declare F = 1;\n#declare F = function { y }\n", 2, 10,
                  "cannot redefine the float identifier 'F' as a function: #undef it first"},
        ErrorCase{"PatternEvaluatedIsUnsupported", "#declare P = function { pattern { agate } }\n#declare V = P(1, 2, 3);\n",
                  2, 14, "unsupported: the pattern function (written at test.pov:2:14)"},
        ErrorCase{"TexturedPigmentEvaluatedIsUnsupported",
                  "#declare P = function { pigment { checker } }\n#declare V = P(1, 2, 3).x;\n", 2, 14,
                  "unsupported: the pigment function"},
        ErrorCase{"DeepNestingIsRefused",
                  "#declare F = function { " + std::string(10000, '(') + "x" + std::string(10000, ')') + " }\n", 1,
                  524, "nested too deeply (more than 500 levels)"}),
    [](const ::testing::TestParamInfo<ErrorCase>& p) { return p.param.name; });

TEST(Functions, RedeclaringAfterUndefWorks) {
  EXPECT_EQ(debug_output("#version 3.7;\n#declare F = function { x }\n#undef F\n#declare F = function { x*2 }\n"
                         "#debug str(F(3, 0, 0), 0, 1)\n"),
            "6.0");
}

TEST(Functions, LocalInAMacroMayBeDeclaredOnEveryCall) {
  // transforms.inc's vtransform() does `#local fn = function { transform { … } }` on every call.
  EXPECT_EQ(debug_output("#version 3.7;\n#macro M(A) #local fn = function { x*A } fn(2, 0, 0) #end\n"
                         "#debug concat(str(M(3), 0, 1), \" \", str(M(4), 0, 1))\n"),
            "6.0 8.0");
}

// The expected lines below are what POV-Ray 3.7.0.10 printed (#debug) for the same scenes.
TEST(Functions, ALocalFunctionReturnedByAMacroIsHeld) {
  // The look after `F` (is a '(' next?) ends the macro, and its #local with it: the function is taken before.
  // (POV-Ray refuses G(2) here, as povtrace does: a function without parameters takes x, y and z.)
  EXPECT_EQ(debug_output("#version 3.7;\n"
                         "#macro A() #local F = function { x + 1 } F #end\n"
                         "#macro A2() #local F = function(a, b) { a * b + 1 } F #end\n"
                         "#macro Pf() #local F = function { pigment { rgb <1,0.5,0.25> } } F #end\n"
                         "#declare G = A();\n"
                         "#declare G2 = A2();\n"
                         "#declare P = Pf();\n"
                         "#debug concat(str(G(2, 0, 0), 0, 3), \" \", str(G2(2, 3), 0, 3), \" \",\n"
                         "              vstr(3, P(0, 0, 0), \",\", 0, 3), \"\\n\")\n"),
            "3.000 7.000 1.000,0.500,0.250\n");
}

TEST(Functions, ALocalFunctionReturnedByAMacroMayBeCalledAtOnce) {
  // `A()(2)`: POV-Ray takes the call of the function the macro returns, in a #debug, in a #declare's expression
  // (with operators and .x after it) and inside another function.
  EXPECT_EQ(debug_output("#version 3.7;\n"
                         "#macro A() #local F = function(a) { a + 1 } F #end\n"
                         "#macro B() #local H = A(); H #end\n"
                         "#macro C() #local F = function { x + y * z } F #end\n"
                         "#declare V1 = A()(2) + 1;\n"
                         "#declare V2 = A()(2) * 3 + 1;\n"
                         "#declare V3 = A()(2).x;\n"
                         "#declare V4 = C()(1, 2, 3);\n"
                         "#declare Hf = function(b) { A()(b) * 10 }\n"
                         "#declare K = B();\n"
                         "#debug concat(str(A()(2), 0, 3), \" \", str(V1, 0, 3), \" \", str(V2, 0, 3), \" \",\n"
                         "              str(V3, 0, 3), \" \", str(V4, 0, 3), \" \", str(Hf(2), 0, 3), \" \",\n"
                         "              str(K(7), 0, 3), \"\\n\")\n"),
            "3.000 4.000 10.000 3.000 7.000 30.000 8.000\n");
}

TEST(Functions, AGlobalFunctionIsCopiedByDeclare) {
  EXPECT_EQ(debug_output("#version 3.7;\n"
                         "#declare F = function(a) { a * 2 }\n"
                         "#declare G = F;\n"
                         "#macro A() F #end\n"
                         "#declare G2 = A();\n"
                         "#debug concat(str(G(2), 0, 3), \" \", str(G2(4), 0, 3), \"\\n\")\n"),
            "4.000 8.000\n");
}

TEST(Functions, LocalPigmentsObjectsAndFinishesReturnedByAMacroResolve) {
  // The other declared values a macro may return as a #local (these were never looked up again; kept so).
  EXPECT_EQ(debug_output("#version 3.7;\n"
                         "#macro P() #local Q = pigment { rgb <1,0.5,0.25> } Q #end\n"
                         "#macro O() #local Q = sphere { <1,2,3>, 1 } Q #end\n"
                         "#macro Fi() #local Q = finish { ambient 0.3 } Q #end\n"
                         "#declare R = P();\n"
                         "#declare PF = function { pigment { R } }\n"
                         "#declare S = O();\n"
                         "#declare Fin = Fi();\n"
                         "#debug concat(vstr(3, PF(0, 0, 0), \",\", 0, 3), \" \", vstr(3, min_extent(S), \",\", 0, 3), "
                         "\"\\n\")\n"),
            "1.000,0.500,0.250 0.000,1.000,2.000\n");
}

TEST(Functions, ZeroPowerWarns) {
  Messages m;
  parse("#version 3.7;\n#declare F = function { pow(x, 0) }\n#debug str(F(5, 0, 0), 0, 1)\n", &m);
  EXPECT_NE(m.joined().find("zero power optimised to the constant 1.0"), std::string::npos) << m.joined();
  EXPECT_EQ(m.items.back(), "1.0");
}

TEST(Functions, VectorResultsInSdl) {
  EXPECT_EQ(eval_terms("T(1, 0, 0)", "#declare T = function { transform { rotate y*90 translate <1,2,3> } }"),
            (std::vector<double>{1, 2, 2, 0, 0}));
  EXPECT_EQ(eval_terms("P(0, 0, 0)", "#declare P = function { pigment { rgbft <0.5, 0.25, 0.125, 0.5, 0.75> } }"),
            (std::vector<double>{0.5, 0.25, 0.125, 0.5, 0.75}));
}

TEST(Functions, DefiningNoiseAndPatternFunctionsIsFine) {
  // Only evaluating them is refused: functions.inc defines f_bozo, f_agate, f_hexagon… without using them.
  EXPECT_NO_THROW(parse("#version 3.7;\n#include \"functions.inc\"\n"
                        "#declare F = function { f_bozo(x, y, z) + f_agate(x, y, z) + f_hexagon(x, y, z).gray }\n"));
}

// ---- Depth and length: evaluation is iterative -----------------------------------------------------------------
TEST(Functions, LongChainOfOperators) {
  std::string body = "x";
  for (int i = 0; i < 10000; ++i) body += "+x";
  EXPECT_EQ(debug_output("#version 3.7;\n#declare F = function { " + body + " }\n#debug str(F(1, 0, 0), 0, 1)\n"),
            "10001.0");
}

TEST(Functions, TenThousandFunctionsCallingEachOther) {
  EXPECT_EQ(debug_output("#version 3.7;\n#declare N = 10000;\n#declare A = array[N];\n"
                         "#declare A[0] = function { x + 1 }\n"
                         "#for (I, 1, N-1)\n  #declare A[I] = function { A[I-1](x, y, z) + 1 }\n#end\n"
                         "#debug str(A[N-1](0.5, 0, 0), 0, 1)\n"),
            "10000.5");
}

TEST(Functions, CallsInALoopAreFast) {
  // 10^5 calls (each with a nested call, an internal function and a 10-term sum) cost about as much as the
  // #while loop around them: compared with the same loop calling sin(), so that the bound holds in any build.
  auto seconds = [](const std::string& scene, std::string& out) {
    const auto start = std::chrono::steady_clock::now();
    out = debug_output(scene);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const std::string loop_head = "#declare S = 0;\n#declare I = 0;\n#while (I < 100000)\n  #declare S = S + ";
  const std::string loop_tail = ";\n  #declare I = I + 1;\n#end\n#debug str(S, 0, 6)\n";
  std::string out, baseline_out;
  const double with_calls = seconds(
      "#version 3.7;\n#include \"functions.inc\"\n"
      "#declare G = function(a) { sin(a)*cos(a) + f_sphere(a, 1, 2, 0.5) }\n"
      "#declare F = function(a, b) { G(a) + sum(i, 1, 10, i*b) }\n" + loop_head + "F(I, 0.001)" + loop_tail, out);
  const double baseline = seconds("#version 3.7;\n" + loop_head + "sin(I)" + loop_tail, baseline_out);
  EXPECT_EQ(out, "4999905530.972989");   // POV-Ray 3.7.0
  EXPECT_EQ(baseline_out, "1.812028");
  EXPECT_LT(with_calls, 3 * baseline + 0.5) << with_calls << " s with calls, " << baseline << " s without";
}

TEST(Functions, WorkIsBoundedWithMaxTokens) {
  // The fuzzer sets max_tokens so that every input ends; a sum() of 10^12 terms must end too.
  ParseOptions o;
  o.max_tokens = 1000;
  const ParseError e = parse_error("#version 3.7;\n#declare F = function { sum(i, 1, 1e12, i) }\n#declare V = F(0, 0, 0);\n", o);
  EXPECT_EQ(e.location().line, 3);
  EXPECT_EQ(e.location().column, 14);
  EXPECT_NE(e.bare_message().find("ParseOptions::max_tokens"), std::string::npos) << e.bare_message();
}

TEST(Functions, PolytubesWithAHugeCountIsNoUndefinedConversion) {
  EXPECT_EQ(debug_output("#version 3.7;\n#include \"functions.inc\"\n"
                         "#debug str(f_polytubes(1, 2, 3, 1e300, 1, 0, 0, 0, 0), 0, 1)\n"),
            "10000.0");   // POV-Ray: (int)1e300 is INT_MIN on x86, so no tube: -(-10000)
}

// ---- The standard includes that need functions -------------------------------------------------------------------
TEST(Functions, StandardIncludesGivePovRayValues) {
  const std::string scene =
    "#version 3.7;\n"
    "#include \"colors.inc\"\n"
    "#include \"math.inc\"\n"
    "#include \"functions.inc\"\n"
    "#include \"transforms.inc\"\n"
    "#include \"shapes.inc\"\n"
    "#macro P(S, V) #debug concat(S, \"=\", str(V,0,17), \"\\n\") #end\n"
    "#macro PV(S, V) #debug concat(S, \"=\", vstr(3, V, \",\", 0,17), \"\\n\") #end\n"
    "P(\"sind30\", sind(30))\n"
    "P(\"cosd60\", cosd(60))\n"
    "P(\"tand45\", tand(45))\n"
    "P(\"asind\", asind(0.5))\n"
    "P(\"acosd\", acosd(0.5))\n"
    "P(\"atand\", atand(1))\n"
    "P(\"atan2d\", atan2d(1, 2))\n"
    "P(\"max3\", max3(1,5,3))\n"
    "P(\"min3\", min3(4,2,3))\n"
    "P(\"even\", even(4)) P(\"odd\", odd(4)) P(\"even3\", even(3))\n"
    "P(\"f_sqr\", f_sqr(3.3))\n"
    "P(\"sgn\", sgn(-2.5)) P(\"sgn0\", sgn(0))\n"
    "P(\"clip\", clip(5, 0, 3))\n"
    "P(\"clamp\", clamp(5.5, 1, 3))\n"
    "P(\"adj_range\", adj_range(0.25, 2, 6))\n"
    "P(\"adj_range2\", adj_range2(0.5, 0, 1, 10, 20))\n"
    "P(\"f_sphere\", f_sphere(1,2,3, 1))\n"
    "P(\"f_torus\", f_torus(1,0.5,0.2, 1, 0.25))\n"
    "P(\"f_rounded_box\", f_rounded_box(1,2,0.5, 0.1, 0.5, 0.5, 0.5))\n"
    "P(\"f_superellipsoid\", f_superellipsoid(0.3,0.4,0.5, 0.5, 0.7))\n"
    "P(\"f_sine_wave\", f_sine_wave(0.3,0.4,0.5))\n"
    "P(\"VDist\", VDist(<1,2,3>, <4,6,3>))\n"
    "P(\"Interp0\", Interpolate(0.3, 0, 1, 10, 20, 0))\n"
    "P(\"Interp2\", Interpolate(0.3, 0, 1, 10, 20, 2))\n"
    "PV(\"VSqr\", VSqr(<1,2,3>))\n"
    "PV(\"vtransform\", vtransform(<1,2,3>, transform { rotate <10,20,30> translate <1,0,-1> scale 1.5 }))\n"
    "PV(\"vinv_transform\", vinv_transform(<1,2,3>, transform { rotate <10,20,30> translate <1,0,-1> scale 1.5 }))\n"
    "#declare T1 = Axis_Rotate_Trans(<1,1,0>, 37);\n"
    "PV(\"AxisRot\", vtransform(<0.3,0.5,0.7>, T1))\n"
    "#declare T2 = Reorient_Trans(<1,0,0>, <0,1,1>)\n"
    "PV(\"Reorient\", vtransform(<0.3,0.5,0.7>, T2))\n"
    "#declare T3 = Point_At_Trans(<1,2,3>);\n"
    "PV(\"PointAt\", vtransform(<0.3,0.5,0.7>, T3))\n"
    "#declare T4 = Rotate_Around_Trans(<0,45,0>, <1,0,0>);\n"
    "PV(\"RotAround\", vtransform(<0.3,0.5,0.7>, T4))\n"
    "PV(\"vGradient\", vGradient(function { x*x + y*y*2 + z }, <1,2,3>))\n"
    "P(\"Gradient_Length\", Gradient_Length(function { x*x + y*y*2 + z }, <1,2,3>))\n"
    "P(\"Divergence\", Divergence(function { x*x }, function { y*y }, function { z*z }, <1,2,3>))\n"
    "#declare G = fn_Gradient(function { x*x + y*y*2 + z })\n"
    "P(\"fn_Gradient\", G(1,2,3))\n"
    "#declare GD = fn_Gradient_Directional(function { x*x + y*y*2 + z }, <1,1,0>)\n"
    "P(\"fn_Gradient_Directional\", GD(1,2,3))\n"
    "PV(\"eval_pigment\", eval_pigment(pigment { rgb <0.2,0.4,0.6> }, <0,0,0>))\n"
    "PV(\"VPerp\", VPerp_To_Vector(<1,2,3>))\n"
    "PV(\"VProject_Plane\", VProject_Plane(<1,2,3>, <0,1,0>))\n"
    "P(\"VAngleD\", VAngleD(<1,0,0>, <1,1,0>))\n";
  const std::string expected =
    "sind30=0.49999999999999994\n"
    "cosd60=0.50000000000000011\n"
    "tand45=0.99999999999999989\n"
    "asind=30.00000000000000355\n"
    "acosd=60.00000000000000711\n"
    "atand=45.00000000000000000\n"
    "atan2d=26.56505117707799002\n"
    "max3=5.00000000000000000\n"
    "min3=2.00000000000000000\n"
    "even=1.00000000000000000\n"
    "odd=0.00000000000000000\n"
    "even3=0.00000000000000000\n"
    "f_sqr=10.88999999999999879\n"
    "sgn=-1.00000000000000000\n"
    "sgn0=0.00000000000000000\n"
    "clip=3.00000000000000000\n"
    "clamp=1.50000000000000000\n"
    "adj_range=3.00000000000000000\n"
    "adj_range2=15.00000000000000000\n"
    "f_sphere=2.74165738677394133\n"
    "f_torus=0.25039204086684486\n"
    "f_rounded_box=1.61172327686236905\n"
    "f_superellipsoid=0.40506700316754707\n"
    "f_sine_wave=0.18159619989581871\n"
    "VDist=5.00000000000000000\n"
    "Interp0=12.06107373853763320\n"
    "Interp2=10.90000000000000036\n"
    "VSqr=1.00000000000000000,4.00000000000000000,9.00000000000000000\n"
    "vtransform=3.10113806909847955,3.43358922393092536,2.64087212130355731\n"
    "vinv_transform=-0.67086457656952492,1.81326976268874640,2.67411338138676857\n"
    "AxisRot=0.61801968771879734,0.18198031228120265,0.64415435381125541\n"
    "Reorient=-0.84852813742385713,0.11213203435596425,0.31213203435596421\n"
    "PointAt=0.80816749911781427,0.41310142588122334,0.07881944750223660\n"
    "RotAround=0.99999999999999989,0.50000000000000000,0.98994949366116658\n"
    "vGradient=1.99999999999977973,7.99999999999911893,0.99999999999944578\n"
    "Gradient_Length=8.30662386291710675\n"
    "Divergence=11.99999999999867839\n"
    "fn_Gradient=8.30662386291710675\n"
    "fn_Gradient_Directional=7.07106781186469568\n"
    "eval_pigment=0.20000000298023224,0.40000000596046448,0.60000002384185791\n"
    "VPerp=0.00000000000000000,0.83205029433784372,-0.55470019622522915\n"
    "VProject_Plane=1.00000000000000000,0.00000000000000000,3.00000000000000000\n"
    "VAngleD=45.00000000000000711\n";
  EXPECT_EQ(debug_output(scene), expected);
}

}  // namespace
// The noise-based internal functions and vturbulence against the values POV-Ray 3.7.0.10 printed with
// #debug str(…, 0, 17) for the same calls (nine digits compared here: eval_float prints nine).
TEST(NoiseFunctions, MatchPovRayValues) {
  const std::string inc = "#include \"functions.inc\"\n";
  const std::string p0 = "0.3, 1.7, -2.2", p1 = "-5.25, 0.125, 3.9";
  EXPECT_NEAR(eval_float("f_noise3d(" + p0 + ")", inc), 0.52885147806171373, 1e-9);
  EXPECT_NEAR(eval_float("f_noise_generator(" + p0 + ", 3)", inc), 0.67029632432102426, 1e-9);
  EXPECT_NEAR(eval_float("f_noise_generator(" + p0 + ", 0)", inc), 0.52718639941302281, 1e-9);   // 0 is 1
  EXPECT_NEAR(eval_float("f_hetero_mf(" + p0 + ", 0.5, 2.1, 5.5, 0.3, 1, 2)", inc), 0.65986461946882957, 1e-9);
  EXPECT_NEAR(eval_float("f_hetero_mf(" + p0 + ", 0.8, 1.9, 4, 0.1, 2, 1)", inc), 0.16062175905264550, 1e-9);
  EXPECT_NEAR(eval_float("f_ridge(" + p0 + ", 2.2, 4.5, 0.6, 0.2, 0.3, 2)", inc), 0.20752287796509511, 1e-9);
  EXPECT_NEAR(eval_float("f_ridge(" + p0 + ", 2, 3, 0.5, 0.7, 0.6, 3)", inc), -0.81242254176999007, 1e-9);
  EXPECT_NEAR(eval_float("f_ridged_mf(" + p0 + ", 0.7, 2.3, 6, 1.1, 2, 2)", inc), 2.04255644207579712, 1e-9);
  EXPECT_NEAR(eval_float("f_ridged_mf(" + p1 + ", 0.7, 2.3, 6, 1.1, 2, 2)", inc), 2.28641764389861857, 1e-9);
  const std::vector<double> v = eval_terms("vturbulence(2.3, 0.6, 4, <" + p0 + ">)");
  ASSERT_GE(v.size(), 3u);
  EXPECT_NEAR(v[0], 0.19754441186730495, 1e-9);   // lambda and omega in single precision, as POV-Ray keeps them
  EXPECT_NEAR(v[1], 0.21260987601758943, 1e-9);
  EXPECT_NEAR(v[2], 0.26598910350948129, 1e-9);
  const std::vector<double> w = eval_terms("vturbulence(2, 0.5 7.9 <" + p1 + ">)");   // commas optional, 7.9 → 7
  ASSERT_GE(w.size(), 3u);
  EXPECT_NEAR(w[0], -0.01564808008513919, 1e-9);
  EXPECT_NEAR(w[1], -0.04631359294260360, 1e-9);
  EXPECT_NEAR(w[2], 0.11116873188239138, 1e-9);
}

// f_noise3d follows the scene's noise generator, including one set after the function was declared.
TEST(NoiseFunctions, NoiseThreeDReadsTheScenesGenerator) {
  const std::string inc = "#include \"functions.inc\"\n";
  EXPECT_NEAR(eval_float("f_noise3d(0.3, 1.7, -2.2)", inc + "global_settings { noise_generator 3 }\n"),
              0.67029632432102426, 1e-9);
  EXPECT_NEAR(eval_float("f_noise3d(0.3, 1.7, -2.2)", inc + "global_settings { noise_generator 1 }\n"),
              0.52718639941302281, 1e-9);
}

}  // namespace povtrace::test
