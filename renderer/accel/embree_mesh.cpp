#include "renderer/accel/embree_mesh.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cstring>

namespace povtrace::render {

namespace {
// One Embree device for the process, made on first use; null if Embree refuses to start (then no mesh uses it).
// One thread: Embree's own worker threads would otherwise stay behind, spinning against the render's threads on a
// small machine, and a 1M-triangle build measured no faster with them (0.76-0.86 s either way).
RTCDevice device() {
  static const RTCDevice d = rtcNewDevice("threads=1");
  return d;
}
}  // namespace

std::unique_ptr<EmbreeMesh> EmbreeMesh::build(const std::vector<float>& vertices,
                                               const std::vector<std::uint32_t>& faces) {
  const RTCDevice dev = device();
  if (!dev || faces.empty()) return nullptr;
  RTCGeometry geometry = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (!geometry) return nullptr;
  const std::size_t vertex_count = vertices.size() / 3;
  // Embree's own buffers: it reads each vertex with a 16-byte load, so they need padding that a std::vector
  // does not promise.
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), vertex_count));
  if (!v) {
    rtcReleaseGeometry(geometry);
    return nullptr;
  }
  std::memcpy(v, vertices.data(), vertex_count * 3 * sizeof(float));
  // The indices too: Embree may read past the last element of a buffer it did not allocate.
  auto* ix = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                 RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t),
                                                                 faces.size() / 3));
  if (!ix) {
    rtcReleaseGeometry(geometry);
    return nullptr;
  }
  std::memcpy(ix, faces.data(), faces.size() * sizeof(std::uint32_t));
  rtcCommitGeometry(geometry);
  RTCScene scene = rtcNewScene(dev);
  // Robust: Embree's watertight test, so a ray through a shared edge of a closed mesh never slips between its two
  // triangles; compact: the smaller node layout (1M triangles are the bench's largest mesh); medium quality, the
  // default: the high one's spatial splits cost build time that a mesh of a million triangles does not win back.
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  if (rtcGetDeviceError(dev) != RTC_ERROR_NONE) {
    rtcReleaseScene(scene);
    return nullptr;
  }
  return std::unique_ptr<EmbreeMesh>(new EmbreeMesh(scene));
}

EmbreeMesh::~EmbreeMesh() { rtcReleaseScene(static_cast<RTCScene>(scene_)); }

bool EmbreeMesh::nearest(const Ray& ray, double t_min, double t_max, std::uint32_t& triangle) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = static_cast<float>(ray.origin.x);
  rh.ray.org_y = static_cast<float>(ray.origin.y);
  rh.ray.org_z = static_cast<float>(ray.origin.z);
  rh.ray.dir_x = static_cast<float>(ray.direction.x);
  rh.ray.dir_y = static_cast<float>(ray.direction.y);
  rh.ray.dir_z = static_cast<float>(ray.direction.z);
  // The interval a little wider than asked, so that single-precision rounding never loses a triangle inside it;
  // the caller's exact test rejects one that is really outside.
  rh.ray.tnear = static_cast<float>(t_min * (1.0 - 1e-5));
  rh.ray.tfar = static_cast<float>(std::min(t_max * (1.0 + 1e-5), 1e38));
  rh.ray.mask = ~0u;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(static_cast<RTCScene>(scene_), &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  triangle = rh.hit.primID;
  return true;
}

}  // namespace povtrace::render
