// Cached persistent outputs (PassDecl::cached) on both backends, under validation: demo_fog
// at a small size, whose opacity_shadow_map is cached — its key (its type, variant and
// parameters, the scene's lights and media, and its input light_view, whose key is
// shadow_map's: the camera, lights, geometry and media) holds still between frames. The
// reference is the same graph with the pass's decl copied and `cached` off (the pass runs
// every frame into the same persistent map), run frame for frame beside it:
// - the pass runs on the first frame and is skipped on the next ones;
// - skipping changes nothing: every frame's image is bit for bit the reference's (with
//   and without read-backs between frames);
// - a change of the scene's media, or of its camera (through shadow_map's light view),
//   makes it run again on the next frame, with the scene as it is now (the image is the
//   reference's under the same change), then it is skipped again; a part of the scene
//   neither key holds (the background) does not.
// The optical depth itself is not read back: froxel_scatter and the scene pass both
// sample it, and a read-back's transition is made from the last reader's stage alone.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/scene/scene.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/shipped_configs.h"

namespace volgraph::testing {
namespace {

constexpr const char* kCachedType = "opacity_shadow_map";

class PassCache : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }

  std::unique_ptr<LoadedConfig> load(std::vector<std::string> sets = {}) {
    Overrides o;
    o.size = kConfigTestSize;  // 64 × 36
    o.sets = std::move(sets);
    return std::make_unique<LoadedConfig>(load_config(config_path("demo_fog.json"), registry_, o));
  }

  // The graph pass of the cached type.
  static uint32_t cached_pass(const Graph& g) {
    for (uint32_t p = 0; p < g.passes.size(); ++p) {
      if (g.passes[p].decl->name == kCachedType) return p;
    }
    ADD_FAILURE() << "no " << kCachedType << " pass";
    return 0;
  }
  // The same graph with the pass not cached (its decl a copy, `cached` off): it runs
  // every frame, into the same persistent resources.
  void uncache(LoadedConfig& c) {
    GraphPass& pass = c.graph.passes[cached_pass(c.graph)];
    uncached_decls_.push_back(std::make_unique<PassDecl>(*pass.decl));
    uncached_decls_.back()->cached = false;
    pass.decl = uncached_decls_.back().get();
  }

  // One frame: whether the pass was skipped, and the frame's image.
  struct Frame {
    bool cached = false;
    Texels image;
  };
  static Frame run(Executor& e, const LoadedConfig& c, bool read = true) {
    Frame f;
    e.run_frame();
    if (read) f.image = e.read_output(0);
    bool found = false;
    for (const PassTiming& t : e.timings()) {
      if (t.type != kCachedType) continue;
      f.cached = t.cached;
      found = true;
    }
    EXPECT_TRUE(found) << "no timing for " << kCachedType << " in " << c.graph.passes.size() << " passes";
    return f;
  }

  PassRegistry registry_;
  std::vector<std::unique_ptr<PassDecl>> uncached_decls_;
};

// Frames 2 and 3 skip the pass; every frame's image is bit for bit the one of the graph
// whose pass runs every frame (its optical depth, which froxel_scatter and the scene's
// surfaces read, is what the pass would write again).
TEST_P(PassCache, TheOpacityShadowMapRunsOnceAndSkippingChangesNothing) {
  const std::unique_ptr<LoadedConfig> cached = load(), uncached = load();
  const GraphPass& pass = cached->graph.passes[cached_pass(cached->graph)];
  ASSERT_TRUE(pass.decl->cached);
  for (const ResourceUse& u : pass.uses) {
    if (u.direction == SlotDirection::output) EXPECT_TRUE(cached->graph.resources[u.resource].desc.persistent);
  }
  uncache(*uncached);
  Executor a(device(), cached->graph, &cached->config.scene, {});
  Executor b(device(), uncached->graph, &uncached->config.scene, {});
  Texels last;
  for (int frame = 1; frame <= 3; ++frame) {
    const Frame fa = run(a, *cached), fb = run(b, *uncached);
    EXPECT_EQ(fa.cached, frame > 1) << "frame " << frame;
    EXPECT_FALSE(fb.cached) << "frame " << frame;
    ASSERT_FALSE(fa.image.rgba.empty());
    EXPECT_TRUE(fa.image.rgba == fb.image.rgba) << "frame " << frame << ": the image differs";
    last = fa.image;
  }
  // The comparison sees the map: a slightly different one (one march step per layer
  // instead of two) gives a different third frame.
  const std::unique_ptr<LoadedConfig> coarser = load({"media_shadow.steps_per_layer=1"});
  uncache(*coarser);
  Executor d(device(), coarser->graph, &coarser->config.scene, {});
  for (int frame = 1; frame < 3; ++frame) run(d, *coarser, false);
  EXPECT_FALSE(run(d, *coarser).image.rgba == last.rgba);
}

