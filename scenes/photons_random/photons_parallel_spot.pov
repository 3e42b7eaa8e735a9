// Photons of a parallel light (shot from a disc across the target's bounding sphere, each standing for an area,
// not a solid angle) and of a spotlight (attenuated by its cone as the light is), each with its own glass target.
// Two lights × two targets: units are shot in POV-Ray's one-thread order (lights, then targets); POV-Ray with two
// threads shoots another map (reference/photons_random/README.md). The floor is a box, not a plane, so that photons
// leaving the glass at grazing angles do not land far away, where their positions depend on rounding.
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.015 } }
camera { location <0, 7, -6> look_at <0, -1, 0.5> angle 60 }
light_source { <-3, 8, 2> color rgb 0.7 parallel point_at <-1.5, 0, 0> photons { refraction on } }
light_source { <4, 8, 2> color rgb 0.9 spotlight point_at <1.8, 0, 0> radius 12 falloff 20 tightness 2
  photons { refraction on } }
box { <-8, -2, -8>, <8, -1, 10> pigment { color rgb 0.8 } finish { ambient 0 } }
sphere { <-1.8, 0.3, 0>, 0.9 pigment { rgbf <1, 1, 0.8, 0.95> } finish { ambient 0 diffuse 0 }
  interior { ior 1.5 } photons { target refraction on } }
sphere { <1.8, 0.3, 0>, 0.9 pigment { rgbf <0.8, 0.9, 1, 0.95> } finish { ambient 0 diffuse 0 }
  interior { ior 1.5 } photons { target refraction on } }
