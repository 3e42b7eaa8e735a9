// Tests all finish terms combined in one finish: ambient colour, emission, diffuse with backside, brilliance, phong, specular, metallic.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-4, 7, -6> color rgb <1, 0.95, 0.9> }
light_source { <5, 3, -4> color rgb <0.4, 0.5, 0.7> }
plane { y, 0 pigment { color rgb <0.6, 0.6, 0.6> } finish { ambient <0.1, 0.08, 0.06> diffuse 0.6 specular 0.3 roughness 0.2 } }
sphere { <-1.6, 1, 0>, 1
  texture {
    pigment { color rgb <0.8, 0.3, 0.2> }
    finish { ambient <0.1, 0.2, 0.3> emission <0.05, 0, 0.1> diffuse 0.7, 0.3 brilliance 2
             phong 0.6 phong_size 30 specular 0.4 roughness 0.02 metallic 0.6 }
  }
}
sphere { <1.6, 1, 0.5>, 1
  texture {
    pigment { color rgb <0.3, 0.6, 0.9> }
    finish { ambient 0.05 diffuse 0.5 brilliance 0.7 phong 0.3 phong_size 8 specular 0.7 roughness 0.01 }
  }
}
