// Tests sky_sphere (pipeline §5): two pigment layers (a gradient with a colour map, and a partly transparent
// gradient over it), emission, a rotate of the sky, and a mirror sphere that reflects the sky.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 1.5, 0> angle 80 }
light_source { <-5, 10, -5> color rgb 1 }
sky_sphere {
  pigment { gradient y color_map { [0 color rgb <0.9, 0.5, 0.2>] [0.4 color rgb <0.2, 0.4, 0.9>] [1 color rgb <0.05, 0.1, 0.4>] } }
  pigment { gradient x color_map { [0 color rgbt <1, 1, 1, 1>] [0.5 color rgbt <1, 1, 1, 0.6>] [1 color rgbt <1, 1, 1, 1>] } scale 0.5 }
  emission rgb <1, 0.95, 0.9>
  rotate z * 10
}
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.3 } }
sphere { <0, 1.2, 0>, 1.2 pigment { color rgb 0.1 } finish { reflection 0.8 } }
