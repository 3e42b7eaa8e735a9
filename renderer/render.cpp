#include "renderer/render.hpp"

#include "renderer/focal_blur.hpp"
#include "renderer/pretrace_run.hpp"
#include "runtime/jitter.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

namespace povtrace::render {

double working_to_linear(const RenderScene& scene, double value) {
  if (scene.gamma_mode == GammaMode::legacy_srgb) return image::srgb_decode(value);
  if (scene.assumed_gamma == 1.0 || value <= 0) return value;
  return std::pow(value, scene.assumed_gamma);
}

namespace {
struct Sample {
  Rgb colour;
  double transmit = 0;
  Sample& operator+=(const Sample& o) { colour += o.colour; transmit += o.transmit; return *this; }
  Sample operator/(double d) const { return {colour / d, transmit / d}; }
};

// A linear value into the single-precision framebuffer: beyond float's range it saturates at the largest float
// instead of becoming infinite (a pigment of rgb 1e59 is legal SDL; its pixels stay finite, and PNG clips them).
float to_pixel(double v) {
  constexpr double top = std::numeric_limits<float>::max();
  return static_cast<float>(std::clamp(v, -top, top));
}

class BlockRenderer {
 public:
  // `out` holds the pixels from (ox, oy) on: the whole frame, or a cropped region.
  // `radiosity_cache`: the pretrace's samples, which every block's radiosity queries read (null without radiosity).
  BlockRenderer(const RenderScene& scene, const RenderSettings& s, image::Image& out, int ox, int oy,
                const radiosity::CacheLevel* radiosity_cache)
      : scene_(scene), s_(s), out_(out), ox_(ox), oy_(oy), tracer_(scene, s.shading, Quality::at_level(s.quality)) {
    if (tracer_.gatherer()) {
      tracer_.gatherer()->set_global(radiosity_cache);
      // POV-Ray's one-thread order: one tile for the whole final pass, its samples kept for the blocks after.
      if (s.radiosity_povray_order) tracer_.begin_block(0);
    }
  }

  // `serial`: the block's number in the frame's row-major grid (its radiosity tile id).
  void render_block(int serial, int x0, int y0, int w, int h) {
    // POV-Ray's one-thread order: one Trace object for the whole final pass, so its shadow cache runs on too.
    if (!(s_.radiosity_povray_order && tracer_.gatherer())) tracer_.begin_block(serial);   // final-pass samples stay the block's own
    if (!s_.antialias) plain(x0, y0, w, h);
    else if (s_.sampling_method == 2) recursive(x0, y0, w, h);
    else adaptive(x0, y0, w, h);
  }
  const RayCounts& counts() const { return tracer_.counts(); }

 private:
  Sample shade(double x, double y) {
    if (scene_.camera.focal_blur) [[unlikely]] return shade_focal_blur(x, y);
    const unsigned rays = camera_rays_per_pixel(scene_.camera);
    if (rays > 1) [[unlikely]] return shade_rays(x, y, rays);
    const std::optional<Ray> ray = camera_ray(scene_.camera, x, y, s_.width, s_.height);
    if (!ray) return {Rgb{0, 0, 0}, 1.0};   // POV-Ray: no ray traced, a black and fully transparent sample
    const Radiance r = tracer_.trace_camera_ray(*ray);
    return {r.colour, r.transmit};
  }

  // Focal blur: the sample is the mean of up to blur_samples rays through the lens (POV-Ray's
  // TraceRayWithFocalBlur, focal_blur.hpp).
  Sample shade_focal_blur(double x, double y) {
    const Radiance r = focal_blur_sample(scene_.camera, s_.width, s_.height, x, y,
                                         [&](const Ray& ray) { return tracer_.trace_camera_ray(ray); });
    return {r.colour, r.transmit};
  }

