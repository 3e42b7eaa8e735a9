// Tests quadric surfaces (POV-Ray's quadric, kept in world space with the transforms folded into the coefficients):
// shapes_old.inc's Ellipsoid, Cylinder_Y (an infinite pillar), QCone_Y and Paraboloid_Y, and a written quadric with
// mixed terms (a hyperboloid of one sheet, rotated).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
camera { location <0, 3, -10> look_at <0, 1, 0> angle 55 }
background { color rgb <0.2, 0.25, 0.35> }
light_source { <-6, 12, -8> color rgb 1 }
light_source { <7, 5, -5> color rgb <0.3, 0.3, 0.35> }
plane { y, -0.5 pigment { checker color rgb 0.85 color rgb 0.45 } }
object { Ellipsoid scale <1.2, 0.6, 0.8> rotate z * 25 translate <-3, 1.2, 0> pigment { color rgb <0.9, 0.4, 0.2> }
         finish { phong 0.6 } }
object { Cylinder_Y scale 0.35 translate <-1.2, 0, 2> pigment { color rgb <0.3, 0.7, 0.4> } }
object { Paraboloid_Y scale <0.5, 0.8, 0.5> rotate x * 180 translate <0.6, 2.2, 0> pigment { color rgb <0.4, 0.5, 0.9> }
         finish { specular 0.4 } }
object { QCone_Y scale <0.3, 1, 0.3> translate <2.6, 1, 3> pigment { color rgb <0.8, 0.8, 0.3> } }
quadric { <4, -1, 4>, <0, 0.6, 0>, <0, 0, 0>, -0.1 rotate <0, 0, 15> translate <3.2, 1, -1>
          pigment { color rgb <0.8, 0.3, 0.7> } }
