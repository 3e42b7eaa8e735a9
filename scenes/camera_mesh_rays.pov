// Tests mesh_camera distribution 0 with two rays per pixel from two meshes (the second one shifted by half a
// pixel), tilted normals (a perspective-like camera) and a mesh transform; the second mesh is shorter than the
// image, so the pixels below it average only the first mesh's ray.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "mesh_camera.inc"
#declare M1 = PixelMesh(320, 200, 4, 3 * 200 / 240, 0.35);
camera {
  mesh_camera { 2 0
    PixelMesh(320, 240, 4, 3, 0.35)
    mesh { M1 translate <2 / 320, 0.25, 0> }
  }
}
MeshCameraScene()
