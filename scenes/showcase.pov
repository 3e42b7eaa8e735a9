// Showcase: a still life using only the first povtrace subset (spheres, boxes, checker floor, three lights incl. a spotlight, metallic highlights).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light <0.9, 0.95, 1.1> }

#declare Eye = <-3.4, 5.2, -9.2>;
#declare Target = <0.2, 0.7, 0.7>;
camera { location Eye look_at Target right x*4/3 up y angle 46 }
background { color rgb <0.04, 0.05, 0.09> }

// Warm key light, cool rim light, and a spotlight picking out the gold sphere.
light_source { <-6, 9, -5> color rgb <0.95, 0.85, 0.7> }
light_source { <7, 5, 6> color rgb <0.25, 0.35, 0.55> }
light_source { <2.5, 7, -3> color rgb <0.8, 0.75, 0.65> spotlight point_at <0.6, 1, 0.9> radius 7 falloff 14 tightness 4 }

#declare F_Floor = finish { ambient 0.06 diffuse 0.75 specular 0.25 roughness 0.08 };
#declare T_Gold = texture {
  pigment { color rgb <0.95, 0.68, 0.25> }
  finish { ambient 0.04 diffuse 0.45 brilliance 2 phong 0.9 phong_size 70 specular 0.5 roughness 0.01 metallic }
};
#declare T_Red = texture { pigment { color rgb <0.8, 0.12, 0.1> } finish { ambient 0.05 diffuse 0.7 phong 0.7 phong_size 90 } };
#declare T_Blue = texture { pigment { color rgb <0.15, 0.3, 0.85> } finish { ambient 0.05 diffuse 0.65 specular 0.8 roughness 0.006 } };
#declare T_Steel = texture {
  pigment { color rgb <0.8, 0.84, 0.9> }
  finish { ambient 0.05 diffuse 0.5 brilliance 3 specular 0.9 roughness 0.004 metallic 0.8 }
};
#declare T_Chalk = texture { pigment { color rgb <0.62, 0.58, 0.52> } finish { ambient 0.08 diffuse 0.7 } };
#declare T_Copper = texture {
  pigment { color rgb <0.85, 0.42, 0.25> }
  finish { ambient 0.04 diffuse 0.5 phong 0.8 phong_size 25 metallic 0.7 }
};

plane { y, -0.001 pigment { checker color rgb <0.82, 0.8, 0.74>, color rgb <0.16, 0.18, 0.24> } finish { F_Floor } }

// Central gold sphere on a low plinth.
box { <-0.9, 0, -0.3>, <2.1, 0.35, 2.2> texture { T_Chalk } }
sphere { <0.6, 1.35, 0.95>, 1 texture { T_Gold } }

// Supporting cast.
sphere { <-2.1, 0.75, -0.4>, 0.75 texture { T_Red } }
sphere { <-1.0, 0.4, -1.6>, 0.4 texture { T_Blue } }
sphere { <3.0, 0.55, -0.9>, 0.55 texture { T_Steel } }
sphere { <0, 0, 0>, 1 scale <0.5, 0.9, 0.5> translate <-3.6, 0.9, 1.8> texture { T_Copper } }
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> rotate y*35 translate <4.2, 0, 3.4> texture { T_Blue } }
box { <-0.35, 0, -0.35>, <0.35, 0.7, 0.35> rotate y*-20 translate <1.6, 0, -1.7> texture { T_Copper } }
sphere { <1.6, 0.95, -1.7>, 0.25 texture { T_Steel } }
