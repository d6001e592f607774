// Pooled transients (graph/pooling.h), the memory a backend without placed memory
// (WebGPU) allocates: a chain of same-sized targets ping-pongs between two objects, a
// different description never shares, outputs and persistent resources keep their own,
// --no-alias pools nothing; on the full frame the figure lies between the lower bound
// and the unaliased sum, and no object ever holds two resources alive together.
#include <gtest/gtest.h>

#include "graph/pooling.h"
#include "tests/fixtures/full_frame.h"

namespace volgraph {
namespace {

PassDecl blit_decl(Format out_format) {
  PassDecl d;
  d.name = "blit";
  d.kind = PassKind::compute;
  d.variants = {{"default", ""}};
  d.slots = {slot_optional_in("source", ResourceKind::texture2d, Usage::sampled, ""),
             slot_out("target", ResourceKind::texture2d, Usage::storage_write, out_format, SizeSpec::of_output(), "")};
  return d;
}

// p0 → p1 → … → p{n−1}, each reading the one before and writing a new target; the last
// target is the graph's output. `formats[i]` is the format p_i writes.
Graph chain(const std::vector<PassDecl>& decls) {
  GraphBuilder b({32, 16, 1}, 0);
  ResourceVersion previous{};
  for (size_t i = 0; i < decls.size(); ++i) {
    const uint32_t p = b.add_pass("p" + std::to_string(i), decls[i]);
    if (i > 0) b.read(p, 0, previous);
    previous = b.create(p, 1, resolve_slot(decls[i], decls[i].slots[1], {32, 16, 1}, 0));
  }
  b.mark_output(previous);
  return b.finish();
}

TEST(Pooling, AChainOfEqualTargetsPingPongsBetweenTwoObjects) {
  const PassDecl half = blit_decl(Format::rgba16_float);
  const Graph g = chain({half, half, half, half, half, half});
  const Plan plan = compile(g);
  const ResourcePool pool = pool_resources(g, plan);
  // Target i lives over passes [i, i + 1] (written by p_i, read by p_{i+1}); the last
  // one, the output, to the end. Neighbours overlap (p_{i+1} reads t_i while writing
  // t_{i+1}); every other one does not: t0, t2, t4 share one object, t1, t3, t5 another.
  EXPECT_EQ(pool.object_of[0], pool.object_of[2]);
  EXPECT_EQ(pool.object_of[2], pool.object_of[4]);
  EXPECT_EQ(pool.object_of[1], pool.object_of[3]);
  EXPECT_EQ(pool.object_of[3], pool.object_of[5]);
  EXPECT_NE(pool.object_of[0], pool.object_of[1]);
  EXPECT_EQ(pool.transient_objects, 2u);
  EXPECT_EQ(pool.transient_bytes, 2 * plan.placements[0].requirements.size);
}

TEST(Pooling, DifferentDescriptionsNeverShare) {
  const Graph g = chain({blit_decl(Format::rgba16_float), blit_decl(Format::rgba32_float), blit_decl(Format::rgba16_float),
                         blit_decl(Format::rgba32_float), blit_decl(Format::r32_float)});
  const ResourcePool pool = pool_resources(g, compile(g));
  EXPECT_EQ(pool.object_of[0], pool.object_of[2]);  // rgba16_float, lifetimes apart
  EXPECT_EQ(pool.object_of[1], pool.object_of[3]);  // rgba32_float, lifetimes apart
  EXPECT_NE(pool.object_of[0], pool.object_of[1]);  // apart in time, not in format
  EXPECT_NE(pool.object_of[4], pool.object_of[0]);  // r32_float: free, but a different format
  EXPECT_EQ(pool.transient_objects, 3u);
  for (const PooledObject& o : pool.objects) {
    for (uint32_t r : o.occupants) EXPECT_TRUE(poolable_together(o.desc, g.resources[r].desc)) << g.resources[r].desc.name;
  }
}

TEST(Pooling, NoAliasGivesEveryResourceItsOwnObject) {
  const PassDecl half = blit_decl(Format::rgba16_float);
  const Graph g = chain({half, half, half, half});
  const ResourcePool pool = pool_resources(g, compile(g, {.alias = false}));
  EXPECT_EQ(pool.transient_objects, 4u);
}

TEST(Pooling, FullFrameLiesBetweenTheLowerBoundAndTheUnaliasedSum) {
  const auto frame = fixtures::full_frame();
  const Plan plan = compile(frame.graph);
  const ResourcePool pool = pool_resources(frame.graph, plan);
  EXPECT_GE(pool.transient_bytes, plan.memory.lower_bound_bytes);
  EXPECT_LE(pool.transient_bytes, plan.memory.unaliased_bytes);
  EXPECT_LT(pool.transient_objects, plan.memory.transient_count);  // something is reused
  for (const PooledObject& o : pool.objects) {
    for (size_t i = 1; i < o.occupants.size(); ++i) {
      const Lifetime& before = plan.lifetimes[o.occupants[i - 1]];
      const Lifetime& after = plan.lifetimes[o.occupants[i]];
      EXPECT_LT(before.last, after.first) << o.desc.name;
    }
    if (o.persistent) EXPECT_EQ(o.occupants.size(), 1u);
  }
}

}  // namespace
}  // namespace volgraph
