// Float expressions: literals, precedence and associativity of + - * /, unary operators,
// comparisons (with POV-Ray's 1e-10 tolerance on = and !=), logical & | !, and ?: .
#version 3.7;
global_settings { assumed_gamma 1 }

#macro Show(Label, Value)
  #debug concat(Label, " -> ", str(Value, 0, 6), "\n")
#end

Show("literals .5 5. 1e3 2.5E-2", .5 + 5. + 1e3 + 2.5E-2)
Show("1+2*3", 1+2*3)
Show("(1+2)*3", (1+2)*3)
Show("7-2-1", 7-2-1)
Show("7-(2-1)", 7-(2-1))
Show("24/4/2", 24/4/2)
Show("2*3/4", 2*3/4)
Show("10/4", 10/4)
Show("-2*-3", -2*-3)
Show("- -3", - -3)
Show("+4", +4)
Show("-(2+3)*2", -(2+3)*2)
Show("2*-(1+1)", 2*-(1+1))
Show("1/3*3", 1/3*3)
Show("0.1+0.2", 0.1+0.2)
Show("1e-7", 1e-7)
Show("-1e-7", -1e-7)
Show("123456789*1000", 123456789*1000)

// Comparisons, logic and the conditional operator need the full expression level:
// inside a macro argument they are written in parentheses.
Show("1<2", (1<2))
Show("2<1", (2<1))
Show("2<=2", (2<=2))
Show("3>=4", (3>=4))
Show("3>2", (3>2))
Show("1=1", (1=1))
Show("1!=2", (1!=2))
Show("1=1+1e-12", (1=1+1e-12))
Show("1=1+1e-9", (1=1+1e-9))
Show("1!=1+1e-12", (1!=1+1e-12))
Show("0.1+0.2=0.3", (0.1+0.2=0.3))
Show("!0", (!0))
Show("!5", (!5))
Show("!!2", (!!2))
Show("1&0", (1&0))
Show("2&3", (2&3))
Show("0|0", (0|0))
Show("0|-1", (0|-1))
Show("1|0&0", (1|0&0))
Show("0&0|1", (0&0|1))
Show("1<2<3", (1<2<3))
Show("3>2>1", (3>2>1))
Show("1+1=2", (1+1=2))
Show("1<2&3<4", (1<2&3<4))
Show("1?2:3", (1?2:3))
Show("0?2:3", (0?2:3))
Show("1?0?4:5:6", (1?0?4:5:6))
Show("0?4:1?5:6", (0?4:1?5:6))
Show("1e-12?1:2", (1e-12?1:2))
Show("2>1?10+1:20", (2>1?10+1:20))
Show("(1<2)*10", (1<2)*10)

Show("1e+3 + 1.e2 + 00.5 + .5e-1", 1e+3 + 1.e2 + 00.5 + .5e-1)
Show("1--1", 1--1)
Show("1+-+-1", 1+-+-1)
Show("- -(-1)", - -(-1))
Show("3*(-2)", 3*(-2))
Show("!1=0", (!1=0))
Show("-1<0", (-1<0))
Show("2<3=1", (2<3=1))
Show("1=1&0", (1=1&0))
Show("!0+1", (!0+1))
Show("1-1?5:6", (1-1?5:6))
Show("1/3+1/3+1/3=1", (1/3+1/3+1/3=1))
Show("1e-300*1e-300", 1e-300*1e-300)

#declare A = 2;
#declare B = A*A + 1;
Show("B = A*A+1", B)
#declare P = <4,5,6>;
Show("-P.x", -P.x)
Show("-P.y*2", -P.y*2)
#declare B = -B;
Show("-B", B)

camera {}
sphere { 0, 1 }
