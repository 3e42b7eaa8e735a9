// mesh_camera { RAYS DISTRIBUTION [MAX_DISTANCE] mesh { … }… [smooth] } inside camera { } (POV-Ray 3.7's
// Parse_Mesh_Camera; facts in docs/issue21-mesh-camera.md):
// - RAYS and DISTRIBUTION are truncated to unsigned integers: RAYS 0 is an error, DISTRIBUTION above 3 too;
//   distributions 2 and 3 take exactly one ray per pixel; distribution 0 at most one ray per mesh.
// - Each `mesh { … }` or `mesh2 { … }` is a mesh (a declared mesh or mesh2 identifier may follow either keyword,
//   with transforms): POV-Ray reads both with its mesh parser. povtrace also accepts an inline mesh2 (POV-Ray stops
//   with "No triangles in triangle mesh.") and refuses a declared object that is not a mesh (POV-Ray crashes).
// - A maximum ray distance (the optional third number) is refused by name for now.
// - `smooth` after the meshes, with distribution 3 only. Distribution 3 uses the first mesh and warns about more.
// - The meshes are not part of the scene: they only say where rays start and where they go.
#include "parser/interpreter.hpp"
#include "parser/statements/camera_light_parser.hpp"

namespace povtrace::sdl {

namespace {
// (unsigned)(float) as POV-Ray converts, with the values C++ leaves undefined (negative, huge, NaN) made explicit.
std::optional<unsigned> as_unsigned(double v) {
  if (!(v > -1.0) || v >= 4294967296.0) return std::nullopt;
  return static_cast<unsigned>(std::max(0.0, std::trunc(v)));
}
}  // namespace

std::shared_ptr<const MeshCamera> CameraLightParser::parse_mesh_camera(const Token& keyword, Unsupported& unsupported) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'mesh_camera'");
  MeshCamera camera;
  const Token rays_at = peek();
  const std::optional<unsigned> rays = as_unsigned(parse_float());
  if (!rays) fail_at(rays_at, "the mesh_camera's rays per pixel must be a whole number from 1");
  if (*rays == 0) fail_at(rays_at, "Rays per pixel may not be 0");
  camera.rays_per_pixel = *rays;
  const Token distribution_at = peek();
  const std::optional<unsigned> distribution = as_unsigned(parse_float());
  if (!distribution || *distribution > 3)
    fail_at(distribution_at, "Unrecognized distribution method (the mesh_camera's are 0, 1, 2 and 3)");
  camera.distribution = *distribution;
  if ((camera.distribution == 2 || camera.distribution == 3) && camera.rays_per_pixel != 1)
    fail_at(rays_at, "Rays per pixel must be 1 for distribution method #2 or #3");
  const Token distance_at = peek();
  camera.max_distance = optional_float(0.0);
  if (camera.max_distance >= 1e-10)   // POV-Ray's EPSILON: below it, no limit
    taint(unsupported, UnsupportedFeature{"the mesh_camera's maximum ray distance", distance_at.loc});
  while (peek().is("mesh") || peek().is("mesh2")) {
    const Token mesh_at = next();
    std::optional<SceneItem> item = try_parse_item(mesh_at);
    const Object* object = item ? std::get_if<Object>(&*item) : nullptr;
    const Mesh* mesh = object ? std::get_if<Mesh>(&object->shape) : nullptr;
    if (!mesh) fail_at(mesh_at, "a mesh_camera takes meshes only (this identifier is another kind of object)");
    camera.meshes.push_back({mesh->data, object->world_from_object,
                             !(object->world_from_object == Matrix::identity())});
  }
  if (peek().is("smooth")) {
    const Token smooth = next();
    if (camera.distribution != 3) fail_at(smooth, "Smooth can only be used with distribution method #3");
    camera.smooth = true;
  }
  const Token close = next();
  if (camera.meshes.empty()) fail_expected(close, "'mesh' or 'mesh2' in mesh_camera { } (at least one mesh)");
  if (!close.is("}")) fail_expected(close, "'mesh', 'mesh2', 'smooth' or '}' in mesh_camera { }");
  if (camera.distribution == 0 && camera.rays_per_pixel > camera.meshes.size())
    fail_at(rays_at, "Rays per pixel must be <= number of meshes for distribution method #0");
  if (camera.distribution == 3 && camera.meshes.size() > 1)
    warn(keyword.loc, "Additional meshes after the first are ignored for distribution method #3");
  return std::make_shared<const MeshCamera>(std::move(camera));
}

}  // namespace povtrace::sdl
