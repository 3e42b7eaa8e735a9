// Tests mesh_camera distribution 3: each pixel's (u, v) found in the uv map of a coarse lens of smooth triangles
// (8 × 6 cells), the ray leaving from that point of the face along the interpolated vertex normals (`smooth`).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "mesh_camera.inc"
#macro LensPoint(U, V) <(U - 0.5) * 4, (V - 0.5) * 3, 0.3 * ((U - 0.5) * (U - 0.5) + (V - 0.5) * (V - 0.5))> #end
#macro LensNormal(U, V) vnormalize(<(U - 0.5) * 0.8, (V - 0.5) * 0.8, 1>) #end
camera {
  mesh_camera { 1 3
    mesh {
      #local J = 0;
      #while (J < 6)
        #local I = 0;
        #while (I < 8)
          #local U0 = I / 8; #local U1 = (I + 1) / 8; #local V0 = J / 6; #local V1 = (J + 1) / 6;
          smooth_triangle { LensPoint(U0, V0), LensNormal(U0, V0), LensPoint(U1, V1), LensNormal(U1, V1),
                            LensPoint(U1, V0), LensNormal(U1, V0) uv_vectors <U0, V0>, <U1, V1>, <U1, V0> }
          smooth_triangle { LensPoint(U0, V0), LensNormal(U0, V0), LensPoint(U0, V1), LensNormal(U0, V1),
                            LensPoint(U1, V1), LensNormal(U1, V1) uv_vectors <U0, V0>, <U0, V1>, <U1, V1> }
          #local I = I + 1;
        #end
        #local J = J + 1;
      #end
    }
    smooth
  }
  location <0, 0, -0.5>
}
MeshCameraScene()
