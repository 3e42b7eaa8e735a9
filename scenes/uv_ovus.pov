// Tests uv_mapping on an ovus (POV-Ray's Ovus::CalcUV): spherical coordinates about <0, top radius / 2, 0>.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.6, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
ovus { 1, 0.7 uv_mapping pigment { checker rgb 1 rgb <0.8, 0.1, 0.1> scale <0.05, 0.1, 1> } rotate y*30 }
