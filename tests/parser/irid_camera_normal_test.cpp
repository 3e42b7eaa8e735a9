// finish irid, global irid_wavelength, the camera's normal and mesh_camera as the parser records them (POV-Ray 3.7's
// Parse_Finish IRID_TOKEN, Parse_Frame IRID_WAVELENGTH_TOKEN, Parse_Camera TNORMAL_TOKEN).
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

SceneDescription scene(const std::string& body) { return parse("#version 3.7;\n" + body); }
std::string error_of(const std::string& body) { return parse_error("#version 3.7;\n" + body).bare_message(); }
const Finish& finish_of(const SceneDescription& s) { return s.objects.at(0).texture->layers.back().finish; }

TEST(IridParse, AmountThicknessTurbulenceInSinglePrecision) {
  const SceneDescription s = scene("sphere { 0, 1 finish { irid { 0.3 thickness 0.7 turbulence <0.1, 9, 9> } } }\n");
  const Finish& f = finish_of(s);
  EXPECT_EQ(f.irid, static_cast<double>(0.3f));
  EXPECT_EQ(f.irid_thickness, static_cast<double>(0.7f));
  EXPECT_EQ(f.irid_turbulence, static_cast<double>(0.1f));   // only x of the vector counts
  const SceneDescription d = scene("sphere { 0, 1 finish { irid { 0.5 } } }\n");
  EXPECT_EQ(finish_of(d).irid_thickness, 0.0);
  EXPECT_EQ(finish_of(d).irid_turbulence, 0.0);
  EXPECT_NE(error_of("sphere { 0, 1 finish { irid { 0.5 phong 1 } } }\n").find("thickness, turbulence or '}'"),
            std::string::npos);
}

TEST(IridParse, Wavelengths) {
  EXPECT_EQ(scene("").settings.irid_wavelength.g, static_cast<double>(0.52f));   // POV-Ray 3.7's defaults
  const SceneDescription s = scene("global_settings { irid_wavelength <0.3, 0.2, 0.1> }\n");
  EXPECT_EQ(s.settings.irid_wavelength.r, static_cast<double>(0.3f));
  EXPECT_EQ(s.settings.irid_wavelength.b, static_cast<double>(0.1f));
}

TEST(CameraNormalParse, ANormalOfItsOwn) {
  const SceneDescription s = scene("camera { location -5*z normal { bumps 0.4 scale 0.1 } look_at 0 }\n");
  ASSERT_TRUE(s.camera.normal);
  EXPECT_EQ(s.camera.normal->kind, NormalKind::bumps);
  EXPECT_EQ(s.camera.normal->amount, 0.4);
  const SceneDescription none = scene("camera { location -5*z }\n");
  EXPECT_FALSE(none.camera.normal);
  EXPECT_NE(error_of("camera { normal { pavement } }\n").find("unsupported"), std::string::npos);
}

constexpr const char* kTwoTriangles =
    "#declare M = mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } triangle { <1, 1, 0>, <1, 2, 0>, <2, 1, 0> } }\n";

TEST(MeshCameraParse, RaysDistributionMeshesSmooth) {
  const SceneDescription s = scene(std::string(kTwoTriangles) +
                                   "camera { mesh_camera { 2.9 0 mesh { M translate x } mesh2 { M } } location <0, 0, -1> }\n");
  EXPECT_EQ(s.camera.projection, Projection::mesh);
  ASSERT_TRUE(s.camera.mesh);
  const MeshCamera& m = *s.camera.mesh;
  EXPECT_EQ(m.rays_per_pixel, 2u);   // truncated
  EXPECT_EQ(m.distribution, 0u);
  ASSERT_EQ(m.meshes.size(), 2u);
  EXPECT_TRUE(m.meshes[0].transformed);
  EXPECT_FALSE(m.meshes[1].transformed);
  EXPECT_EQ(m.meshes[0].data, m.meshes[1].data);   // one declared mesh, shared
  EXPECT_EQ(m.meshes[0].data->triangle_count(), 2u);
  const SceneDescription u = scene(std::string(kTwoTriangles) + "camera { mesh_camera { 1 3 mesh { M } smooth } }\n");
  EXPECT_TRUE(u.camera.mesh->smooth);
  Messages w;
  parse("#version 3.7;\n" + std::string(kTwoTriangles) + "camera { mesh_camera { 1 3 mesh { M } mesh { M } } }\n", &w);
  EXPECT_NE(w.joined().find("Additional meshes after the first are ignored"), std::string::npos) << w.joined();
}

TEST(MeshCameraParse, POVRaysErrorsAndOurs) {
  const std::string m = kTwoTriangles;
  EXPECT_NE(error_of(m + "camera { mesh_camera { 0 0 mesh { M } } }\n").find("Rays per pixel may not be 0"),
            std::string::npos);
  EXPECT_NE(error_of(m + "camera { mesh_camera { 1 4 mesh { M } } }\n").find("Unrecognized distribution method"),
            std::string::npos);
  EXPECT_NE(error_of(m + "camera { mesh_camera { 2 2 mesh { M } mesh { M } } }\n").find("must be 1 for distribution"),
            std::string::npos);
  EXPECT_NE(error_of(m + "camera { mesh_camera { 2 0 mesh { M } } }\n").find("<= number of meshes"), std::string::npos);
  EXPECT_NE(error_of(m + "camera { mesh_camera { 1 0 mesh { M } smooth } }\n").find("Smooth can only be used"),
            std::string::npos);
  EXPECT_NE(error_of(m + "camera { mesh_camera { 1 0 } }\n").find("at least one mesh"), std::string::npos);
  EXPECT_NE(error_of(m + "camera { mesh_camera { 1 0 mesh { M } } angle 40 }\n").find("no angle"), std::string::npos);
  // POV-Ray crashes on a declared object that is not a mesh.
  EXPECT_NE(error_of("#declare S = sphere { 0, 1 }\ncamera { mesh_camera { 1 0 mesh { S } } }\n").find("meshes only"),
            std::string::npos);
  EXPECT_NE(error_of(m + "camera { mesh_camera { 1 0 5 mesh { M } } }\n").find("maximum ray distance"),
            std::string::npos);
}

}  // namespace
}  // namespace povtrace::test