  // A mesh camera's rays per pixel: the mean of the rays it traces (POV-Ray's TracePixel; a sample without any is
  // black and fully transparent).
  Sample shade_rays(double x, double y, unsigned rays) {
    Rgb colour{0, 0, 0};
    double transmit = 0;
    unsigned traced = 0;
    for (unsigned n = 0; n < rays; ++n) {
      const std::optional<Ray> ray = camera_ray(scene_.camera, x, y, s_.width, s_.height, n);
      if (!ray) continue;
      const Radiance r = tracer_.trace_camera_ray(*ray);
      colour += r.colour;
      transmit += r.transmit;
      ++traced;
    }
    if (traced == 0) return {Rgb{0, 0, 0}, 1.0};
    return {colour * (1.0 / traced), transmit / traced};
  }

  // AA colour distance (§7): decode the working gamma, encode with the AA gamma, sum |Δ| over R, G, B and T.
  double aa_encode(double v) const {
    return std::pow(std::max(working_to_linear(scene_, v), 0.0), 1.0 / s_.antialias_gamma);
  }
  bool differ(const Sample& a, const Sample& b) const {
    double d = std::fabs(aa_encode(a.colour.x) - aa_encode(b.colour.x)) +
               std::fabs(aa_encode(a.colour.y) - aa_encode(b.colour.y)) +
               std::fabs(aa_encode(a.colour.z) - aa_encode(b.colour.z));
    if (s_.output_alpha) d += std::fabs(a.transmit - b.transmit);
    return d >= s_.antialias_threshold;
  }

  void store(int x, int y, const Sample& s) {
    if (s_.region && !s_.region->contains(x, y)) return;   // computed for its block's sake only
    float* p = out_.pixel(x - ox_, y - oy_);
    const double alpha = s_.output_alpha ? 1.0 - s.transmit : 1.0;
    p[0] = to_pixel(working_to_linear(scene_, s.colour.x));
    p[1] = to_pixel(working_to_linear(scene_, s.colour.y));
    p[2] = to_pixel(working_to_linear(scene_, s.colour.z));
    p[3] = static_cast<float>(alpha);
  }

  void plain(int x0, int y0, int w, int h) {
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x) store(x, y, shade(x, y));
  }

  // Method 1 supersampling of pixel (px, py): n×n sub-samples plus the centre sample, averaged (§7).
  Sample supersample(double px, double py, const Sample& centre) {
    const int n = s_.antialias_depth;
    const double step = 1.0 / n, r = 0.5 - step / 2;
    const double js = s_.jitter ? s_.jitter_amount / n : 0.0;
    Sample sum = centre;
    for (double yy = -r; yy <= r + 1e-10; yy += step)
      for (double xx = -r; xx <= r + 1e-10; xx += step) {
        double sx = px + xx, sy = py + yy;
        if (js > 0) {
          const auto [jx, jy] = povray_jitter2d(sx, sy);
          sx += jx * js;
          sy += jy * js;
        }
        sum += shade(sx, sy);
      }
    return sum / (n * n + 1);
  }

  // Method 1 (§7): blocks with a traced frame row above and column to the left; each pixel compared with its
  // left and top neighbours, supersampling every pixel of a differing pair at most once.
  void adaptive(int x0, int y0, int w, int h) {
    const int fw = w + 1;
    std::vector<Sample> pix(static_cast<std::size_t>(fw) * (h + 1));
    std::vector<char> done(pix.size(), 0);
    auto at = [&](int x, int y) { return static_cast<std::size_t>(y - y0 + 1) * fw + (x - x0 + 1); };
    for (int x = x0; x < x0 + w; ++x) { pix[at(x, y0 - 1)] = shade(x, y0 - 1); done[at(x, y0 - 1)] = 1; }
    for (int y = y0; y < y0 + h; ++y) {
      pix[at(x0 - 1, y)] = shade(x0 - 1, y);
      done[at(x0 - 1, y)] = 1;
      for (int x = x0; x < x0 + w; ++x) {
        Sample& c = pix[at(x, y)];
        c = shade(x, y);
        const bool left = differ(pix[at(x - 1, y)], c), top = differ(pix[at(x, y - 1)], c);
        if (left && !done[at(x - 1, y)]) {
          pix[at(x - 1, y)] = supersample(x - 1, y, pix[at(x - 1, y)]);
          done[at(x - 1, y)] = 1;
        }
        if (top && !done[at(x, y - 1)]) {
          pix[at(x, y - 1)] = supersample(x, y - 1, pix[at(x, y - 1)]);
          done[at(x, y - 1)] = 1;
        }
        if (left || top) {
          c = supersample(x, y, c);
          done[at(x, y)] = 1;
        }
      }
    }
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x) store(x, y, pix[at(x, y)]);
  }

