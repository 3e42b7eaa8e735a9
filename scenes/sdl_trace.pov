// trace() and inside() at parse time: markers dropped along -y onto a CSG landscape (a box with a torus groove
// and a sphere dent cut out, and a rotated cone on it), each placed at the hit point and leaning along the
// returned normal; rays that miss (outside the landscape) leave their marker out. shapes.inc's IsectN places the
// lower row through its macro parameters. Marker colours come from inside() of a cylinder, a shape whose inside
// test only the renderer carries.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
#include "transforms.inc"

camera { location <0, 7, -9> look_at <0, 0, 0> angle 50 }
light_source { <-6, 12, -8> rgb 1 }
light_source { <8, 6, -3> rgb 0.4 }
background { rgb <0.2, 0.25, 0.35> }

#declare Land = union {
  difference {
    box { <-4, -1, -3>, <4, 0, 3> }
    torus { 2, 0.6 translate <-0.5, 0, 0.3> }
    sphere { <2.5, 0.4, -1.2>, 1 }
  }
  cone { <0, 0, 0>, 0.9, <0, 1.5, 0>, 0 rotate 15*z translate <2.2, 0, 1.6> }
}
object { Land pigment { rgb <0.55, 0.5, 0.4> } finish { phong 0.2 } }

#declare Zone = cylinder { <0, -2, 0>, <0, 2, 0>, 1.6 translate <-0.5, 0, 0.3> }

#declare Ix = 0;
#while (Ix < 17)
  #declare Iz = 0;
  #while (Iz < 13)
    #declare Start = <-4.4 + Ix * 0.55, 4, -3.3 + Iz * 0.55>;
    #declare N = <0, 0, 0>;
    #declare P = trace(Land, Start, -y, N);
    #if (vlength(N) > 0)
      cylinder { 0, 0.35*y, 0.04
        pigment { rgb (inside(Zone, P) ? <0.9, 0.2, 0.1> : <0.1, 0.4, 0.9>) }
        Reorient_Trans(y, N)
        translate P
      }
    #end
    #declare Iz = Iz + 1;
  #end
  #declare Ix = Ix + 1;
#end

// The front row through shapes.inc: IsectN returns true and sets Pt and Norm only on a hit.
#declare K = 0;
#while (K < 9)
  #declare Pt = <0, 0, 0>;
  #declare Norm = <0, 0, 0>;
  #if (IsectN(<-3.6 + 0.9 * K, 0.5, -6>, <0, -0.1, 1>, Land, Pt, Norm))
    sphere { Pt + 0.12 * Norm, 0.12 pigment { rgb <0.2, 0.8, 0.3> } }
  #end
  #declare K = K + 1;
#end
