// uv coordinates of hits for uv_mapping against hand-computed values (POV-Ray 3.7 Sphere::UVCoord, Box::UVCoord,
// Torus::CalcUV, Mesh::UVCoord, ObjectBase::UVCoord).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/description.hpp"
#include "tests/geometry/mesh_kit.hpp"

namespace povtrace::test {
namespace {

std::array<double, 2> uv_at(const render::Primitive& p, Vec3 world_point, std::uint32_t element = 0, double u = 0,
                            double v = 0) {
  render::SurfaceHit hit;
  hit.leaf = &p;
  hit.element = element;
  hit.u = u;
  hit.v = v;
  return render::uv_coordinates(hit, world_point);
}

void expect_uv(const std::array<double, 2>& uv, double u, double v) {
  EXPECT_NEAR(uv[0], u, 1e-12);
  EXPECT_NEAR(uv[1], v, 1e-12);
}

TEST(UvCoordinates, SphereTakesLongitudeAndLatitudeInItsOwnSpace) {
  const render::Primitive s = sphere({1, 2, 3}, 2);
  expect_uv(uv_at(s, {3, 2, 3}), 0.0, 0.5);     // +x of the centre: on the equator, longitude 0
  expect_uv(uv_at(s, {1, 2, 5}), 0.25, 0.5);    // +z: a quarter turn
  expect_uv(uv_at(s, {1, 2, 1}), 0.75, 0.5);    // −z: three quarters
  expect_uv(uv_at(s, {-1, 2, 3}), 0.5, 0.5);    // −x
  expect_uv(uv_at(s, {1, 4, 3}), 0.0, 1.0);     // the north pole: u 0
  expect_uv(uv_at(s, {1 + std::sqrt(3.0), 3, 3}), 0.0, 0.5 + 1.0 / 6.0);   // 30° north
  // Transforms are undone first: the sphere's own +x keeps longitude 0 wherever it is turned to.
  const render::Primitive turned = transformed(sphere({0, 0, 0}, 1), Matrix::rotation({0, 90, 0}));
  const Vec3 own_x = turned.world_from_object.point({1, 0, 0});
  expect_uv(uv_at(turned, own_x), 0.0, 0.5);
}

TEST(UvCoordinates, BoxLaysItsFacesOutAsACube) {
  const render::Primitive b = box({0, 0, 0}, {2, 4, 8});
  // A point at a quarter along each free axis; normalised coordinates 0.25.
  expect_uv(uv_at(b, {0, 1, 2}), 0.25 / 4, 1.0 / 3 + 0.25 / 3);          // −x
  expect_uv(uv_at(b, {2, 1, 2}), 0.75 - 0.25 / 4, 1.0 / 3 + 0.25 / 3);   // +x
  expect_uv(uv_at(b, {0.5, 0, 2}), 0.25 + 0.25 / 4, 0.25 / 3);           // −y
  expect_uv(uv_at(b, {0.5, 4, 2}), 0.25 + 0.25 / 4, 1.0 - 0.25 / 3);     // +y
  expect_uv(uv_at(b, {0.5, 1, 0}), 1.0 - 0.25 / 4, 1.0 / 3 + 0.25 / 3);  // −z
  expect_uv(uv_at(b, {0.5, 1, 8}), 0.25 + 0.25 / 4, 1.0 / 3 + 0.25 / 3); // +z
}

TEST(UvCoordinates, TorusTakesTheAnglesAroundYAndAroundTheTube) {
  render::Primitive p;   // a torus of major radius 2 (p.a.x) and minor radius 0.5, as make_torus sets it up
  p.type = render::ShapeType::torus;
  p.a = {2, 0.5, 0};
  // Outer equator at +x: atan2(0, 2.5) = 0 → u = 1 − π/2π = 0.5; tube angle atan2(0, 0.5) = 0 → v = 0.5.
  expect_uv(uv_at(p, {2.5, 0, 0}), 0.5, 0.5);
  // On top of the tube at +z: u = 1 − (π/2 + π)/2π = 0.25; v = (π/2 + π)/2π = 0.75.
  expect_uv(uv_at(p, {0, 0.5, 2}), 0.25, 0.75);
}

TEST(UvCoordinates, MeshWeighsItsCornersUvByTheBarycentricCoordinates) {
  auto data = std::make_shared<MeshData>(*mesh_data({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}));
  data->uvs = {0.5, 0.5, 1, 0, 0, 1};
  data->face_uvs = {2, 1, 0};
  const render::Primitive m = mesh(data);
  // Barycentric (u, v) weigh the second and third corners: 0.2·<1, 0> + 0.3·<0.5, 0.5> + 0.5·<0, 1>.
  expect_uv(uv_at(m, {0.2, 0.3, 0}, 0, 0.2, 0.3), 0.2 * 1 + 0.3 * 0.5, 0.3 * 0.5 + 0.5 * 1);
  const render::Primitive plain = mesh(mesh_data({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}));
  expect_uv(uv_at(plain, {0.2, 0.3, 0}, 0, 0.2, 0.3), 0, 0);   // no uv_vectors: <0, 0> everywhere
}

TEST(UvCoordinates, OtherShapesGiveTheWorldXAndY) {
  const render::Primitive p = plane({0, 1, 0}, -1);
  expect_uv(uv_at(p, {3.5, -1, 7}), 3.5, -1);
  const render::Primitive t = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  expect_uv(uv_at(t, {0.2, 0.3, 0}, 0, 0.2, 0.3), 0.2, 0.3);
}

}  // namespace
}  // namespace povtrace::test
