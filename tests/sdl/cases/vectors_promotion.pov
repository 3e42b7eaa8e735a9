// Vector expressions: 2- to 5-component literals, float-to-vector promotion in arithmetic, component
// access (.x .y .z .t .u .v), the x y z t u v constants, and vstr printing more or fewer components
// than a value has.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro V3(Label, V)
  #debug concat(Label, " = <", vstr(3, V, ",", 0, 3), ">\n")
#end
#macro V2(Label, V)
  #debug concat(Label, " = <", vstr(2, V, ",", 0, 3), ">\n")
#end
#macro V4(Label, V)
  #debug concat(Label, " = <", vstr(4, V, ",", 0, 3), ">\n")
#end
#macro V5(Label, V)
  #debug concat(Label, " = <", vstr(5, V, ",", 0, 3), ">\n")
#end
#macro F(Label, V)
  #debug concat(Label, " = ", str(V, 0, 3), "\n")
#end

V3("<1,2,3>*2", <1,2,3>*2)
V3("2*<1,2,3>", 2*<1,2,3>)
V3("<1,2,3>+1", <1,2,3>+1)
V3("1-<1,2,3>", 1-<1,2,3>)
V3("<1,2,3>/2", <1,2,3>/2)
V3("6/<1,2,3>", 6/<1,2,3>)
V3("<1,2,3>*<2,3,4>", <1,2,3>*<2,3,4>)
V3("<4,9,16>/<2,3,4>", <4,9,16>/<2,3,4>)
V3("-<1,-2,3>", -<1,-2,3>)
V3("<1+1, 2*3, -1>", <1+1, 2*3, -1>)
V3("x*2+y*3-z", x*2+y*3-z)
V3("<1,2,3>+<1,1,1>*2", <1,2,3>+<1,1,1>*2)
V3("(x+y)*(y+z)", (x+y)*(y+z))
V2("<1,2>+<3,4>", <1,2>+<3,4>)
V2("<1,2>*3", <1,2>*3)
V2("u+2*v", u+2*v)
V4("<1,2,3,4>+1", <1,2,3,4>+1)
V4("<1,2,3,4>*<2,2,2,2>", <1,2,3,4>*<2,2,2,2>)
V4("<0,0,0,0>+t*5 (t cannot start a value)", <0,0,0,0>+t*5)
V5("<1,2,3,4,5>*2", <1,2,3,4,5>*2)
V5("<1,2,3,4,5>-<5,4,3,2,1>", <1,2,3,4,5>-<5,4,3,2,1>)
V3("vstr(3) of <1,2>", <1,2>)
V5("vstr(5) of <1,2,3>", <1,2,3>)
V2("vstr(2) of <1,2,3,4,5>", <1,2,3,4,5>)
V3("vstr(3) of the float 5", 5)
V5("vstr(5) of the float -2", -2)

#declare P = <4,5,6>;
F("P.x", P.x)
F("P.y", P.y)
F("P.z", P.z)
F("P.x+P.y*P.z", P.x+P.y*P.z)
F("(P*2).y", (P*2).y)
F("<7,8,9>.z", <7,8,9>.z)
#declare Q = <1,2,3,4>;
F("Q.t", Q.t)
#declare W = <1,2>;
F("W.u", W.u)
F("W.v", W.v)
#declare P2 = P + <0.5,0.5,0.5>;
V3("P2", P2)
#declare S = 3;
V3("S*x + P", S*x + P)
V3("<S, S*S, S*S*S>", <S, S*S, S*S*S>)
V3("<P.z, P.y, P.x>", <P.z, P.y, P.x>)
V3("<-1, -P.y, +P.z>", <-1, -P.y, +P.z>)
V3("<1,2,3>*(1+1)", <1,2,3>*(1+1))
V3("nested <<1,2,3>.x, 0, 1>", <<1,2,3>.x, 0, 1>)

camera {}
sphere { 0, 1 }