  // Method 2 (§7): corners of every pixel (shared, unjittered); where any pair differs and depth remains,
  // trace edge midpoints and centre and recurse into the four quarters.
  Sample jittered(double x, double y) {
    const double js = s_.jitter ? s_.jitter_amount / ((1 << s_.antialias_depth) + 1) : 0.0;
    if (js > 0) {
      const auto [jx, jy] = povray_jitter2d(x, y);
      return shade(x + jx * js, y + jy * js);
    }
    return shade(x, y);
  }
  Sample subdivide(double x, double y, double d, const Sample& c00, const Sample& c01, const Sample& c10,
                   const Sample& c11, int level) {
    const Sample* cs[4] = {&c00, &c01, &c10, &c11};
    bool split = false;
    for (int i = 0; i < 4 && level > 0 && !split; ++i)
      for (int j = i + 1; j < 4 && !split; ++j) split = differ(*cs[i], *cs[j]);
    if (!split) return average4(c00, c01, c10, c11);
    const Sample l = jittered(x - d, y), t = jittered(x, y - d), r = jittered(x + d, y), b = jittered(x, y + d),
                 m = jittered(x, y);
    const double h = d / 2;
    Sample sum = subdivide(x - h, y - h, h, c00, l, t, m, level - 1);
    sum += subdivide(x - h, y + h, h, l, c01, m, b, level - 1);
    sum += subdivide(x + h, y - h, h, t, m, c10, r, level - 1);
    sum += subdivide(x + h, y + h, h, m, b, r, c11, level - 1);
    return sum / 4;
  }
  static Sample average4(const Sample& a, const Sample& b, const Sample& c, const Sample& d) {
    Sample s = a;
    s += b;
    s += c;
    s += d;
    return s / 4;
  }
  void recursive(int x0, int y0, int w, int h) {
    const int cw = w + 1;
    std::vector<Sample> corners(static_cast<std::size_t>(cw) * (h + 1));
    for (int j = 0; j <= h; ++j)
      for (int i = 0; i <= w; ++i) corners[static_cast<std::size_t>(j) * cw + i] = shade(x0 + i - 0.5, y0 + j - 0.5);
    auto c = [&](int i, int j) -> const Sample& { return corners[static_cast<std::size_t>(j) * cw + i]; };
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i)
        store(x0 + i, y0 + j, subdivide(x0 + i, y0 + j, 0.5, c(i, j), c(i, j + 1), c(i + 1, j), c(i + 1, j + 1),
                                        s_.antialias_depth - 1));
  }

  const RenderScene& scene_;
  const RenderSettings& s_;
  image::Image& out_;
  int ox_, oy_;
  Tracer tracer_;
};
}  // namespace

