// Tests mesh_camera distribution 0 with one ray per pixel: a flat mesh, one face per pixel, makes an orthographic
// camera; `location` z moves every ray's start back along its face normal. POV-Ray reads pixel row y from face row
// y - 1 (row 0 twice), which shows as one row of shift.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "mesh_camera.inc"
camera { mesh_camera { 1 0 PixelMesh(320, 240, 6, 4.5, 0) } location <0, 0, -1> }
MeshCameraScene()
