// Camera rays for every POV-Ray 3.7 projection (facts from POV-Ray's tracepixel.cpp CreateCameraRay and
// SetupCamera; povray-pixel-pipeline.md §1 for the planar ones).
//
// Pixel position: x + ½ and y + ½ measured from the top-left corner; u = x/W − ½ and v = ½ − y/H for the planar,
// ultra-wide and cylindrical projections; 2u and 2v (from −1 to 1) for fisheye, omnimax and panoramic.
// The non-planar projections use unit right, up and direction vectors; the aspect ratio they apply comes from
// the lengths before normalising (SetupCamera): |up| for cylinder 1 and 3, |right| for 2 and 4, |up|/|right|
// for ultra_wide_angle, |right|/|up| for fisheye and omnimax. Fisheye and omnimax trace no ray outside their
// circle (the pixel is black and fully transparent).
#include <cmath>

#include "scene/pov_vector_math.hpp"
#include "renderer/render.hpp"
#include "renderer/pattern/normal_perturbation.hpp"
#include "renderer/mesh_camera.hpp"
#include "renderer/focal_blur.hpp"

namespace povtrace::render {

namespace {

constexpr double kDegree = M_PI / 180.0;

// v rotated by `angle` radians about the unit axis a (right-hand rule; POV-Ray's axis rotation).
Vec3 rotated_about(Vec3 v, Vec3 a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(a, v) * s + a * (dot(a, v) * (1.0 - c));
}

// Polar angle of (x, y) as POV-Ray measures it for its circular projections (asin based).
double polar_angle(double x, double y, double radius) {
  if (radius == 0.0) return 0.0;
  return x < 0.0 ? M_PI - std::asin(y / radius) : std::asin(y / radius);
}

// A ray needs a direction: where the camera's vectors cancel out for this pixel (a degenerate camera that the
// parser lets through, as POV-Ray renders it) no ray is traced, rather than one with a NaN direction.
std::optional<Ray> along(Vec3 origin, Vec3 direction) {
  const double l = length(direction);
  if (!(l > 0.0) || !std::isfinite(l)) return std::nullopt;
  return Ray{origin, direction * (1.0 / l)};   // POV-Ray's VNormalize: times the reciprocal of the length
}

// The ray before its direction is normalised (focal blur moves it first, as POV-Ray's JitterCameraRay does).
std::optional<Ray> aim(Vec3 origin, Vec3 direction) { return Ray{origin, direction}; }

// POV-Ray's Vector3d::normalize, which SetupCamera applies: a zero vector stays zero (a fisheye camera with
// `direction 0` looks sideways, it does not turn NaN).
Vec3 normalize_or_zero(Vec3 v) {
  const double l = length(v);
  return l != 0.0 ? v / l : v;
}

// x0, y0 end as POV-Ray leaves them (the polar angle and the angle off the axis), which a camera normal reads.
std::optional<Ray> fisheye(const RenderCamera& c, double& x0, double& y0) {
  x0 *= c.right_length;
  y0 *= c.up_length;
  const double rad = std::sqrt(x0 * x0 + y0 * y0);
  if (rad > 1.0) return std::nullopt;
  x0 = polar_angle(x0, y0, rad);
  y0 = rad * c.angle * kPovPiOver360;
  return aim(c.location, c.right * (std::cos(x0) * std::sin(y0)) + c.up * (std::sin(x0) * std::sin(y0)) +
                               c.direction * std::cos(y0));
}

// Omnimax: the 1.283458 aspect of the dome format, a polynomial radius-to-angle map, nothing below 45° under the
// projection axis.
std::optional<Ray> omnimax(const RenderCamera& c, double& x0, double& y0) {
  const double aspect = c.aspect;
  if (aspect > 1.0) {
    if (aspect > 1.283458) {
      x0 *= aspect / 1.283458;
      y0 = (y0 - 1.0) / 1.283458 + 1.0;
    } else {
      y0 = (y0 - 1.0) / aspect + 1.0;
    }
  } else {
    y0 /= aspect;
  }
  const double rad = std::sqrt(x0 * x0 + y0 * y0);
  if (rad > 1.0) return std::nullopt;
  x0 = polar_angle(x0, y0, rad);
  // POV-Ray's polynomial, its powers as products.
  y0 = 1.411269 * rad - 0.09439 * rad * rad * rad + 0.25674 * rad * rad * rad * rad * rad;
  const double cx = std::cos(x0), sx = std::sin(x0), cy = std::cos(y0), sy = std::sin(y0);
  if (sx * sy < std::tan(135.0 * kDegree) * cy) return std::nullopt;
  return aim(c.location, c.right * (cx * sy) + c.up * (sx * sy) + c.direction * cy);
}

std::optional<Ray> panoramic(const RenderCamera& c, double& x0, double& y0) {
  x0 = (1.0 - x0) * M_PI;
  y0 = M_PI_2 * y0;
  double ty;
  if (std::fabs(M_PI / 2 - std::fabs(y0)) < tolerance::epsilon) ty = y0 > 0.0 ? tolerance::bound_huge : -tolerance::bound_huge;
  else ty = std::tan(y0);
  return aim(c.location, c.right * std::cos(x0) + c.up * ty + c.direction * std::sin(x0));
}

// The angles as POV-Ray forms them: the fraction of the image times (field of view / 360) · 2π.
std::optional<Ray> spherical(const RenderCamera& c, double& x0, double& y0) {
  y0 *= (c.v_angle / 360) * (2 * M_PI);
  x0 *= (c.h_angle / 360) * (2 * M_PI);
  const Vec3 up_down = rotated_about(c.direction, normalize_or_zero(c.right), -y0);
  return aim(c.location, rotated_about(up_down, normalize_or_zero(c.up), x0));
}

std::optional<Ray> projected_ray(const RenderCamera& c, double px, double py, int width, int height, double& x0,
                                 double& y0) {
  const double u = px / width - 0.5;
  const double v = ((height - 1) - py) / height - 0.5;
  const double half_angle = c.angle * kDegree;
  x0 = u;
  y0 = v;
  switch (c.projection) {
    case Projection::perspective: return aim(c.location, c.direction + c.right * u + c.up * v);
    case Projection::orthographic: return aim(c.location + c.right * u + c.up * v, c.direction);
    case Projection::fisheye:
    case Projection::omnimax:
      x0 = 2.0 * px / width - 1.0;
      y0 = 2.0 * ((height - 1) - py) / height - 1.0;
      return c.projection == Projection::fisheye ? fisheye(c, x0, y0) : omnimax(c, x0, y0);
    case Projection::panoramic:
      x0 = px / width;
      y0 = 2.0 * ((height - 1) - py) / height - 1.0;
      return panoramic(c, x0, y0);
    case Projection::spherical: return spherical(c, x0, y0);
    case Projection::ultra_wide_angle: {
      const double a = u * half_angle, b = v * half_angle * c.aspect;
      return aim(c.location, c.right * std::sin(a) + c.up * std::sin(b) + c.direction * (std::cos(a) * std::cos(b)));
    }
    case Projection::cylinder1: {
      const double a = u * half_angle;
      return aim(c.location, c.right * std::sin(a) + c.up * (v * c.aspect) + c.direction * std::cos(a));
    }
    case Projection::cylinder2: {
      const double b = v * half_angle;
      return aim(c.location, c.right * (u * c.aspect) + c.up * std::sin(b) + c.direction * std::cos(b));
    }
    case Projection::cylinder3: {
      const double a = u * half_angle;
      return aim(c.location + c.up * (v * c.aspect), c.right * std::sin(a) + c.direction * std::cos(a));
    }
    case Projection::cylinder4: {
      const double b = v * half_angle;
      return aim(c.location + c.right * (u * c.aspect), c.up * std::sin(b) + c.direction * std::cos(b));
    }
    case Projection::mesh: break;   // mesh_camera_ray
  }
  return std::nullopt;
}

}  // namespace

std::optional<Ray> camera_ray(const RenderCamera& c, double x, double y, int width, int height, unsigned ray_number,
                              bool through_lens) {
  // POV-Ray's CreateCameraRay: the pixel centre is (x + 0.5, y − 0.5) and rows count from the bottom; the screen
  // coordinates are formed in its order of operations, so that rays agree to the last bit (a pattern with a jump,
  // such as a function pattern wrapping at 1, shows any difference).
  double x0 = 0, y0 = 0;   // a mesh camera leaves them at 0 (POV-Ray never sets them there)
  std::optional<Ray> ray = c.projection == Projection::mesh
                               ? mesh_camera_ray(*c.mesh, x + 0.5, y - 0.5, width, height, ray_number)
                               : projected_ray(c, x + 0.5, y - 0.5, width, height, x0, y0);
  if (ray && through_lens && c.focal_blur) jitter_lens(*c.focal_blur, x + 0.5, y - 0.5, static_cast<int>(ray_number),
                                                      ray->origin, ray->direction);
  if (ray) ray = along(ray->origin, ray->direction);
  if (ray && c.normal) {
    // A camera normal bends the unit direction by its pattern at <x0, y0, 0> (POV-Ray has no hit there: uv, slope
    // and the like read nothing); the ray is normalised again.
    const Vec3 bent = perturb_normal(*c.normal, ray->direction, TexturePoint({x0, y0, 0.0}), c.normal_waves);
    ray = along(ray->origin, bent);
  }
  return ray;
}

unsigned camera_rays_per_pixel(const RenderCamera& c) {
  return c.projection == Projection::mesh && c.mesh ? c.mesh->rays_per_pixel : 1;
}

bool origins_vary(const RenderCamera& c) {
  return c.projection == Projection::orthographic || c.projection == Projection::cylinder3 ||
         c.projection == Projection::cylinder4 || c.projection == Projection::mesh;
}

RenderCamera make_render_camera(const Camera& camera) {
  RenderCamera c;
  c.projection = camera.projection;
  c.location = camera.location;
  c.direction = camera.direction;
  c.up = camera.up;
  c.right = camera.right;
  c.angle = camera.angle;
  c.h_angle = camera.h_angle;
  c.v_angle = camera.v_angle;
  if (std::optional<FocalBlurSetup> blur = make_focal_blur(camera))
    c.focal_blur = std::make_shared<const FocalBlurSetup>(std::move(*blur));
  c.up_length = length(camera.up);
  c.right_length = length(camera.right);
  switch (camera.projection) {
    case Projection::perspective:
    case Projection::orthographic:
    case Projection::panoramic:
    case Projection::spherical: c.aspect = c.right_length / c.up_length; return c;
    case Projection::cylinder1:
    case Projection::cylinder3: c.aspect = c.up_length; break;
    case Projection::cylinder2:
    case Projection::cylinder4: c.aspect = c.right_length; break;
    case Projection::ultra_wide_angle: c.aspect = c.up_length / c.right_length; break;
    case Projection::fisheye:
    case Projection::omnimax: c.aspect = c.right_length / c.up_length; break;
    case Projection::mesh: return c;   // its rays come from the meshes (render_scene.cpp makes them ready)
  }
  c.direction = normalize_or_zero(c.direction);
  c.up = normalize_or_zero(c.up);
  c.right = normalize_or_zero(c.right);
  return c;
}

}  // namespace povtrace::render
