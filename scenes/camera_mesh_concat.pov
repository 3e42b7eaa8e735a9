// Tests mesh_camera distribution 1 (the meshes' faces one after another: the top half from the first mesh, the
// bottom half from the second) and a negative direction z, which flips every ray against its face normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "mesh_camera.inc"
#declare M1 = PixelMesh(320, 120, 4, 1.5, 0.2);
#declare M2 = PixelMesh(320, 120, 4, 1.5, 0.2);
camera {
  mesh_camera { 1 1
    mesh { M1 translate y * 0.75 rotate y * 180 }
    mesh { M2 translate -y * 0.75 rotate y * 180 }
  }
  direction -z
}
MeshCameraScene()