RenderResult render(const RenderScene& scene, const RenderSettings& settings) {
  RenderResult result;
  const bool crop = settings.crop_to_region && settings.region;
  result.image = crop ? image::Image(settings.region->width(), settings.region->height())
                      : image::Image(settings.width, settings.height);
  result.image.has_alpha = settings.output_alpha;
  const int ox = crop ? settings.region->x0 : 0, oy = crop ? settings.region->y0 : 0;
  const int bs = std::max(4, settings.block_size);
  // The blocks of the (0,0)-anchored grid that meet the region: columns bx0…, rows by0…
  image::PixelRect area{0, 0, settings.width - 1, settings.height - 1};
  if (settings.region) {
    const image::PixelRect& r = *settings.region;
    if (r.x0 < 0 || r.y0 < 0 || r.x1 >= settings.width || r.y1 >= settings.height)
      throw std::invalid_argument("render region outside the image");
    area = r;
    if (!crop) result.image.region = r;
  }
  const int bx0 = area.empty() ? 0 : area.x0 / bs, by0 = area.empty() ? 0 : area.y0 / bs;
  const int bx = area.empty() ? 0 : area.x1 / bs - bx0 + 1, by = area.empty() ? 0 : area.y1 / bs - by0 + 1;
  const int blocks = bx * by;
  std::atomic<int> next{0}, done{0};
  std::atomic<bool> stop{false};
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const int threads = scene.radiosity && settings.radiosity_povray_order
                          ? 1
                          : std::clamp(settings.threads > 0 ? settings.threads : static_cast<int>(hw), 1,
                                       std::max(1, blocks));
  std::vector<RayCounts> counts(static_cast<std::size_t>(threads));

  // Radiosity: the pretrace first, over the whole frame (POV-Ray's one-thread order: renderer/pretrace_run.hpp);
  // then every block of the final pass reads its samples and keeps the ones it makes to itself (POV-Ray's
  // High_Reproducibility rule for the final pass), so a block's pixels do not depend on which blocks ran before it.
  PretraceResult pretrace;
  if (scene.radiosity && blocks > 0) {
    pretrace = run_pretrace(scene, settings);
    result.rays += pretrace.rays;
    if (pretrace.cancelled) {
      result.cancelled = true;
      return result;
    }
  }

  auto worker = [&](int id) {
    BlockRenderer br(scene, settings, result.image, ox, oy, scene.radiosity ? &pretrace.cache : nullptr);
    // Blocks are handed out one at a time, so no core idles at the end of a frame while work remains.
    for (int b = next++; b < blocks; b = next++) {
      if (stop.load(std::memory_order_relaxed) || (settings.cancel && settings.cancel->load())) {
        stop = true;
        break;
      }
      const int x0 = (bx0 + b % bx) * bs, y0 = (by0 + b / bx) * bs;
      const int w = std::min(bs, settings.width - x0), h = std::min(bs, settings.height - y0);
      const image::PixelRect stored{std::max(x0, area.x0), std::max(y0, area.y0), std::min(x0 + w - 1, area.x1),
                                    std::min(y0 + h - 1, area.y1)};
      if (!settings.skip_block || !settings.skip_block(stored)) {
        br.render_block((y0 / bs) * ((settings.width + bs - 1) / bs) + x0 / bs, x0, y0, w, h);
        if (settings.block_done) settings.block_done(result.image, stored);
      }
      ++done;
    }
    counts[static_cast<std::size_t>(id)] = br.counts();
  };
  // Workers signal when they stop, so the progress monitor never outlives the render by a polling period.
  std::mutex finished_mutex;
  std::condition_variable finished_cv;
  int running = threads;
  auto run_worker = [&](int id) {
    worker(id);
    std::lock_guard lock(finished_mutex);
    --running;
    finished_cv.notify_all();
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(run_worker, i);
  if (settings.progress) {
    std::thread own(run_worker, 0);
    std::unique_lock lock(finished_mutex);
    while (!finished_cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return running == 0; })) {
      settings.progress(static_cast<double>(done.load()) / std::max(1, blocks));
      if (settings.cancel && settings.cancel->load()) stop = true;
    }
    lock.unlock();
    own.join();
  } else {
    run_worker(0);
  }
  for (auto& t : pool) t.join();
  for (const auto& c : counts) result.rays += c;
  result.cancelled = stop.load() || (settings.cancel && settings.cancel->load());
  return result;
}

}  // namespace povtrace::render
