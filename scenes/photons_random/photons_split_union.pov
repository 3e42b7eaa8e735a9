// A target union POV-Ray splits into its children (a union without clipped_by or bounded_by): each child becomes a
// target of its own, shot at its own bounding sphere, one after the other; a photon that meets the other child
// first is dropped. A patterned texture on one child shares each photon among the textures its pattern picks, and
// the other child's target multiplier (`target 0.7`, inherited by its parts) spaces its photons closer. Three targets:
// POV-Ray with two threads shoots another map than with one (reference/photons_random/README.md).
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.02 } }
camera { location <0, 7, -5> look_at <0, -1, 0.5> angle 55 }
light_source { <-2, 9, 4> color rgb 1 photons { refraction on reflection on } }
box { <-8, -2, -8>, <8, -1, 10> pigment { color rgb 0.8 } finish { ambient 0 } }
union {
  sphere { <-1.5, 0.2, 0>, 0.8
    texture { checker texture { pigment { rgbf <1, 0.6, 0.6, 0.95> } finish { ambient 0 diffuse 0 } }
                      texture { pigment { rgbf <0.6, 0.6, 1, 0.95> } finish { ambient 0 diffuse 0 } } scale 0.3 }
    interior { ior 1.5 } }
  union {
    box { <0.8, -0.6, -0.6>, <2.2, 0.8, 0.6> }
    sphere { <1.5, 1.1, 0>, 0.4 }
    pigment { rgbf <1, 1, 0.7, 0.9> } finish { ambient 0 diffuse 0 reflection 0.2 } interior { ior 1.3 }
    photons { target 0.7 }
  }
  photons { target refraction on reflection on }
}
