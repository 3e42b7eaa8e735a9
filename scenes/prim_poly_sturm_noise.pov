// Tests that povtrace's Sturm solver is POV-Ray's, numerical failures included: the sphere of radius √2 written as
// the order-6 poly (x² + y² + z²)³ − 8 = 0. Far from it the ray's sextic has coefficients of very different sizes,
// and POV-Ray's polysolve (false position stopped at |p(t)/t| < 1e-12, Sturm counts that come out of order) returns
// spurious roots on a large share of the rays that miss it and loses some that hit: the noise in this image is
// POV-Ray's own, pixel for pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0, 0> angle 30 }
light_source { <-6, 10, -8> color rgb 1 }
background { color rgb <0.2, 0.25, 0.35> }
// (x²+y²+z²)³ − 8
poly { 6, <1, 0, 0, 0, 3, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3, 0, 0, 6, 0, 0, 0, 0, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 3, 0, 0, 0, 0, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -8>
  pigment { rgb <1, 0.6, 0.3> } translate <0.5, -0.25, 1> }
