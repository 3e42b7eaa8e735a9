// Tests slope: the angle of the surface normal to a direction (simple and block forms, low/high ranges, point_at),
// mixed with altitude, under transforms and on bumped normals (POV-Ray's PNormal is the perturbed normal).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -8> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
#declare Map = color_map { [0 rgb <0.1, 0.1, 0.6>] [0.5 rgb <0.2, 0.8, 0.2>] [0.5 rgb <0.6, 0.4, 0.2>] [1 rgb 1] }
plane { y, 0 pigment { slope y color_map { Map } } normal { bumps 0.8 scale 0.3 } finish { ambient 0.8 diffuse 0.2 } }
#declare Ball = sphere { 0, 0.8 }
object { Ball translate <-3, 0.8, 2> pigment { slope y color_map { Map } } finish { ambient 1 diffuse 0 } }
object { Ball translate <-1, 0.8, 2> pigment { slope <1, 1, 0> color_map { Map } } finish { ambient 1 diffuse 0 } }
object { Ball translate <1, 0.8, 2> pigment { slope { -z, 0.3, 0.8 } color_map { Map } } finish { ambient 1 diffuse 0 } }
object { Ball translate <3, 0.8, 2> pigment { slope { point_at <3, 3, -2> } color_map { Map } } finish { ambient 1 diffuse 0 } }
object { Ball translate <-2, 0.8, 0> pigment { slope { y altitude y, 0.2, 1.6 } color_map { Map } } finish { ambient 1 diffuse 0 } }
object { Ball translate <0, 0.8, 0> pigment { slope { <0, 2, 0>, 0.5, 1 altitude <0, 1, 0.5> } color_map { Map } scale 0.7 } finish { ambient 1 diffuse 0 } }
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> rotate <20, 30, 0> translate <2, 0.3, 0>
  texture { slope x texture_map { [0.3 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 }]
                                  [0.7 pigment { rgb <0, 1, 1> } finish { ambient 1 diffuse 0 }] } } }
