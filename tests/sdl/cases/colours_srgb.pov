// sRGB colour forms (srgb srgbf srgbt srgbft): the sRGB-encoded components are decoded to linear
// values once assumed_gamma is set; filter and transmit are taken as they are.
#version 3.7;
global_settings { assumed_gamma 1 }

#macro C(Label, X)
  #local K = color X;
  #debug concat(Label, ": ", str(K.red, 0, 6), " ", str(K.green, 0, 6), " ",
                str(K.blue, 0, 6), " ", str(K.filter, 0, 6), " ", str(K.transmit, 0, 6), "\n")
#end

C("srgb 0.5", srgb 0.5)
C("srgb <0,0.04,1>", srgb <0,0.04,1>)
C("srgb <0.2,0.6,0.9>", srgb <0.2,0.6,0.9>)
C("srgbf <0.5,0.5,0.5,0.5>", srgbf <0.5,0.5,0.5,0.5>)
C("srgbt <0.25,0.5,0.75,0.3>", srgbt <0.25,0.5,0.75,0.3>)
C("srgbft <0.1,0.2,0.3,0.4,0.5>", srgbft <0.1,0.2,0.3,0.4,0.5>)

camera {}
sphere { 0, 1 }
