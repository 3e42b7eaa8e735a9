// Colour forms and colour arithmetic: rgb rgbf rgbt rgbft with vectors and floats, colour/color
// with a plain vector or float, red/green/blue/filter/transmit overrides, colour arithmetic with
// colours, floats and vectors, and the dot items .red .green .blue .filter .transmit .gray.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro C(Label, X)
  #local K = color X;
  #debug concat(Label, ": ", str(K.red, 0, 6), " ", str(K.green, 0, 6), " ",
                str(K.blue, 0, 6), " ", str(K.filter, 0, 6), " ", str(K.transmit, 0, 6), "\n")
#end

C("rgb 0.5", rgb 0.5)
C("rgb <0.1,0.2,0.3>", rgb <0.1,0.2,0.3>)
C("rgbf 0.5", rgbf 0.5)
C("rgbf <0.1,0.2,0.3,0.4>", rgbf <0.1,0.2,0.3,0.4>)
C("rgbt 0.25", rgbt 0.25)
C("rgbt <0.1,0.2,0.3,0.4>", rgbt <0.1,0.2,0.3,0.4>)
C("rgbft 0.75", rgbft 0.75)
C("rgbft <0.1,0.2,0.3,0.4,0.5>", rgbft <0.1,0.2,0.3,0.4,0.5>)
C("float 0.5", 0.5)
C("<1,2,3>", <1,2,3>)
C("<1,2,3,4>", <1,2,3,4>)
C("<1,2,3,4,5>", <1,2,3,4,5>)
C("x", x)
C("rgb 0.5 + 0.1", rgb 0.5 + 0.1)
C("rgb <1,0,0> filter 0.5", rgb <1,0,0> filter 0.5)
C("rgb <1,0,0> transmit 0.5", rgb <1,0,0> transmit 0.5)
C("color red 1 green .5", color red 1 green .5)
C("color blue 1", color blue 1)
C("color rgb 1 blue 0", color rgb 1 blue 0)
C("rgbft 0.2 red 1 transmit 0.9", color rgbft 0.2 red 1 transmit 0.9)

#declare A = rgb <1,0.5,0.25>;
#declare B = rgbf <0.5,0.5,2,0.5>;
C("A", A)
C("B", B)
C("A*B", A*B)
C("A+B", A+B)
C("A-B", A-B)
C("A/2", A/2)
C("2*A", 2*A)
C("A+0.1", A+0.1)
C("-A", -A)
C("A*<1,2,3>", A*<1,2,3>)
C("(A+B)/2", (A+B)/2)
C("color A filter 0.2", color A filter 0.2)
C("color A transmit 0.3", color A transmit 0.3)
C("rgb A", rgb A)
C("color B red 0", color B red 0)
#declare V = <0.2,0.4,0.6>;
C("rgb V", rgb V)
C("rgbf <V.x,V.y,V.z,0.5>", rgbf <V.x,V.y,V.z,0.5>)
C("rgb V*2", rgb V*2)
#declare Gr = rgbft <0.1,0.2,0.3,0.4,0.5>;
#debug concat("Gr.gray = ", str(Gr.gray, 0, 6), "\n")
#debug concat("Gr.x .y .z .t = ", str(Gr.x, 0, 3), " ", str(Gr.y, 0, 3), " ",
              str(Gr.z, 0, 3), " ", str(Gr.t, 0, 3), "\n")
#debug concat("vstr(5, Gr) = ", vstr(5, Gr, ",", 0, 3), "\n")
#debug concat("vstr(3, A) = ", vstr(3, A, ",", 0, 3), "\n")

camera {}
sphere { 0, 1 }
