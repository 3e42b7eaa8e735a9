// The radiosity pretrace of a render (docs/issue19-study.md §2, §9.2 item 5): before the final pass, the image's
// blocks are traced at a few jittered points per cell in passes of finer cells, and the radiosity queries of those
// rays fill the sample cache the final pass reuses.
//
// It runs in POV-Ray's one-thread order (povray +WT1): every pass's blocks one after the other in serial order,
// pass after pass, each query seeing every sample made before it, one direction cursor per bounce depth running
// through the whole pretrace. So the cache is POV-Ray's +WT1 cache sample for sample, whatever the thread count.
// It is not spread over threads: any parallel order changes which directions each sample shoots, and its image
// then differs from POV-Ray's +WT1 as a +WT2 render does (measured in docs/issue19-study.md §12), while this order
// leaves only the final pass to differ. The pretrace is a small share of most renders; the final pass is parallel.
//
// The pretrace covers the whole frame even when a region is rendered (POV-Ray pretraces the region only), so a
// region's pixels stay those of the full render (MPI tiles, --assemble, +C rely on it).
#pragma once

#include "renderer/radiosity/gather.hpp"
#include "renderer/render.hpp"

namespace povtrace::render {

struct PretraceResult {
  radiosity::CacheLevel cache;   // every pretrace sample, in the order made
  RayCounts rays;
  bool cancelled = false;
};

// The pretrace of `scene` (which has radiosity) for an image of settings.width × settings.height in blocks of
// settings.block_size.
PretraceResult run_pretrace(const RenderScene& scene, const RenderSettings& settings);

}  // namespace povtrace::render
