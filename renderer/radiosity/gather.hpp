// The radiosity value A at a surface point (docs/issue19-study.md §3.4, §4; POV-Ray 3.7 source/backend/lighting/
// radiosity.cpp, RadiosityFunction::ComputeAmbient and GatherLight): reuse the cached samples near the point when
// they weigh enough, else gather a new sample by tracing sample rays over the hemisphere and file it in the
// block's private level (sample_levels.hpp). One Gatherer per thread (it holds POV-Ray's per-thread "ticket"
// state of radiosity: the running quality and the direction cursors); the rays themselves are traced by the
// caller through the SampleTracer interface, so this file knows nothing of shading.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/radiosity/render_settings.hpp"
#include "renderer/radiosity/sample_levels.hpp"
#include "renderer/radiosity/weights.hpp"
#include "scene/vecmath.hpp"

namespace povtrace::render::radiosity {

// A cached sample: what the weight needs (weights.hpp) and its illuminance A (before gray_threshold and
// brightness, study §3.1).
struct CachedSample {
  SampleGeometry geometry;
  Vec3 illuminance;
};
using CacheLevel = SampleLevel<CachedSample>;

// How the tracer must trace one sample ray (study §4.4). POV-Ray changes its ticket for the ray: radiosity depth
// d+1, trace level ⌊1.5(d+1)⌋, a raised maximum level, radiosity's adc_bailout, and the importance share.
struct SampleRayParams {
  int depth = 1;             // the radiosity depth of the surfaces the ray hits (d + 1)
  int level = 2;             // the ray's trace level in povtrace's numbering (POV-Ray's ticket level + 1)
  int max_level = 5;         // the deepest level allowed below it (povtrace's `level > max` test)
  double weight = 0.5;       // the ray weight, max(adc_bailout + 1e−10, (0.5·brightness)^(d+1))
  double adc_bailout = 0.01; // radiosity's adc_bailout, for the whole ray tree below
  float importance_queried = 0;   // i/(n−1): the ray is dropped at a first object less important than this
};

// What the tracer reports of one sample ray.
struct SampleRayResult {
  Vec3 colour;               // the traced colour (meaningless when not kept)
  double depth = 0;          // distance to its first hit; HUGE_VAL or more for a miss or a ray cut off
  float importance = 1;      // the importance found: the first object's, or the default for a miss
  bool kept = true;          // importance ≥ importance_queried
};

class SampleTracer {
 public:
  virtual SampleRayResult trace_sample(Vec3 origin, Vec3 direction, const SampleRayParams& params) = 0;

 protected:
  ~SampleTracer() = default;
};

// One radiosity query of the shading (trace.cpp ComputeLightedTexture): the point, its raw and layer normals (both
// facing the viewer; negated for diffuse_back), the weight the radiosity term will be seen with, and the
// radiosity depth of the ray being shaded.
struct AmbientQuery {
  Vec3 point;
  Vec3 raw_normal;
  Vec3 layer_normal;
  double weight = 1;
  int depth = 0;
  // The ray's maximum trace level when the query is made (POV-Ray raises it for sample rays, never lowers it).
  int max_level = 5;
};

class Gatherer {
 public:
  // `camera` is the camera location (the reuse radii scale with the distance to it).
  Gatherer(const RenderRadiosity& radiosity, Vec3 camera);

  // Starts a tile (POV-Ray's BeforeTile): its tile id and pass (1, 2, … in the pretrace, with E × low_error_factor
  // and linear weights; final_pass_id for the render), no samples of its own yet, direction cursors back to 0
  // (study §9.2 item 5), top-level statistics reset. A tile is one block, or a group of pretrace blocks run one
  // after the other that see each other's samples (renderer/pretrace_run.cpp).
  void begin_block(int tile, int pass);
  // Goes on to radiosity pass `pass` keeping the samples and the direction cursors (POV-Ray's one-thread order,
  // where one evaluator runs the whole pretrace).
  void set_pass(int pass);
  // The importance a sample ray found at its first hit (or the default for a miss), as the tracer finds it, before
  // the hit is shaded. POV-Ray keeps it in the ray's ticket, which the sample rays of any gather made while shading
  // that hit overwrite: a ray is then kept and compensated by the importance the last of those found (radiosity.cpp
  // GatherLight reads the ticket after TraceRay). Reproduced, since it changes images with importance < 1.
  void importance_found(float importance) {
    found_importance_ = importance;
    ++importance_writes_;
  }
  // Resets the depth-0 statistics only (POV-Ray's ResetTopLevelStats, before each adaptive sub-block).
  void reset_top_level_stats() {
    top_queries_ = 0;
    top_reuse_ = 0;
  }
  // The samples every lookup may see besides the block's own (null: none). Immutable during a pass.
  void set_global(const CacheLevel* global) { global_ = global; }

  // The radiosity value returned to the surface: A (reused, gathered or blended), desaturated by gray_threshold
  // and multiplied by brightness (study §3.4).
  Vec3 ambient(const AmbientQuery& q, SampleTracer& tracer);

  // The samples made since begin_block, in the order made (merged into the global level in block order).
  const CacheLevel& block_samples() const { return block_; }
  CacheLevel& block_samples() { return block_; }
  // Depth-0 queries since begin_block and the sum of their 4·Σw before any gather (adaptive pretrace, §2.4).
  long top_level_queries() const { return top_queries_; }
  float top_level_reuse() const { return top_reuse_; }
  float running_quality() const { return quality_; }

  // The radiosity value of the samples offered to query q: Σw and Σw·A/Σw (A is 0 when Σw is 0), summed in
  // the fixed order global level then block level, each in insertion order.
  struct Lookup {
    double weight_sum = 0;
    Vec3 illuminance;
  };
  Lookup lookup(const Query& q);

 private:
  // GatherLight: shoots the rays of one new sample, files it when usable, and returns its illuminance and quality.
  struct Gathered {
    Vec3 illuminance;
    double quality = 0;
  };
  Gathered gather(const AmbientQuery& q, Vec3 effective_normal, SampleTracer& tracer);

  const RenderRadiosity& radiosity_;
  Vec3 camera_;
  bool final_pass_ = true;
  double error_bound_;                 // E0, × low_error_factor in the pretrace
  const CacheLevel* global_ = nullptr;
  CacheLevel block_;
  std::vector<std::size_t> cursors_;   // per depth: the next pool entry
  std::vector<std::uint32_t> scratch_;
  int tile_ = 0;
  int pass_ = 0;
  float quality_ = 1;                  // POV-Ray's ticket.radiosityQuality
  float found_importance_ = 1;         // POV-Ray's ticket.radiosityImportanceFound (importance_found)
  unsigned long importance_writes_ = 0;
  long top_queries_ = 0;
  float top_reuse_ = 0;                // single precision, as POV-Ray sums it
};

// The pass id of the final pass (POV-Ray's FINAL_TRACE), distinct from the pretrace passes 1, 2, …
inline constexpr int final_pass_id = 1000;

}  // namespace povtrace::render::radiosity
