// Tests light_group: a group's lights light only its objects (a red light on the left group, a negative light on the
// right one), objects outside any group see only the scene's light, `global_lights on` lets the scene's light in, a
// nested group's objects see both groups' lights, and the group's transforms move its lights with its objects.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0.5, 0> angle 45 right x * 4 / 3 }
light_source { <-5, 10, -10> color rgb 0.8 }
plane { y, -1 pigment { rgb 0.7 } }
light_group {
  sphere { <0, 0, 0>, 0.8 pigment { rgb 1 } }
  box { <-0.5, -1, 1>, <0.5, 0, 2> pigment { rgb <0.6, 0.8, 1> } }
  light_source { <2, 3, -3> color rgb <1, 0.3, 0.2> }
  translate <-2.6, 0, 0>
}
light_group {
  sphere { <0, 0, 0>, 0.8 pigment { rgb 1 } }
  light_source { <-1, 2, -3> color rgb -0.5 shadowless }
  light_group {
    cylinder { <0, -1, 1.5>, <0, 0.5, 1.5>, 0.4 pigment { rgb <1, 1, 0.5> } }
    light_source { <0, 4, 0> color rgb <0.2, 0.4, 1> }
    global_lights on
  }
  global_lights on
  translate <0.2, 0, 0>
}
sphere { <2.8, 0, 0>, 0.8 pigment { rgb 1 } }
light_group { light_source { <0, 5, -5> color rgb 10 } }
