// The pixel loop (STYLE.md (a) step 5), separate from the shading function: camera rays through pixel centres
// (povray-pixel-pipeline.md §1), POV-Ray's antialiasing methods (§7), 32×32 blocks on a pool of threads, and the
// working-gamma decode into a linear framebuffer (§6). The image is bit-identical whatever the thread count:
// every block is computed on its own, including the frame pixels that method 1 compares against.
#pragma once

#include <optional>

#include <atomic>
#include <functional>

#include "renderer/image/image.hpp"
#include "renderer/render_scene.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render {

struct RenderSettings {
  int width = 800;
  int height = 600;
  int threads = 0;                  // 0: every hardware thread
  bool antialias = false;
  double antialias_threshold = 0.3;
  int antialias_depth = 3;
  int sampling_method = 1;          // 1 non-recursive (POV-Ray's default), 2 recursive
  bool jitter = true;
  double jitter_amount = 1.0;
  double antialias_gamma = 2.5;
  bool output_alpha = false;
  ShadingModel shading = ShadingModel::povray;
  int block_size = 32;              // POV-Ray's Render_Block_Size; also method 1's comparison blocks
  int quality = 9;                  // POV-Ray's +Q0…+Q9 (tracer.hpp Quality); quick colours (+Q0…+Q5) are applied
                                    // when the scene is built (BuildOptions::quick_colours)
  // Only the pixels of this rectangle are rendered (+SR +ER +SC +EC); the others keep the framebuffer's initial
  // black, opaque value, which is what POV-Ray 3.7 writes outside a region (alpha 1 even with +UA; checked with
  // Debian's povray 3.7.0.10). Blocks stay on the grid anchored at (0,0), and a block that straddles the
  // region's edge is computed whole, only its region pixels stored: a region's pixels are then bit-identical to
  // the same pixels of a full render (MPI tiles and `--assemble` rely on this). A deliberate deviation from
  // POV-Ray, which starts its block grid at the region's corner, so its method-1 antialiasing of a region can
  // differ at block edges from its full render.
  std::optional<image::PixelRect> region;
  // With a region: the result image is only the region's rectangle (its pixel (0,0) is the region's corner), not
  // the full frame; for MPI tiles, which would otherwise fill and send a whole frame per tile. Same pixel values.
  bool crop_to_region = false;
  std::function<void(double fraction_done)> progress;   // called from the calling thread
  // Called once per finished block with the image being filled and the rectangle of the pixels the block stored
  // (frame coordinates, clipped to the region; with crop_to_region the image's pixel (0,0) is the region's
  // corner), from the worker thread that rendered it, possibly concurrently: the callee synchronises. The block's
  // pixels in the image are final when it is called and no other thread writes them, so the callee may read
  // them (+C's state file records them). Not called for a block abandoned by a cancel.
  std::function<void(const image::Image& image, const image::PixelRect& block)> block_done;
  // Called before each block with the rectangle block_done would report for it, from the worker thread about to
  // render it (concurrently: the callee must be safe to call so). True: the block is not rendered, its pixels
  // keep the framebuffer's initial value (the caller fills them: +C puts back the blocks of an interrupted
  // render, app/render_state.hpp), block_done is not called for it, and it counts as done for the progress.
  // The blocks that are rendered are computed exactly as without skipping (every block is independent).
  std::function<bool(const image::PixelRect& block)> skip_block;
  const std::atomic<bool>* cancel = nullptr;            // set to stop promptly (Ctrl-C)
  // Radiosity's final pass in POV-Ray's one-thread order (povray +WT1) too, on one thread: the blocks one after the
  // other, one direction cursor running through them, each block seeing the samples of the blocks before it. With
  // the pretrace (always in that order, renderer/pretrace_run.hpp) it reproduces POV-Ray's +WT1 radiosity sample
  // for sample. By default the final pass is parallel, each block keeping its new samples to itself.
  bool radiosity_povray_order = false;
};

struct RenderResult {
  image::Image image;               // linear light, alpha only with output_alpha
  RayCounts rays;
  bool cancelled = false;
};

RenderResult render(const RenderScene& scene, const RenderSettings& settings);

// The camera ray through continuous pixel position (x, y) (integer = pixel centre, y = 0 top row); none where the
// projection traces no ray (outside a fisheye's or omnimax's circle). renderer/camera.cpp.
// Ray `ray_number` (0 … camera_rays_per_pixel − 1) of the sample at (x, y); none where the camera traces nothing.
// With `through_lens` and a camera with focal blur, the ray leaves from lens point `ray_number` instead
// (focal_blur.hpp; the sample's sub-pixel offset is the caller's).
std::optional<Ray> camera_ray(const RenderCamera& camera, double x, double y, int width, int height,
                              unsigned ray_number = 0, bool through_lens = false);
// How many rays each sample averages (a mesh camera's rays per pixel, else 1).
unsigned camera_rays_per_pixel(const RenderCamera& camera);
// Whether camera rays start at different points (orthographic, cylinder 3 and 4).
bool origins_vary(const RenderCamera& camera);
RenderCamera make_render_camera(const Camera& camera);

// Working-space value → linear light (pipeline §6).
double working_to_linear(const RenderScene& scene, double value);

}  // namespace povtrace::render
