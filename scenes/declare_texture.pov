// Tests #declare of textures, pigments and finishes used by name: texture { T }, pigment { P }, finish { F }.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare P_Red = pigment { color rgb <0.9, 0.25, 0.2> };
#declare F_Shiny = finish { ambient 0.08 diffuse 0.6 phong 0.8 phong_size 60 };
#declare T_Floor = texture { pigment { checker color rgb <0.85, 0.85, 0.8>, color rgb <0.3, 0.3, 0.35> } finish { ambient 0.1 diffuse 0.7 } };
#declare T_Blue = texture { pigment { color rgb <0.2, 0.4, 0.9> } finish { ambient 0.05 diffuse 0.7 specular 0.6 roughness 0.03 } };
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, -0.5 texture { T_Floor } }
sphere { <-1.6, 0.6, 0>, 1.1 texture { pigment { P_Red } finish { F_Shiny } } }
sphere { <1.6, 0.6, 0.3>, 1.1 texture { T_Blue } }
box { <-0.4, -0.5, 1.8>, <0.4, 0.3, 2.6> pigment { P_Red } finish { F_Shiny } }
