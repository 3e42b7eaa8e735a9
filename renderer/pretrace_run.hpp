// The radiosity pretrace of a render (docs/issue19-study.md §2, §9.2 item 5): before the final pass, the image's
// blocks are traced at a few jittered points per cell in passes of finer cells, and the radiosity queries of those
// rays fill the sample cache the final pass reuses.
//
// Deterministic for any thread count. Within a pass the cache of the earlier passes is read-only; the blocks of a
// pass are split into groups that never see each other's new samples, each group's blocks run one after the
// other in serial order on one thread and see each other's (POV-Ray's High_Reproducibility scheme: in pass p,
// 2^(p−1) groups, block serial mod 2^(p−1); view.cpp, radiositytask.cpp), with the direction cursors restarting at
// each group. After the pass the groups' samples are appended to the cache in group order. The same blocks,
// groups and order whatever the threads, so the same cache.
//
// The pretrace covers the whole frame even when a region is rendered (POV-Ray pretraces the region only), so a
// region's pixels stay those of the full render (MPI tiles, --assemble, +C rely on it).
#pragma once

#include "renderer/radiosity/gather.hpp"
#include "renderer/render.hpp"

namespace povtrace::render {

struct PretraceResult {
  radiosity::CacheLevel cache;   // every pretrace sample, in the order merged
  RayCounts rays;
  bool cancelled = false;
};

// The pretrace of `scene` (which has radiosity) for an image of settings.width × settings.height in blocks of
// settings.block_size, on `threads` threads (on one in settings.radiosity_povray_order, where the cache is the
// pretrace's samples in the order made, every pass's blocks one group whose cursors run on across the passes).
PretraceResult run_pretrace(const RenderScene& scene, const RenderSettings& settings, int threads);

}  // namespace povtrace::render
