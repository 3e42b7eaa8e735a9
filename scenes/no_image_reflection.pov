// Tests the object modifiers no_image and no_reflection (and no_radiosity, which changes nothing without
// radiosity) in front of a mirror, with shadows on the floor from every object. Left to right: a red sphere with
// no_image (only in the mirror, and through nothing), a green one with no_reflection (not in the mirror), both
// behind a glass sphere (refracted camera rays are image rays; the mirror seen through the glass and the glass seen
// in the mirror carry both flags); a blue box with both (only its shadow); a union split into its children, whose
// no_image cylinder is hidden from the camera; a clipped union (kept whole) whose no_image cone the camera still
// sees directly (POV-Ray's union children test) but not through the ior-1 window in front of it, and whose
// no_reflection disc is missing in the mirror; a merge whose no_image child does not hide the other child's
// surface inside it; an intersection whose no_image child is not tested at all.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 4, -9> look_at <0, 1, 1> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 scale 0.7 } }
box { <-7, 0, 2.5>, <7, 3.2, 2.7> pigment { rgb <0.1, 0.1, 0.2> } finish { reflection 0.8 } }

sphere { <-4.5, 0.5, 0>, 0.5 pigment { rgb <1, 0.2, 0.2> } no_image }
sphere { <-3, 0.5, 0>, 0.5 pigment { rgb <0.2, 1, 0.2> } no_reflection no_radiosity }
sphere { <-2.6, 1.6, -3>, 0.8
  pigment { rgbf <1, 1, 1, 0.9> } finish { reflection 0.1 phong 0.5 } interior { ior 1.5 } }
box { <-1.9, 0, -0.4>, <-1.1, 0.8, 0.4> pigment { rgb <0.2, 0.3, 1> } no_image no_reflection }

union {
  sphere { <0, 0.5, 0>, 0.5 pigment { rgb <1, 1, 0.2> } }
  cylinder { <0, 0.9, 0>, <0, 2, 0>, 0.15 pigment { rgb <1, 0.5, 0> } no_image }
}
union {
  sphere { <1.5, 0.5, 0>, 0.5 pigment { rgb <1, 0.6, 0.2> } }
  cone { <1.5, 0.9, 0>, 0.35, <1.5, 2.2, 0>, 0 pigment { rgb <0.8, 0.2, 1> } no_image }
  disc { <1.5, 0.02, -0.8>, y, 0.35 pigment { rgb <0.2, 1, 1> } no_reflection 1 }
  clipped_by { box { <-10, -1, -10>, <10, 10, 10> } }
}
box { <0.8, 0, -1.25>, <2.2, 1.8, -1.15> pigment { rgbt <1, 1, 1, 0.7> } }
merge {
  sphere { <3, 0.6, 0>, 0.6 pigment { rgb <0.2, 0.9, 0.9> } }
  sphere { <3.3, 0.9, -0.3>, 0.45 pigment { rgb <1, 0.2, 0.8> } no_image }
}
intersection {
  box { <4.1, 0, -0.4>, <4.9, 1, 0.4> pigment { rgb <0.9, 0.9, 0.9> } }
  sphere { <4.5, 0.5, 0>, 0.6 pigment { rgb <1, 0.3, 0.1> } no_image }
}
// A flag set on the union reaches its children; `no_image 0` on a copy clears a declared object's flag.
#declare Hidden = sphere { <0, 0.3, -2>, 0.3 pigment { rgb <1, 1, 1> } no_image }
union { object { Hidden translate <-0.8, 0, 0> } object { Hidden translate <0.8, 0, 0> no_image 0 } no_reflection }
