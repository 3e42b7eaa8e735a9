// The Gatherer (renderer/radiosity/gather.hpp) against a scripted SampleTracer: when it gathers and when it reuses
// (study §3.4), what a sample ray is asked to do (§4.4), importance and quality (§4.4, §4.5), the harmonic-mean
// radius and its clamps, and the near-hit rule that keeps a sample out of the cache (§3.1).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "renderer/radiosity/gather.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render::radiosity;

// Every ray sees `colour` at distance `depth`; its first object has importance `importance`.
struct ScriptedTracer final : SampleTracer {
  Vec3 colour{0.5, 0.25, 1};
  double depth = 1;
  float importance = 1;
  std::vector<SampleRayParams> calls;
  SampleRayResult trace_sample(Vec3, Vec3, const SampleRayParams& p) override {
    calls.push_back(p);
    SampleRayResult r;
    r.colour = colour;
    r.depth = depth;
    r.importance = importance;
    r.kept = !(importance < p.importance_queried);
    return r;
  }
};

RenderRadiosity settings(int count = 35, int nearest = 5) {
  SceneDescription scene;
  RadiositySettings s;
  s.count = count;
  s.nearest_count = nearest;
  scene.radiosity = s;
  return make_render_radiosity(scene);
}

// A point 10 units from the camera, facing up.
AmbientQuery at_origin() { return AmbientQuery{{0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 1.0, 0, 5}; }
const Vec3 camera{0, 10, 0};

TEST(Gatherer, GathersOnceThenReusesInTheFinalPass) {
  const RenderRadiosity rad = settings();
  Gatherer g(rad, camera);
  g.begin_block(0, final_pass_id);
  ScriptedTracer t;
  const Vec3 a = g.ambient(at_origin(), t);
  EXPECT_EQ(t.calls.size(), 35u);
  EXPECT_NEAR(a.x, 0.5, 1e-12);
  EXPECT_NEAR(a.y, 0.25, 1e-12);
  EXPECT_NEAR(a.z, 1, 1e-12);
  ASSERT_EQ(g.block_samples().size(), 1u);
  const SampleGeometry& s = g.block_samples()[0].geometry;
  EXPECT_FLOAT_EQ(s.radius, 1.0f);    // harmonic mean of equal distances, inside [0.15, 2]
  EXPECT_FLOAT_EQ(s.quality, 1.0f);
  EXPECT_EQ(s.pass, final_pass_id);
  (void)g.ambient(at_origin(), t);    // any positive weight is enough in the final pass
  EXPECT_EQ(t.calls.size(), 35u);
  EXPECT_EQ(g.top_level_queries(), 2);
}

TEST(Gatherer, SampleRaysGetTheirOwnTicket) {
  const RenderRadiosity rad = settings();
  Gatherer g(rad, camera);
  g.begin_block(0, final_pass_id);
  ScriptedTracer t;
  (void)g.ambient(at_origin(), t);
  ASSERT_EQ(t.calls.size(), 35u);
  EXPECT_EQ(t.calls[0].depth, 1);
  EXPECT_EQ(t.calls[0].level, 2);        // POV-Ray's trace level ⌊1.5⌋ = 1, povtrace numbers it + 1
  EXPECT_EQ(t.calls[0].max_level, 5);
  EXPECT_DOUBLE_EQ(t.calls[0].weight, 0.5);
  EXPECT_DOUBLE_EQ(t.calls[0].adc_bailout, 0.01);
  EXPECT_FLOAT_EQ(t.calls[0].importance_queried, 0.0f);
  EXPECT_FLOAT_EQ(t.calls[34].importance_queried, 1.0f);
}

TEST(Gatherer, RadiusIsClampedToTheReuseBounds) {
  const RenderRadiosity rad = settings();
  for (const auto& [depth, expected] : {std::pair{0.01, 0.15f}, std::pair{50.0, 2.0f}, std::pair{HUGE_VAL, 2.0f}}) {
    Gatherer g(rad, camera);
    g.begin_block(0, final_pass_id);
    ScriptedTracer t;
    t.depth = depth;
    (void)g.ambient(at_origin(), t);
    ASSERT_EQ(g.block_samples().size(), 1u);
    EXPECT_FLOAT_EQ(g.block_samples()[0].geometry.radius, expected) << depth;
  }
}

TEST(Gatherer, AlmostTouchingHitKeepsTheSampleOutOfTheCache) {
  const RenderRadiosity rad = settings();
  Gatherer g(rad, camera);
  g.begin_block(0, final_pass_id);
  ScriptedTracer t;
  t.depth = 1e-4;   // not above 1e−4 × (0.2 × 10)
  const Vec3 a = g.ambient(at_origin(), t);
  EXPECT_NEAR(a.x, 0.5, 1e-12);
  EXPECT_TRUE(g.block_samples().empty());
}

TEST(Gatherer, ImportanceDropsRaysAndCompensatesTheKeptOnes) {
  const RenderRadiosity rad = settings();
  Gatherer g(rad, camera);
  g.begin_block(0, final_pass_id);
  ScriptedTracer t;
  t.importance = 0.5f;   // rays 0…17 of 35 kept (17/34 = 0.5), each with quality 35/18
  const Vec3 a = g.ambient(at_origin(), t);
  EXPECT_NEAR(a.x, 0.5, 1e-12);
  ASSERT_EQ(g.block_samples().size(), 1u);
  EXPECT_NEAR(g.block_samples()[0].geometry.quality, 1.0f, 1e-6);
}

TEST(Gatherer, PretraceNeedsEnoughWeightAndBlendsWhatItFound) {
  const RenderRadiosity rad = settings();
  Gatherer g(rad, camera);
  g.begin_block(3, 1);
  ScriptedTracer t;
  (void)g.ambient(at_origin(), t);
  t.colour = {1, 1, 1};
  // Σw = 1 at the same point: 4·1 < nearest_count 5, so it gathers again and blends 1:1.
  const Vec3 a = g.ambient(at_origin(), t);
  EXPECT_EQ(t.calls.size(), 70u);
  EXPECT_NEAR(a.x, 0.75, 1e-12);
  EXPECT_NEAR(a.y, 0.625, 1e-12);
  EXPECT_EQ(g.block_samples().size(), 2u);
  EXPECT_EQ(g.block_samples()[1].geometry.tile, 3);
  EXPECT_FLOAT_EQ(g.top_level_reuse(), 4.0f);   // 0 before the first gather, 4·1 before the second
}

TEST(Gatherer, CursorRunsOnWithinABlockAndRestartsPerBlock) {
  const RenderRadiosity rad = settings(5);
  Gatherer g(rad, camera);
  struct Recorder final : SampleTracer {
    std::vector<Vec3> directions;
    SampleRayResult trace_sample(Vec3, Vec3 d, const SampleRayParams&) override {
      directions.push_back(d);
      return SampleRayResult{{0, 0, 0}, 1, 1, true};
    }
  } r;
  g.begin_block(0, 1);
  (void)g.ambient(at_origin(), r);
  (void)g.ambient(AmbientQuery{{5, 0, 0}, {0, 1, 0}, {0, 1, 0}, 1.0, 0, 5}, r);
  g.begin_block(1, 1);
  (void)g.ambient(at_origin(), r);
  ASSERT_EQ(r.directions.size(), 15u);
  const DirectionPool pool(1600);
  for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(r.directions[i], pool[i]) << i;   // normal +y: as is
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(r.directions[10 + i], pool[i]) << i;
}

TEST(Gatherer, NormalOnShootsAroundTheLayerNormalAboveTheSurface) {
  RenderRadiosity rad = settings();
  rad.settings.normal = true;
  Gatherer g(rad, camera);
  g.begin_block(0, final_pass_id);
  struct Recorder final : SampleTracer {
    std::vector<Vec3> directions;
    SampleRayResult trace_sample(Vec3, Vec3 d, const SampleRayParams&) override {
      directions.push_back(d);
      return SampleRayResult{{1, 1, 1}, 1, 1, true};
    }
  } r;
  const Vec3 raw{0, 1, 0};
  const Vec3 bent = normalize(Vec3{0.3, 1, 0});
  (void)g.ambient(AmbientQuery{{0, 0, 0}, raw, bent, 1.0, 0, 5}, r);
  ASSERT_EQ(r.directions.size(), 35u);
  double towards_bend = 0;
  for (const Vec3& d : r.directions) {
    EXPECT_GT(dot(d, raw), 0);   // rejected below the raw surface
    towards_bend += d.x;
  }
  EXPECT_GT(towards_bend / 35, 0.1);   // centred on the bent normal, not on +y
  ASSERT_EQ(g.block_samples().size(), 1u);
  EXPECT_EQ(g.block_samples()[0].geometry.normal, bent);   // most rays used the bent frame
  // Without `normal on` the raw normal is used throughout.
  const RenderRadiosity plain = settings();
  Gatherer h(plain, camera);
  h.begin_block(0, final_pass_id);
  Recorder q;
  (void)h.ambient(AmbientQuery{{0, 0, 0}, raw, bent, 1.0, 0, 5}, q);
  const DirectionPool pool(1600);
  for (std::size_t i = 0; i < 35; ++i) EXPECT_EQ(q.directions[i], pool[i]);
  EXPECT_EQ(h.block_samples()[0].geometry.normal, raw);
}

TEST(Gatherer, AGatherBelowARayOverwritesTheImportanceItIsKeptBy) {
  // POV-Ray keeps the importance a sample ray found in the ticket, which the sample rays of a gather made while
  // shading its hit overwrite; GatherLight then keeps and compensates the ray by the last value written. Here every
  // ray hits an object of importance 1 whose shading "gathers" with a last ray that finds 0.25: of 5 rays only
  // i/4 ≤ 0.25 (i = 0, 1) are kept, each weighted 5/(⌊0.25·4⌋ + 1) = 2.5.
  const RenderRadiosity rad = settings(5);
  Gatherer g(rad, camera);
  g.begin_block(0, final_pass_id);
  struct Nested final : SampleTracer {
    Gatherer* g = nullptr;
    int i = 0;
    SampleRayResult trace_sample(Vec3, Vec3, const SampleRayParams& p) override {
      g->importance_found(1.0f);    // the ray's own hit, before shading
      g->importance_found(0.25f);   // the last sample ray of a gather below it
      SampleRayResult r;
      r.colour = Vec3{1, 1, 1} * static_cast<double>(i++);
      r.depth = 1;
      r.importance = 1.0f;
      r.kept = !(r.importance < p.importance_queried);
      return r;
    }
  } t;
  t.g = &g;
  const Vec3 a = g.ambient(at_origin(), t);
  EXPECT_EQ(t.i, 5);
  EXPECT_NEAR(a.x, 0.5, 1e-12);   // rays 0 and 1 only; the plain rule would keep all five (mean 2)
  ASSERT_EQ(g.block_samples().size(), 1u);
  EXPECT_NEAR(g.block_samples()[0].geometry.quality, 2 * 2.5 / 5, 1e-6);   // Σ quality / n
}

}  // namespace
