// User-defined functions (function { }): parameter lists, the default x y z parameters, the float
// operators and built-ins inside a function body, functions calling functions, select() for
// conditions, and functions from the standard include files (math.inc sind/cosd, functions.inc
// f_sphere).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "math.inc"
#include "functions.inc"

#macro F(Label, V)
  #debug concat(Label, " = ", str(V, 0, 6), "\n")
#end

#declare Square = function(a) { a * a }
F("Square(3)", Square(3))
F("Square(-1.5)", Square(-1.5))
#declare Poly = function(a, b) { a*a + 2*a*b - b/4 }
F("Poly(2,3)", Poly(2,3))
#declare Xyz = function { x + 2*y + 3*z }
F("Xyz(1,2,3)", Xyz(1,2,3))
#declare Prec = function(a, b, c) { a - b - c + a*b/c }
F("Prec(10,2,4)", Prec(10,2,4))
#declare Unary = function(a) { -a*-a - -a }
F("Unary(3)", Unary(3))
#declare Cmp = function(a, b) { (a < b) + 2*(a = b) + 4*(a > b) }
F("Cmp(1,2)", Cmp(1,2))
F("Cmp(2,2)", Cmp(2,2))
F("Cmp(3,2)", Cmp(3,2))
#declare Logic = function(a, b) { (a & b) + 2*(a | b) }
F("Logic(1,0)", Logic(1,0))
F("Logic(0,0)", Logic(0,0))
#declare Builtins = function(a) {
  abs(a) + sqrt(abs(a)) + pow(a, 2) + exp(0) + ln(1) + sin(0) + cos(0) + min(a, 0) + max(a, 1)
}
F("Builtins(-4)", Builtins(-4))
#declare Modulo = function(a, b) { mod(a, b) }
F("Modulo(-7,3)", Modulo(-7,3))
F("Modulo(7.5,2)", Modulo(7.5,2))
#declare Floors = function(a) { floor(a) + ceil(a) * 10 + int(a) * 100 }
F("Floors(-1.5)", Floors(-1.5))
#declare Sel = function(a) { select(a, -1, 0, 1) }
F("Sel(-3)", Sel(-3))
F("Sel(0)", Sel(0))
F("Sel(9)", Sel(9))
#declare Trig = function(a) { atan2(a, 1) + degrees(pi) + radians(180) + tanh(a) }
F("Trig(0.5)", Trig(0.5))
#declare Twice = function(a) { 2 * Square(a) }
F("Twice(5)", Twice(5))
#declare Compose = function(a, b) { Poly(Square(a), b) + Xyz(a, b, 1) }
F("Compose(1,2)", Compose(1,2))
#declare K = 7;
#declare UsesK = function(a) { a + K }
#declare K = 100;
F("UsesK(1) (K read when declared)", UsesK(1))
#declare Pi2 = function { pi * 2 + x*0 }
F("Pi2(0,0,0)", Pi2(0,0,0))
F("Square(Square(2)) + 1", Square(Square(2)) + 1)

F("sind(30)", sind(30))
F("cosd(60)", cosd(60))
F("sind(-90)", sind(-90))
F("asind(0.5)", asind(0.5))
F("f_sphere(1,0,0,0.5)", f_sphere(1,0,0,0.5))
F("f_sphere(1,2,2,1)", f_sphere(1,2,2,1))
F("f_sphere(0,0,0,2)", f_sphere(0,0,0,2))

camera {}
sphere { 0, 1 }
