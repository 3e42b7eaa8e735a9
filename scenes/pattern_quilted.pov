// Tests quilted: as a pigment pattern (no frequency by default) with control0/control1 and a colour map, and as a
// normal (its own perturbation, POV-Ray's normal.cpp quilted) with several controls, scaled and rotated.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 25 }
light_source { <-10, 10, -20> color rgb 1 }
#macro Tile(T, Column, Row)
  box { <-0.48, -0.48, 0>, <0.48, 0.48, 1> texture { T } translate <Column - 1.5, 1 - Row, 0> }
#end
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Lit = finish { ambient 0.1 diffuse 0.8 specular 0.5 roughness 0.02 }
Tile(texture { pigment { quilted scale 0.2 } finish { Flat } }, 0, 0)
Tile(texture { pigment { quilted control0 0 control1 1 color_map { [0 rgb <0.2, 0, 0.4>] [0.5 rgb <1, 0.8, 0.3>] }
  scale 0.15 } finish { Flat } }, 1, 0)
Tile(texture { pigment { quilted control0 -0.5 control1 1.5 frequency 2 scale 0.25 } finish { Flat } }, 2, 0)
Tile(texture { pigment { rgb 0.8 } normal { quilted 1 scale 0.2 } finish { Lit } }, 3, 0)
Tile(texture { pigment { rgb <0.7, 0.8, 1> } normal { quilted 0.6 control0 0 control1 1 scale 0.15 } finish { Lit } }, 0, 1)
Tile(texture { pigment { rgb 0.8 } normal { quilted 1.5 control0 1 control1 1 scale 0.3 rotate <20, 30, 0> }
  finish { Lit } }, 1, 1)
Tile(texture { pigment { rgb <1, 0.8, 0.7> } normal { quilted -0.8 control0 0.3 control1 0.7 scale 0.1 } finish { Lit } }, 2, 1)
Tile(texture { quilted texture_map { [0.3 pigment { rgb <0, 0.4, 0> } finish { Flat }] [0.3 pigment { rgb 1 } finish { Flat }] }
  scale 0.2 }, 3, 1)