// The same without reading anything back in between (a read-back adds barriers of its
// own): frames that skip the pass leave its map as the plan expects it.
TEST_P(PassCache, SkippedFramesWithoutReadBacksKeepTheMap) {
  const std::unique_ptr<LoadedConfig> cached = load(), uncached = load();
  uncache(*uncached);
  Executor a(device(), cached->graph, &cached->config.scene, {});
  Executor b(device(), uncached->graph, &uncached->config.scene, {});
  for (int frame = 1; frame <= 3; ++frame) {
    EXPECT_EQ(run(a, *cached, false).cached, frame > 1) << "frame " << frame;
    run(b, *uncached, false);
  }
  const Frame fa = run(a, *cached), fb = run(b, *uncached);
  EXPECT_TRUE(fa.cached);
  EXPECT_TRUE(fa.image.rgba == fb.image.rgba);
}

// A change of what the pass reads — the media, or the camera through shadow_map's light
// view — makes it run again on the next frame, with the scene as it is now: its image is
// the uncached graph's under the same change, bit for bit; then it is skipped again. A
// part of the scene neither reads (the background) changes nothing.
TEST_P(PassCache, AChangedSceneRunsThePassAgain) {
  const std::unique_ptr<LoadedConfig> cached = load(), uncached = load();
  uncache(*uncached);
  ASSERT_FALSE(cached->config.scene.media.volumes.empty());
  Executor a(device(), cached->graph, &cached->config.scene, {});
  Executor b(device(), uncached->graph, &uncached->config.scene, {});
  auto both = [&](const char* what, bool expect_cached) {
    const Frame fa = run(a, *cached), fb = run(b, *uncached);
    EXPECT_EQ(fa.cached, expect_cached) << what;
    EXPECT_TRUE(fa.image.rgba == fb.image.rgba) << what << ": the image differs from the uncached graph's";
    return fa;
  };
  both("frame 1", false);
  const Frame unchanged = both("frame 2", true);

  // The fog ball, denser: its shadow in the fog and on the ground darkens.
  for (LoadedConfig* c : {cached.get(), uncached.get()}) {
    for (double& v : c->config.scene.media.volumes[0].medium.sigma_s) v *= 4.0;
  }
  const Frame denser = both("the media changed", false);
  EXPECT_FALSE(denser.image.rgba == unchanged.image.rgba);
  both("nothing changed since the media did", true);

  // The camera: shadow_map's directional fit follows it, so its light view changes, and
  // with it the key of the pass that reads it.
  for (LoadedConfig* c : {cached.get(), uncached.get()}) c->config.scene.camera.position[0] += 0.5;
  both("the camera moved", false);
  both("nothing changed since the camera moved", true);

  for (LoadedConfig* c : {cached.get(), uncached.get()}) {
    for (double& v : c->config.scene.background) v *= 2.0;
  }
  both("the background is in neither key", true);
}

// When it runs again it reads the scene as it is then, not as it was on its first frame:
// with every frame alike (no jitter, no accumulation), the image after the media change is
// a fresh executor's first frame of the changed scene.
TEST_P(PassCache, ARunAfterAChangeReadsTheSceneAsItIsNow) {
  const std::vector<std::string> still = {"fog_media.jitter=false", "fog_temporal.alpha=1"};
  const std::unique_ptr<LoadedConfig> c = load(still);
  Executor e(device(), c->graph, &c->config.scene, {});
  run(e, *c);
  EXPECT_TRUE(run(e, *c).cached);
  for (double& v : c->config.scene.media.volumes[0].medium.sigma_s) v *= 4.0;
  const Frame changed = run(e, *c);
  EXPECT_FALSE(changed.cached);
  Executor fresh(device(), c->graph, &c->config.scene, {});
  EXPECT_TRUE(run(fresh, *c).image.rgba == changed.image.rgba);
}

INSTANTIATE_TEST_SUITE_P(Backends, PassCache, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
