// Tests mesh_camera distribution 2: two meshes side by side, each for half of the image width (POV-Ray indexes
// the second one's faces by the image column, not its own, which shifts it by a face row).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "mesh_camera.inc"
#declare M1 = PixelMesh(160, 240, 3, 4.5, 0.3);
#declare M2 = PixelMesh(160, 240, 3, 4.5, 0.3);
camera {
  mesh_camera { 1 2
    mesh { M1 translate -x * 0.2 }
    mesh { M2 translate x * 0.2 }
  }
}
MeshCameraScene()
