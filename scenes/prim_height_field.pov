// Tests the height_field from a small grey PNG (height_field_terrain.png, 33 x 25 samples): flat triangles, the
// same with smooth normals, and one cut by water_level, seen from different sides.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
height_field { png "height_field_terrain.png"
  translate <-0.5, 0, -0.5> scale <3, 1.2, 3> translate <-2, 0, 0.5>
  pigment { color rgb <0.9, 0.5, 0.3> } finish { phong 0.4 } }
height_field { png "height_field_terrain.png" smooth
  translate <-0.5, 0, -0.5> scale <3, 1.2, 3> rotate y * 30 translate <2, 0, 0.5>
  pigment { color rgb <0.3, 0.8, 0.4> } finish { phong 0.4 } }
height_field { "height_field_terrain.png" water_level 0.45 smooth
  translate <-0.5, 0, -0.5> scale <2.5, 1.5, 1.2> rotate <-20, 0, 0> translate <0, 0.6, -3>
  pigment { color rgb <0.4, 0.5, 0.95> } }
