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

#include "renderer/render.hpp"

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

// POV-Ray's Vector3d::normalize, which SetupCamera applies: a zero vector stays zero (a fisheye camera with
// `direction 0` looks sideways, it does not turn NaN).
Vec3 normalize_or_zero(Vec3 v) {
  const double l = length(v);
  return l != 0.0 ? v / l : v;
}

std::optional<Ray> fisheye(const RenderCamera& c, double x0, double y0) {
  x0 *= c.right_length;
  y0 *= c.up_length;
  const double rad = std::sqrt(x0 * x0 + y0 * y0);
  if (rad > 1.0) return std::nullopt;
  const double phi = polar_angle(x0, y0, rad);
  const double theta = rad * c.angle * M_PI / 360.0;
  return along(c.location, c.right * (std::cos(phi) * std::sin(theta)) + c.up * (std::sin(phi) * std::sin(theta)) +
                               c.direction * std::cos(theta));
}

// Omnimax: the 1.283458 aspect of the dome format, a polynomial radius-to-angle map, nothing below 45° under the
// projection axis.
std::optional<Ray> omnimax(const RenderCamera& c, double x0, double y0) {
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
  const double phi = polar_angle(x0, y0, rad);
  const double theta = 1.411269 * rad - 0.09439 * std::pow(rad, 3) + 0.25674 * std::pow(rad, 5);
  const double cx = std::cos(phi), sx = std::sin(phi), cy = std::cos(theta), sy = std::sin(theta);
  if (sx * sy < std::tan(135.0 * kDegree) * cy) return std::nullopt;
  return along(c.location, c.right * (cx * sy) + c.up * (sx * sy) + c.direction * cy);
}

std::optional<Ray> panoramic(const RenderCamera& c, double across, double y0) {
  const double x0 = (1.0 - across) * M_PI;
  const double lat = M_PI / 2 * y0;
  double ty;
  if (std::fabs(M_PI / 2 - std::fabs(lat)) < tolerance::epsilon) ty = lat > 0.0 ? tolerance::bound_huge : -tolerance::bound_huge;
  else ty = std::tan(lat);
  return along(c.location, c.right * std::cos(x0) + c.up * ty + c.direction * std::sin(x0));
}

std::optional<Ray> spherical(const RenderCamera& c, double u, double v) {
  const double lat = v * c.v_angle * kDegree, lon = u * c.h_angle * kDegree;
  const Vec3 up_down = rotated_about(c.direction, normalize_or_zero(c.right), -lat);
  return along(c.location, rotated_about(up_down, normalize_or_zero(c.up), lon));
}

}  // namespace

std::optional<Ray> camera_ray(const RenderCamera& c, double x, double y, int width, int height) {
  // POV-Ray's CreateCameraRay: the pixel centre is (x + 0.5, y − 0.5) and rows count from the bottom; the screen
  // coordinates are formed in its order of operations, so that rays agree to the last bit (a pattern with a jump,
  // such as a function pattern wrapping at 1, shows any difference).
  const double px = x + 0.5, py = y - 0.5;
  const double u = px / width - 0.5;
  const double v = ((height - 1) - py) / height - 0.5;
  const double u2 = 2.0 * px / width - 1.0, v2 = 2.0 * ((height - 1) - py) / height - 1.0;
  const double half_angle = c.angle * kDegree;
  switch (c.projection) {
    case Projection::perspective: return along(c.location, c.direction + c.right * u + c.up * v);
    case Projection::orthographic: return along(c.location + c.right * u + c.up * v, c.direction);
    case Projection::fisheye: return fisheye(c, u2, v2);
    case Projection::omnimax: return omnimax(c, u2, v2);
    case Projection::panoramic: return panoramic(c, px / width, v2);
    case Projection::spherical: return spherical(c, u, v);
    case Projection::ultra_wide_angle: {
      const double a = u * half_angle, b = v * half_angle * c.aspect;
      return along(c.location, c.right * std::sin(a) + c.up * std::sin(b) + c.direction * (std::cos(a) * std::cos(b)));
    }
    case Projection::cylinder1: {
      const double a = u * half_angle;
      return along(c.location, c.right * std::sin(a) + c.up * (v * c.aspect) + c.direction * std::cos(a));
    }
    case Projection::cylinder2: {
      const double b = v * half_angle;
      return along(c.location, c.right * (u * c.aspect) + c.up * std::sin(b) + c.direction * std::cos(b));
    }
    case Projection::cylinder3: {
      const double a = u * half_angle;
      return along(c.location + c.up * (v * c.aspect), c.right * std::sin(a) + c.direction * std::cos(a));
    }
    case Projection::cylinder4: {
      const double b = v * half_angle;
      return along(c.location + c.right * (u * c.aspect), c.up * std::sin(b) + c.direction * std::cos(b));
    }
  }
  return std::nullopt;
}

bool origins_vary(const RenderCamera& c) {
  return c.projection == Projection::orthographic || c.projection == Projection::cylinder3 ||
         c.projection == Projection::cylinder4;
}

RenderCamera make_render_camera(const Camera& camera) {
  RenderCamera c{camera.projection, camera.location, camera.direction, camera.up, camera.right};
  c.angle = camera.angle;
  c.h_angle = camera.h_angle;
  c.v_angle = camera.v_angle;
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
  }
  c.direction = normalize_or_zero(c.direction);
  c.up = normalize_or_zero(c.up);
  c.right = normalize_or_zero(c.right);
  return c;
}

}  // namespace povtrace::render
