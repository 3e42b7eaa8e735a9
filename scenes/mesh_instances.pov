// Tests a declared mesh placed many times: one mesh (a small closed tetrahedron with per-triangle textures),
// copied with object { } under different translations, rotations and non-uniform scales; the copies share it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.4, 0.4, 0.35> } finish { ambient 0.1 diffuse 0.7 } }
#declare Orange = texture { pigment { color rgb <0.95, 0.55, 0.15> } finish { phong 0.4 } }
#declare Teal = texture { pigment { color rgb <0.15, 0.7, 0.7> } }
#declare Tetra = mesh {
  triangle { <-0.5, 0, -0.29>, <0.5, 0, -0.29>, <0, 0.82, 0> texture { Orange } }
  triangle { <0.5, 0, -0.29>, <0, 0, 0.58>, <0, 0.82, 0> texture { Teal } }
  triangle { <0, 0, 0.58>, <-0.5, 0, -0.29>, <0, 0.82, 0> }
  triangle { <-0.5, 0, -0.29>, <0, 0, 0.58>, <0.5, 0, -0.29> }
  pigment { color rgb <0.85, 0.85, 0.9> }
}
#for (I, 0, 4)
  #for (J, 0, 2)
    object { Tetra
      scale <1 + 0.2 * J, 1 + 0.3 * I, 1>
      rotate y * (25 * I + 40 * J)
      translate <-3 + 1.5 * I, 0, -0.5 + 1.6 * J>
    }
  #end
#end
