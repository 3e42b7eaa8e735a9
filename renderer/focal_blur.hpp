// Focal blur as POV-Ray 3.7 renders it (tracepixel.cpp: TraceRayWithFocalBlur, JitterCameraRay, FocalBlurData).
// Every sample of a pixel becomes up to blur_samples camera rays whose eye points spread over the aperture; rays
// agree where they cross the plane in focus. POV-Ray's lens points and sub-pixel positions are deterministic (fixed
// hexagonal grids, a Halton sequence on the disc, its jitter lookup and hash), reproduced here, so the image matches
// POV-Ray's; the confidence test ends a pixel's rays early when their variance is small enough.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "scene/description.hpp"
#include "renderer/render.hpp"

namespace povtrace::render {

struct FocalBlurSetup {
  double aperture = 0.0;
  int samples = 0, min_samples = 0;
  std::vector<double> thresholds;                  // the variance below which sample count n + 1 may stop
  std::vector<std::pair<double, double>> grid;     // the lens point of each ray, in the unit aperture
  std::vector<int> batches;                        // rays per confidence test, ending in 0 (then 4 at a time)
  double max_jitter = 0.0;                         // each lens point moves by up to this (times the jitter lookup)
  Vec3 location, x_perp, y_perp;                   // the eye and the lens plane's axes
  double focal_scale = 1.0;                        // the focal distance over the direction's length
};

// The setup of a camera with focal blur (aperture ≠ 0 and blur_samples > 0), else none. A mesh camera has none:
// POV-Ray draws its rays from its meshes, one per mesh and pixel, and never moves them.
std::optional<FocalBlurSetup> make_focal_blur(const Camera& camera);

// POV-Ray's JitterCameraRay for ray `ray_number` at the adjusted pixel position (x, y) (CreateCameraRay's x + ½,
// y − ½): the eye moves across the aperture and the raw (unnormalised) direction turns so the ray still crosses
// the focal plane where the unblurred one does. The origin becomes the camera location plus that offset, for
// every projection (POV-Ray's behaviour, also for orthographic cameras).
void jitter_lens(const FocalBlurSetup& blur, double x, double y, int ray_number, Vec3& origin, Vec3& direction);

// The sub-pixel offset of ray `n` of the sample at (x, y) (TraceRayWithFocalBlur: a 16 × 16 cell picked by
// POV-Ray's hash of the position, then jittered).
std::pair<double, double> focal_blur_offset(double x, double y, int n);

// The rays of one sample at pixel position (x, y): ray n leaves from lens point n (camera_ray through the lens) at
// the sample's sub-pixel offset, and `trace(ray)` returns its colour and transmit (a Radiance). POV-Ray's sum and
// confidence test: a position where the camera traces no ray counts as black and fully transparent in the variance,
// adds nothing to the colour, and the sum is divided by the number of rays tried.
template <class Trace>
auto focal_blur_sample(const RenderCamera& camera, int width, int height, double x, double y, Trace&& trace) {
  const FocalBlurSetup& blur = *camera.focal_blur;
  decltype(trace(std::declval<const Ray&>())) sum{};
  // POV-Ray's colours are floats: each ray's colour, the sums and the variance are rounded to float as there, so
  // that the test stops at the same ray.
  float s1[4] = {0, 0, 0, 0}, s2[4] = {0, 0, 0, 0};
  int n = 0;
  std::size_t level = 0;
  do {
    int batch = 4;
    if (!blur.batches.empty() && blur.batches[level] > 0) batch = blur.batches[level++];
    for (int i = 0; i < batch && n < blur.samples; ++i, ++n) {
      const auto [dx, dy] = focal_blur_offset(x, y, n);
      float c[4] = {0, 0, 0, 1};
      if (const std::optional<Ray> ray = camera_ray(camera, x + dx, y + dy, width, height, static_cast<unsigned>(n), true)) {
        const auto r = trace(*ray);
        sum.colour += r.colour;
        sum.transmit += r.transmit;
        c[0] = static_cast<float>(r.colour.x);
        c[1] = static_cast<float>(r.colour.y);
        c[2] = static_cast<float>(r.colour.z);
        c[3] = static_cast<float>(r.transmit);
      }
      for (int k = 0; k < 4; ++k) {
        s1[k] += c[k];
        s2[k] = static_cast<float>(static_cast<double>(s2[k]) + static_cast<double>(c[k]) * c[k]);
      }
    }
    const double count = n;
    bool settled = n >= blur.min_samples;
    for (int k = 0; k < 4 && settled; ++k) {
      const double mean = s1[k] / count;
      const auto variance = static_cast<float>((s2[k] / count - mean * mean) / count);
      settled = variance < blur.thresholds[static_cast<std::size_t>(n - 1)];
    }
    if (settled) break;
  } while (n < blur.samples);
  sum.colour = sum.colour / static_cast<double>(n);
  sum.transmit /= static_cast<double>(n);
  return sum;
}

}  // namespace povtrace::render
