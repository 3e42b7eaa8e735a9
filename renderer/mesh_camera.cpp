// mesh_camera rays, as POV-Ray 3.7 makes them (docs/issue21-mesh-camera.md). The arithmetic follows POV-Ray's order
// and precision (single-precision corners and normals, the centroid summed in single precision), so that a ray
// leaves from the same point in the same direction as POV-Ray's.
#include "renderer/mesh_camera.hpp"

#include "scene/pov_vector_math.hpp"

#include <algorithm>
#include <cmath>

namespace povtrace::render {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON

Vec3 corner(const MeshData& d, std::uint32_t face, int k) { return d.vertex(d.faces[3 * face + k]); }

Vec3 widened(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }
std::array<float, 3> narrowed(Vec3 v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

// The largest component's axis, ties as POV-Ray breaks them.
int dominant_axis(Vec3 v) {
  const double x = std::fabs(v.x), y = std::fabs(v.y), z = std::fabs(v.z);
  return x > y ? (x > z ? 0 : 2) : (y > z ? 1 : 2);
}

// Compute_Mesh_Triangle: the flat normal (P3 − P1) × (P2 − P1), scaled by its reciprocal length, and whether POV-Ray
// then swaps the first two corners (so that the triangle winds one way around its dominant axis).
void flat_normal_and_swap(Vec3 p1, Vec3 p2, Vec3 p3, std::array<float, 3>& normal, std::uint8_t& swapped) {
  Vec3 n = cross(p3 - p1, p2 - p1);
  const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  swapped = 0;
  if (len == 0.0) {
    normal = narrowed(n);
    return;
  }
  n = n * (1.0 / len);
  normal = narrowed(n);
  switch (dominant_axis(n)) {
    case 0: swapped = (p2.y - p3.y) * (p2.z - p1.z) < (p2.z - p3.z) * (p2.y - p1.y); break;
    case 1: swapped = (p2.x - p3.x) * (p2.z - p1.z) < (p2.z - p3.z) * (p2.x - p1.x); break;
    default: swapped = (p2.x - p3.x) * (p2.y - p1.y) < (p2.y - p3.y) * (p2.x - p1.x); break;
  }
}

// compute_smooth_triangle's frame for the corners as POV-Ray holds them (after any swap): the axis along which the
// third edge runs most, and the perpendicular from the first corner to that edge, scaled so that its dot product
// with the first corner's offset is −1 (in single precision where POV-Ray keeps it).
void smooth_frame(Vec3 p1, Vec3 p2, Vec3 p3, std::array<float, 3>& perp, std::uint8_t& axis) {
  axis = static_cast<std::uint8_t>(dominant_axis(p3 - p2));
  Vec3 t1 = p2 - p3;
  t1 = pov_normalized(t1);
  const Vec3 t2 = p1 - p3;
  t1 = t1 * dot(t2, t1);
  std::array<float, 3> p = narrowed(t1 - t2);
  const float len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  const float inv = static_cast<float>(1.0 / static_cast<double>(len));
  for (float& c : p) c *= inv;
  const double ud = dot(t2, widened(p));
  const float k = static_cast<float>(-ud);
  const float t = static_cast<float>(1.0 / static_cast<double>(k));
  for (float& c : p) c *= t;
  perp = p;
}

// The face's corners (and their indices into the normals and uvs) in POV-Ray's order.
struct FaceCorners {
  Vec3 p[3];
  std::uint32_t vertex[3], normal[3], uv[3];
  bool smooth = false;
};
FaceCorners corners_of(const RenderMeshCamera::CameraMesh& m, std::uint32_t face) {
  const MeshData& d = *m.data;
  FaceCorners c;
  for (int k = 0; k < 3; ++k) {
    c.vertex[k] = d.faces[3 * face + k];
    c.p[k] = d.vertex(c.vertex[k]);
    c.normal[k] = d.face_normals.empty() ? MeshData::flat : d.face_normals[3 * face + k];
    c.uv[k] = d.face_uvs.empty() ? 0 : d.face_uvs[3 * face + k];
  }
  c.smooth = c.normal[0] != MeshData::flat;
  if (m.swapped[face]) {
    std::swap(c.p[0], c.p[1]);
    std::swap(c.vertex[0], c.vertex[1]);
    std::swap(c.uv[0], c.uv[1]);
    if (c.smooth) std::swap(c.normal[0], c.normal[1]);   // POV-Ray swaps the vertex normals of smooth faces only
  }
  return c;
}

// Smooth_Mesh_Normal: the vertex normals interpolated at `at` (mesh space), not normalised. A face without vertex
// normals keeps its flat normal (POV-Ray reads outside its normal array there).
Vec3 smooth_normal(const RenderMeshCamera::CameraMesh& m, std::uint32_t face, const FaceCorners& c, Vec3 at) {
  if (!c.smooth) return widened(m.flat_normals[face]);
  const MeshData& d = *m.data;
  const Vec3 n1 = d.normal(c.normal[0]), n2 = d.normal(c.normal[1]), n3 = d.normal(c.normal[2]);
  const Vec3 off = at - c.p[0];
  const std::array<float, 3>& perp = m.perp[face];
  const double u = off.x * perp[0] + off.y * perp[1] + off.z * perp[2];
  if (u < kEpsilon) return n1;
  const int a = m.v_axis[face];
  const double w = ((off[a] / u + c.p[0][a]) - c.p[1][a]) / (c.p[2][a] - c.p[1][a]);
  return {n1.x + u * ((n2.x - n1.x) + w * (n3.x - n2.x)), n1.y + u * ((n2.y - n1.y) + w * (n3.y - n2.y)),
          n1.z + u * ((n2.z - n1.z) + w * (n3.z - n2.z))};
}

// The ray from `origin` (mesh space) along `normal`: moved by the offset, flipped, then placed by the mesh.
Ray placed_ray(const RenderMeshCamera& cam, const RenderMeshCamera::CameraMesh& m, Vec3 origin, Vec3 normal) {
  Vec3 o{origin.x + cam.offset * normal.x, origin.y + cam.offset * normal.y, origin.z + cam.offset * normal.z};
  Vec3 d = cam.flip ? normal * -1.0 : normal;
  if (m.transformed) {
    o = m.world_from_object.point(o);
    d = m.object_from_world.normal_from_inverse(d);
  }
  return Ray{o, d};
}

// Distributions 0 to 2: the ray from the face's centroid (single-precision sum of the corners, over 3).
Ray centroid_ray(const RenderMeshCamera& cam, const RenderMeshCamera::CameraMesh& m, std::uint32_t face) {
  const MeshData& d = *m.data;
  const float* v1 = &d.vertices[3 * d.faces[3 * face]];
  const float* v2 = &d.vertices[3 * d.faces[3 * face + 1]];
  const float* v3 = &d.vertices[3 * d.faces[3 * face + 2]];
  const Vec3 centroid{(v1[0] + v2[0] + v3[0]) / 3.0f, (v1[1] + v2[1] + v3[1]) / 3.0f, (v1[2] + v2[2] + v3[2]) / 3.0f};
  return placed_ray(cam, m, centroid, widened(m.flat_normals[face]));
}

// Distribution 3: the lowest-index face of the first mesh whose uv triangle holds (u, v), among those the buckets of
// u and v both list; the ray leaves from the point of that face at those barycentric coordinates.
std::optional<Ray> uv_ray(const RenderMeshCamera& cam, double u, double v) {
  const RenderMeshCamera::CameraMesh& m = cam.meshes.front();
  const MeshData& d = *m.data;
  const auto bucket = [](double t) { return t * 10 < 1.0 ? 0u : std::min(static_cast<unsigned>(t * 10), 9u); };
  const std::vector<std::uint32_t>& ub = cam.u_buckets[bucket(u)];
  const std::vector<std::uint32_t>& vb = cam.v_buckets[bucket(v)];
  for (std::size_t word = 0; word < ub.size(); ++word) {
    const std::uint32_t both = ub[word] & vb[word];
    if (both == 0) continue;
    for (unsigned bit = 0; bit < 32; ++bit) {
      if (!(both & (1u << bit))) continue;
      const auto face = static_cast<std::uint32_t>(word * 32 + bit);
      const FaceCorners c = corners_of(m, face);
      const auto uv = [&](int k, int axis) { return d.uvs.empty() ? 0.0 : d.uvs[2 * c.uv[k] + axis]; };
      const double p1u = uv(0, 0), p2u = uv(1, 0), p3u = uv(2, 0), p1v = uv(0, 1), p2v = uv(1, 1), p3v = uv(2, 1);
      const double s = (p2u - p1u) * (p3v - p1v) - (p3u - p1u) * (p2v - p1v);
      const double b1 = ((p2u - u) * (p3v - v) - (p3u - u) * (p2v - v)) / s;
      const double b2 = ((p3u - u) * (p1v - v) - (p1u - u) * (p3v - v)) / s;
      const double b3 = ((p1u - u) * (p2v - v) - (p2u - u) * (p1v - v)) / s;
      if (b1 < 0 || b2 < 0 || b3 < 0) continue;   // NaN weights pass, as in POV-Ray
      const Vec3 at{c.p[0].x * b1 + c.p[1].x * b2 + c.p[2].x * b3, c.p[0].y * b1 + c.p[1].y * b2 + c.p[2].y * b3,
                    c.p[0].z * b1 + c.p[1].z * b2 + c.p[2].z * b3};
      const Vec3 normal = cam.smooth ? smooth_normal(m, face, c, at) : widened(m.flat_normals[face]);
      return placed_ray(cam, m, at, normal);
    }
  }
  return std::nullopt;
}

// POV-Ray's U_Xref / V_Xref: face i is listed in every tenth from its lowest to its highest corner's (truncated,
// capped at 9; povtrace also keeps negative ones at 0, where POV-Ray writes outside its table).
void fill_buckets(RenderMeshCamera& cam) {
  const RenderMeshCamera::CameraMesh& m = cam.meshes.front();
  const MeshData& d = *m.data;
  const std::size_t words = (m.faces() + 31) / 32;
  for (int b = 0; b < 10; ++b) {
    cam.u_buckets[b].assign(words, 0);
    cam.v_buckets[b].assign(words, 0);
  }
  for (std::uint32_t face = 0; face < m.faces(); ++face) {
    for (int axis = 0; axis < 2; ++axis) {
      int lo = 0, hi = 0;
      for (int k = 0; k < 3; ++k) {
        const double t = d.uvs.empty() ? 0.0 : d.uvs[2 * d.face_uvs[3 * face + k] + axis];
        const int b = static_cast<int>(std::clamp(t * 10, -1e9, 1e9));
        lo = k == 0 ? b : std::min(lo, b);
        hi = k == 0 ? b : std::max(hi, b);
      }
      lo = std::clamp(lo, 0, 9);
      hi = std::clamp(hi, 0, 9);
      auto& buckets = axis == 0 ? cam.u_buckets : cam.v_buckets;
      for (int b = lo; b <= hi; ++b) buckets[b][face / 32] |= 1u << (face % 32);
    }
  }
}
}  // namespace

std::shared_ptr<const RenderMeshCamera> make_mesh_camera(const MeshCamera& camera, double location_z,
                                                         double direction_z) {
  auto cam = std::make_shared<RenderMeshCamera>();
  cam->rays_per_pixel = camera.rays_per_pixel;
  cam->distribution = camera.distribution;
  cam->smooth = camera.smooth;
  cam->offset = location_z;
  cam->flip = direction_z < -kEpsilon;
  std::size_t total = 0;
  for (const MeshCameraMesh& source : camera.meshes) {
    RenderMeshCamera::CameraMesh m;
    m.data = source.data;
    m.transformed = source.transformed;
    m.world_from_object = source.world_from_object;
    if (m.transformed) m.object_from_world = source.world_from_object.inverse();
    const std::size_t faces = m.faces();
    m.flat_normals.resize(faces);
    m.swapped.resize(faces);
    const std::vector<float>& written = m.data->flat_normals;   // a mesh { }: from the corners as written
    for (std::uint32_t f = 0; f < faces; ++f) {
      flat_normal_and_swap(corner(*m.data, f, 0), corner(*m.data, f, 1), corner(*m.data, f, 2), m.flat_normals[f],
                           m.swapped[f]);
      if (!written.empty()) m.flat_normals[f] = {written[3 * f], written[3 * f + 1], written[3 * f + 2]};
    }
    if (camera.smooth && cam->meshes.empty()) {
      m.perp.resize(faces);
      m.v_axis.resize(faces);
      for (std::uint32_t f = 0; f < faces; ++f) {
        const FaceCorners c = corners_of(m, f);
        smooth_frame(c.p[0], c.p[1], c.p[2], m.perp[f], m.v_axis[f]);
      }
    }
    total += faces;
    cam->face_totals.push_back(total);
    cam->meshes.push_back(std::move(m));
  }
  if (cam->distribution == 3) fill_buckets(*cam);
  return cam;
}

std::optional<Ray> mesh_camera_ray(const RenderMeshCamera& cam, double x, double y, int width, int height,
                                   unsigned ray_number) {
  // No sample outside the image (the pixel grid's neighbours that antialiasing reads): clamped to it.
  x = std::max(0.0, std::min(x, width - 1.0));
  y = std::max(0.0, std::min(y, height - 1.0));
  const auto xi = static_cast<std::uint32_t>(x), yi = static_cast<std::uint32_t>(y);
  const auto w = static_cast<std::uint32_t>(width);
  switch (cam.distribution) {
    case 0: {   // ray r from mesh r, all meshes indexed alike
      if (ray_number >= cam.meshes.size()) return std::nullopt;
      const RenderMeshCamera::CameraMesh& m = cam.meshes[ray_number];
      const std::uint32_t face = yi * w + xi;
      if (face >= m.faces()) return std::nullopt;
      return centroid_ray(cam, m, face);
    }
    case 1: {   // the meshes one after another; POV-Ray adds ray_number × all faces, so only ray 0 is ever traced
      const auto total = static_cast<std::uint32_t>(cam.face_totals.back());
      const std::uint32_t face = yi * w + xi + ray_number * total;
      if (face >= total) return std::nullopt;
      const std::size_t k = static_cast<std::size_t>(
          std::upper_bound(cam.face_totals.begin(), cam.face_totals.end(), face) - cam.face_totals.begin());
      const std::uint32_t first = k == 0 ? 0 : static_cast<std::uint32_t>(cam.face_totals[k - 1]);
      return centroid_ray(cam, cam.meshes[k], face - first);
    }
    case 2: {   // side by side; the face index uses the image's column, not the sub-image's (POV-Ray's own rule)
      const std::size_t n = cam.meshes.size();
      const std::size_t k = std::min(static_cast<std::size_t>(x / (static_cast<double>(width) / n)), n - 1);
      const RenderMeshCamera::CameraMesh& m = cam.meshes[k];
      const std::uint32_t face = yi * (w / static_cast<std::uint32_t>(n)) + xi;
      if (face >= m.faces()) return std::nullopt;
      return centroid_ray(cam, m, face);
    }
    default:   // 3: by the first mesh's uv map
      return uv_ray(cam, (x - 0.5) / width, 1.0 - (y + 0.5) / height);
  }
}

}  // namespace povtrace::render
