// Tests #declare of floats, vectors and colours with expressions (+ - * / unary minus, parentheses, float*vector, x/y/z).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare R = 0.8;
#declare Gap = (R * 2 + 0.5) / 1;
#declare Base = <0, R, 0>;
#declare Lift = y * 0.25;
#declare CamPos = <0, 2 * R + 0.4, -(5 + 2)>;
#declare Warm = color rgb <1, 0.6, 0.3>;
#declare Cool = color rgb <0.3, 0.6, 1> * 0.9;
#declare Amb = 0.1 / 2;
#declare Mix = (Warm + Cool) / 2;
#declare Kd = 1 - 0.3;
camera { location CamPos look_at Base + Lift }
background { color rgb <0.1, 0.15, 0.25> }
light_source { CamPos + <-4, 5, 1> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient Amb diffuse Kd } }
sphere { Base - x * Gap, R pigment { color Warm } finish { ambient Amb diffuse Kd phong 0.5 } }
sphere { Base, R * (1 + 0.25) - 0.2 pigment { color Cool } finish { ambient Amb diffuse Kd phong 0.5 } }
sphere { Base + x * Gap + -z * 0.5, R / 2 translate Lift * 2 pigment { color Mix } finish { ambient Amb diffuse Kd phong 0.5 } }
