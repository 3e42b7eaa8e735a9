// Tests the text shape: the four fonts POV-Ray ships (serif timrom with kerning, cyrvetic, monospace crystal, the
// povlogo symbol font through its Microsoft symbol character map), an offset vector between characters, a
// built-in font (internal 2), text seen from the side and from behind (walls and both faces), and a scaled,
// rotated text.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -7.5> look_at <0, 0.9, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-5, 9, -8> color rgb <1, 1, 1> }
light_source { <6, 4, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
text { ttf "timrom.ttf" "WAVE To" 0.3, 0
  translate <-3.0, 2.3, 0.5> pigment { color rgb <0.9, 0.6, 0.2> } finish { phong 0.6 } }
text { ttf "cyrvetic.ttf" "Glyph?" 0.5, <0.05, 0.02, 0>
  rotate y * -35 translate <0.2, 0.9, -1.6> pigment { color rgb <0.3, 0.8, 0.4> } finish { specular 0.5 } }
text { ttf "crystal.ttf" "mono 42" 0.2, 0
  scale <0.7, 1.1, 1> rotate <-20, 15, 5> translate <-3.6, 0.6, -1.8> pigment { color rgb <0.3, 0.5, 0.95> } }
text { ttf "povlogo.ttf" "P" 0.4, 0
  scale 1.6 rotate y * 160 translate <4.2, 0.05, 1.8> pigment { color rgb <0.95, 0.3, 0.3> } finish { phong 0.4 } }
text { internal 2 "&@%" 1.2, 0
  scale 0.8 rotate y * 30 translate <-1.0, 0.05, -3.0> pigment { color rgb <0.9, 0.85, 0.3> } }
