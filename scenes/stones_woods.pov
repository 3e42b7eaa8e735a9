// Tests the textures of POV-Ray's stones.inc, woods.inc and textures.inc, built from the noise-based patterns
// (the stones with a crand finish are left out: POV-Ray draws crand from an unseeded random stream).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "textures.inc"
#include "stones.inc"
#include "woods.inc"
camera { location <0, 0, -10> look_at 0 angle 25 }
light_source { <-10, 10, -20> color rgb 1 }
#macro Tile(T, Column, Row) box { <-0.48, -0.48, 0>, <0.48, 0.48, 1> texture { T } translate <Column - 1.5, 1 - Row, 0> } #end
Tile(T_Stone1, 0, 0)
Tile(T_Stone9, 1, 0)
Tile(T_Stone3, 2, 0)
Tile(T_Stone25, 3, 0)
Tile(T_Wood1, 0, 1)
Tile(T_Wood10, 1, 1)
Tile(T_Wood22, 2, 1)
Tile(texture { pigment { Jade } }, 3, 1)
Tile(texture { pigment { Blood_Marble } }, 0, 2)
Tile(texture { pigment { Cherry_Wood } }, 1, 2)
Tile(texture { pigment { White_Marble } normal { bumps 0.3 scale 0.05 } }, 2, 2)
Tile(texture { Rosewood }, 3, 2)
