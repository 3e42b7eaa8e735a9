// Tests material_map: a palette image (povmap.png, 16 colours) whose index picks one of four textures (patterned,
// reflective, plain and gradient ones), moved by the texture's transforms, and a grey image (Mount1.png, no palette:
// red · 255 picks, modulo the three textures) wrapped around a sphere with map_type 1 and interpolate 2. With
// interpolation POV-Ray's palette index of a grey image is int(−Σ weights), 0 or −1 by the weights' last bit (0 picks
// the first texture): the sphere and its texture are left unmoved so that the image position is the same to the bit.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-2.6, 1, -10> look_at <-2.6, 0, 0> angle 55 }
light_source { <-10, 20, -20> color rgb 1 }
background { color rgb <0.2, 0.3, 0.4> }
plane { y, -3.2 pigment { checker color rgb 0.8 color rgb 0.4 } }
box { <0, 0, 0>, <1, 1, 0.1>
  texture {
    material_map {
      png "povmap.png"
      texture { pigment { color rgb <0.3, 0.1, 1> } normal { ripples 0.85 frequency 10 } finish { specular 0.75 }
                scale 0.1 }
      texture { pigment { color rgb 1 } finish { ambient 0 diffuse 0.2 reflection 0.8 } }
      texture { pigment { color rgb <1, 0.3, 0.7> } finish { ambient 1 diffuse 0 } }
      texture { pigment { gradient y color_map { [0 color rgb <1, 0, 0>] [0.5 color rgb <0, 0, 1>]
                                                   [1 color rgb <0, 1, 0>] } } }
    }
  }
  scale <5, 4, 1> translate <-7.6, -2, 0>
}
sphere { <0, 0, 0>, 2.2
  texture {
    material_map {
      png "Mount1.png" map_type 1 interpolate 2
      texture { pigment { color rgb <0.9, 0.6, 0.2> } }
      texture { pigment { color rgb <0.2, 0.5, 0.9> } finish { phong 0.6 } }
      texture { pigment { checker color rgb 1 color rgb 0.2 scale 0.2 } }
    }
  }
}
